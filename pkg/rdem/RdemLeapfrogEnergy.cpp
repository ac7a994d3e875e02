/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/RdemLeapfrogEnergy.hpp>
#include <pkg/rdem/RdemRanks.hpp>
#include <pkg/rdem/math/DensityScaling.hpp>
#include <pkg/rdem/math/LeapfrogEnergy.hpp>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((RdemLeapfrogEnergy));
CREATE_LOGGER(RdemLeapfrogEnergy);

NewtonIntegrator* RdemLeapfrogEnergy::checkedIntegrator()
{
	if (checked && checkedEngines.same(scene->engines)) return checked;
	NewtonIntegrator* newton = integrator ? integrator.get() : rdem::findEngine<NewtonIntegrator>(scene);
	const long        self = rdem::positionOf(scene, this), other = rdem::positionOf(scene, newton);
	if (other < 0 || other > self)
		throw std::runtime_error(
		        std::string("RdemLeapfrogEnergy (O.engines[") + std::to_string(self)
		        + "]) books the steps of a NewtonIntegrator that runs before it, but "
		        + (!newton             ? "O.engines has no NewtonIntegrator"
		                   : other < 0 ? "its integrator is not in O.engines"
		                               : "the NewtonIntegrator is O.engines[" + std::to_string(other) + "], after it")
		        + ": place RdemLeapfrogEnergy after the NewtonIntegrator (rdem.engines() does)");
	checkedEngines.take(scene->engines);
	checked = newton;
	return newton;
}

void RdemLeapfrogEnergy::action()
{
	const NewtonIntegrator& newton = *checkedIntegrator();
	if (!scene->trackEnergy) return; // recordedIter stays behind: the next tracked step starts afresh
	const size_t nBodies = scene->bodies->size();
	// the step's velocities before the integrator, kept from the last step (see the class documentation)
	const bool paired = recordedIter == scene->iter - 1 && velAfter.size() == nBodies && !scene->isPeriodic && !newton.densityScaling;
	const Real dt = scene->dt, damping = newton.damping;
	const bool damped = paired && damping != 0;
	// a step whose Δt differs from the last tracked one's (a time stepper's update): its jump is booked (stepChangeJump)
	const bool stepChanged = paired && lastDt > 0 && dt != lastDt;
	if (damped || stepChanged) scene->forces.sync(); // synced by the integrator already; a no-op then
	Real kinTrans = 0, kinRot = 0, withBefore = 0, withAfter = 0, jump = 0;
	velAfter.resize(nBodies, Vector3r::Zero());
	angVelAfter.resize(nBodies, Vector3r::Zero());
	for (const auto& b : *scene->bodies) {
		if (!b || b->isClumpMember() || (newton.mask > 0 && !b->maskCompatible(newton.mask)) || rdem::notOwned(*scene, *b))
			continue; // as the integrator
		const State& s  = *b->state;
		const size_t id = size_t(b->getId());
		Vector3r     v0 = paired ? velAfter[id] : s.vel, w0 = paired ? angVelAfter[id] : s.angVel;
		for (int i = 0; i < 3; ++i) { // blocked: the imposed velocity, which the integrator does not change
			if (s.blockedDOFs & State::axisDOF(i, false)) v0[i] = s.vel[i];
			if (s.blockedDOFs & State::axisDOF(i, true)) w0[i] = s.angVel[i];
		}
		velAfter[id]    = s.vel;
		angVelAfter[id] = s.angVel;
		if (!paired) continue;
		// the inertial mass and inertia (RdemDensityScaling: m/s, I/s; gravity acts on m)
		const Real     f = rdem::inertialFactor(s.densityScaling);
		const Vector3r J = s.inertia * f;
		const Matrix3r R = s.ori.toRotationMatrix();
		const Matrix3r I = b->isAspherical() ? Matrix3r(R * J.asDiagonal() * R.transpose()) : Matrix3r(J.asDiagonal());
		kinTrans += rdem::pairedKineticEnergy<Real>(s.mass * f, v0, s.vel, Matrix3r::Zero(), w0, s.angVel);
		kinRot += rdem::pairedKineticEnergy<Real>(0, v0, s.vel, I, w0, s.angVel);
		if (stepChanged) {
			Vector3r F = scene->forces.getForce(b->getId()), T = scene->forces.getTorque(b->getId());
			for (int i = 0; i < 3; ++i) { // blocked: the kinetic term stays; gravity's work was booked with the new Δt
				if (s.blockedDOFs & State::axisDOF(i, false)) F[i] = -s.mass * newton.gravity[i];
				if (s.blockedDOFs & State::axisDOF(i, true)) T[i] = 0;
			}
			jump += rdem::stepChangeJump<Real>(lastDt, dt, v0, F, s.mass, newton.gravity, w0, T);
		}
		if (!damped || !s.isDamped || s.blockedDOFs == State::DOF_ALL) continue;
		Vector3r       D = rdem::dampingForce<Real>(s.mass, s.mass, v0, s.vel, dt, scene->forces.getForce(b->getId()), newton.gravity);
		const Vector3r T = scene->forces.getTorque(b->getId());
		// NewtonIntegrator::action: the aspherical integrator damps the torque, the spherical one the angular acceleration
		const bool aspherical = newton.exactAsphericalRot && b->isAspherical() && (s.blockedDOFs & State::DOF_RXRYRZ) == State::DOF_NONE;
		Vector3r   Dt = aspherical ? rdem::cundallDampingTorque<Real>(damping, T, w0) : Vector3r(s.inertia.cwiseProduct(s.angVel - w0) / dt - T);
		if (f != 1) { // RdemDensityScaling handed the integrator s(F + m g) - m g and s T: the damping of the scaled body is 1/s of what they give
			D *= f;
			Dt *= f;
		}
		for (int i = 0; i < 3; ++i) {
			if (s.blockedDOFs & State::axisDOF(i, false)) D[i] = 0;
			if (s.blockedDOFs & State::axisDOF(i, true)) Dt[i] = 0;
		}
		withBefore -= (D.dot(v0) + Dt.dot(w0)) * dt;
		withAfter -= (D.dot(s.vel) + Dt.dot(s.angVel)) * dt;
	}
	const long step = scene->iter;
	recordedIter    = step;
	lastDt          = dt;
	if (stepChanged) {
		stepChangeEnergy -= jump;
		scene->energy->set(stepChangeEnergy, "rdemStepChange", stepChangeIx);
	}
	if (!paired) { // NewtonIntegrator's values of this step stand; this engine's booking takes over from them
		int ix = -1;
		scene->energy->findId("nonviscDamp", ix, false, /*create*/ false);
		dampingWork    = ix >= 0 ? scene->energy->energies.get(size_t(ix)) : Real(0);
		pendingDamping = 0;
		return;
	}
	if (newton.kinSplit) {
		int transIx = -1, rotIx = -1;
		scene->energy->set(kinTrans, "kinTrans", transIx);
		scene->energy->set(kinRot, "kinRot", rotIx);
	} else
		scene->energy->set(kinTrans + kinRot, "kinetic", kineticIx);
	if (!damped) return;
	rdem::SplitWork<Real> work { pendingDamping };
	dampingWork += work.step(withBefore, withAfter);
	pendingDamping = work.pending;
	scene->energy->set(dampingWork, "nonviscDamp", dampIx);
}

} // namespace yade
