/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The one place that knows every engine and functor of the plugin: it hands them their shared state and checks their
   order; none of them knows another. */
#include <core/InteractionLoop.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Collider.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/Ig2_RdemBlock_RdemBlock_RdemGeom.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/RdemCellStrainUpdater.hpp>
#include <pkg/rdem/RdemContactGate.hpp>
#include <pkg/rdem/RdemForceAssembler.hpp>
#include <pkg/rdem/RdemInteractionLoop.hpp>
#include <pkg/rdem/RdemPoissonEngine.hpp>
#include <pkg/rdem/RdemSharedState.hpp>
#include <pkg/rdem/RdemTimeStepper.hpp>
#include <algorithm>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((RdemSharedState));
CREATE_LOGGER(RdemSharedState);

bool rdem::BodyTravel::currentFor(const Scene& scene) const { return iter == scene.iter && !scene.isPeriodic && epoch >= 0; }

void RdemSharedState::postLoad(RdemSharedState&)
{
	tensionBreaks.reset();
	shearBreaks.reset();
	tensionBreaks += int(savedTensionBreaks);
	shearBreaks += int(savedShearBreaks);
}

int RdemSharedState::takeActiveSetChanges()
{
	const int n = activeSetChanges.get();
	if (n != 0) activeSetChanges.reset();
	return n;
}

void RdemSharedState::join(const Interaction& I)
{
	activeSetChanges += 1;
	const std::lock_guard<std::mutex> lock(joinedMutex);
	joined.push_back(JoinedPhys { I.phys, I.getId1(), I.getId2() });
}

void RdemSharedState::bookSpringEnergies(Scene* scene, const rdem::SpringEnergies<Real>& e)
{
	/* Once an energy has its index, a zero adds nothing and is not booked; the names are made once, not at every call
	   (a std::string per energy and interaction was 9 % of a step of the MI1 wall, measured by scripts/profile_step.py). */
	static const std::string names[7]
	        = { "rdemElastic", "rdemDashpot", "rdemFriction", "rdemBondBreak", "rdemFractureTension", "rdemFractureShear", "rdemCrushing" };
	const Real values[7] = { e.elastic, e.dashpot, e.friction, e.bondBreak, e.fractureTension, e.fractureShear, e.crushing };
	for (int k = 0; k < (e.softening ? 7 : 4); ++k)
		if (energyIx[k] < 0 || values[k] != 0) scene->energy->add(values[k], names[k], energyIx[k], /*reset every step: the elastic energy*/ k == 0);
	// Made at its first release only: a scene whose contacts never drop a loaded spring keeps the energies it had.
	static const std::string contactRelease = "rdemContactRelease";
	if (e.contactRelease != 0) scene->energy->add(e.contactRelease, contactRelease, energyIx[7], false);
}

void RdemSharedState::releaseEnergies(Body::id_t id1, Body::id_t id2, const rdem::SpringEnergies<Real>& e)
{
	const std::lock_guard<std::mutex> lock(releasedMutex);
	released.push_back(ReleasedEnergies { id1, id2, e });
}

rdem::SpringEnergies<Real> RdemSharedState::takeReleasedEnergies()
{
	std::sort(released.begin(), released.end(), [](const ReleasedEnergies& a, const ReleasedEnergies& b) {
		return a.id1 != b.id1 ? a.id1 < b.id1 : a.id2 < b.id2;
	});
	rdem::SpringEnergies<Real> sum;
	for (const auto& r : released)
		sum += r.e;
	released.clear();
	return sum;
}

vector<RdemSharedState::JoinedPhys> RdemSharedState::takeJoined()
{
	vector<JoinedPhys> out;
	out.swap(joined);
	return out;
}

RdemSharedState& RdemSharedState::of(Scene* scene, shared_ptr<RdemSharedState>& mine)
{
	if (!mine) {
		rdem::forEachLoopFunctor<Law2_RdemGeom_RdemPhys_FaceSprings>(scene, [&](Law2_RdemGeom_RdemPhys_FaceSprings& law) {
			if (!mine) mine = law.shared;
		});
		if (!mine) mine = shared_ptr<RdemSharedState>(new RdemSharedState); // no law: nothing breaks, nothing to share
	}
	if (!mine->checkedEngines.same(scene->engines)) mine->checkEngines(scene, mine);
	return *mine;
}

