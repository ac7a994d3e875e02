/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>
#include <core/Interaction.hpp>

namespace yade {

/// On YADE's MPI (yade.mpy): keeps the bonds between blocks of different subdomains through mpy's split of the scene,
/// which erases them, and puts them back on the ranks that own one of their blocks before anything reads them.
class RdemBondKeeper : public GlobalEngine {
public:
	void action() override;
	/// Python: record the real interactions between bodies of different subdomains; returns how many.
	long keep();
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemBondKeeper,GlobalEngine,R"""(Keeps the bonds across subdomain boundaries of a distributed run (:ref:`mpy`, YADE built with ``ENABLE_MPI``) through mpy's split of the scene.

When mpy splits a scene (``mpy.splitScene``, at the first ``mpy.mpirun``), each worker first erases every body of the other subdomains (``mpy.parallelCollide``: ``unboundRemoteBodies``, ``eraseRemote``), and with them their interactions, on every rank at once; the bodies it then needs as ghosts are sent by their owners, with the interactions the owners still have. A bond between blocks of two subdomains is thus lost on both ranks, and its blocks, face to face, touch again as a contact a few steps later: the run departs from the serial one where the load reaches the cut. Springs and the Poisson effect need the bond on both ranks, as the serial run has it.

``keep()`` (``rdem.distributed.prepare`` calls it, with the subdomains assigned and the whole scene on every rank) records the real interactions between bodies of different subdomains; they go with the scene that the master sends to the workers (the same objects as in its interaction container). At its first step after the split, before any other engine (``rdem.distributed.prepare`` puts it first), the engine puts back each recorded interaction whose two bodies this rank holds and one of which it owns, in place of the contact-less interaction the collider may have made for the pair, and forgets the others (the master keeps none: it holds no block). The bond's springs, crack state and history are those of the moment of ``keep()``. Without MPI, or before the split, it does nothing.)""",
		((vector<shared_ptr<Interaction>>,kept,,Attr::hidden,"The interactions between bodies of different subdomains recorded by ``keep()`` and not yet put back (saved: mpy sends them with the scene)."))
		((long,restored,0,Attr::readonly,"Interactions this rank put back after the split."))
		,
		/* ctor */,
		.def("keep",&RdemBondKeeper::keep,"Record the real interactions between bodies of different subdomains (:yref:`Body.subdomain`, assigned before), to put them back after mpy's split; returns how many. Needs YADE with MPI.")
	);
	// clang-format on
	DECLARE_LOGGER;
};
REGISTER_SERIALIZABLE(RdemBondKeeper);

} // namespace yade
