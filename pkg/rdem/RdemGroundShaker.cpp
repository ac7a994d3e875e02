/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/dem/NewtonIntegrator.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/NumberText.hpp>
#include <pkg/rdem/RdemGroundShaker.hpp>
#include <algorithm>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RdemGroundShaker));
CREATE_LOGGER(RdemGroundShaker);

void RdemGroundShaker::postLoad(RdemGroundShaker&)
{
	if (mode != "prescribed" && mode != "inertial")
		throw std::invalid_argument("RdemGroundShaker.mode = '" + mode + "': must be 'prescribed' or 'inertial'");
	for (size_t k = 1; k < times.size(); ++k)
		if (!(times[k] > times[k - 1]))
			throw std::invalid_argument(
			        "RdemGroundShaker.times: must increase (times[" + std::to_string(k) + "] = " + rdem::numberText(times[k]) + " after "
			        + rdem::numberText(times[k - 1]) + ")");
	for (const auto* v : { &accelerations, &velocities, &displacements })
		if (!v->empty() && v->size() != times.size() && !times.empty())
			throw std::invalid_argument(
			        "RdemGroundShaker: accelerations, velocities and displacements must have as many entries as times ("
			        + std::to_string(times.size()) + ")");
}

Vector3r RdemGroundShaker::interpolate(const vector<Vector3r>& v, Real t, bool holdLast) const
{
	if (v.empty() || times.empty() || t <= times.front()) return Vector3r::Zero();
	if (t >= times.back()) return holdLast ? v.back() : Vector3r::Zero();
	const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()); // times[k-1] <= t < times[k]
	const Real   w = (t - times[k - 1]) / (times[k] - times[k - 1]);
	return scale * ((1 - w) * v[k - 1] + w * v[k]);
}

Vector3r RdemGroundShaker::accelerationAt(Real t) const { return interpolate(accelerations, t, false); }

Vector3r RdemGroundShaker::velocityAt(Real t) const { return interpolate(velocities, t, false); }

Vector3r RdemGroundShaker::displacementAt(Real t) const
{
	if (!displacements.empty() && !times.empty() && t >= times.back()) return scale * displacements.back();
	return interpolate(displacements, t, true);
}

void RdemGroundShaker::action()
{
	const Real t = scene->time, dt = scene->dt;
	if (mode == "inertial") {
		rdem::forEachEngine<NewtonIntegrator>(scene, [&](NewtonIntegrator& newton) { newton.gravity = gravity - accelerationAt(t); });
		return;
	}
	// Velocity over this step that puts the base on the ground displacement at its end (exact at every step).
	const Vector3r v    = (displacementAt(t + dt) - displacementAt(t)) / dt;
	Real           work = 0;                      // done on the base by the rest of the scene over this step [J]
	if (scene->trackEnergy) scene->forces.sync(); // NewtonIntegrator, next, syncs too: nothing more is added in between
	for (int id : ids) {
		const auto& b = Body::byId(Body::id_t(id), scene);
		if (!b) continue;
		if (scene->trackEnergy) // the base's kinetic energy, which NewtonIntegrator books, comes from the motion too
			work -= b->state->mass * (v.squaredNorm() - b->state->vel.squaredNorm()) / 2;
		b->state->vel = v;
		if (scene->trackEnergy) work += scene->forces.getForce(Body::id_t(id)).dot(v) * dt;
	}
	if (scene->trackEnergy) scene->energy->add(work, "groundWork", workIx, /*reset every step*/ false);
}

} // namespace yade
