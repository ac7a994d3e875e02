/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/Ig2_RdemBlock_RdemBlock_RdemGeom.hpp>
#include <pkg/rdem/InertialMass.hpp>
#include <pkg/rdem/InteractionOrder.hpp>
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <pkg/rdem/NumberText.hpp>
#include <pkg/rdem/RdemBlock.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemMat.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemRanks.hpp>
#include <pkg/rdem/RdemTimeStepper.hpp>
#include <pkg/rdem/math/ContactBound.hpp>
#include <pkg/rdem/math/DensityScaling.hpp>
#include <pkg/rdem/math/Elasticity.hpp>
#include <pkg/rdem/math/StepperUpdate.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((RdemTimeStepper));
CREATE_LOGGER(RdemTimeStepper);

namespace {
	/// Per body id, whether the body carries a bond (an interaction with segments).
	vector<char> bondedBodies(Scene* sc)
	{
		vector<char> bonded(sc->bodies->size(), 0);
		for (const auto& I : *sc->interactions) {
			const auto* g = I->isReal() ? dynamic_cast<const RdemGeom*>(I->geom.get()) : nullptr;
			if (g && g->nSegments() > 0) bonded[size_t(I->getId1())] = bonded[size_t(I->getId2())] = 1;
		}
		return bonded;
	}

	/// How contacts are made: the scene's formulation (Ip2_RdemMat_RdemMat_RdemPhys::formulationOf) and the sample grid of
	/// the Ig2 of the InteractionLoop (the default grid if there is none).
	struct ContactSetup {
		rdem::SpringModulus modulus        = rdem::SpringModulus::Paper;
		int                 samplesPerEdge = 2;
	};

	ContactSetup contactSetup(Scene* sc)
	{
		ContactSetup c;
		c.modulus = Ip2_RdemMat_RdemMat_RdemPhys::formulationOf(sc);
		rdem::forEachLoopFunctor<Ig2_RdemBlock_RdemBlock_RdemGeom>(
		        sc, [&](const Ig2_RdemBlock_RdemBlock_RdemGeom& ig2) { c.samplesPerEdge = ig2.contactSamples(); });
		return c;
	}

	/// Springs per area [N/m³] of a contact that a block without bonds can still make: its own stiffness per area for
	/// its smallest half-extent ℓ (eq. 11; a contact spring, in series with the other block's (eq. 12), is softer).
	/// Their dashpots are left out: a contact that has not started has no velocity history to damp, and the caps of the
	/// law (Law2…::dashpotCap) would make any bound on them the caps' sum over six faces, six times m/Δt, which no step
	/// satisfies; the contact's own dashpots enter the estimate once it exists (contact samples).
	std::pair<Real, Real> contactToCome(const RdemBlock& shape, const RdemMat& mat, const ContactSetup& setup)
	{
		const Real ell = shape.extents.minCoeff();
		return { rdem::normalStiffnessPerArea(mat.young, mat.poisson, ell, setup.modulus), rdem::shearStiffnessPerArea(mat.young, mat.poisson, ell) };
	}

	/* Adds to every free block that carries no bond the Gershgorin terms of a flush contact on each of its six faces
	   (rdem::faceContactOmega2), at the block's own stiffness per area for its smallest half-extent ℓ (eq. 11; a contact
	   spring, in series with the other block's (eq. 12), is softer): the contacts the collider has not made yet, which the
	   step must allow for between two updates; a loose block may have none yet (then the step would be unbounded). A
	   bonded block already carries the terms of its bonds, of the same order as those of contacts on its free faces
	   (the estimate bounds ω² by about twice its largest eigenvalue), and a bonded specimen keeps its step. */
	void addContactBound(vector<Real>& omega2, const vector<char>& bonded, Scene* sc)
	{
		const ContactSetup setup = contactSetup(sc);
		for (const auto& b : *sc->bodies) {
			if (!b || b->state->blockedDOFs == State::DOF_ALL || bonded[size_t(b->id)] || rdem::isGhost(*sc, *b)) continue;
			const auto* shape = dynamic_cast<RdemBlock*>(b->shape.get());
			const auto* mat   = dynamic_cast<RdemMat*>(b->material.get());
			if (!shape || !mat) continue;
			const auto k = contactToCome(*shape, *mat, setup);
			for (int face = 0; face < 6; ++face)
				omega2[size_t(b->id)] += rdem::faceContactOmega2<Real>(
				        shape->extents,
				        face / 2,
				        setup.samplesPerEdge,
				        k.first,
				        k.second,
				        rdem::inertialMass(*b->state),
				        rdem::inertialMinInertia(*b->state));
		}
	}
}

