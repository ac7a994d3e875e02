/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/InteractionLoop.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Collider.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/OpenMPLoops.hpp>
#include <pkg/rdem/RdemBlock.hpp>
#include <pkg/rdem/RdemContactGate.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/math/SeparationBound.hpp>
#include <atomic>
#include <numeric>

namespace yade {

YADE_PLUGIN((RdemContactGate));
CREATE_LOGGER(RdemContactGate);

namespace {
	/// Root of x in a union-find forest, with path halving.
	long findRoot(vector<long>& parent, long x)
	{
		while (parent[size_t(x)] != x)
			x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
		return x;
	}

	/// Epochs of travel records, unique in the process: a certificate made against one record never matches another.
	std::atomic<long> lastEpoch { 0 };

	/// Circumradius of a body's block about its centroid [m]; 0 for other shapes (the functor sees only blocks).
	Real blockRadius(const Shape* shape)
	{
		const auto* block = dynamic_cast<const RdemBlock*>(shape);
		return block ? block->extents.norm() : Real(0);
	}
}

void RdemContactGate::updateTravel(rdem::BodyTravel& t)
{
	const long nBodiesNow = long(scene->bodies->size());
	bool       restart    = t.iter != scene->iter - 1 || long(t.travel.size()) != nBodiesNow;
	if (restart) {
		t.travel.assign(size_t(nBodiesNow), 0);
		t.body.assign(size_t(nBodiesNow), nullptr);
		t.shape.assign(size_t(nBodiesNow), nullptr);
		t.pos.resize(size_t(nBodiesNow));
		t.ori.resize(size_t(nBodiesNow));
		t.radius.assign(size_t(nBodiesNow), 0);
	}
	// A body or shape that is not the one seen in the last step (erased, replaced, first step) restarts the record.
	bool replaced = false;
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) reduction(|| : replaced) num_threads(rdem::threadsFor(ompThreads))
#endif
	for (long id = 0; id < nBodiesNow; ++id) {
		const Body* b = Body::byId(Body::id_t(id), scene).get();
		if (!b) {
			replaced           = replaced || t.body[size_t(id)];
			t.body[size_t(id)] = nullptr;
			continue;
		}
		const State& s = *b->state;
		// The same body and shape as in the last step, and a block's extents not changed in place (radius > 0: a block).
		const bool same = b == t.body[size_t(id)] && b->shape.get() == t.shape[size_t(id)]
		        && !(t.radius[size_t(id)] > 0 && static_cast<const RdemBlock*>(b->shape.get())->extents.norm() != t.radius[size_t(id)]);
		if (!same) {
			replaced             = true;
			t.body[size_t(id)]   = b;
			t.shape[size_t(id)]  = b->shape.get();
			t.radius[size_t(id)] = blockRadius(b->shape.get());
		} else
			t.travel[size_t(id)] += rdem::rigidTravel<Real>(t.pos[size_t(id)], t.ori[size_t(id)], s.pos, s.ori, t.radius[size_t(id)]);
		t.pos[size_t(id)] = s.pos;
		t.ori[size_t(id)] = s.ori;
	}
	if (restart || replaced) {
		std::fill(t.travel.begin(), t.travel.end(), Real(0));
		t.epoch = ++lastEpoch;
	}
	t.iter = scene->iter;
}

string RdemContactGate::topologyReason() const
{
	const long   nb = long(scene->bodies->size());
	vector<long> parent(static_cast<size_t>(nb), 0);
	std::iota(parent.begin(), parent.end(), 0L);
	vector<char> bonded(static_cast<size_t>(nb), 0);
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		const auto* g = dynamic_cast<const RdemGeom*>(I->geom.get());
		if (!g || g->nSegments() == 0)
			return "interaction #" + std::to_string(I->getId1()) + "+#" + std::to_string(I->getId2()) + " is a contact, not a bond";
		bonded[size_t(I->getId1())] = bonded[size_t(I->getId2())] = 1;
		parent[size_t(findRoot(parent, I->getId1()))]             = findRoot(parent, I->getId2());
	}
	long root = -1, nBlocks = 0;
	for (long id = 0; id < nb; ++id) {
		const auto& b = Body::byId(Body::id_t(id), scene);
		if (!b) continue;
		if (!dynamic_cast<const RdemBlock*>(b->shape.get())) return "body #" + std::to_string(id) + " is not an RdemBlock";
		++nBlocks;
		if (!bonded[size_t(id)]) continue;
		const long r = findRoot(parent, id);
		if (root < 0) root = r;
		else if (r != root)
			return "bodies #" + std::to_string(root) + " and #" + std::to_string(id) + " belong to two assemblies that are not bonded together";
	}
	for (long id = 0; id < nb; ++id)
		if (Body::byId(Body::id_t(id), scene) && !bonded[size_t(id)] && nBlocks > 1) return "block #" + std::to_string(id) + " has no bond";
	return "";
}

void RdemContactGate::setColliders(bool deadFlag) const
{
	rdem::forEachEngine<Collider>(scene, [&](Collider& collider) { collider.dead = deadFlag; });
}

void RdemContactGate::action()
{
	RdemSharedState& sh = RdemSharedState::of(scene, shared); // checks the engines when they changed: before the loop makes forces
	if (open) {
		// Latched (possibly set by the user or restored by O.load): make sure the collider runs.
		if (reason.empty()) {
			reason = "opened by the user";
			setColliders(false);
		}
		updateTravel(sh.travel);
		return;
	}
	if (sh.brokenSprings() > 0) reason = "a restoring spring broke";
	else if (long(scene->bodies->size()) != nBodies || long(scene->interactions->size()) != nInteractions) {
		reason        = topologyReason();
		nBodies       = long(scene->bodies->size());
		nInteractions = long(scene->interactions->size());
	}
	open = !reason.empty();
	setColliders(!open);
	if (open) {
		LOG_INFO("contact detection on from iteration " << scene->iter << ": " << reason);
		updateTravel(sh.travel);
	}
}

} // namespace yade
