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

/// Partial density scaling: bodies with State::densityScaling s in (0, 1) move with the inertia m/s, I/s under their true weight.
class RdemDensityScaling : public GlobalEngine {
public:
	/// Throws std::runtime_error if it is not the engine right before its NewtonIntegrator, if that integrator's own
	/// densityScaling is on, or if it damps without gravity (dampGravity false) while a body is scaled.
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemDensityScaling,GlobalEngine,R"""(Partial density scaling for quasi-static runs ([Itasca2020]_; ``rdem.walltest.scaleDensity`` sets it up): every body with :yref:`State::densityScaling` $s$ in $(0, 1)$ moves as if its mass and moments of inertia were $m/s$ and $I/s$, while gravity keeps acting on its true mass $m$: $(m/s)\,\mathbf{a}=\mathbf{F}+m\mathbf{g}$, $(I/s)\dot{\boldsymbol\omega}+\boldsymbol\omega\times(I/s)\boldsymbol\omega=\mathbf{T}$. Static equilibria and the weight are unchanged; the light or stiff blocks that set the critical step respond more slowly, and the step rises. Bodies with $s\le 0$ (YADE's default, $-1$) or $s=1$ are left alone, bit for bit.

:yref:`NewtonIntegrator::densityScaling` means the same but its aspherical rotation integrators do not scale the torque (``delValle2023``, the default, multiplies the angular velocity by $s$ twice a step), and it is set only with a :yref:`GlobalStiffnessTimeStepper`; so it stays off and this engine, placed right before the integrator after every engine that adds forces, adds $(s-1)(\mathbf{F}+m\mathbf{g})$ to the force and $(s-1)\mathbf{T}$ to the torque of each scaled body (``rdem::densityScalingForce``): the integrator's $\mathbf{F}'/m+\mathbf{g}$ is then $s(\mathbf{F}/m+\mathbf{g})$, and Euler's equations, linear in the inertia, give the motion of $I/s$ under $s\mathbf{T}$. Cundall's damping of the integrator then acts on the scaled acceleration, as on any body (it needs :yref:`NewtonIntegrator::dampGravity`, the default). After this engine :yref:`O.forces<Omega.forces>` holds these forces $\mathbf{F}'$ for the scaled bodies.

Everything that uses a body's mass for its inertia takes the inertial mass $m/s$ (``rdem::inertialFactor``): :yref:`RdemTimeStepper` (its mass matrix, the Gershgorin rows), the dashpots' stability caps of :yref:`Law2_RdemGeom_RdemPhys_FaceSprings`, the Poisson engine's bounds, and the kinetic energy and damping work of :yref:`RdemLeapfrogEnergy`; gravity's work (``gravWork``) stays with $m$.)""",
		((shared_ptr<NewtonIntegrator>,integrator,,,"The integrator that moves the bodies (``rdem.walltest.scaleDensity`` hands it); ``None``: the NewtonIntegrator in :yref:`O.engines<Omega.engines>`, found at the first step."))
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	/// The integrator of this step, checked to run right after this engine; scene->engines as checked.
	NewtonIntegrator*     checkedIntegrator();
	rdem::EngineListStamp checkedEngines;
	NewtonIntegrator*     checked = nullptr;
};
REGISTER_SERIALIZABLE(RdemDensityScaling);

} // namespace yade
