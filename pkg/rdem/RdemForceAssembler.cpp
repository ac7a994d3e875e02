/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemForceAssembler.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <algorithm>

namespace yade {

YADE_PLUGIN((RdemForceAssembler));

void RdemForceAssembler::rebuild()
{
	const size_t nBodies = scene->bodies->size();
	vector<std::pair<Body::id_t, Side>> all; // (body, side), ordered below by body, then by the other body's id
	for (const auto& I : *scene->interactions) {
		if (!I->isReal() || !dynamic_cast<const RdemPhys*>(I->phys.get())) continue;
		all.push_back({ I->getId1(), Side { I, false } });
		all.push_back({ I->getId2(), Side { I, true } });
	}
	auto other = [](const std::pair<Body::id_t, Side>& e) { return e.second.second ? e.second.interaction->getId1() : e.second.interaction->getId2(); };
	std::sort(all.begin(), all.end(), [&](const auto& a, const auto& b) { return a.first != b.first ? a.first < b.first : other(a) < other(b); });
	first.assign(nBodies + 1, 0);
	sides.clear();
	sides.reserve(all.size());
	for (const auto& e : all) {
		++first[size_t(e.first) + 1];
		sides.push_back(e.second);
	}
	for (size_t b = 0; b < nBodies; ++b)
		first[b + 1] += first[b];
	builtBodies       = long(nBodies);
	builtInteractions = long(scene->interactions->size());
}

void RdemForceAssembler::action()
{
	const bool changed = Law2_RdemGeom_RdemPhys_FaceSprings::takeActiveSetChanged(scene);
	if (changed || builtIter != scene->iter - 1 || builtBodies != long(scene->bodies->size())
	    || builtInteractions != long(scene->interactions->size()))
		rebuild();
	builtIter          = scene->iter;
	const long nBodies = long(scene->bodies->size());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static)
#endif
	for (long id = 0; id < nBodies; ++id) {
		if (first[size_t(id)] == first[size_t(id) + 1]) continue;
		Vector3r f = Vector3r::Zero(), t = Vector3r::Zero();
		for (size_t k = first[size_t(id)]; k < first[size_t(id) + 1]; ++k) {
			const Side& s = sides[k];
			const auto* p = static_cast<const RdemPhys*>(s.interaction->phys.get());
			if (!p || p->forceIter != scene->iter) continue; // not deferred, or not computed in this step
			if (s.second) {
				f += p->force;
				t += p->torque2;
			} else {
				f -= p->force;
				t += p->torque1;
			}
		}
		scene->forces.addForce(Body::id_t(id), f);
		scene->forces.addTorque(Body::id_t(id), t);
	}
}

} // namespace yade
