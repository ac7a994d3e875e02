/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>
#include <pkg/dem/NewtonIntegrator.hpp>
#include <pkg/rdem/RdemSharedState.hpp>

namespace yade {

/// Books the kinetic energy and the integrator's damping in O.energy as the leapfrog's exact energy balance needs them.
class RdemLeapfrogEnergy : public GlobalEngine {
public:
	/// Throws std::runtime_error naming the engines if it does not follow its NewtonIntegrator in O.engines (checked at
	/// the first step and whenever O.engines changes).
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemLeapfrogEnergy,GlobalEngine,R"""(Makes the total of :yref:`O.energy<Scene.energy>` constant to round-off in an undamped linear scene, at any stable time step, and balanced step by step with damping (pkg/rdem/math/LeapfrogEnergy.hpp; the derivation is in :ref:`theory §6 <rdem-theory-6>`). Placed after :yref:`NewtonIntegrator`, with no engine between them that changes velocities (``rdem.engines()`` puts it last, after :yref:`RdemFiniteGuard`); it acts only with :yref:`O.trackEnergy<Omega.trackEnergy>`.

:yref:`NewtonIntegrator` books ``kinetic`` as $\frac12 m v_{n-1/2}^2$, at the velocity half a step before the positions $x_n$ at which the springs' energy (``rdemElastic``, ``rdemPoisson``) and gravity's work (``gravWork``) are booked: the total then swings by $O(\omega\Delta t)$, tens of percent at the default step, without drifting. This engine sets ``kinetic`` to the leapfrog's kinetic energy of step $n$, $\frac12 m\,v_{n-1/2}\cdot v_{n+1/2}+\frac12\omega_{n-1/2}\cdot I\,\omega_{n+1/2}$ (``rdem::pairedKineticEnergy``; for linear forces $K_n+U(x_n)$ is exactly conserved [HairerLubichWanner2006]_), and ``nonviscDamp`` to the work that Cundall's damping of the integrator really did, each step's force split over its two half steps as the law books its dashpots (``rdem::SplitWork``): the force from the velocity change beyond the forces and gravity (``rdem::dampingForce``), the torque of the aspherical integrator from its rule (``rdem::cundallDampingTorque``) in place of NewtonIntegrator's first-order estimate $|F||v|d\,\Delta t$.

Bodies scaled by :yref:`RdemDensityScaling` (:yref:`State::densityScaling` $s$) are booked with their inertial mass $m/s$ and inertia $I/s$, and their damping force and torque as $1/s$ of what the integrator applied to the scaled forces; gravity's work stays with $m$ (``rdem::inertialFactor``). :yref:`NewtonIntegrator::densityScaling` itself leaves NewtonIntegrator's values standing.

Rotations are paired the same way, with the inertia in global axes after the step; the balance then holds up to the rotation integrator's small-rotation error. Degrees of freedom that are blocked (imposed velocities) keep NewtonIntegrator's $\frac12 mv^2$. Velocities are read after the integrator and kept for the next step: a velocity set by hand between two steps on a free degree of freedom counts, in that step, as if the integrator had made it (impose velocities on blocked DOFs, as YADE does). A step whose $\Delta t$ differs from the last one's (a :yref:`RdemTimeStepper` update) shifts that conserved total by $\frac12(\Delta t_n-\Delta t_{n-1})\,(v_{n-1/2}\cdot(F_n-mg)+\omega_{n-1/2}\cdot T_n)$ summed over the bodies (``rdem::stepChangeJump``: the integrator advances the velocities with the new step from forces of positions reached with the old one): a numerical shift, not work, booked as ``rdemStepChange`` with the opposite sign so that the total stays constant across it (in a cracking house, 7.7 % shorter steps shifted it by 2.8 mJ, 10 % of the energy that step exchanged).

At the first tracked step, after a step without tracking, and in periodic scenes (whose kinetic energy NewtonIntegrator takes from fluctuation velocities) NewtonIntegrator's values stand.)""",
		((shared_ptr<NewtonIntegrator>,integrator,,,"The integrator whose steps are booked (``rdem.engines()`` hands it); ``None``: the NewtonIntegrator in :yref:`O.engines<Omega.engines>`, found at the first step."))
		((vector<Vector3r>,velAfter,,(Attr::hidden|Attr::readonly),"$v_{n+1/2}$ of every body after the last tracked step [m/s] (saved: a reloaded run books on as the uninterrupted one)."))
		((vector<Vector3r>,angVelAfter,,(Attr::hidden|Attr::readonly),"$\\omega_{n+1/2}$ of every body after the last tracked step [rad/s]."))
		((long,recordedIter,-1,(Attr::hidden|Attr::readonly),"The step whose velocities ``velAfter`` holds; -1: none."))
		((Real,dampingWork,0,(Attr::hidden|Attr::readonly),"``nonviscDamp`` as booked by this engine, cumulated [J]."))
		((Real,pendingDamping,0,(Attr::hidden|Attr::readonly),"The second half of the last step's damping work, booked in the next step [J]."))
		((Real,lastDt,0,(Attr::hidden|Attr::readonly),"$\\Delta t$ of the last tracked step [s] (saved): a step with another one books the jump of ``rdemStepChange``."))
		((Real,stepChangeEnergy,0,(Attr::hidden|Attr::readonly),"``rdemStepChange`` as booked by this engine, cumulated [J]."))
		((int,stepChangeIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
		((int,kineticIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
		((int,dampIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	/// The integrator of this step, checked to run before this engine; scene->engines as checked, to check again when it changes.
	NewtonIntegrator*     checkedIntegrator();
	rdem::EngineListStamp checkedEngines;
	NewtonIntegrator*     checked = nullptr;
};
REGISTER_SERIALIZABLE(RdemLeapfrogEnergy);

} // namespace yade
