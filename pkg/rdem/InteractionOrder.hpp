/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Scene.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <algorithm>
#include <utility>

namespace yade {
namespace rdem {

	/* The real interactions of the plugin (RdemGeom and RdemPhys) in the order of their bodies' ids. Sums over them do
	   not depend on the order of the interaction container, which O.load (interactions without geometry are not saved
	   and come back at its end) and the collider change: a reloaded run then takes the same time steps to the last bit. */
	inline vector<const Interaction*> interactionsInIdOrder(const Scene* scene)
	{
		vector<const Interaction*> out;
		for (const auto& I : *scene->interactions)
			if (I->isReal() && dynamic_cast<const RdemGeom*>(I->geom.get()) && dynamic_cast<const RdemPhys*>(I->phys.get())) out.push_back(I.get());
		std::sort(out.begin(), out.end(), [](const Interaction* a, const Interaction* b) {
			return std::make_pair(a->getId1(), a->getId2()) < std::make_pair(b->getId1(), b->getId2());
		});
		return out;
	}

} // namespace rdem
} // namespace yade
