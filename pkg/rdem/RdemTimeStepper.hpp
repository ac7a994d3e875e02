/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/TimeStepper.hpp>

namespace yade {

/// Critical time step of block assemblies from block masses, inertias, all spring and Poisson stiffnesses.
class RdemTimeStepper : public TimeStepper {
public:
	void computeTimeStep(Scene*) override;
	/// Every timeStepUpdateInterval steps, and every step while O.dt is not a positive number (computeTimeStep refuses it).
	/// Throws std::invalid_argument (Python: ValueError) for timeStepUpdateInterval = 0.
	bool isActivated() override;
	/// Throws std::invalid_argument (Python: ValueError) for safety outside (0, 1].
	void postLoad(RdemTimeStepper&);
	/// The estimate itself, 2/ω_max [s] (no safety factor); inf if nothing is elastic yet.
	Real estimate(Scene* scene) const;
	Real estimatePy() const;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemTimeStepper,TimeStepper,R"""(Time step for the refined DEM with the Poisson effect: ``O.dt = safety·Δt_crit``.

YADE's :yref:`PWaveTimeStep<yade.utils.PWaveTimeStep>` ignores boxes and :yref:`GlobalStiffnessTimeStepper` assumes sphere contacts, so this stepper bounds the highest eigenfrequency of the assembly with Gershgorin's theorem on the mass-normalised stiffness: for every free block $b$, $\omega_b^2=\sum_i 2\left(k_{t,i}/m_b + k_{r,i}/I_{min,b}\right)+P_b/m_b$, summed over the springs $i$ of its segments and contact samples, $k_{t}=\max(\bar{k}_n,\bar{k}_s)A$, $k_{r}=A(\bar{k}_n|\mathbf{r}\times\mathbf{n}|^2+\bar{k}_s(|\mathbf{r}|^2+(\mathbf{r}\cdot\mathbf{n})^2))$ with $\mathbf{r}$ the arm from the centroid, and $P_b$ the Poisson row-sum bound of :yref:`RdemPoissonEngine`; $\Delta t_{crit}=2/\max_b\omega_b$ (central differences). The bound is conservative; doc/stability.md reports the measured stability limit as a fraction of it.

When not :yref:`active<TimeStepper::active>` (a positive ``O.dt`` was set by the user), it only warns once if ``O.dt`` exceeds the estimate (and sets ``warned``), and it stops the run with ``ValueError`` if ``O.dt`` is zero or not finite.)""",
		((Real,safety,0.8,Attr::triggerPostLoad,"Fraction of the critical step used for ``O.dt``."))
		((bool,contactBound,false,,"Also allow for the contacts that blocks can still make (scenes with a collider, ``rdem.engines(recontact=True)``): every free block that carries no bond gets the terms of a flush contact on each of its six faces, at its own stiffness per area (doc/theory.md §6). Without it the step follows only the contacts that exist: none for a falling block, and a step set while a corner touches is unstable once a face lands."))
		((Real,criticalDt,0,Attr::readonly,"Last estimate of the critical time step, without the safety factor [s]."))
		((bool,warned,false,(Attr::readonly|Attr::noSave),"Whether the too-large ``O.dt`` warning was printed (once per engine)."))
		,
		/* ctor */,
		.def("estimate",&RdemTimeStepper::estimatePy,"Critical time step of the current scene [s], without the safety factor.")
	);
	// clang-format on
	DECLARE_LOGGER;
};
REGISTER_SERIALIZABLE(RdemTimeStepper);

} // namespace yade
