/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/RdemFiniteGuard.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RdemFiniteGuard));
CREATE_LOGGER(RdemFiniteGuard);

void RdemFiniteGuard::action()
{
	scene->forces.sync();
	for (const auto& b : *scene->bodies) {
		if (!b) continue;
		const State& s = *b->state;
		/* One test per body: NaN and ±inf propagate through the sum (inf - inf is NaN); a finite sum can only overflow
		   for values near 1e308, which the detailed test below then lets pass. The force and torque are read only for
		   bodies with a blocked DOF: on a free body NewtonIntegrator, which runs before, has already carried a
		   non-finite force or torque into the velocities and the position of this step. */
		Real sum = s.pos.sum() + s.ori.coeffs().sum() + s.vel.sum() + s.angVel.sum();
		if (s.blockedDOFs != State::DOF_NONE) sum += scene->forces.getForce(b->id).sum() + scene->forces.getTorque(b->id).sum();
		if (math::isfinite(sum)) continue;
		const Vector3r&    f = scene->forces.getForce(b->id);
		const Vector3r&    t = scene->forces.getTorque(b->id);
		std::ostringstream what; // only for the offending body: a stream per body would cost more than the checks
		if (!s.pos.allFinite()) what << "position " << s.pos.transpose();
		else if (!s.ori.coeffs().allFinite())
			what << "orientation (quaternion x y z w) " << s.ori.coeffs().transpose();
		else if (!s.vel.allFinite())
			what << "velocity " << s.vel.transpose();
		else if (!s.angVel.allFinite())
			what << "angular velocity " << s.angVel.transpose();
		else if (!f.allFinite())
			what << "force " << f.transpose();
		else if (!t.allFinite())
			what << "torque " << t.transpose();
		else
			continue;
		std::ostringstream msg;
		msg << "RdemFiniteGuard: at iteration " << scene->iter << ", body " << b->id << " has a non-finite " << what.str();
		std::ostringstream bad;
		for (const auto& idI : b->intrs) {
			const auto& I = idI.second;
			const auto* p = I->isReal() ? dynamic_cast<const RdemPhys*>(I->phys.get()) : nullptr;
			if (p && !p->force.allFinite()) bad << " (" << I->getId1() << "," << I->getId2() << ")";
		}
		if (bad.str().empty()) msg << "; no interaction on it has a non-finite force (look at its own state, permanent forces and other engines)";
		else
			msg << "; interactions on it with a non-finite force:" << bad.str();
		LOG_ERROR(msg.str());
		throw std::runtime_error(msg.str());
	}
}

} // namespace yade