Real RdemTimeStepper::gershgorin(Scene* sc)
{
	vector<Real> omega2(sc->bodies->size(), 0); // row sums of the mass-normalised stiffness per body [1/s²]
	for (RdemStiffnessSource* source : RdemSharedState::of(sc, shared).stiffnessSources)
		source->addOmega2Bound(sc, omega2); // the law's springs, the Poisson engine's elements and cells
	if (contactBound) addContactBound(omega2, bondedBodies(sc), sc);
	for (const auto& b : *sc->bodies)
		if (b && rdem::isGhost(*sc, *b)) omega2[size_t(b->id)] = 0; // moved by its owner (see assemble)
	const Real w2 = *std::max_element(omega2.begin(), omega2.end());
	return w2 > 0 ? 2 / math::sqrt(w2) : std::numeric_limits<Real>::infinity();
}

namespace {
	/* The contacts a free block without bonds can still make (contactBound, doc/sphinx/rdemTheory.rst §6): springs to fixed points at
	   the trapezoid sample grid of each of its six faces, at its own stiffness per area for its smallest half-extent
	   (eq. 11). A flush contact with an equal block (springs in series, half as stiff, on half the mass in relative
	   motion) has the same frequency; with a fixed block, this bound. */
	void addContactsToCome(rdem::BlockStiffness<Real>& K, const Body& b, const ContactSetup& setup)
	{
		const auto* shape = dynamic_cast<const RdemBlock*>(b.shape.get());
		const auto* mat   = dynamic_cast<const RdemMat*>(b.material.get());
		if (!shape || !mat) return;
		const auto      k = contactToCome(*shape, *mat, setup);
		const Matrix3r  R = b.state->ori.toRotationMatrix();
		const Vector3r& h = shape->extents;
		for (int face = 0; face < 6; ++face) {
			const int      axis = face / 2, k1 = (axis + 1) % 3, k2 = (axis + 2) % 3;
			const Vector3r n = (face % 2 ? 1 : -1) * Vector3r::Unit(axis);
			for (const auto& p :
			     rdem::faceSamplePoints<Real>(h[axis] * n, Vector3r::Unit(k1), Vector3r::Unit(k2), h[k1], h[k2], setup.samplesPerEdge))
				K.addPointSpring(b.id, -1, R * p.pos, Vector3r::Zero(), R * n, k.first * p.weight, k.second * p.weight);
		}
	}
}

void RdemTimeStepper::assemble(
        Scene*                            sc,
        const vector<const Interaction*>& inIdOrder,
        rdem::BlockStiffness<Real>&       K,
        rdem::BlockStiffness<Real>&       C,
        vector<rdem::BodyScale<Real>>&    scale)
{
	for (RdemStiffnessSource* source : RdemSharedState::of(sc, shared).stiffnessSources)
		source->addStiffness(sc, inIdOrder, K, C, capDt); // the law's springs and dashpots, the Poisson engine's elements and cells
	bodyScales(sc, scale);
	if (!contactBound) return;
	const vector<char> bonded = bondedBodies(sc);
	const ContactSetup setup  = contactSetup(sc);
	for (const auto& b : *sc->bodies)
		if (b && !rdem::isGhost(*sc, *b) && b->state->blockedDOFs != State::DOF_ALL && !bonded[size_t(b->id)]) addContactsToCome(K, *b, setup);
}

void RdemTimeStepper::bodyScales(Scene* sc, vector<rdem::BodyScale<Real>>& scale)
{
	scale.assign(sc->bodies->size(), rdem::BodyScale<Real>());
	for (const auto& b : *sc->bodies) {
		if (!b) continue;
		// On a rank of a distributed run (yade.mpy), a ghost's motion is its owner's: its DOFs are fixed here, so that
		// the estimate is that of the rank's own blocks, with all their springs (rdem::isGhost, computeTimeStep).
		const State&   s       = *b->state;
		const unsigned blocked = rdem::isGhost(*sc, *b) ? unsigned(State::DOF_ALL) : unsigned(s.blockedDOFs);
		const Real     f       = rdem::inertialFactor(s.densityScaling); // the inertial mass and inertia (density scaling)
		scale[size_t(b->id)]   = rdem::bodyScale<Real>(s.mass * f, Vector3r(s.inertia * f), s.ori.toRotationMatrix(), blocked);
	}
}

