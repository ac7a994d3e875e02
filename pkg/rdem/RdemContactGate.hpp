/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Body.hpp>
#include <core/GlobalEngine.hpp>

namespace yade {

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
	};
}

/// Keeps the collider dead while no new contact is possible: one intact bonded assembly and nothing else; once open,
/// records how far each block has moved (rdem::BodyTravel) for the geometry functor's pairs found apart.
class RdemContactGate : public GlobalEngine {
public:
	void action() override;
	/// The travel record, shared with the scene's Ig2_RdemBlock_RdemBlock_RdemGeom.
	const shared_ptr<rdem::BodyTravel> travel { new rdem::BodyTravel };
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemContactGate,GlobalEngine,R"""(Contact detection on demand: switches the :yref:`Collider` of ``O.engines`` on only once new contacts can occur.

Named after what it is, a gate in front of the collider, rather than after a verb as YADE names engines: the name is in saved scenes (``O.save``), in every script, test and document of the plugin, and in ``rdem.contactGate()``; a rename would break saved scenes.

While every body is an :yref:`RdemBlock`, all blocks form **one** assembly connected by bonds (interactions with restoring springs, :yref:`RdemGeom`), and no restoring spring has broken (:yref:`Law2_RdemGeom_RdemPhys_FaceSprings::tensionBreaks` + ``shearBreaks`` = 0), two blocks that are not bonded can only touch after strains far beyond the failure strains of the springs. The collider is then kept :yref:`dead<Engine::dead>`, and the scene pays nothing for contact detection (the bonds are made by :yref:`utils.createInteraction` and need no collider). The gate opens for good, and the collider runs from then on, at the first of: a broken spring, a body that is not an :yref:`RdemBlock` or has no bond, two assemblies that are not bonded together, an interaction that is not a bond. The topology is checked when the gate first runs and again whenever the number of bodies or interactions changes.

Place it just before the collider (``rdem.engines()`` does); ``open=True`` forces the collider on.

*Pairs found apart.* While open, the gate records at every step how far each block has moved since (a bound on the displacement of any of its points, ``rdem::rigidTravel``) and hands the record to :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom`, which then tests a pair of neighbours it found apart again only once the two blocks may have moved enough to touch (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom::skipApart`). A cost of a few tens of instructions per block and step.)""",
		((bool,open,false,,"Whether contact detection is on (latches once true)."))
		((string,reason,"",Attr::readonly,"Why the gate opened (empty while closed)."))
		((long,nBodies,-1,(Attr::readonly|Attr::noSave),"Number of bodies at the last topology check (-1: none yet)."))
		((long,nInteractions,-1,(Attr::readonly|Attr::noSave),"Number of interactions at the last topology check."))
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	/// Why contacts can occur given the bodies and bonds of the scene, empty if they cannot.
	string topologyReason() const;
	/// Set the dead flag of every collider of the scene.
	void setColliders(bool dead) const;
	/// Add this step's motion of every body to the travel record (restarted with a new epoch when steps were missed or
	/// bodies changed) and hand the record to the geometry functors.
	void updateTravel();
};
REGISTER_SERIALIZABLE(RdemContactGate);

} // namespace yade
