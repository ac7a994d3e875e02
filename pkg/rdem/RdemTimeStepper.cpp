/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemTimeStepper.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemPoissonEngine.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((RdemTimeStepper));
CREATE_LOGGER(RdemTimeStepper);

namespace {
	/// Adds, for one point spring, the Gershgorin terms 2(k_t/m + k_r/I_min) of one body [1/s²].
	void addPoint(vector<Real>& omega2, const State& s, Body::id_t id, const Vector3r& point, const Vector3r& n, Real area, const RdemPhys& p)
	{
		if (s.blockedDOFs == State::DOF_ALL) return;
		const Vector3r r  = point - s.pos;
		const Real     kn = p.weightNormal * p.kn, ks = p.weightShear * p.ks;
		const Real     kt = math::max(kn, ks) * area;
		const Real     kr = area * (kn * r.cross(n).squaredNorm() + ks * (r.squaredNorm() + math::pow(r.dot(n), 2)));
		omega2[size_t(id)] += 2 * (kt / s.mass + kr / s.inertia.minCoeff());
	}
}

Real RdemTimeStepper::estimate(Scene* sc) const
{
	vector<Real> omega2(sc->bodies->size(), 0);
	for (const auto& I : *sc->interactions) {
		if (!I->isReal()) continue;
		const auto* g = dynamic_cast<RdemGeom*>(I->geom.get());
		const auto* p = dynamic_cast<RdemPhys*>(I->phys.get());
		if (!g || !p) continue;
		const State& s1 = *Body::byId(I->getId1(), sc)->state;
		const State& s2 = *Body::byId(I->getId2(), sc)->state;
		for (size_t i = 0; i < g->nSegments(); ++i) {
			const Vector3r point = s1.pos + s1.ori * g->segPoint1[i];
			addPoint(omega2, s1, I->getId1(), point, g->normal.squaredNorm() > 0 ? g->normal : Vector3r(s1.ori * g->segNormal1), g->segArea[i], *p);
			addPoint(omega2, s2, I->getId2(), point, g->normal.squaredNorm() > 0 ? g->normal : Vector3r(s1.ori * g->segNormal1), g->segArea[i], *p);
		}
		for (size_t k = 0; k < g->sampleKey.size(); ++k) {
			addPoint(omega2, s1, I->getId1(), g->samplePoint[k], g->sampleNormal[k], g->sampleArea[k], *p);
			addPoint(omega2, s2, I->getId2(), g->samplePoint[k], g->sampleNormal[k], g->sampleArea[k], *p);
		}
	}
	for (const auto& e : sc->engines) {
		const auto* poisson = dynamic_cast<RdemPoissonEngine*>(e.get());
		if (!poisson || poisson->dead) continue;
		const vector<Real> P = poisson->stiffnessBound();
		for (size_t id = 0; id < P.size(); ++id) {
			const auto& b = Body::byId(Body::id_t(id), sc);
			if (b && P[id] > 0 && b->state->blockedDOFs != State::DOF_ALL) omega2[id] += P[id] / b->state->mass;
		}
	}
	const Real w2 = *std::max_element(omega2.begin(), omega2.end());
	return w2 > 0 ? 2 / math::sqrt(w2) : std::numeric_limits<Real>::infinity();
}

Real RdemTimeStepper::estimatePy() const { return estimate(Omega::instance().getScene().get()); }

void RdemTimeStepper::postLoad(RdemTimeStepper&)
{
	if (!(safety > 0 && safety <= 1)) throw std::invalid_argument("RdemTimeStepper.safety = " + std::to_string(safety) + ": must be in (0, 1]");
}

bool RdemTimeStepper::isActivated()
{
	if (timeStepUpdateInterval < 1) throw std::invalid_argument("RdemTimeStepper.timeStepUpdateInterval = 0: must be an integer >= 1 [steps]");
	return scene->iter % timeStepUpdateInterval == 0 || !(scene->dt > 0 && std::isfinite(scene->dt));
}

void RdemTimeStepper::computeTimeStep(Scene* sc)
{
	if (!active && !(sc->dt > 0 && std::isfinite(sc->dt)))
		throw std::invalid_argument(
		        "O.dt = " + std::to_string(sc->dt) + ": the time step must be finite and > 0 [s] (or O.dt = -1 to let RdemTimeStepper choose it)");
	criticalDt = estimate(sc);
	if (!std::isfinite(criticalDt)) return;
	if (active) sc->dt = safety * criticalDt;
	else if (sc->dt > criticalDt && !warned) {
		LOG_WARN("O.dt = " << sc->dt << " s exceeds the estimated critical time step " << criticalDt
		                   << " s of this block assembly; the explicit integration may be unstable. Use O.dt = -1 to let RdemTimeStepper choose.");
		warned = true;
	}
}

} // namespace yade