Real RdemTimeStepper::lanczos(Scene* sc, const vector<const Interaction*>& inIdOrder, bool keepStiffest)
{
	const size_t                  nB = sc->bodies->size();
	rdem::BlockStiffness<Real>    K(nB), C(nB);
	vector<rdem::BodyScale<Real>> scale;
	/* After a break (keepStiffest), K is the same: a broken segment keeps its spring as a contact spring of the same k̄A
	   (forPointSprings), and the Poisson cells' terms only scale down with the intact fraction (releaseOnCrack); its
	   dashpot is new. So λ_K and its Ritz vector are kept (springCriticalDt, saved), and the dashpots' part is redone:
	   C alone first (RdemStiffnessSource::addDashpots, the interactions that can have a dashpot), K only if the damped
	   limit's lower bound from λ_K and λ_C is below what the step can use (then the Lanczos runs on Δt²K̃ + 2ΔtC̃ need
	   it). The same numbers as assembling both, to the bit: C's terms come in the same order. */
	const bool keep = keepStiffest && ritzVector.size() == 6 * nB && springCriticalDt > 0 && math::isfinite(springCriticalDt);
	if (keep) {
		for (RdemStiffnessSource* source : RdemSharedState::of(sc, shared).stiffnessSources)
			source->addDashpots(sc, inIdOrder, C, capDt);
		bodyScales(sc, scale);
	} else
		assemble(sc, inIdOrder, K, C, scale);
	rdem::NormalisedOperators<Real> ops(scale);
	const size_t                    n          = ops.size();
	const vector<char>              mask       = ops.mask();
	const auto                      normalised = [&](const rdem::BlockStiffness<Real>& X) { // y = P S X S P x
                return [&](const Real* x, Real* y) { ops.apply(X, x, y); };
	};
	const auto largest = [&](const rdem::BlockStiffness<Real>& X, vector<Real>& start) { // λ_max of P S X S P
		// warm start mixed with 10 % of a generic vector: a new stiff spot (a contact) far from the old mode is still found
		return rdem::lanczosLargest<Real>(normalised(X), n, mask, start, 2, lanczosMaxSteps, lanczosTolerance, Real(0.1));
	};
	const Real lambdaK = keep ? Real(4) / (springCriticalDt * springCriticalDt) : Real(0);
	const auto est     = keep ? rdem::LargestEigenvalue<Real> { lambdaK, 0, 0 } : largest(K, ritzVector);
	if (!keep) {
		lanczosSteps     = est.steps;
		lanczosResidual  = est.ritz > 0 ? est.residual / est.ritz : Real(0);
		springCriticalDt = est.upper() > 0 ? 2 / math::sqrt(est.upper()) : std::numeric_limits<Real>::infinity();
	}
	dashpotRate = C.empty() ? Real(0) : largest(C, dashpotRitzVector).upper();
	/* The root of λ_max(Δt²K̃ + 2ΔtC̃) = 4 itself, not its bound from λ_K and λ_C (exact only where the stiffest mode is the
	   most damped), from the sum of the two Ritz vectors (the mode of the limit mixes the two; nothing more is saved). */
	vector<Real> start(n, 0);
	if (dashpotRate > 0)
		for (size_t i = 0; i < n; ++i)
			start[i] = ritzVector[i] + dashpotRitzVector[i];
	// an automatic step under contactLimit is at most contactDt: a root above it need not be found closer
	const Real enough = active && contactLimit ? rdem::criticallyDampedStep(springCriticalDt) : std::numeric_limits<Real>::infinity();
	if (keep && !(rdem::dampedCriticalStep(est.upper(), dashpotRate) >= enough)) { // the Lanczos runs below need K
		rdem::BlockStiffness<Real>    again(nB); // C and the scales once more, as assemble makes them with K (already made)
		vector<rdem::BodyScale<Real>> same;
		assemble(sc, inIdOrder, K, again, same);
	}
	const auto both   = [&](const Real* x, Real* kx, Real* cx) { ops.applyBoth(K, C, x, kx, cx); };
	const auto damped = rdem::dampedCriticalStepOfBoth<Real>(
	        both, normalised(K), n, mask, start, est.upper(), dashpotRate, lanczosMaxSteps, lanczosTolerance, 8, enough);
	dampedRounds     = damped.rounds;
	dampedRitzVector = damped.rounds > 0 ? start : vector<Real>();
	return damped.step;
}

