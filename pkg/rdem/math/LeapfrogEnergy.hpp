/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The energy balance of the leapfrog, exact step by step for a linear system (Hairer, Lubich & Wanner 2006, Geometric Numerical Integration, §I.1.4).

   YADE's NewtonIntegrator is the leapfrog (central differences): in step n, with the forces F_n of the positions x_n,
   gravity g and the integrator's own damping force D_n,
       v_{n+1/2} = v_{n-1/2} + Δt (F_n + m g + D_n)/m,      x_{n+1} = x_n + Δt v_{n+1/2}.
   The springs' energy U(x_n) and gravity's work are booked at the positions x_n. The kinetic energy that pairs with
   them is the product of the two half-step velocities,
       K_n = ½ m v_{n-1/2}·v_{n+1/2}                                                        [J]
   (not ½ m v_{n-1/2}², what NewtonIntegrator books). For linear forces F = -Kx (K symmetric) K_n + ½ x_nᵀK x_n is
   conserved exactly, whatever the stable step (the leapfrog's modified energy, [HairerLubichWanner2006]_): one step
   changes K by ½ v_{n+1/2}·(F_n + F_{n+1})Δt (the definition of v_{n+3/2} and v_{n-1/2}) and U by
   ½ (x_{n+1} - x_n)·K(x_{n+1} + x_n) = -½ v_{n+1/2}·(F_n + F_{n+1})Δt. Gravity (a constant force) enters the same way.

   Other forces change K_n + U_n by ½ v_{n+1/2}·(D_n + D_{n+1})Δt per step. Their work is therefore booked as the
   trapezoid rule over the two half steps: W_n, the energy a force D_n of step n dissipates, is -½ D_n·v_{n-1/2}Δt in
   step n and -½ D_n·v_{n+1/2}Δt in step n+1 (SplitWork). Then K_n + U_n + W_n (the total of O.energy) is constant to
   round-off, step by step, for any D (Cundall's non-viscous damping, dashpots), as the law books its contact dashpots
   (rdem::contactSpringForce). The force of the integrator's damping is what the velocity change holds beyond the
   forces and gravity (dampingForce): the force really applied, whatever rule made it.

   Rotations are not linear; the same pairing, ½ ω_{n-1/2}·I ω_{n+1/2} with the inertia I in global axes, conserves
   the energy up to the small-rotation error of the rotation integrator. Units: SI; forces on the body. */
#pragma once

#include <Eigen/Core>

namespace yade {
namespace rdem {

	/// Kinetic energy of a body paired across step n: ½ m v_{n-1/2}·v_{n+1/2} + ½ ω_{n-1/2}·I ω_{n+1/2} [J], with I the
	/// inertia tensor in global axes [kg·m²], m the mass [kg], v [m/s], ω [rad/s].
	template <class S>
	S pairedKineticEnergy(
	        S                             mass,
	        const Eigen::Matrix<S, 3, 1>& velBefore,
	        const Eigen::Matrix<S, 3, 1>& velAfter,
	        const Eigen::Matrix<S, 3, 3>& inertia,
	        const Eigen::Matrix<S, 3, 1>& angVelBefore,
	        const Eigen::Matrix<S, 3, 1>& angVelAfter)
	{
		return (mass * velBefore.dot(velAfter) + angVelBefore.dot(inertia * angVelAfter)) / 2;
	}

	/* Force the integrator's damping applied to a body in one step [N]: m(v_{n+1/2} - v_{n-1/2})/Δt - F_n - m_g g, the
	   part of the velocity change that the forces F_n [N] and gravity g [m/s²] do not explain. mass is the inertial mass
	   (with YADE's density scaling s, m/s) [kg], gravityMass the mass gravity acts on [kg]. Components of blocked
	   degrees of freedom must be left out by the caller (their velocity is imposed). */
	template <class S>
	Eigen::Matrix<S, 3, 1> dampingForce(
	        S                             mass,
	        S                             gravityMass,
	        const Eigen::Matrix<S, 3, 1>& velBefore,
	        const Eigen::Matrix<S, 3, 1>& velAfter,
	        S                             dt,
	        const Eigen::Matrix<S, 3, 1>& force,
	        const Eigen::Matrix<S, 3, 1>& gravity)
	{
		return mass * (velAfter - velBefore) / dt - force - gravityMass * gravity;
	}

	/* Damping torque of Cundall's non-viscous damping d on a body rotated by YADE's aspherical integrator
	   (NewtonIntegrator::cundallDamp1st, after [Cundall1987]_): each global component of the torque T [N·m] scaled by
	   1 - d sgn(T_i ω_i), ω the mid-step angular velocity ω_{n-1/2} [rad/s]; returns the change, -d sgn(T_i ω_i) T_i
	   [N·m]. (That integrator does not advance ω linearly in the torque, so the torque cannot be read off the change of
	   ω as dampingForce reads the force.) */
	template <class S> Eigen::Matrix<S, 3, 1> cundallDampingTorque(S damping, const Eigen::Matrix<S, 3, 1>& torque, const Eigen::Matrix<S, 3, 1>& angVel)
	{
		Eigen::Matrix<S, 3, 1> out;
		for (int i = 0; i < 3; ++i) {
			const S p = torque[i] * angVel[i];
			out[i]    = -damping * (p > 0 ? S(1) : (p < 0 ? S(-1) : S(0))) * torque[i];
		}
		return out;
	}

	/* The jump of the booked total in a step n whose Δt_n differs from the last step's Δt_{n-1} (a time stepper's
	   update), per body [J]: J = ½(Δt_n - Δt_{n-1}) (v_{n-1/2}·(F_n - m g) + ω_{n-1/2}·T_n). The integrator advances
	   v_{n+1/2} = v_{n-1/2} + Δt_n a_n, so K_n exceeds the value that pairs with the balance of the old step by
	   ½(Δt_n - Δt_{n-1}) v_{n-1/2}·(F_n + D_n + m g); gravity's work booked with Δt_n, -m g·v_{n-1/2}Δt_n, differs from
	   -m g·(x_n - x_{n-1}) by -(Δt_n - Δt_{n-1}) m g·v_{n-1/2}; the first half of the damping's work (SplitWork),
	   -½ D_n·v_{n-1/2}Δt_n, by -½(Δt_n - Δt_{n-1}) D_n·v_{n-1/2}. From step n on the balance holds for the new step.
	   Booking -J keeps the total constant across the change. The rotations' term is the kinetic one (first order: the
	   rotation integrator is not linear in the torque). F_n, T_n: the forces and torques of step n [N, N·m]; gravityMass
	   the mass gravity g acts on [kg]. */
	template <class S>
	S stepChangeJump(
	        S                             dtBefore,
	        S                             dtAfter,
	        const Eigen::Matrix<S, 3, 1>& vel,
	        const Eigen::Matrix<S, 3, 1>& force,
	        S                             gravityMass,
	        const Eigen::Matrix<S, 3, 1>& gravity,
	        const Eigen::Matrix<S, 3, 1>& angVel,
	        const Eigen::Matrix<S, 3, 1>& torque)
	{
		return (dtAfter - dtBefore) * (vel.dot(force - gravityMass * gravity) + angVel.dot(torque)) / 2;
	}

	/* Energy a linear spring of stiffness k [N/m] releases when it is removed in step n (a restoring spring that breaks),
	   so that the balance above stays exact: ½ k u_{n-1}·u_n with u_{n-1} = u_n - Δt v_{n-1/2}, its elongation u_n [m] and
	   the velocity v_{n-1/2} [m/s] at which it grew in the last step. For one spring between a mass and a wall: K_{n-1}
	   + U_{n-1} = K_n + (U_n without the spring) + ½ k u_{n-1}u_n, the step's kinetic change being -½ k u_{n-1} v_{n-1/2}Δt;
	   booking ½ k u_n² instead creates ½ k u_n·(u_n - u_{n-1}), the spring force times half the last step's travel, at
	   every break of a spring that was still stretching [J]. */
	template <class S> S releasedSpringEnergy(S k, const Eigen::Matrix<S, 3, 1>& u, const Eigen::Matrix<S, 3, 1>& vel, S dt)
	{
		return k * u.dot(u - dt * vel) / 2;
	}

	/// releasedSpringEnergy of a spring along one axis: ½ k u (u - Δt v) [J].
	template <class S> S releasedSpringEnergy(S k, S u, S vel, S dt) { return k * u * (u - dt * vel) / 2; }

	/* Work of forces that act through one step, booked so that the leapfrog's energy balances (see above): a force D_n
	   of step n does -½ D_n·v_{n-1/2}Δt in step n and -½ D_n·v_{n+1/2}Δt in step n+1. pending is the second half of
	   the last step's dissipation [J]; keep it between steps (and in a saved scene). */
	template <class S> struct SplitWork {
		S pending = 0;
		/// Energy dissipated in this step [J], from this step's dissipation with the earlier velocity, -D_n·v_{n-1/2}Δt,
		/// and with the later one, -D_n·v_{n+1/2}Δt [J]: the pending half of the last step plus half the first; keeps
		/// half the second for the next step.
		S step(S withVelBefore, S withVelAfter)
		{
			const S now = pending + withVelBefore / 2;
			pending     = withVelAfter / 2;
			return now;
		}
	};

} // namespace rdem
} // namespace yade
