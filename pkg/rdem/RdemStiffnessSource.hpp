/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <lib/base/Math.hpp>
#include <pkg/rdem/math/StiffnessSpectrum.hpp>

namespace yade {

class Scene;
class Interaction;

/* What adds to the linear stiffness of a block assembly, for RdemTimeStepper's critical step (doc/sphinx/rdemTheory.rst §6): the
   law (its springs and contact dashpots) and the Poisson engine (its elements and cells). Each gives its own terms, as
   it applies them, so that the time stepper derives nothing itself. RdemSharedState lists the sources of a scene. */
class RdemStiffnessSource {
public:
	virtual ~RdemStiffnessSource() = default;
	/// Adds to K the linear stiffness of this source's forces at the current configuration [N/m, N·m/rad] (without
	/// the geometric stiffness), to C its dashpots [N·s/m], capped for the step capDt as they are applied (0: no cap).
	/// Sums in an order that does not depend on the interaction container's (O.load changes it): that of inIdOrder,
	/// the scene's rdem::interactionsInIdOrder, made once by the caller for all sources.
	virtual void
	addStiffness(Scene* scene, const vector<const Interaction*>& inIdOrder, rdem::BlockStiffness<Real>& K, rdem::BlockStiffness<Real>& C, Real capDt)
	        = 0;
	/// Adds to C this source's dashpots alone, the same terms in the same order as addStiffness adds to C [N·s/m]
	/// (RdemTimeStepper's update after a break, which keeps K).
	virtual void addDashpots(Scene* scene, const vector<const Interaction*>& inIdOrder, rdem::BlockStiffness<Real>& C, Real capDt) = 0;
	/// Adds to omega2[id], for every body that is not fixed, a Gershgorin bound of the squared eigenfrequency this
	/// source's terms give it [1/s²].
	virtual void addOmega2Bound(Scene* scene, vector<Real>& omega2) = 0;
};

} // namespace yade