vector<Real> RdemTimeStepper::springSignature(Scene* sc, const vector<const Interaction*>& inIdOrder)
{
	// what K depends on besides the poses: which springs exist and how stiff they are, which DOFs are free
	Real nReal = 0, nSegments = 0, nSamples = 0, stiffness = 0, blocked = 0, mass = 0;
	for (const Interaction* I : inIdOrder) {
		const auto* g = static_cast<const RdemGeom*>(I->geom.get());
		const auto* p = static_cast<const RdemPhys*>(I->phys.get());
		nReal += 1;
		nSegments += Real(g->nSegments());
		nSamples += Real(g->sampleKey.size() + g->nPatch());
		stiffness += p->weightNormal * p->kn + p->weightShear * p->ks;
	}
	for (const auto& b : *sc->bodies)
		if (b) {
			blocked += b->state->blockedDOFs;
			mass += rdem::inertialMass(*b->state);
		}
	return { Real(sc->bodies->size()), nReal, nSegments, nSamples, stiffness, blocked, mass, Real(brokenSprings(sc)) };
}

bool RdemTimeStepper::contactsPossible(Scene* sc)
{
	if (brokenSprings(sc) > 0) return true;
	vector<char> bonded(sc->bodies->size(), 0);
	for (const auto& I : *sc->interactions) {
		if (!I->isReal()) continue;
		const auto* g = dynamic_cast<RdemGeom*>(I->geom.get());
		if (!g) continue;
		if (!g->sampleKey.empty() || g->nPatch() > 0) return true;
		if (g->nSegments() > 0) bonded[size_t(I->getId1())] = bonded[size_t(I->getId2())] = 1;
	}
	if (!contactBound) return false;
	for (const auto& b : *sc->bodies)
		if (b && b->state->blockedDOFs != State::DOF_ALL && !bonded[size_t(b->id)] && !rdem::isGhost(*sc, *b)) return true;
	return false;
}

Real RdemTimeStepper::estimate(Scene* sc, const vector<const Interaction*>& inIdOrder)
{
	springCriticalDt = std::numeric_limits<Real>::infinity(); // set by the Lanczos estimate; the Gershgorin bound is one value
	capDt            = capStep(sc);
	if (method != "gershgorin") return lanczos(sc, inIdOrder);
	springCriticalDt = gershgorin(sc);
	return springCriticalDt;
}

Real RdemTimeStepper::estimateDashpots(Scene* sc, const vector<const Interaction*>& inIdOrder)
{
	capDt = capStep(sc);
	return lanczos(sc, inIdOrder, true);
}

Real RdemTimeStepper::estimatePy(const string& how)
{
	Scene* sc = Omega::instance().getScene().get();
	if (how.empty()) return estimate(sc, rdem::interactionsInIdOrder(sc));
	if (how == "dashpots") return estimateDashpots(sc, rdem::interactionsInIdOrder(sc)); // what an update for a break alone computes
	if (how != "lanczos" && how != "gershgorin") throw std::invalid_argument("method = '" + how + "': must be 'lanczos', 'gershgorin' or 'dashpots'");
	const string saved = method;
	method             = how;
	const Real dt      = estimate(sc, rdem::interactionsInIdOrder(sc));
	method             = saved;
	return dt;
}

