/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemContactGate.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Collider.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/RdemBlock.hpp>
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
		parent[size_t(findRoot(parent, I->getId1()))] = findRoot(parent, I->getId2());
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
	for (const auto& e : scene->engines)
		if (dynamic_cast<Collider*>(e.get())) e->dead = deadFlag;
}

void RdemContactGate::action()
{
	if (open) {
		// Latched (possibly set by the user or restored by O.load): make sure the collider runs.
		if (reason.empty()) {
			reason = "opened by the user";
			setColliders(false);
		}
		return;
	}
	if (Law2_RdemGeom_RdemPhys_FaceSprings::brokenSprings(scene) > 0) reason = "a restoring spring broke";
	else if (long(scene->bodies->size()) != nBodies || long(scene->interactions->size()) != nInteractions) {
		reason        = topologyReason();
		nBodies       = long(scene->bodies->size());
		nInteractions = long(scene->interactions->size());
	}
	open = !reason.empty();
	setColliders(!open);
	if (open) LOG_INFO("contact detection on from iteration " << scene->iter << ": " << reason);
}

} // namespace yade
