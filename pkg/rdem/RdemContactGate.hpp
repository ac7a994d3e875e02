/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>
#include <pkg/rdem/RdemSharedState.hpp>

namespace yade {

/// Keeps the collider dead while no new contact is possible: one intact bonded assembly and nothing else; once open,
/// records how far each block has moved (rdem::BodyTravel) for the geometry functor's pairs found apart.
class RdemContactGate : public GlobalEngine {
public:
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemContactGate,GlobalEngine,R"""(Contact detection on demand: switches the :yref:`Collider` of ``O.engines`` on only once new contacts can occur.

Named after what it is, a gate in front of the collider, rather than after a verb as YADE names engines: the name is in saved scenes (``O.save``), in every script, test and document of the plugin, and in ``rdem.contactGate()``; a rename would break saved scenes.

While every body is an :yref:`RdemBlock`, all blocks form **one** assembly connected by bonds (interactions with restoring springs, :yref:`RdemGeom`), and no restoring spring has broken (:yref:`Law2_RdemGeom_RdemPhys_FaceSprings::tensionBreaks` + ``shearBreaks`` = 0), two blocks that are not bonded can only touch after strains far beyond the failure strains of the springs. The collider is then kept :yref:`dead<Engine::dead>`, and the scene pays nothing for contact detection (the bonds are made by :yref:`utils.createInteraction` and need no collider). The gate opens for good, and the collider runs from then on, at the first of: a broken spring, a body that is not an :yref:`RdemBlock` or has no bond, two assemblies that are not bonded together, an interaction that is not a bond. The topology is checked when the gate first runs and again whenever the number of bodies or interactions changes.

Place it just before the collider (``rdem.engines()`` does); ``open=True`` forces the collider on.

*Pairs found apart.* While open, the gate records at every step how far each block has moved since (a bound on the displacement of any of its points, ``rdem::rigidTravel``) in :yref:`RdemSharedState`, where :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` reads it, which then tests a pair of neighbours it found apart again only once the two blocks may have moved enough to touch (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom::skipApart`. A cost of a few tens of instructions per block and step.)""",
		((bool,open,false,,"Whether contact detection is on (latches once true)."))
		((string,reason,"",Attr::readonly,"Why the gate opened (empty while closed)."))
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`: the broken springs, the travel record; handed by ``rdem.engines()``; None: the law's, taken at the first step)."))
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
	/// Add this step's motion of every body to the travel record t (restarted with a new epoch when steps were missed or
	/// bodies changed).
	void updateTravel(rdem::BodyTravel& t);
};
REGISTER_SERIALIZABLE(RdemContactGate);

} // namespace yade
