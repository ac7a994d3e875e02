/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemCellBonds.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/math/GroupByKey.hpp>
#include <algorithm>

namespace yade {

long RdemCellBonds::generation = 0;

void RdemCellBonds::refresh(const Scene* scene)
{
	const long nB = long(scene->bodies->size()), nI = long(scene->interactions->size());
	if (builtGeneration == generation && builtInteractions == nI && builtBodies == nB) return;
	bonds.clear();
	vector<Body::id_t> bodyOfSide;
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		const auto* p = dynamic_cast<const RdemPhys*>(I->phys.get());
		if (!p || (p->cellCoef1 == 0 && p->cellCoef2 == 0)) continue;
		bonds.push_back(I);
		bodyOfSide.push_back(I->getId1());
		bodyOfSide.push_back(I->getId2());
	}
	vector<size_t> order;
	rdem::groupByKey(bodyOfSide, size_t(nB), first, order);
	sides.clear();
	sides.reserve(order.size());
	for (size_t side : order)
		sides.push_back(Side { bonds[side / 2], side % 2 == 1 });
	auto other = [](const Side& s) { return s.second ? s.I->getId1() : s.I->getId2(); };
	for (size_t b = 0; b + 1 < first.size(); ++b)
		std::sort(sides.begin() + long(first[b]), sides.begin() + long(first[b + 1]), [&](const Side& x, const Side& y) { return other(x) < other(y); });
	builtGeneration   = generation;
	builtInteractions = nI;
	builtBodies       = nB;
}

} // namespace yade
