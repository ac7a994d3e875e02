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
	staleSides        = 0;
}

void RdemForceAssembler::addSides(const vector<RdemSharedState::JoinedPhys>& joined)
{
	const size_t                        nBodies = first.size() - 1;
	vector<std::pair<Body::id_t, Side>> add; // (body, side) to add
	for (const auto& j : joined)
		for (const bool second : { false, true }) {
			const Body::id_t body = second ? j.id2 : j.id1;
			if (body < 0 || size_t(body) >= nBodies) return rebuild();
			bool present = false; // back after a pause, and still in the list
			for (size_t k = first[size_t(body)]; k < first[size_t(body) + 1] && !present; ++k)
				present = sides[k].phys == j.phys;
			if (!present) add.emplace_back(body, Side { j.phys, second ? j.id1 : j.id2, second });
		}
	if (add.empty()) return;
	std::sort(add.begin(), add.end(), [](const std::pair<Body::id_t, Side>& x, const std::pair<Body::id_t, Side>& y) {
		return x.first != y.first ? x.first < y.first : x.second.other < y.second.other;
	});
	// One pass: each body's list merged with its new sides by the other body's id (a side that stopped, skipped in the
	// sums, may share its other body with a new one: their order does not matter).
	vector<Side>   merged;
	vector<size_t> mergedFirst(nBodies + 1);
	merged.reserve(sides.size() + add.size());
	size_t a = 0;
	for (size_t b = 0; b < nBodies; ++b) {
		mergedFirst[b] = merged.size();
		size_t k       = first[b];
		for (;;) {
			const bool fromAdd = a < add.size() && size_t(add[a].first) == b;
			if (!fromAdd && k == first[b + 1]) break;
			if (fromAdd && (k == first[b + 1] || add[a].second.other < sides[k].other)) merged.push_back(std::move(add[a++].second));
			else
				merged.push_back(std::move(sides[k++]));
		}
	}
	mergedFirst[nBodies] = merged.size();
	sides.swap(merged);
	first.swap(mergedFirst);
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
	RdemSharedState& sh      = RdemSharedState::of(scene, shared);
	const int        changes = sh.takeActiveSetChanges();
	const auto       joined  = sh.takeJoined();
	staleSides += 2 * size_t(std::max(0, changes - int(joined.size()))); // the interactions that stopped
	const bool missed = builtIter != scene->iter - 1 || builtBodies != long(scene->bodies->size());
	if (!incremental) {
		if (changes > 0 || missed || builtInteractions != long(scene->interactions->size())) rebuild();
	} else if (missed || staleSides > sides.size() / 8)
		rebuild();
	else if (!joined.empty())
		addSides(joined);
	builtIter          = scene->iter;
	const long nBodies = long(scene->bodies->size());
	prepareDirectSums(scene, nBodies);
	const bool energies = scene->trackEnergy;
	if (energies) bodyEnergies.assign(size_t(nBodies), rdem::SpringEnergies<Real>());
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
			if (energies && !s.second && p->energyIter == scene->iter) bodyEnergies[size_t(id)] += p->stepEnergies; // once, with body 1
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
	if (energies) bookEnergies(sh);
}

void RdemForceAssembler::bookEnergies(RdemSharedState& sh)
{
	rdem::SpringEnergies<Real> sum;
	for (const auto& e : bodyEnergies) // bodies by id, each its interactions by the other body's id
		sum += e;
	sum += sh.takeReleasedEnergies();
	sh.bookSpringEnergies(scene, sum);
}

} // namespace yade
