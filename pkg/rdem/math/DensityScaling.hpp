/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Partial density scaling for quasi-static runs ([Itasca2020]_'s density scaling, YADE's State::densityScaling): a body
   with factor s in (0, 1] moves as if its inertia were m/s and I/s (kg, kg·m²) while gravity keeps acting on its true
   mass m: its accelerations are s times those of the true body, gravity's included,
       (m/s) a = F + m g,      (I/s) ω̇ + ω × (I/s) ω = T,
   so that every static equilibrium (a = 0, ω̇ = 0) is that of the unscaled body and only its response to unbalanced
   forces is slower. s <= 0 (YADE's default -1) means no scaling. Everything that uses a body's mass for its inertia
   (the critical step, the dashpots' stability caps, the kinetic energy) uses the inertial mass m/s; gravity and the
   applied loads use m. Units: SI; forces on the body. */
#pragma once
#include <Eigen/Core>

namespace yade {
namespace rdem {

	/// The factor 1/s of a body's inertial mass and inertia over its true ones, for YADE's State::densityScaling s; 1
	/// for s <= 0 (no scaling, YADE's default -1). Exactly 1 for s = 1 and s <= 0, so that m·inertialFactor(s) is m bit
	/// for bit in an unscaled scene.
	template <class S> S inertialFactor(S densityScaling) { return densityScaling > 0 ? 1 / densityScaling : S(1); }

	/* What to add to a body's force F [N] so that YADE's NewtonIntegrator, which computes a = F/m + g with the true mass m
	   [kg] and gravity g [m/s²], gives the scaled acceleration s (F/m + g): (s - 1)(F + m g). Its torque T [N·m] gets
	   (s - 1) T: Euler's equations are linear in the inertia, (I/s) ω̇ + ω × (I/s) ω = T is I ω̇ + ω × I ω = s T, so
	   the aspherical integrator with the true inertia and the torque s T moves the body as the inertia I/s would. */
	template <class S>
	Eigen::Matrix<S, 3, 1> densityScalingForce(S densityScaling, const Eigen::Matrix<S, 3, 1>& force, S mass, const Eigen::Matrix<S, 3, 1>& gravity)
	{
		return (densityScaling - 1) * (force + mass * gravity);
	}

} // namespace rdem
} // namespace yade
