/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/OpenMPLoops.hpp>
#include <pkg/rdem/RdemForceAssembler.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/math/GroupByKey.hpp>
#include <algorithm>

namespace yade {

YADE_PLUGIN((RdemForceAssembler));

void RdemForceAssembler::rebuild()
{
	/* Sides grouped by body (rdem::groupByKey, a counting sort), then each body's short list sorted by the other body's
	   id: O(sides) plus a few comparisons per side, instead of one sort of all sides (the rebuild runs at nearly every
	   step once contacts come and go). Side 2k is interaction k seen from its first body, 2k+1
	   from its second. */
	const size_t               nBodies = scene->bodies->size();
	vector<const Interaction*> intrs; // the real interactions of the law, in container order
	vector<Body::id_t>         bodyOfSide;
	for (const auto& I : *scene->interactions) {
		if (!I->isReal() || !dynamic_cast<const RdemPhys*>(I->phys.get())) continue;
		intrs.push_back(I.get());
		bodyOfSide.push_back(I->getId1());
		bodyOfSide.push_back(I->getId2());
	}
	vector<size_t> order;
	rdem::groupByKey(bodyOfSide, nBodies, first, order);
	sides.clear();
	sides.reserve(order.size());
	for (size_t side : order) {
		const Interaction& I      = *intrs[side / 2];
		const bool         second = side % 2 == 1;
		sides.push_back(Side { I.phys, second ? I.getId1() : I.getId2(), second });
	}
	for (size_t b = 0; b < nBodies; ++b)
		std::sort(sides.begin() + long(first[b]), sides.begin() + long(first[b + 1]), [](const Side& x, const Side& y) { return x.other < y.other; });
	builtBodies       = long(nBodies);
	builtInteractions = long(scene->interactions->size());
}

void RdemForceAssembler::prepareDirectSums(Scene* scene, long nBodies)
{
	/* Per-body sums (each body written by one thread only) go straight into the container's synced arrays
	   (ForceContainer::addForceUnsynced), to which sync() adds the other engines' per-thread contributions; permanent
	   forces still mark the container unsynced at its reset. ForceContainer::addForce writes the container's shared flag
	   and per-thread maximum id at every call, a cache line every thread writes: its cost did not fall with a second
	   thread. The container is first made to cover every body. */
	if (nBodies <= 0) return;
	scene->forces.addMaxId(Body::id_t(nBodies - 1));
	scene->forces.syncSizesOfContainers();
}

void RdemForceAssembler::action()
{
	const bool changed = RdemSharedState::of(scene, shared).takeActiveSetChanged();
	if (changed || builtIter != scene->iter - 1 || builtBodies != long(scene->bodies->size()) || builtInteractions != long(scene->interactions->size()))
		rebuild();
	builtIter          = scene->iter;
	const long nBodies = long(scene->bodies->size());
	prepareDirectSums(scene, nBodies);
	/* Bodies in descending id order: the law has just written the forces in the order of the interaction container,
	   which is about ascending body ids, so the physics it wrote last are read first, while they are still in the cache
	   (in cubes beyond the last-level cache, the ones it wrote first are gone by then); and the next step's interaction
	   loop starts where this pass ends. The order of each body's own sum is unchanged. */
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(ompThreads))
#endif
	for (long r = 0; r < nBodies; ++r) {
		const long id = nBodies - 1 - r;
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
