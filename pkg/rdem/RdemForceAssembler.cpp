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
	/* Counting sort by body id (one pass to count each body's sides, one to place them), then each body's short list
	   sorted by the other body's id: O(sides) plus a few comparisons per side, instead of one sort of all sides (the
	   rebuild runs at nearly every step once contacts come and go, doc/performance.md). */
	const size_t                           nBodies = scene->bodies->size();
	vector<const shared_ptr<Interaction>*> intrs; // the real interactions of the law, in container order
	first.assign(nBodies + 1, 0);
	for (const auto& I : *scene->interactions) {
		if (!I->isReal() || !dynamic_cast<const RdemPhys*>(I->phys.get())) continue;
		intrs.push_back(&I);
		++first[size_t(I->getId1()) + 1];
		++first[size_t(I->getId2()) + 1];
	}
	for (size_t b = 0; b < nBodies; ++b)
		first[b + 1] += first[b];
	sides.assign(first[nBodies], Side { nullptr, -1, false });
	vector<size_t> fill(first.begin(), first.end() - 1);
	for (const shared_ptr<Interaction>* I : intrs) {
		sides[fill[size_t((*I)->getId1())]++] = Side { (*I)->phys, (*I)->getId2(), false };
		sides[fill[size_t((*I)->getId2())]++] = Side { (*I)->phys, (*I)->getId1(), true };
	}
	for (size_t b = 0; b < nBodies; ++b)
		std::sort(sides.begin() + long(first[b]), sides.begin() + long(first[b + 1]), [](const Side& x, const Side& y) { return x.other < y.other; });
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
	if (nBodies == 0) return;
	/* Each body's sum goes straight into the container's synced arrays (addForceUnsynced), which sync() adds the
	   per-thread contributions to: every body is written by one thread only. ForceContainer::addForce writes the
	   container's shared flag and per-thread maximum id at every call, a cache line both threads write; its cost did
	   not fall with a second thread (doc/performance.md). The sizes are made to cover every body first. */
	scene->forces.addMaxId(Body::id_t(nBodies - 1));
	scene->forces.syncSizesOfContainers();
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static)
#endif
	for (long id = 0; id < nBodies; ++id) {
		if (first[size_t(id)] == first[size_t(id) + 1]) continue;
		Vector3r f = Vector3r::Zero(), t = Vector3r::Zero();
		for (size_t k = first[size_t(id)]; k < first[size_t(id) + 1]; ++k) {
			const Side& s = sides[k];
			// Not deferred, or not computed in this step (also a physics the interaction has dropped since the lists were
			// built: held here, it is still valid, and its forceIter is old).
			const auto* p = static_cast<const RdemPhys*>(s.phys.get());
			if (p->forceIter != scene->iter) continue;
			if (s.second) {
				f += p->force;
				t += p->torque2;
			} else {
				f -= p->force;
				t += p->torque1;
			}
		}
		scene->forces.addForceUnsynced(Body::id_t(id), f);
		scene->forces.addTorqueUnsynced(Body::id_t(id), t);
	}
}

} // namespace yade
