/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>

namespace yade {

/// Moves the ground as a recorded or synthetic ground motion prescribes: the base blocks follow it, or every body feels its inertial load.
class RdemGroundShaker : public GlobalEngine {
public:
	void action() override;
	/// Throws std::invalid_argument (Python: ValueError) for an unknown mode, times that do not increase, arrays of different lengths.
	void postLoad(RdemGroundShaker&);
	/// Ground acceleration, velocity and displacement at time t (linear interpolation; before the record: zero, after it: at rest at the last displacement).
	Vector3r accelerationAt(Real t) const;
	Vector3r velocityAt(Real t) const;
	Vector3r displacementAt(Real t) const;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemGroundShaker,GlobalEngine,R"""(Applies a ground motion (``rdem.ground_motion.GroundMotion``: acceleration, velocity and displacement sampled at ``times``, the last two integrated from the first) to the scene, in one of two ways (``rdem.earthquake.shaker`` makes it from a record):

* ``mode='prescribed'``: the base blocks ``ids`` move with the ground. Their translations are blocked (``xyz`` of :yref:`State::blockedDOFs`, set by ``rdem.earthquake.shaker``) and at every step their velocity is set to $(\mathbf{u}_g(t+\Delta t)-\mathbf{u}_g(t))/\Delta t$, so that :yref:`NewtonIntegrator` puts them exactly on the ground displacement $\mathbf{u}_g$ at every step. The structure is shaken through its bonds and contacts with the base, as on a shaking table: right for anything that rocks, slides or lifts off its base (rocking, overturning, a wall standing on a footing).
* ``mode='inertial'``: the ground does not move; every body feels the inertial load $-m\,\mathbf{a}_g(t)$, added to :yref:`NewtonIntegrator::gravity` (``gravity`` $-\mathbf{a}_g$). Displacements are then relative to the ground: right for a structure bonded to a rigid base that does not lift off, and what building codes' spectra and most frame analyses assume; it avoids following large ground displacements.

With :yref:`O.trackEnergy<Omega.trackEnergy>` and ``mode='prescribed'``, ``groundWork`` in :yref:`O.energy<Scene.energy>` is minus the work the ground motion has done (cumulated): on the rest of the scene (in the leapfrog pairing, the force of a step times the base's displacement over it) and on the base blocks' own kinetic energy, which :yref:`NewtonIntegrator` books as ``kinetic``; so that the total energy stays constant in a conservative scene; in ``mode='inertial'`` the work of the inertial load is in :yref:`NewtonIntegrator`'s ``gravWork``.

Before ``times[0]`` the ground is at rest at zero displacement, after the last time at rest at its last displacement. ``scale`` multiplies the motion.)""",
		((string,mode,"prescribed",Attr::triggerPostLoad,"``'prescribed'`` (base blocks move) or ``'inertial'`` (inertial load on every body)."))
		((vector<Real>,times,,Attr::triggerPostLoad,"Sampling times of the motion, increasing [s] (``O.time`` is the time axis)."))
		((vector<Vector3r>,accelerations,,Attr::triggerPostLoad,"Ground acceleration at ``times`` [m/s²]."))
		((vector<Vector3r>,velocities,,Attr::triggerPostLoad,"Ground velocity at ``times`` [m/s] (integrated from the accelerations)."))
		((vector<Vector3r>,displacements,,Attr::triggerPostLoad,"Ground displacement at ``times`` [m] (integrated from the velocities)."))
		((vector<int>,ids,,,"Base blocks moved with the ground (``mode='prescribed'``)."))
		((Vector3r,gravity,Vector3r(0,0,-9.81),,"Gravity of the scene [m/s²]; with ``mode='inertial'`` :yref:`NewtonIntegrator::gravity` is set to ``gravity`` $-$ ``scale`` $\\mathbf{a}_g(t)$ every step."))
		((Real,scale,1,,"Factor on the whole motion."))
		((int,workIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
		,
		/* ctor */,
		.def("accelerationAt",&RdemGroundShaker::accelerationAt,(py::arg("t")),"Ground acceleration at time t, scaled [m/s²].")
		.def("velocityAt",&RdemGroundShaker::velocityAt,(py::arg("t")),"Ground velocity at time t, scaled [m/s].")
		.def("displacementAt",&RdemGroundShaker::displacementAt,(py::arg("t")),"Ground displacement at time t, scaled [m].")
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	Vector3r interpolate(const vector<Vector3r>& v, Real t, bool holdLast) const;
};
REGISTER_SERIALIZABLE(RdemGroundShaker);

} // namespace yade