void RdemSharedState::checkEngines(Scene* scene, const shared_ptr<RdemSharedState>& self)
{
	const auto hand = [&](shared_ptr<RdemSharedState>& theirs, const char* who, size_t at) {
		if (!theirs) theirs = self;
		else if (theirs != self)
			throw std::runtime_error(
			        std::string(who) + " (in O.engines[" + std::to_string(at)
			        + "]) holds another RdemSharedState than the other engines of the plugin: they must share one to see the same cracks. "
			          "rdem.engines() hands one to all; set its shared = None to give it the law's");
	};
	long loop = -1, assembler = -1, updater = -1, gate = -1, collider = -1;
	bool defers = false;
	stiffnessSources.clear();
	cells = nullptr;
	for (size_t i = 0; i < scene->engines.size(); ++i) {
		Engine* e = scene->engines[i].get();
		if (auto* il = dynamic_cast<InteractionLoop*>(e)) {
			if (auto* rl = dynamic_cast<RdemInteractionLoop*>(il)) hand(rl->shared, "RdemInteractionLoop", i);
			bool ours = false;
			for (const auto& f : il->lawDispatcher->functors)
				if (auto* law = dynamic_cast<Law2_RdemGeom_RdemPhys_FaceSprings*>(f.get())) {
					hand(law->shared, "Law2_RdemGeom_RdemPhys_FaceSprings", i);
					defers = defers || law->deferForces;
					stiffnessSources.push_back(law);
					ours = true;
				}
			for (const auto& f : il->geomDispatcher->functors)
				if (auto* ig2 = dynamic_cast<Ig2_RdemBlock_RdemBlock_RdemGeom*>(f.get()))
					hand(ig2->shared, "Ig2_RdemBlock_RdemBlock_RdemGeom", i);
			if (ours && loop < 0) loop = long(i);
		} else if (auto* a = dynamic_cast<RdemForceAssembler*>(e)) {
			hand(a->shared, "RdemForceAssembler", i);
			if (loop >= 0 && assembler < 0) assembler = long(i);
		} else if (auto* g = dynamic_cast<RdemContactGate*>(e)) {
			hand(g->shared, "RdemContactGate", i);
			if (gate < 0) gate = long(i);
		} else if (auto* u = dynamic_cast<RdemCellStrainUpdater*>(e)) {
			hand(u->shared, "RdemCellStrainUpdater", i);
			if (updater < 0) updater = long(i);
		} else if (auto* t = dynamic_cast<RdemTimeStepper*>(e))
			hand(t->shared, "RdemTimeStepper", i);
		else if (auto* p = dynamic_cast<RdemPoissonEngine*>(e)) {
			hand(p->shared, "RdemPoissonEngine", i);
			stiffnessSources.push_back(p);
			if (!cells) cells = &p->cellNetwork();
		} else if (dynamic_cast<Collider*>(e) && collider < 0)
			collider = long(i);
	}
	if (defers && assembler < 0)
		throw std::runtime_error(
		        "Law2_RdemGeom_RdemPhys_FaceSprings.deferForces is True but no RdemForceAssembler follows the InteractionLoop (O.engines["
		        + std::to_string(loop)
		        + "]), so nothing would apply the deferred forces: put RdemForceAssembler() right after the InteractionLoop "
		          "(rdem.engines() does), or set deferForces=False");
	if (updater >= 0 && loop >= 0 && updater > loop)
		throw std::runtime_error(
		        "RdemCellStrainUpdater (O.engines[" + std::to_string(updater) + "]) must come before the InteractionLoop (O.engines["
		        + std::to_string(loop) + "]): the law reads the cells' strains of the step (rdem.engines(poisson='consistent') places it)");
	if (gate >= 0 && collider >= 0 && gate > collider)
		throw std::runtime_error(
		        "RdemContactGate (O.engines[" + std::to_string(gate) + "]) must come before the collider (O.engines[" + std::to_string(collider)
		        + "]), which it switches on when contacts can occur (rdem.engines() places it)");
	deferredForces = defers;
	checkedEngines.take(scene->engines);
}

} // namespace yade