boost::python::list RdemTimeStepper::blockRows()
{
	Scene*       sc = Omega::instance().getScene().get();
	const size_t nB = sc->bodies->size();
	vector<Real> omega2(nB, 0); // the Gershgorin rows of gershgorin(), with the inertial masses
	for (RdemStiffnessSource* source : RdemSharedState::of(sc, shared).stiffnessSources)
		source->addOmega2Bound(sc, omega2);
	if (contactBound) addContactBound(omega2, bondedBodies(sc), sc);
	rdem::BlockStiffness<Real>    K(nB), C(nB);
	vector<rdem::BodyScale<Real>> scale;
	const Real                    saved = capDt;
	capDt                               = 0; // the dashpots of eq. 13 without the caps, which fall with a larger step
	assemble(sc, rdem::interactionsInIdOrder(sc), K, C, scale);
	capDt = saved;
	boost::python::list rows;
	for (size_t b = 0; b < nB; ++b) {
		const auto* body = Body::byId(Body::id_t(b), sc).get();
		Real        c    = 0;
		if (body && !rdem::isGhost(*sc, *body) && !C.empty()) c = 2 * rdem::largestBlockEigenvalue<Real>(C.diagonalBlock(b), scale[b]);
		const bool fixed = !body || rdem::isGhost(*sc, *body) || body->state->blockedDOFs == State::DOF_ALL;
		rows.append(boost::python::make_tuple(fixed ? Real(0) : omega2[b], fixed ? Real(0) : c));
	}
	return rows;
}

vector<Real> RdemTimeStepper::stiffnessTimes(const vector<Real>& x)
{
	Scene*                        sc = Omega::instance().getScene().get();
	const size_t                  nB = sc->bodies->size();
	rdem::BlockStiffness<Real>    K(nB), C(nB);
	vector<rdem::BodyScale<Real>> scale;
	if (x.size() != 6 * nB)
		throw std::invalid_argument(
		        "RdemTimeStepper.stiffnessTimes: x has " + std::to_string(x.size()) + " values: must have 6 per body (" + std::to_string(6 * nB) + ")");
	capDt = capStep(sc);
	assemble(sc, rdem::interactionsInIdOrder(sc), K, C, scale);
	vector<Real> y(x.size());
	K.multiply(x.data(), y.data());
	return y;
}

void RdemTimeStepper::postLoad(RdemTimeStepper&)
{
	if (!(safety > 0 && safety <= 1)) throw std::invalid_argument("RdemTimeStepper.safety = " + rdem::numberText(safety) + ": must be in (0, 1]");
	if (method != "lanczos" && method != "gershgorin")
		throw std::invalid_argument("RdemTimeStepper.method = '" + method + "': must be 'lanczos' or 'gershgorin'");
	if (!(lanczosTolerance > 0 && lanczosTolerance <= 0.1))
		throw std::invalid_argument("RdemTimeStepper.lanczosTolerance = " + rdem::numberText(lanczosTolerance) + ": must be in (0, 0.1]");
	if (lanczosMaxSteps < 2) throw std::invalid_argument("RdemTimeStepper.lanczosMaxSteps = " + std::to_string(lanczosMaxSteps) + ": must be >= 2");
}

bool RdemTimeStepper::isActivated()
{
	if (timeStepUpdateInterval < 1) throw std::invalid_argument("RdemTimeStepper.timeStepUpdateInterval = 0: must be an integer >= 1 [steps]");
	/* also at once when a spring breaks: its contact dashpot acts from the next step, and may need a shorter step now;
	   not while the step is held by contactLimit (contactLimited): that step allows for a critical dashpot on the
	   stiffest mode, which is what a break brings, as a contact that forms between two updates does */
	const bool due = scene->iter % timeStepUpdateInterval == 0 || !(scene->dt > 0 && math::isfinite(scene->dt)) || (!active && scene->dt != checkedDt)
	        || (brokenSprings(scene) != brokenAtEstimate && !contactLimited);
	return rdem::anyOverRanks(*scene, due); // distributed: all ranks together (computeTimeStep reduces over them)
}

