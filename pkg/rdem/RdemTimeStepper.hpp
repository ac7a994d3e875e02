/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/TimeStepper.hpp>
#include <pkg/rdem/RdemSharedState.hpp>
#include <pkg/rdem/math/StiffnessSpectrum.hpp>

namespace yade {

/// Critical time step of block assemblies from block masses, inertias, all spring and Poisson stiffnesses: the largest
/// eigenvalue of the mass-normalised stiffness by Lanczos iterations (default) or its Gershgorin bound.
class RdemTimeStepper : public TimeStepper {
public:
	void computeTimeStep(Scene*) override;
	/// Every timeStepUpdateInterval steps, at the step after a spring broke (unless contactLimited), and every step while
	/// O.dt is not a positive number (computeTimeStep refuses it).
	/// Throws std::invalid_argument (Python: ValueError) for timeStepUpdateInterval = 0.
	bool isActivated() override;
	/// Throws std::invalid_argument (Python: ValueError) for safety outside (0, 1], an unknown method or bad Lanczos settings.
	void postLoad(RdemTimeStepper&);
	/// The estimate itself, Δt_crit [s] (2/ω_max without dashpots; no safety factor), by ``method``; inf if nothing is elastic yet.
	/// inIdOrder: the scene's rdem::interactionsInIdOrder.
	Real estimate(Scene* scene, const vector<const Interaction*>& inIdOrder);
	/// Python: the estimate by ``method`` or by the method named (``'lanczos'``, ``'gershgorin'``, ``'dashpots'``: λ_K kept).
	Real estimatePy(const string& method);
	/// Python: K·x, K the linear stiffness the estimate uses (assemble), x 6 values per body (u [m], θ [rad]) [N, N·m].
	vector<Real> stiffnessTimes(const vector<Real>& x);
	/// Python: per body id, (ω_b², c_b): its Gershgorin row of the mass-normalised stiffness [1/s²] (as ``method='gershgorin'``)
	/// and 2 λ_max of its diagonal block of the mass-normalised dashpots, uncapped [1/s]; (0, 0) for a fixed body.
	boost::python::list blockRows();
	/// The linear stiffness K of the scene and its contact dashpots C, as their sources give them (RdemStiffnessSource:
	/// the law's springs and dashpots, the Poisson engine's elements and cells), plus the contacts that can still form
	/// (contactBound), and each body's mass normalisation; inIdOrder: the scene's rdem::interactionsInIdOrder.
	void assemble(
	        Scene*                            scene,
	        const vector<const Interaction*>& inIdOrder,
	        rdem::BlockStiffness<Real>&       K,
	        rdem::BlockStiffness<Real>&       C,
	        vector<rdem::BodyScale<Real>>&    scale);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemTimeStepper,TimeStepper,R"""(Time step for the refined DEM with the Poisson effect: ``O.dt = safety·Δt_crit``.

YADE's :yref:`PWaveTimeStep<yade.utils.PWaveTimeStep>` ignores boxes and :yref:`GlobalStiffnessTimeStepper` assumes sphere contacts, so this stepper finds the highest eigenfrequency $\omega_{max}$ of the assembly itself; $\Delta t_{crit}=2/\omega_{max}$ (central differences) while no contact dashpot acts. The contact dashpots of eq. 13 act on the mid-step velocity and lower the limit: leapfrog is stable while $\lambda_{max}(\Delta t^2\tilde{K}+2\Delta t\tilde{C})\le 4$ ($\tilde{K}$, $\tilde{C}$ the mass-normalised stiffness and dashpots). ``criticalDt`` is the root of $\lambda_{max}(\Delta t^2\tilde{K}+2\Delta t\tilde{C})=4$, found by Lanczos runs on that matrix (``rdem::dampedCriticalStepOfBoth``, bracketed to $2\cdot$ ``lanczosTolerance``, the lower end taken) from its lower bound $4/(\lambda_C+\sqrt{\lambda_C^2+4\lambda_K})$, $\lambda_K=\omega_{max}^2$, $\lambda_C$ the largest eigenvalue of $\tilde{C}$ (``rdem::dampedCriticalStep``; for one oscillator $(2/\omega)(\sqrt{1+\zeta^2}-\zeta)$ [Belytschko2000]_, 0.41 of $2/\omega$ at critical damping), which is exact only where the stiffest mode is the most damped (MI1 at its peak: 14.48 µs against the bound's 13.65 µs). $\tilde{C}$ holds the dashpots of the contact samples, and of the broken segments that touch, capped as the law caps them for the current ``O.dt`` (a larger step lowers the caps); the contacts to come (``contactBound``) add their springs only.

*Lanczos* (``method='lanczos'``, the default): $\omega_{max}^2=\lambda_{max}$ of $A=PSKSP$, $K$ the linear stiffness of the current configuration (every segment spring of a bond, every contact sample, the contacts blocks can still make with ``contactBound``, the Poisson elements and cells with the offset correction of the shear springs (:yref:`RdemPhys::offsetCorrection`), without the geometric stiffness), $S$ the inverse square root of each block's mass and rotated inertia, $P$ its free DOFs; by Lanczos iterations with full reorthogonalisation, warm-started from the last estimate's Ritz vector, until the residual of the largest Ritz value $\theta$ is below ``lanczosTolerance``·$\theta$; $\lambda_{max}\approx\theta+r$ [Parlett1998]_ [ZhouLi2011]_. Measured against the exact limit: 0.02–0.05 % below it. $\lambda_C$ the same way, from its own Ritz vector, when a dashpot acts.

*Gershgorin* (``method='gershgorin'``, the fallback, 2.2–2.7 times below the limit): for every free block $b$, $\omega_b^2=\sum_i 2\left(k_{t,i}/m_b + k_{r,i}/I_{min,b}\right)+P_b/m_b$, summed over the springs $i$ of its segments and contact samples, $k_{t}=\max(\bar{k}_n,\bar{k}_s)A$, $k_{r}=A(\bar{k}_n|\mathbf{r}\times\mathbf{n}|^2+\bar{k}_s(|\mathbf{r}|^2+(\mathbf{r}\cdot\mathbf{n})^2))$ with $\mathbf{r}$ the arm from the centroid, and $P_b$ the Poisson row-sum bound of :yref:`RdemPoissonEngine`; $\omega_{max}\le\max_b\omega_b$. It leaves the dashpots out: at 0.37–0.44 of the undamped limit it is already about where critical dashpots put the limit (0.41 of it), and the law's caps keep the dashpots of small blocks below critical.

When not :yref:`active<TimeStepper::active>` (a positive ``O.dt`` was set by the user), a fixed ``O.dt`` above the Lanczos estimate of the springs' limit $2/\omega_{max}$ is refused when it is first seen (at the first step, or when it was changed): the step stops before the integrator moves anything and ``O.run`` raises ``RuntimeError`` with a message naming ``O.dt`` and the limit, unless ``refuseUnstableDt`` is false; if the limit falls below it later (contacts), if only the dashpots' limit is exceeded (their compression-only clamp and caps often keep such a run bounded, as the paper's 2 µs after cracking), or with the Gershgorin method, it warns once (and sets ``warned``). ``O.dt`` zero or not finite stops the run the same way.

On a distributed run (:ref:`mpy`, YADE built with ``ENABLE_MPI``) each rank estimates the limits of its own blocks, with its ghosts' DOFs fixed (their owners move them), and all ranks take the minimum over ranks (one ``MPI_Allreduce`` of three reals at each update, and of one integer at every step, so that all ranks update together): one ``O.dt`` for all, and a fixed ``O.dt`` is checked against that minimum. A rank's mass-normalised stiffness is then a principal submatrix of the whole scene's, so the minimum is not below the whole scene's limit (Cauchy's interlacing), and above it only by a mode that spans two subdomains; ``criticalDt``, ``springCriticalDt`` and ``contactDt`` are the rank's own.)""",
		((Real,safety,0.8,Attr::triggerPostLoad,"Fraction of the critical step used for ``O.dt``."))
		((string,method,"lanczos",Attr::triggerPostLoad,"How $\\omega_{max}$ is found: ``'lanczos'`` (default: tight, see above) or ``'gershgorin'`` (a bound 2.2–2.7 times too high, one pass over the springs)."))
		((Real,lanczosTolerance,1e-3,Attr::triggerPostLoad,"Lanczos iterations stop when the residual of the largest Ritz value is below this fraction of it, in (0, 0.1]."))
		((int,lanczosMaxSteps,60,Attr::triggerPostLoad,"Most Lanczos steps per estimate, >= 2 (the estimate is then $\\theta+r$ whatever $r$ is)."))
		((bool,reuseUnchanged,true,,"Keep the last Lanczos estimate while the springs are unchanged (the same bodies, interactions, bonded segments, contact samples, stiffnesses, broken springs, blocked DOFs and masses), at most 99 updates in a row: a bonded assembly before it cracks then costs one estimate per 10 000 steps (``timeStepUpdateInterval`` 100)."))
		((bool,refuseUnstableDt,true,,"Refuse a fixed ``O.dt`` above the Lanczos estimate when it is first seen (see above); false: only warn (to measure instability on purpose)."))
		((int,lanczosSteps,0,(Attr::readonly|Attr::noSave),"Lanczos steps of the last estimate."))
		((Real,lanczosResidual,0,(Attr::readonly|Attr::noSave),"Residual $r/\\theta$ of the last Lanczos estimate."))
		((vector<Real>,ritzVector,,Attr::readonly,"The last estimate's Ritz vector of $A$, 6 values per body id, mass-normalised (saved: the next estimate starts from it, also after ``O.load``): the stiffest mode (its motion is $S$ times it)."))
		((vector<Real>,dashpotRitzVector,,Attr::readonly,"As ``ritzVector``, of the dashpots' $\\lambda_C$: the most damped mode."))
		((vector<Real>,dampedRitzVector,,(Attr::readonly|Attr::noSave),"As ``ritzVector``, of $\\Delta t^2\\tilde{K}+2\\Delta t\\tilde{C}$ at the damped limit: the mode that sets ``criticalDt`` while dashpots act (empty otherwise; not saved: made from the two above)."))
		((int,dampedRounds,0,(Attr::readonly|Attr::noSave),"Lanczos runs on $\\Delta t^2\\tilde{K}+2\\Delta t\\tilde{C}$ that found the damped limit at the last estimate (0: no dashpot acts, the limit is $2/\\omega_{max}$)."))
		((Real,dashpotRate,0,(Attr::readonly|Attr::noSave),"$\\lambda_C$ of the last Lanczos estimate: largest eigenvalue of the mass-normalised contact dashpots [1/s]; 0 when no dashpot acts (a bonded assembly before it cracks)."))
		((vector<Real>,lastSignature,,(Attr::hidden|Attr::readonly),"What the springs were at the last Lanczos estimate (reuseUnchanged; saved, so that a reloaded run takes the same decisions)."))
		((int,reused,0,Attr::readonly,"Updates since the last estimate of $\\lambda_K$ that kept it (``reuseUnchanged``): those that kept the whole estimate, and those after a break that redid only the dashpots' part."))
		((Real,checkedDt,0,(Attr::hidden|Attr::readonly),"The fixed ``O.dt`` last checked against the limit [s] (saved, as everything the next steps depend on: a reloaded run takes the same decisions)."))
		((long,brokenAtEstimate,0,(Attr::hidden|Attr::readonly),"Springs broken when the last estimate was made (a break triggers a new one unless ``contactLimited``; saved)."))
		((bool,contactLimited,false,Attr::readonly,"Whether the automatic step of the last update was held by ``contactLimit`` (the damped limit ``criticalDt`` at or above ``contactDt``, over all ranks). While it is, a spring that breaks waits for the next regular update (``timeStepUpdateInterval``) instead of triggering one: ``contactDt`` already allows for a critically damped contact on the stiffest mode, which is what a break brings, as a contact that forms between two updates does (saved, so that a reloaded run takes the same decisions)."))
		((bool,contactBound,false,,"Also allow for the contacts that blocks can still make (scenes with a collider, ``rdem.engines(recontact=True)``): every free block that carries no bond gets the terms of a flush contact on each of its six faces, at its own stiffness per area (:ref:`theory §6 <rdem-theory-6>`). Without it the step follows only the contacts that exist: none for a falling block, and a step set while a corner touches is unstable once a face lands."))
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`: a spring that breaks triggers a new estimate, unless ``contactLimited``; handed by ``rdem.engines()``; None: the law's, taken at the first step)."))
		((Real,criticalDt,0,Attr::readonly,"Last estimate of the critical time step, without the safety factor [s]; while dashpots act and ``contactLimit`` applies to an automatic step, a lower bound of it once that reaches ``contactDt`` (the step cannot be larger)."))
		((bool,contactLimit,true,,"While contacts act or can form (a contact sample, a broken spring, or with ``contactBound`` a free block without bonds), keep the automatic step below the limit of a critically damped stiffest mode too: ``O.dt = safety·min(criticalDt, contactDt)`` with ``contactDt`` $=(\\sqrt{2}-1)\\,2/\\omega_{max}$ [Belytschko2000]_ (``rdem::criticallyDampedStep`` of ``springCriticalDt``). Contacts that form between two estimates bring their critical dashpots (eq. 13, $h=1$), which the estimate has not seen; on the stiffest mode they lower its limit to 0.41 of the undamped one. At 0.8 of the Lanczos limit the law's dashpot caps bind on such contacts and the contact dynamics change with the step (measured: a rocking block that no longer overturns, a dry wall that falls below its tilt limit). A bonded assembly before its first break keeps the tight step. While the step is held by this limit (``contactLimited``), a spring that breaks does not trigger an update before the regular one: its contact dashpot is such a contact."))
		((Real,contactDt,0,(Attr::readonly|Attr::noSave),"The limit applied by ``contactLimit`` at the last automatic step, $(\\sqrt{2}-1)$ ``springCriticalDt`` [s]; inf while no contact can act (not computed for a fixed ``O.dt``)."))
		((Real,springCriticalDt,0,Attr::readonly,"Critical step of the springs alone, $2/\\omega_{max}$, of the last estimate [s]: a fixed ``O.dt`` above it is refused; one between ``criticalDt`` (with the contact dashpots) and it only warns."))
		((bool,warned,false,(Attr::readonly|Attr::noSave),"Whether the too-large ``O.dt`` warning was printed (once per engine)."))
		,
		/* ctor */,
		.def("estimate",&RdemTimeStepper::estimatePy,(py::arg("method")=""),"Critical time step of the current scene [s], without the safety factor, by ``method`` or by the method named (``'lanczos'``, ``'gershgorin'``; ``'dashpots'``: as an update for a break alone, with $\\lambda_K$ and its Ritz vector kept from the last estimate).")
		.def("blockRows",&RdemTimeStepper::blockRows,"Per body id, $(\\omega_b^2, c_b)$ of the current scene, with the inertial masses (:yref:`RdemDensityScaling`): $\\omega_b^2$ its Gershgorin row of the mass-normalised stiffness [1/s²] (as ``method='gershgorin'``, ``contactBound`` included), $c_b=2\\lambda_{max}(S_bC_{bb}S_b)$ the bound of its row of the mass-normalised contact dashpots (eq. 13, without the caps) [1/s], from its diagonal block $C_{bb}$ ($C\\preceq 2\\,\\mathrm{blockdiag}(C_{bb})$ for a sum of pair dashpots). Leapfrog is stable while $\\Delta t^2\\omega_b^2+2\\Delta t\\,c_b\\le 4$ for every block (a bound, below the Lanczos limit); ``rdem.quasi_static.inertialScales`` takes these rows. $(0, 0)$ for a fixed body.")
		.def("stiffnessTimes",&RdemTimeStepper::stiffnessTimes,(py::arg("x")),"$K\\mathbf{x}$ [N, N·m], $K$ the linear stiffness of the current configuration that the estimate uses (the sources' terms, :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` and :yref:`RdemPoissonEngine`, plus the contacts to come with ``contactBound``), $\\mathbf{x}$ 6 values per body id: displacement [m] and small rotation [rad] in global axes (tests/yade/test_stiffness_source.py checks it against the forces).")
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	Real gershgorin(Scene* scene);
	/// keepStiffest: take λ_K and its Ritz vector from the last estimate (springCriticalDt), redo the dashpots' λ_C and the damped limit.
	Real lanczos(Scene* scene, const vector<const Interaction*>& inIdOrder, bool keepStiffest = false);
	/// Each body's mass normalisation (inertial masses; a ghost of a distributed run fixed), by body id.
	void bodyScales(Scene* scene, vector<rdem::BodyScale<Real>>& scale);
	/// Refuse or warn about a fixed O.dt above the scene's limits (over all ranks of a distributed run) [s].
	void checkFixedDt(Scene* scene, Real criticalDtAll, Real springCriticalDtAll);
	/// The step for which the dashpots are capped as the law caps them (Law2…::dashpotCap): O.dt when the estimate
	/// is made, 0 (no cap) if O.dt is not yet set [s]. A step chosen larger than it lowers the caps, so the estimate holds.
	Real capDt = 0;
	/// The step the law caps the dashpots for in this step: O.dt, or 0 (no cap) before a step is set [s].
	static Real capStep(const Scene* sc) { return sc->dt > 0 && math::isfinite(sc->dt) ? sc->dt : Real(0); }
	/// An update for a break alone: λ_K and its Ritz vector kept, the dashpots' part redone (lanczos with keepStiffest).
	Real estimateDashpots(Scene* scene, const vector<const Interaction*>& inIdOrder);
	/// Whether a contact acts or can form: a contact sample, a broken spring, or (contactBound) a free block without bonds.
	bool contactsPossible(Scene* scene);
	/// What K depends on besides the poses (reuseUnchanged), from the scene's rdem::interactionsInIdOrder.
	vector<Real> springSignature(Scene* scene, const vector<const Interaction*>& inIdOrder);
	/// Restoring springs broken so far in the scene (RdemSharedState).
	long brokenSprings(Scene* sc) { return RdemSharedState::of(sc, shared).brokenSprings(); }
};
REGISTER_SERIALIZABLE(RdemTimeStepper);

} // namespace yade
