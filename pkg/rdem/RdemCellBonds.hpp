/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Interaction.hpp>
#include <core/Scene.hpp>

namespace yade {

/* The bonds of the Poisson cells (doc/theory.md §5.4), listed once and per body, for RdemCellStrainUpdater and the
   cells of RdemPoissonEngine. Not a YADE class: each engine keeps its own lists, rebuilt when the bodies, the
   interactions or the cells (a new RdemPoissonEngine.build) changed. */
class RdemCellBonds {
public:
	/// One side of a bond in a body's list: the interaction (held, so that a released bond is seen as not real) and
	/// whether the body is its second body.
	struct Side {
		shared_ptr<Interaction> I;
		bool                    second;
	};
	/// Rebuilds the lists if the scene changed since the last call.
	void refresh(const Scene* scene);
	/// Number of bodies the per-body lists cover.
	size_t nBodies() const { return first.empty() ? 0 : first.size() - 1; }
	/// Every bond with a cell coefficient, in the container's order.
	vector<shared_ptr<Interaction>> bonds;
	/// Body b's bonds are sides[first[b]] … sides[first[b+1] - 1], sorted by the other body's id.
	vector<size_t> first;
	vector<Side>   sides;
	/// Incremented by RdemPoissonEngine::build: lists made before it are rebuilt.
	static long generation;

private:
	long builtGeneration = -1, builtInteractions = -1, builtBodies = -1;
};

} // namespace yade
