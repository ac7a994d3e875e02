/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>

namespace yade {

/// Stops a run at the first non-finite position, orientation, velocity, force or torque, naming the body and its interactions.
class RdemFiniteGuard : public GlobalEngine {
public:
	/// Throws std::runtime_error naming the first (lowest-id) body with a non-finite state or force.
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC(RdemFiniteGuard,GlobalEngine,R"""(Stops the simulation as soon as a body's position, orientation, velocity, angular velocity, force or torque is NaN or infinite, instead of letting a run carry on with garbage.

Named after what it is rather than after a verb as YADE names engines: the name is in saved scenes (``O.save``) and in the scripts, tests and documents of the plugin; a rename would break saved scenes.

Placed after :yref:`NewtonIntegrator` (``rdem.engines(finiteGuard=True)``, the default), it checks every body every step and throws ``RuntimeError`` (so ``O.run`` stops and Python sees the error) with a message naming the iteration, the first body (lowest id) with a non-finite quantity, that quantity, and every interaction on that body whose :yref:`RdemPhys::force` is non-finite (the usual origin). Forces and torques are read for bodies with a blocked DOF; on a free body the integrator has already carried a non-finite force into the velocity and position of the same step, and the message names those. The check costs well under 1 % of a step of the paper's 1200-block scene.)""");
	// clang-format on
	DECLARE_LOGGER;
};
REGISTER_SERIALIZABLE(RdemFiniteGuard);

} // namespace yade
