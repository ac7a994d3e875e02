/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/Ig2_RdemBlock_RdemBlock_RdemGeom.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/OpenMPLoops.hpp>
#include <pkg/rdem/RdemBlock.hpp>
#include <pkg/rdem/RdemInteractionLoop.hpp>
#include <pkg/rdem/RdemPrefetch.hpp>
#include <pkg/rdem/math/SeparationBound.hpp>

namespace yade {

YADE_PLUGIN((RdemInteractionLoop));
CREATE_LOGGER(RdemInteractionLoop);

namespace {
	/// The first functor of type T in a dispatcher's list, nullptr if none.
	template <class T, class V> T* firstOfType(const V& functors)
	{
		for (const auto& f : functors)
			if (auto* t = dynamic_cast<T*>(f.get())) return t;
		return nullptr;
	}
}

bool RdemInteractionLoop::ownStepPossible() const
{
#ifdef YADE_MPI
	/* YADE's loop erases the pairs of two bodies of other subdomains; a body's subdomain can change in place (mpy's
	   migration) without the travel record restarting, so a sleeper could be such a pair: not proven equal, not used. */
	return false;
#else
	// A collider that leaves the removal of the pairs it did not see to this loop needs every pair visited.
	const long colliderRun = scene->interactions->iterColliderLastRun;
	return !loopOnSortedInteractions && !(colliderRun >= 0 && colliderRun == scene->iter);
#endif
}

Ig2_RdemBlock_RdemBlock_RdemGeom* RdemInteractionLoop::sleepFunctor(const RdemSharedState& sh) const
{
	// currentFor: the record of this step (RdemContactGate ran before this loop) of a scene that is not periodic.
	if (!sleepApart || !ownStepPossible() || !sh.travel.currentFor(*scene)) return nullptr;
	auto* ig2 = firstOfType<Ig2_RdemBlock_RdemBlock_RdemGeom>(geomDispatcher->functors);
	return ig2 && ig2->shared.get() == &sh ? ig2 : nullptr;
}

std::pair<Ig2_RdemBlock_RdemBlock_RdemGeom*, Law2_RdemGeom_RdemPhys_FaceSprings*> RdemInteractionLoop::laneFunctors() const
{
	if (!bondLane || !callbacks.empty() || scene->isPeriodic || !ownStepPossible()) return { nullptr, nullptr };
	auto* ig2 = firstOfType<Ig2_RdemBlock_RdemBlock_RdemGeom>(geomDispatcher->functors);
	auto* law = firstOfType<Law2_RdemGeom_RdemPhys_FaceSprings>(lawDispatcher->functors);
	if (!ig2 || !law) return { nullptr, nullptr };
	return { ig2, law };
}

void RdemInteractionLoop::rotations()
{
	const long n = long(scene->bodies->size());
	rot.resize(size_t(n));
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(ompThreads))
#endif
	for (long i = 0; i < n; ++i)
		if (const auto& b = (*scene->bodies)[Body::id_t(i)]) rot[size_t(i)] = b->state->ori.toRotationMatrix();
}

bool RdemInteractionLoop::inLane(const Interaction& I, const Law2_RdemGeom_RdemPhys_FaceSprings& law) const
{
	// the law cached by the dispatch takes only RdemGeom and RdemPhys; real: the functors made both
	if (I.functorCache.constLaw.get() != &law || !I.isReal() || !static_cast<const RdemGeom&>(*I.geom).bonded) return false;
	const auto& bodies = *scene->bodies;
	const auto &b1 = bodies[I.getId1()], &b2 = bodies[I.getId2()];
	return b1 && b2 && !b1->isClump() && !b2->isClump();
}

void RdemInteractionLoop::bondInLane(const shared_ptr<Interaction>& I, const Ig2_RdemBlock_RdemBlock_RdemGeom& ig2, Law2_RdemGeom_RdemPhys_FaceSprings& law)
{
	// Ig2_RdemBlock_RdemBlock_RdemGeom::go of a bond: the prefetch, then this step's face normal and segment kinematics
	if (const int distance = rdem::prefetchDistanceFor(ig2.prefetchDistance, scene->interactions->size()))
		rdem::prefetchInteractionsAhead(*scene, *I, distance);
	const Body::id_t id1 = I->getId1(), id2 = I->getId2();
	const State &    s1 = *(*scene->bodies)[id1]->state, &s2 = *(*scene->bodies)[id2]->state;
	static_cast<RdemGeom&>(*I->geom).updateBond(rot[size_t(id1)], rot[size_t(id2)], s2.pos + Vector3r::Zero() - s1.pos);
	// the physics functor leaves a real interaction as it is; the law, as the dispatch calls it
	if (!law.Law2_RdemGeom_RdemPhys_FaceSprings::go(I->geom, I->phys, I.get())) scene->interactions->requestErase(I);
}

bool RdemInteractionLoop::worthSleeping(const Ig2_RdemBlock_RdemBlock_RdemGeom& ig2)
{
	const Real skipped = ig2.skippedTests.get(), witnessed = ig2.witnessTests.get();
	const bool worth = fellAsleepLastStep || skipped != skippedSeen || witnessed != witnessSeen;
	skippedSeen      = skipped;
	witnessSeen      = witnessed;
	return worth;
}

