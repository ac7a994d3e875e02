/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <lib/base/openmp-accu.hpp>
#include <lib/serialization/Serializable.hpp>
#include <core/Body.hpp>
#include <core/Engine.hpp>
#include <core/Interaction.hpp>
#include <pkg/rdem/RdemStiffnessSource.hpp>
#include <pkg/rdem/math/FaceSprings.hpp>
#include <boost/weak_ptr.hpp>
#include <functional>
#include <mutex>

namespace yade {

class Scene;
class RdemCellNetwork;

namespace rdem {
	/* How far each body has moved since a reference step [m]: by body id, the sum over steps of rdem::rigidTravel,
	   which bounds the displacement of every point of the body. Kept by RdemContactGate while contact detection runs,
	   read by Ig2_RdemBlock_RdemBlock_RdemGeom to know when a pair found apart must be tested again
	   (math/SeparationBound.hpp). */
	struct BodyTravel {
		long                 iter  = -1; ///< the step whose configurations travel is up to date with (-1: none yet)
		long                 epoch = -1; ///< changes whenever the record restarts: a certificate of another epoch is void
		vector<Real>         travel;     ///< by body id [m]
		vector<const Body*>  body;       ///< by body id: the configuration last seen (body, its shape, position, orientation)
		vector<const Shape*> shape;
		vector<Vector3r>     pos;
		vector<Quaternionr>  ori;
		vector<Real>         radius; ///< circumradius of the block about its centroid, 0 for other shapes [m]
		/// Whether the record holds the configurations of step iter of a scene that is not periodic.
		bool currentFor(const Scene& scene) const;
		/// Whether the summed travel of bodies id1 and id2 is still below reach [m] (of the record as it is: see certifies).
		bool withinReach(Real reach, Body::id_t id1, Body::id_t id2) const
		{
			const Real t = travel[size_t(id1)] + travel[size_t(id2)];
			return t >= 0 && t < reach;
		}
		/* Whether a certificate that the pair id1, id2 stays apart up to a summed travel of reach [m], made against the
		   record of epoch certEpoch (RdemGap), holds in this step of scene: the one test of a certificate, made by
		   Ig2_RdemBlock_RdemBlock_RdemGeom, and by RdemInteractionLoop for the pairs it does not visit (it checks the epoch
		   and currentFor once per step, then withinReach by pair). */
		bool certifies(const Scene& scene, long certEpoch, Real reach, Body::id_t id1, Body::id_t id2) const
		{
			return certEpoch == epoch && currentFor(scene) && withinReach(reach, id1, id2);
		}
	};

	/// O.engines as last seen, without owning the engines (an engine that held the list it is in would never be freed).
	class EngineListStamp {
	public:
		/// Whether engines is the list seen last (the same engines in the same order).
		bool same(const vector<shared_ptr<Engine>>& engines) const
		{
			if (engines.size() != seen.size()) return false;
			for (size_t i = 0; i < engines.size(); ++i)
				if (seen[i].lock() != engines[i]) return false;
			return true;
		}
		void take(const vector<shared_ptr<Engine>>& engines) { seen.assign(engines.begin(), engines.end()); }

