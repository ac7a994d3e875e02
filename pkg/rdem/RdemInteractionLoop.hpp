/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/InteractionLoop.hpp>
#include <pkg/rdem/RdemSharedState.hpp>

namespace yade {

class Ig2_RdemBlock_RdemBlock_RdemGeom;
class Law2_RdemGeom_RdemPhys_FaceSprings;
class RdemGap;

/// YADE's InteractionLoop that does not visit the pairs of blocks known apart (RdemGap) while the geometry functor's test would find them apart.
class RdemInteractionLoop : public InteractionLoop {
public:
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemInteractionLoop,InteractionLoop,R"""(:yref:`InteractionLoop` of a refined-DEM scene (``rdem.engines()`` makes it): the same dispatchers, functors, callbacks and special constructor, and the same work for every interaction it visits, but it does not visit the pairs of blocks that :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` found apart while its test would find them apart again: by their certificate, or by their witness axis (below).

After the first crack many of the collider's pairs are grid neighbours whose bounding boxes overlap but which are apart by a strain-sized gap (6628 of the 12 650 interactions of the paper's cube loaded at 20 mm/s to three times its first-break displacement, 17 372 of 126 232 in the collapse of 10⁴ blocks after 3000 steps; pairs that only touch have no certificate): the geometry functor finds each of them apart in a few loads (:yref:`RdemGap`: the pair stays apart while the summed travel of its blocks $T_1+T_2$ stays below the certificate's reach $R$, the travel recorded by :yref:`RdemContactGate` in :yref:`RdemSharedState`), but YADE's loop reaches it through the interaction, both bodies, their shapes and states and the dispatch first. This loop keeps, by position in the interaction container, a flat array of the pairs whose geometry functor returned false with a certificate of the current travel record (*sleepers*: the interaction's address, both ids, $R$), and in the next steps skips a sleeper without touching its interaction while it is still the interaction at that position and $T_1+T_2<R$: exactly when the functor's certificate test (``rdem::BodyTravel::certifies``) would find it apart, so the run is the same to the last bit (tests/yade/test_interaction_loop.py). The pairs skipped are counted in the functor's :yref:`skippedTests<Ig2_RdemBlock_RdemBlock_RdemGeom.skippedTests>`, as if it had tested them, and in :yref:`sleptPairs<RdemInteractionLoop.sleptPairs>`.

Pairs that only touch (the neighbours of a wall, of a dry-stacked cube: their overlap is about zero along a face axis, so no certificate) are decided by the functor's witness axis (:yref:`RdemGap.witness`). They sleep too, with their axis and the blocks' half-extents: in the next steps the loop makes the functor's witness test itself (``rdem::witnessVerdict``, the same function) from the blocks' poses in the travel record, which are those of the step, and skips the pair while the axis still separates the blocks by more than the round-off and leaves a slack that makes no certificate (else the functor is called and makes it); these are counted in :yref:`witnessTests<Ig2_RdemBlock_RdemBlock_RdemGeom.witnessTests>`, as the functor counts them.

The sleepers are forgotten, and the loop is YADE's own for the step, whenever they cannot be trusted or the certificates do not apply: the travel record is not of this step or has restarted (a body erased, added or replaced), the number of bodies changed, a collider asks the loop to remove the pairs it did not see (``InteractionContainer::iterColliderLastRun``), the cell is periodic, ``loopOnSortedInteractions`` is set, the geometry functor does not share this loop's :yref:`RdemSharedState`, or YADE is built with MPI (a body's subdomain can change without the travel record seeing it). In a step after one in which no pair was known apart (none slept or fell asleep, the functor counted none) the loop is YADE's too, until the functor counts one: a scene without such pairs (every pair a bond or a contact) does not pay for the sleepers. Witness sleepers are woken while the functor's :yref:`skipApart<Ig2_RdemBlock_RdemBlock_RdemGeom.skipApart>` is off, as the functor then makes no witness test. A sleeper whose position now holds another interaction (the container moves its last interaction into the place of an erased one) is visited. A sleeping pair reset in place (``InteractionContainer::requestErase``, which ``O.interactions.erase`` calls) is tested again only when its certificate runs out, where YADE's loop tests it at once: its certificate proves the blocks apart, so the results are the same, but the certificates made afterwards, and so ``skippedTests`` and ``witnessTests``, can differ.)""",
		((bool,sleepApart,true,,"Skip the pairs known apart without visiting them (above); False: YADE's :yref:`InteractionLoop` at every step, the reference the tests compare against. The same results either way."))
		((bool,bondLane,true,Attr::noSave,"Visit the bonds (:yref:`RdemGeom.bonded`, intact or cracked) without YADE's dispatch: the geometry functor's update of a bond (``RdemGeom::updateBond``, with the blocks' rotation matrices made once per block and step instead of twice per bond) and the law's :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` called directly, the same functions with the same arguments as through the dispatch, so the run is the same to the last bit (tests/yade/test_interaction_loop.py). Used in the steps this loop makes itself (a scene that is not periodic, without callbacks, ``loopOnSortedInteractions`` or a collider that asks for the removal of the pairs it did not see; not with MPI); False: every interaction through the dispatch. Not saved: a loaded scene uses the lane."))
		((long,sleptPairs,0,Attr::noSave,"Visits of pairs known apart skipped so far (each also counted in :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom.skippedTests` if by its certificate, in :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom.witnessTests` if by its witness axis); not saved with the scene."))
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`): the blocks' travel, which decides whether a certificate holds; the geometry functor must hold the same (handed by ``rdem.engines()``; None: the law's, taken at the first step)."))
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	/// A pair found apart, at its position in linIntrs: with a certificate of the travel record sleepEpoch, or a witness axis.
	struct Sleeper {
		const Interaction* I   = nullptr; ///< the interaction when it fell asleep; nullptr: no sleeper at this position
		Body::id_t         id1 = -1, id2 = -1;
		Real               reach   = 0;  ///< RdemGap::reach [m] (a certificate)
		int                witness = -1; ///< RdemGap::witness, for a pair that only touches: -1 for a certificate
		Vector3r           hA, hB;       ///< the blocks' half-extents (a witness sleeper) [m]
	};
	/* By position in scene->interactions->linIntrs. A sleeper's interaction is also owned by keep at the same position
	   while it sleeps, so that its address cannot be taken by a new interaction while the sleeper holds it: an
	   interaction erased and another created at the same address and moved to the same position would otherwise pass
	   the pointer compare. keep is touched only when a pair falls asleep or wakes, not in the loop's test. */
	vector<Sleeper>                 sleepers;
	vector<shared_ptr<Interaction>> keep;
	long                            sleepEpoch  = -1; ///< the travel record's epoch the sleepers' certificates refer to
	long                            sleepBodies = -1; ///< the number of bodies when the sleepers were recorded
	/* Whether the last step made by this loop put a pair to sleep; and the functor's skippedTests and witnessTests at the
	   start of the last step: if neither a pair fell asleep nor either count grew, no pair is known apart (the sleepers
	   are all woken), and YADE's loop runs until the functor counts one (worthSleeping). */
	bool fellAsleepLastStep = true;
	Real skippedSeen = -1, witnessSeen = -1;

	/// Whether this loop can make the step itself, as YADE's loop would (not with MPI, loopOnSortedInteractions or a
	/// collider that asks for the removal of the pairs it did not see): the sleepers and the bond lane need it.
	bool ownStepPossible() const;
	/// The geometry functor of blocks that shares sh, if the sleepers can be used in this step; nullptr: YADE's loop.
	Ig2_RdemBlock_RdemBlock_RdemGeom* sleepFunctor(const RdemSharedState& sh) const;
	/// The functors of the bond lane (bondLane), when it can be used in this step: this loop's geometry functor of blocks
	/// and law, {nullptr, nullptr} otherwise.
	std::pair<Ig2_RdemBlock_RdemBlock_RdemGeom*, Law2_RdemGeom_RdemPhys_FaceSprings*> laneFunctors() const;
	/// The blocks' rotation matrices of this step, by body id (the bond lane); made by rotations().
	vector<Matrix3r> rot;
	void             rotations();
	/// Whether I is a bond of two blocks that the lane takes (its law cached by the dispatch is law).
	bool inLane(const Interaction& I, const Law2_RdemGeom_RdemPhys_FaceSprings& law) const;
	/// The bond I in the lane: what Ig2_RdemBlock_RdemBlock_RdemGeom::go and the law do with a bond, without the dispatch.
	void bondInLane(const shared_ptr<Interaction>& I, const Ig2_RdemBlock_RdemBlock_RdemGeom& ig2, Law2_RdemGeom_RdemPhys_FaceSprings& law);
	/// Whether the last step showed pairs known apart (fellAsleepLastStep, skippedSeen, witnessSeen); records the functor's counts.
	bool worthSleeping(const Ig2_RdemBlock_RdemBlock_RdemGeom& ig2);
	/// Forgets every sleeper.
	void wakeAll();
	/// Makes the sleepers' arrays as long as the interaction container, forgetting them if they cannot be trusted.
	void prepareSleepers(const rdem::BodyTravel& travel);
	/* Records I, at position k and just found apart by the functor ig2, as a sleeper if its RdemGap holds a certificate of
	   the current travel record (sleepEpoch), or else, with skipApart, a witness axis (the pair only touches); returns
	   whether it did. */
	bool fallAsleep(long k, const shared_ptr<Interaction>& I, const Ig2_RdemBlock_RdemBlock_RdemGeom& ig2);
	/* Whether sleeper s is still apart in this step, as the functor's knownApart would find it: its certificate holds,
	   or its witness axis still separates the blocks (their poses from the travel record of this step) and leaves a
	   slack that makes no certificate (else the functor is called, which makes it); witness: whether the functor makes
	   witness tests (its skipApart). */
	static bool stillApart(const Sleeper& s, const rdem::BodyTravel& travel, bool witness);
	/* One interaction, as YADE's InteractionLoop::action treats it in a scene that is not periodic; returns whether the
	   geometry functor found a pair that was not real apart. */
	bool visit(const shared_ptr<Interaction>& I, const vector<IntrCallback::FuncPtr>& callbackPtrs);
	/// The physics, the law and the callbacks of I, whose geometry functor returned true (bodies b1, b2 in its order).
	void applyPhysicsAndLaw(const shared_ptr<Interaction>& I, Body& b1, Body& b2, bool wasReal, const vector<IntrCallback::FuncPtr>& callbackPtrs);
	/// Sets the dispatchers' and their functors' scene, as YADE's loop does; returns the callbacks' functions of the step.
	vector<IntrCallback::FuncPtr> prepareStep();
};
REGISTER_SERIALIZABLE(RdemInteractionLoop);

} // namespace yade
