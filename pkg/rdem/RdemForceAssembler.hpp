/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>
#include <core/Interaction.hpp>
#include <pkg/rdem/RdemSharedState.hpp>

namespace yade {

/// Sums the interaction forces of Law2_RdemGeom_RdemPhys_FaceSprings per body, in the order of the other body's id.
class RdemForceAssembler : public GlobalEngine {
public:
	void action() override;
	/// Makes scene->forces ready for per-body sums added with addForceUnsynced/addTorqueUnsynced over bodies
	/// 0 … nBodies-1, each body by one thread only (see the definition for why); call it outside a parallel region.
	static void prepareDirectSums(Scene* scene, long nBodies);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemForceAssembler,GlobalEngine,R"""(Applies the forces and torques that :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` left in :yref:`RdemPhys` (with :yref:`Law2_RdemGeom_RdemPhys_FaceSprings::deferForces`), summing them body by body in the order of the other body's id.

Floating-point sums depend on their order. The law alone adds its forces in the order of the interaction container, which ``O.load`` changes (interactions without geometry, e.g. released bonds, are not saved and come back at the end of the container when the collider finds the pair again); the sum of a body's forces then differs in the last bits and a reloaded run drifts from the uninterrupted one. Summed here in a fixed order, it continues bit for bit (tests/yade/test_save_load.py), and the result no longer depends on the number of threads. With :yref:`O.trackEnergy<Omega.trackEnergy>` it books the law's energies of the step as well (``rdemElastic``, ``rdemDashpot``, …), summed in the same fixed order (each interaction with its first body, bodies by id, then the bonds released in the step by their ids): the energies of a reloaded run continue to the bit too, and do not depend on the number of threads. Place it right after the :yref:`InteractionLoop` (``rdem.engines()`` does).

The per-body lists, sorted by the other body's id, are kept from step to step. The interactions that the law reports as starting to leave forces (in :yref:`RdemSharedState`) are merged into them in one pass (``incremental``); those that stop stay in the lists, skipped (their physics has an old ``forceIter``), until they make up an eighth of the lists, or the number of bodies changes, or the assembler missed a step: then the lists are built again from the interactions. A step costs one pass over the lists, and one more in a step in which contacts start.)""",
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`, handed by ``rdem.engines()``; None: the law's, taken at the first step)."))
		((bool,incremental,true,Attr::noSave,"Merge the interactions that start leaving forces into the lists (default); False: build the lists again from all interactions whenever an interaction starts or stops, or their number changes (the reference that tests/yade/test_force_assembler.py compares against; the same sums, in the same order). Not saved."))
	);
	// clang-format on

private:
	/// One side of an interaction in a body's list: the interaction's physics (held directly, one pointer less to follow
	/// each step), the other body, and whether the body is the interaction's second body.
	struct Side {
		shared_ptr<IPhys> phys;
		Body::id_t        other;
		bool              second;
	};
	vector<size_t>                     first; // the list of body b is sides[first[b] .. first[b+1]) (not saved: rebuilt after O.load)
	vector<Side>                       sides; // all lists, bodies in id order, each sorted by the other body's id
	long                               builtIter = -1, builtBodies = -1, builtInteractions = -1;
	size_t                             staleSides = 0; // sides of interactions that stopped leaving forces since the last rebuild, at most
	vector<rdem::SpringEnergies<Real>> bodyEnergies;   // with O.trackEnergy: the energies of each body's interactions as body 1, this step
	void                               rebuild();
	/// Books the energies of the step (bodyEnergies, then the interactions released in it) in that order.
	void bookEnergies(RdemSharedState& sh);
	/// Merges the sides of the joined physics that are not in the lists yet into them, each list staying sorted.
	void addSides(const vector<RdemSharedState::JoinedPhys>& joined);
};
REGISTER_SERIALIZABLE(RdemForceAssembler);

} // namespace yade