void RdemTimeStepper::checkFixedDt(Scene* sc, Real criticalDtAll, Real springCriticalDtAll)
{
	const bool firstSeen = sc->dt != checkedDt;
	checkedDt            = sc->dt;
	if (!(sc->dt > criticalDtAll)) return;
	// above the springs' limit the run blows up; between it and the lower limit with the contact dashpots it may, but the
	// dashpots' compression-only clamp and caps (Law2…::dashpotCap) often hold it: a warning
	const bool         springs = sc->dt > springCriticalDtAll;
	std::ostringstream msg;
	msg << "O.dt = " << sc->dt << " s exceeds the critical time step " << (springs ? springCriticalDtAll : criticalDtAll) << " s ("
	    << (springs ? "2/omega_max of the springs" : "with the contact dashpots") << ", " << method
	    << " estimate of RdemTimeStepper) of this block assembly: the explicit integration is unstable ";
	if (springs && firstSeen && method == "lanczos" && refuseUnstableDt) {
		msg << "and would blow up. Set O.dt <= " << springCriticalDtAll
		    << " s, or O.dt = -1 to let RdemTimeStepper choose (RdemTimeStepper.refuseUnstableDt = False to run anyway).";
		throw std::invalid_argument(msg.str());
	}
	if (warned) return;
	msg << (springs ? "or may become so." : "where the dashpots act, unless their clamp and caps hold it; watch the energy.")
	    << " Use O.dt = -1 to let RdemTimeStepper choose.";
	LOG_WARN(msg.str());
	warned = true;
}

void RdemTimeStepper::computeTimeStep(Scene* sc)
{
	if (!active && !(sc->dt > 0 && math::isfinite(sc->dt)))
		throw std::invalid_argument(
		        "O.dt = " + rdem::numberText(sc->dt) + ": the time step must be finite and > 0 [s] (or O.dt = -1 to let RdemTimeStepper choose it)");
	// the interactions in id order, sorted once for the signature and the assembly (the same interactions in both)
	const vector<const Interaction*> inIdOrder = method == "lanczos" ? rdem::interactionsInIdOrder(sc) : vector<const Interaction*>();
	const vector<Real>               signature = method == "lanczos" && reuseUnchanged ? springSignature(sc, inIdOrder) : vector<Real>();
	const bool                       young     = reused < 99 && criticalDt > 0; // a fresh estimate at least every 100 updates
	// an update for a break alone (not one of the regular ones): what the break changes, the dashpots; K's changes since
	// the last estimate (poses, contacts) are taken at the next regular update, as without the break
	const bool                  breakOnly = sc->iter % timeStepUpdateInterval != 0 && brokenSprings(sc) != brokenAtEstimate;
	const rdem::StepperDecision decision  = rdem::stepperDecision(young, signature, lastSignature, breakOnly);
	if (decision.what == rdem::StepperUpdate::Fresh) {
		criticalDt = estimate(sc, inIdOrder);
		reused     = 0;
	} else {
		if (decision.what == rdem::StepperUpdate::Dashpots) criticalDt = estimateDashpots(sc, inIdOrder);
		++reused;
	}
	if (decision.recordSignature) lastSignature = signature;
	brokenAtEstimate = brokenSprings(sc);
	const Real inf   = std::numeric_limits<Real>::infinity();
	const bool step  = active && math::isfinite(criticalDt); // this rank sets a step (not computed for a fixed O.dt)
	if (step) contactDt = method == "lanczos" && contactLimit && contactsPossible(sc) ? rdem::criticallyDampedStep(springCriticalDt) : inf;
	/* One step for all ranks of a distributed run (yade.mpy): each rank's limits are those of its own blocks (their ghosts'
	   DOFs fixed, assemble), and the scene's are their minima (rdem::minOverRanks: an MPI_Allreduce, which every rank
	   reaches, as isActivated is the same on all). A rank's mass-normalised stiffness is then a principal submatrix of the
	   whole scene's, so by Cauchy's interlacing these minima are not below the whole scene's limits; they are above them
	   only by a mode that spans two subdomains. With one rank they are this scene's limits. */
	Real all[3] = { criticalDt, springCriticalDt, step ? contactDt : inf };
	rdem::minOverRanks(*sc, all, 3);
	if (!math::isfinite(all[0])) { // nothing elastic yet: nothing to check a fixed O.dt against
		checkedDt = sc->dt;
		return;
	}
	// the damped limit at or above contactDt, over all ranks: breaks wait for the next regular update (isActivated)
	contactLimited = active && math::isfinite(all[2]) && all[0] >= all[2];
	if (active) sc->dt = safety * math::min(all[0], all[2]);
	else
		checkFixedDt(sc, all[0], all[1]);
}

} // namespace yade
