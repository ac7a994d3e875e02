/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/RdemDensityScaling.hpp>
#include <pkg/rdem/RdemRanks.hpp>
#include <pkg/rdem/math/DensityScaling.hpp>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((RdemDensityScaling));
CREATE_LOGGER(RdemDensityScaling);

NewtonIntegrator* RdemDensityScaling::checkedIntegrator()
{
	if (checked && checkedEngines.same(scene->engines)) return checked;
	NewtonIntegrator* newton = integrator ? integrator.get() : rdem::findEngine<NewtonIntegrator>(scene);
	const long        self = rdem::positionOf(scene, this), other = rdem::positionOf(scene, newton);
	if (other != self + 1)
		throw std::runtime_error(
		        std::string("RdemDensityScaling (O.engines[") + std::to_string(self) + "]) scales the forces that its NewtonIntegrator applies, but "
		        + (!newton             ? "O.engines has no NewtonIntegrator"
		                   : other < 0 ? "its integrator is not in O.engines"
		                               : "the NewtonIntegrator is O.engines[" + std::to_string(other) + "], not the next engine")
		        + ": place RdemDensityScaling right before the NewtonIntegrator, after every engine that adds forces (rdem.walltest.scaleDensity "
		          "does)");
	if (newton->densityScaling)
		throw std::runtime_error(
		        "RdemDensityScaling: NewtonIntegrator.densityScaling is on, which would scale the accelerations a second time: turn it off");
	checkedEngines.take(scene->engines);
	checked = newton;
	return newton;
}

void RdemDensityScaling::action()
{
	const NewtonIntegrator& newton = *checkedIntegrator();
	bool                    synced = false;
	for (const auto& b : *scene->bodies) {
		if (!b || b->isClumpMember() || rdem::notOwned(*scene, *b)) continue;
		const State& s = *b->state;
		if (!(s.densityScaling > 0) || s.densityScaling == 1 || s.blockedDOFs == State::DOF_ALL) continue;
		if (!synced) {
			if (!newton.dampGravity && newton.damping != 0)
				throw std::runtime_error(
				        "RdemDensityScaling: NewtonIntegrator.dampGravity is False with damping " + std::to_string(newton.damping)
				        + ": the damping of a scaled body would then act on a part of its weight; set dampGravity = True (the default)");
			scene->forces.sync(); // the sums of every engine's forces; added to directly below, so it stays synced
			synced = true;
		}
		const Body::id_t id = b->getId();
		const Vector3r   F = scene->forces.getForce(id), T = scene->forces.getTorque(id);
		scene->forces.addForceUnsynced(id, rdem::densityScalingForce<Real>(s.densityScaling, F, s.mass, newton.gravity));
		scene->forces.addTorqueUnsynced(id, (s.densityScaling - 1) * T);
	}
}

} // namespace yade