void RdemInteractionLoop::wakeAll()
{
	sleepers.clear();
	keep.clear();
	sleepEpoch = -1;
}

void RdemInteractionLoop::prepareSleepers(const rdem::BodyTravel& travel)
{
	const long nBodies = long(scene->bodies->size());
	if (travel.epoch != sleepEpoch || nBodies != sleepBodies) {
		wakeAll();
		sleepEpoch  = travel.epoch;
		sleepBodies = nBodies;
	}
	// Positions beyond the container's end are dropped (and their interactions released); new ones have no sleeper.
	const size_t n = size_t(scene->interactions->size());
	sleepers.resize(n);
	keep.resize(n);
}

bool RdemInteractionLoop::fallAsleep(long k, const shared_ptr<Interaction>& I, const Ig2_RdemBlock_RdemBlock_RdemGeom& ig2)
{
	if (!I->geom || I->geom->getClassIndex() != RdemGap::getClassIndexStatic()) return false;
	const auto& gap = static_cast<const RdemGap&>(*I->geom);
	Sleeper     s { I.get(), I->getId1(), I->getId2(), gap.reach, -1, Vector3r::Zero(), Vector3r::Zero() };
	if (gap.epoch != sleepEpoch) { // no certificate, or one of another record: its witness axis, if it has one
		if (!ig2.skipApart || gap.witness < 0) return false;
		s.witness = gap.witness;
		s.hA      = static_cast<const RdemBlock&>(*Body::byId(s.id1, scene)->shape).extents; // the functor's order (visit)
		s.hB      = static_cast<const RdemBlock&>(*Body::byId(s.id2, scene)->shape).extents;
	}
	sleepers[size_t(k)] = s;
	keep[size_t(k)]     = I;
	return true;
}

bool RdemInteractionLoop::stillApart(const Sleeper& s, const rdem::BodyTravel& travel, bool witness)
{
	if (s.witness < 0) return travel.withinReach(s.reach, s.id1, s.id2); // the certificate's test (BodyTravel::certifies)
	if (!witness) return false;                                          // the functor makes no witness test (skipApart off)
	const size_t a = size_t(s.id1), b = size_t(s.id2);
	const auto   v = rdem::witnessVerdict<Real>(travel.pos[a], travel.ori[a], s.hA, travel.pos[b], travel.ori[b], s.hB, s.witness);
	return v.apart && !rdem::certifiableSlack<Real>(v.slack, s.hA, s.hB);
}

vector<IntrCallback::FuncPtr> RdemInteractionLoop::prepareStep()
{
	lawDispatcher->scene  = scene;
	physDispatcher->scene = scene;
	geomDispatcher->scene = scene;
	geomDispatcher->updateScenePtr();
	physDispatcher->updateScenePtr();
	lawDispatcher->updateScenePtr();
	// callbacks return the function to call for each interaction of this step, or NULL: not called in this step
	vector<IntrCallback::FuncPtr> callbackPtrs;
	for (const auto& cb : callbacks) {
		cb->scene = scene;
		callbackPtrs.push_back(cb->stepInit());
	}
	return callbackPtrs;
}

/* As the body of the loop of YADE's InteractionLoop::action (core/InteractionLoop.cpp of YADE 2025.2.0, GPL v2 or later,
   as this plugin), for the steps this loop makes itself (sleepFunctor): no periodic shift (the cell is not periodic),
   no removal of the pairs the collider did not see (not asked), no subdomains (not with MPI), linIntrs in its order. */
bool RdemInteractionLoop::visit(const shared_ptr<Interaction>& I, const vector<IntrCallback::FuncPtr>& callbackPtrs)
{
	const shared_ptr<Body>& b1_ = Body::byId(I->getId1(), scene);
	const shared_ptr<Body>& b2_ = Body::byId(I->getId2(), scene);
	if (!b1_ || !b2_) { // a body vanished
		scene->interactions->requestErase(I);
		return false;
	}
	if (b1_->isClump() || b2_->isClump()) return false;
	// no geometry functor for these shapes (known), or a body without a shape: no interaction possible
	if (!I->functorCache.geomExists || !b1_->shape || !b2_->shape) {
		assert(!I->isReal());
		return false;
	}
	bool swap = false;
	if (!I->functorCache.geom) {
		I->functorCache.geom = geomDispatcher->getFunctor2D(b1_->shape, b2_->shape, swap);
		if (!I->functorCache.geom) { // remember that there is none
			I->functorCache.geomExists = false;
			return false;
		}
	}
	// the geometry functor takes the bodies in its order: swap them within the interaction (not remembered)
	if (swap) I->swapOrder();
	const shared_ptr<Body>& b1      = swap ? b2_ : b1_;
	const shared_ptr<Body>& b2      = swap ? b1_ : b2_;
	const bool              wasReal = I->isReal();
	if (!I->functorCache.geom->go(b1->shape, b2->shape, *b1->state, *b2->state, Vector3r::Zero(), /*force*/ false, I)) {
		if (wasReal) {
			LOG_WARN("IGeomFunctor returned false on existing interaction!");
			scene->interactions->requestErase(I); // reset, perhaps erased in the next step
		}
		return !wasReal;
	}
	applyPhysicsAndLaw(I, *b1, *b2, wasReal, callbackPtrs);
	return false;
}