	private:
		vector<boost::weak_ptr<Engine>> seen;
	};
}

/// What the plugin's engines and functors of one scene share: the crack state, the record of the deferred forces, the
/// blocks' travel; one object handed to each of them, and the check of their order.
class RdemSharedState : public Serializable {
public:
	/* Restoring springs broken so far in tension (eq. 15) and in shear (eq. 16), summed over the law's threads. Not
	   attributes: YADE's attribute macros instantiate boost::python::extract<OpenMPAccumulator<…>>, which gcc 12 flags
	   with -Wmaybe-uninitialized; saved through savedTensionBreaks and savedShearBreaks (preSave, postLoad). */
	OpenMPAccumulator<int> tensionBreaks, shearBreaks;
	/// Restoring springs broken so far (tension + shear): what the engines that follow cracks watch.
	long brokenSprings() const { return long(tensionBreaks.get()) + long(shearBreaks.get()); }
	/// Interactions that started or stopped leaving deferred forces since the last takeActiveSetChanges (law's threads).
	OpenMPAccumulator<int> activeSetChanges;
	/// How many interactions started or stopped leaving deferred forces since the last call; resets the record. Lets
	/// RdemForceAssembler keep its per-body lists between such events.
	int takeActiveSetChanges();
	/// A physics that started leaving deferred forces (new, or back after a pause), with its bodies.
	struct JoinedPhys {
		shared_ptr<IPhys> phys;
		Body::id_t        id1, id2;
	};
	/// Records that I starts leaving deferred forces in this step (the law's threads; an active-set change as well).
	void join(const Interaction& I);
	/// The physics that joined since the last call, in no particular order; empties the record (RdemForceAssembler).
	vector<JoinedPhys> takeJoined();
	/* The springs' energies of a step added to O.energy (rdemElastic, a current value; rdemDashpot, rdemFriction,
	   rdemBondBreak, rdemContactRelease and the softening ones, cumulated): by the law interaction by interaction when it applies its own
	   forces, else once per step by RdemForceAssembler, summed in a fixed order (bodies by id, each interaction once, then
	   the interactions released in the step by their ids): a sum that O.load and the number of threads do not change. */
	void bookSpringEnergies(Scene* scene, const rdem::SpringEnergies<Real>& e);
	/// The energies of an interaction that the law released in this step (its physics is reset: they reach
	/// RdemForceAssembler this way; the law's threads).
	void releaseEnergies(Body::id_t id1, Body::id_t id2, const rdem::SpringEnergies<Real>& e);
	/// The sum of the energies recorded by releaseEnergies since the last call, in the order of the interactions' ids;
	/// empties the record.
	rdem::SpringEnergies<Real> takeReleasedEnergies();
	/// How far each block has moved (written by RdemContactGate, read by Ig2_RdemBlock_RdemBlock_RdemGeom; not saved).
	rdem::BodyTravel travel;
	/// What adds to the scene's linear stiffness (its laws and Poisson engine, in the order of O.engines), for
	/// RdemTimeStepper (set by the check of the engines).
	vector<RdemStiffnessSource*> stiffnessSources;
	/// The Poisson cells, owned by the scene's RdemPoissonEngine, whose strains RdemCellStrainUpdater updates before the
	/// interaction loop (set by the check of the engines; none without a Poisson engine).
	RdemCellNetwork* cells = nullptr;
	/// Set for one step by RdemGhostExchange (YADE's MPI), taken by RdemPoissonEngine for RdemCellNetwork::applyForces:
	/// replaces the ghosts' ∂W/∂ε by their owners' (arguments: the cells' block ids and ∂W/∂ε by compact index).
	std::function<void(const vector<Body::id_t>&, vector<Vector3r>&)> cellStressSync;
	/* The shared state of an engine or functor of scene whose own is `mine`: if mine is None, the one of the scene's
	   Law2_RdemGeom_RdemPhys_FaceSprings (handed to it here). Checks the scene's engines when their list changed since
	   the last check (see checkEngines). Throws std::runtime_error if there is none. */
	static RdemSharedState& of(Scene* scene, shared_ptr<RdemSharedState>& mine);
	void                    preSave(RdemSharedState&)
	{
		savedTensionBreaks = tensionBreaks.get();
		savedShearBreaks   = shearBreaks.get();
	}
	void postLoad(RdemSharedState&);
	long tensionBreaksPy() const { return tensionBreaks.get(); }
	long shearBreaksPy() const { return shearBreaks.get(); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemSharedState,Serializable,R"""(What the plugin's engines and functors of one scene share, so that none of them reaches into another: the crack state (the restoring springs broken so far, counted by :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` and watched by :yref:`RdemContactGate`, :yref:`RdemTimeStepper` and :yref:`RdemPoissonEngine`), the record of interactions that start or stop leaving deferred forces (for :yref:`RdemForceAssembler`), and the blocks' travel (:yref:`RdemContactGate` for :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom`).

``rdem.engines()`` makes one and hands it to each of them (their ``shared`` attribute); an engine list made by hand gets the law's at its first step. The order of the engines is checked then, and again whenever :yref:`O.engines<Omega.engines>` changes, not at every step: the run stops with an error naming the engine that is missing or out of place. Saved with the scene.)""",
		((long,savedTensionBreaks,0,Attr::hidden,"``tensionBreaks`` when the scene was saved (restored on load)."))
		((long,savedShearBreaks,0,Attr::hidden,"``shearBreaks`` when the scene was saved (restored on load)."))
		((bool,deferredForces,false,(Attr::hidden|Attr::readonly),"The law leaves its forces to an :yref:`RdemForceAssembler` that follows its InteractionLoop (set by the check of the engines; saved, so that the first step after ``O.load`` applies them as the uninterrupted run does, before the check runs again)."))
		,
		/* ctor */
		,
		.add_property("tensionBreaks",&RdemSharedState::tensionBreaksPy,"Restoring springs broken in tension (eq. 15) so far.")
		.add_property("shearBreaks",&RdemSharedState::shearBreaksPy,"Restoring springs broken in shear (eq. 16) so far.")
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	std::mutex         joinedMutex; // a few interactions join in a step: a lock is cheap
	vector<JoinedPhys> joined;
	struct ReleasedEnergies {
		Body::id_t                 id1, id2;
		rdem::SpringEnergies<Real> e;
	};
	std::mutex               releasedMutex; // as joined: rare
	vector<ReleasedEnergies> released;
	int                      energyIx[8] = { -1, -1, -1, -1, -1, -1, -1, -1 }; // O.energy's indices of the springs' energies (not saved)
	rdem::EngineListStamp    checkedEngines;                                   // O.engines at the last check
	/* Once per engine list (the first step, and whenever O.engines changes): hands self (this object) to the plugin's
	   engines and functors that have none, and throws std::runtime_error naming the engine that holds another one, is
	   missing or is out of place: an RdemForceAssembler after the InteractionLoop whose law defers its forces, an
	   RdemCellStrainUpdater before it, an RdemContactGate before the collider. Sets deferredForces. */
	void checkEngines(Scene* scene, const shared_ptr<RdemSharedState>& self);
};
REGISTER_SERIALIZABLE(RdemSharedState);

} // namespace yade