/* The rest of the body of YADE's loop (core/InteractionLoop.cpp, as visit): the physics, the law and the callbacks of an
   interaction whose geometry functor returned true. */
void RdemInteractionLoop::applyPhysicsAndLaw(
        const shared_ptr<Interaction>& I, Body& b1, Body& b2, bool wasReal, const vector<IntrCallback::FuncPtr>& callbackPtrs)
{
	bool swap = false;
	if (!I->functorCache.phys) {
		I->functorCache.phys = physDispatcher->getFunctor2D(b1.material, b2.material, swap);
		assert(!swap); // IPhysFunctors are symmetric
	}
	if (!I->functorCache.phys)
		throw std::runtime_error(
		        "Undefined or ambiguous IPhys dispatch for types " + b1.material->getClassName() + " and " + b2.material->getClassName() + ".");
	I->functorCache.phys->go(b1.material, b2.material, I);
	assert(I->phys);
	if (!wasReal) I->iterMadeReal = scene->iter; // created right now
	// the law's functor is cached once the interaction has its geometry and physics
	if (!I->functorCache.constLaw) {
		I->functorCache.constLaw = lawDispatcher->getFunctor2D(I->geom, I->phys, swap);
		if (!I->functorCache.constLaw) {
			LOG_FATAL(
			        "None of given Law2 functors can handle interaction #"
			        << I->getId1() << "+" << I->getId2() << ", types geom:" << I->geom->getClassName() << "=" << I->geom->getClassIndex()
			        << " and phys:" << I->phys->getClassName() << "=" << I->phys->getClassIndex()
			        << " (LawDispatcher::getFunctor2D returned empty functor)");
			exit(1);
		}
		assert(!swap); // the arguments are of different types
	}
	if (!I->functorCache.constLaw->go(I->geom, I->phys, I.get())) scene->interactions->requestErase(I);
	if (!I->isReal()) return; // the law may have reset it
	for (size_t j = 0; j < callbacks.size(); j++)
		if (callbackPtrs[j] != NULL) (*(callbackPtrs[j]))(callbacks[j].get(), I.get());
}

void RdemInteractionLoop::action()
{
	RdemSharedState&                  sh    = RdemSharedState::of(scene, shared); // checks the engines when they changed
	Ig2_RdemBlock_RdemBlock_RdemGeom* ig2   = sleepFunctor(sh);
	const bool                        sleep = ig2 && worthSleeping(*ig2);
	const auto                        lane  = laneFunctors();
	if (!sleep) {
		wakeAll();
		fellAsleepLastStep = false;
		if (!lane.first) {
			InteractionLoop::action();
			return;
		}
	}
	if (sleep) prepareSleepers(sh.travel);
	if (lane.first) rotations();
	const vector<IntrCallback::FuncPtr> callbackPtrs = prepareStep();
	const long                          size         = long(scene->interactions->size());
	// linIntrs and the sleepers by position, read through pointers the calls in the loop cannot change
	const shared_ptr<Interaction>* const linIntrs = size > 0 ? &(*scene->interactions)[0] : nullptr;
	Sleeper* const                       sleeping = sleep ? sleepers.data() : nullptr;
	const rdem::BodyTravel&              travel   = sh.travel;
	const bool                           witness  = ig2 && ig2->skipApart;
	long                                 slept = 0, witnessed = 0, fellAsleep = 0;
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(guided) reduction(+ : slept, witnessed, fellAsleep) \
        num_threads(ompThreads > 0 ? math::min(ompThreads, omp_get_max_threads()) : omp_get_max_threads())
#endif
	for (long k = 0; k < size; k++) {
		const shared_ptr<Interaction>& I = linIntrs[k];
		if (sleep) {
			Sleeper& s = sleeping[k];
			if (s.I) {
				// the functor's test (the epoch and the record of the certificates checked for the step above)
				if (s.I == I.get() && stillApart(s, travel, witness)) {
					if (s.witness < 0) slept++;
					else
						witnessed++;
					continue;
				}
				s.I = nullptr; // woken: another interaction at k, or the blocks may have moved enough to touch
				keep[size_t(k)].reset();
			}
		}
		if (lane.first && inLane(*I, *lane.second)) {
			bondInLane(I, *lane.first, *lane.second);
			continue;
		}
		if (!visit(I, callbackPtrs)) continue;
		if (sleep && fallAsleep(k, I, *ig2)) fellAsleep++;
	}
	if (!sleep) return;
	fellAsleepLastStep = fellAsleep > 0;
	sleptPairs += slept + witnessed;
	ig2->skippedTests += Real(slept);     // tested by their certificate, as the functor would have
	ig2->witnessTests += Real(witnessed); // by their witness axis
}

} // namespace yade
