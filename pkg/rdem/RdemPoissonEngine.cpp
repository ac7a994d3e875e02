/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/InteractionLoop.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/InertialMass.hpp>
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <pkg/rdem/OpenMPLoops.hpp>
#include <pkg/rdem/RdemBlock.hpp>
#include <pkg/rdem/RdemForceAssembler.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemMat.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemPoissonEngine.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <pkg/rdem/math/BlockCells.hpp>
#include <pkg/rdem/math/DensityScaling.hpp>
#include <pkg/rdem/math/Elasticity.hpp>
#include <pkg/rdem/math/GroupByKey.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RdemPoissonEngine));
CREATE_LOGGER(RdemPoissonEngine);

namespace {
	/* K·u for one element. YADE builds with EIGEN_DONT_VECTORIZE (its flags, which the plugin must share), so Eigen's
	   product is scalar; written column by column (axpy), the loop vectorizes without reordering any sum, and the result
	   is the same to the last bit as the row-by-row product of the same column order. */
	rdem::Vec24<Real> multiply(const rdem::Mat24<Real>& K, const rdem::Vec24<Real>& u)
	{
		Real        out[24] = {};
		const Real* col     = K.data(); // column-major
		for (int j = 0; j < 24; ++j, col += 24) {
			const Real uj = u[j];
			for (int i = 0; i < 24; ++i)
				out[i] += col[i] * uj;
		}
		return Eigen::Map<const rdem::Vec24<Real>>(out);
	}
}

void RdemPoissonEngine::postLoad(RdemPoissonEngine&)
{
	if (elements != "auto" && elements != "hex8" && elements != "cells")
		throw std::invalid_argument("RdemPoissonEngine.elements = '" + elements + "': must be 'auto', 'hex8' or 'cells'");
	stiffness.clear();
	stiffnessOf.clear();
	bonds.clear();
	scalesBroken = -1;
}

void RdemPoissonEngine::prepare()
{
	/* Elements of the same shape, size, material and skin share one K_p: a regular grid has a handful of distinct
	   matrices instead of one 4.6 kB matrix per element, and the product K_p·u runs from cache.
	   Shapes are compared on node coordinates relative to node 0, rounded to 1e-10 of the element's diagonal, λ to 1e-12 of the largest. */
	const size_t nEl = size_t(nElements());
	stiffness.clear();
	stiffnessOf.assign(nEl, 0);
	std::map<vector<long long>, size_t> distinct;
	const Real                          lambdaMax = lambda.empty() ? Real(0) : *std::max_element(lambda.begin(), lambda.end());
	for (size_t e = 0; e < nEl; ++e) {
		const Real        q = 1e-10 * (refPos[8 * e + 7] - refPos[8 * e]).norm();
		vector<long long> key;
		const auto        nearest = [](Real x) { return static_cast<long long>(math::round(x)); };
		for (size_t a = 1; a < 8; ++a)
			for (int d = 0; d < 3; ++d)
				key.push_back(nearest((refPos[8 * e + a][d] - refPos[8 * e][d]) / q));
		key.push_back(lambdaMax > 0 ? nearest(lambda[e] / lambdaMax * 1e12) : 0);
		for (size_t f = 0; f < 6; ++f)
			key.push_back(nearest(skin[6 * e + f] * 1e10));
		const auto it = distinct.find(key);
		if (it != distinct.end()) {
			stiffnessOf[e] = it->second;
			continue;
		}
		stiffnessOf[e] = stiffness.size();
		distinct.emplace(key, stiffness.size());
		stiffness.push_back(elementStiffness(e));
	}
	/* Nodal forces are written per element and summed per body (slots of a body in element order): one addition per
	   body instead of one per element node, and a sum whose order does not depend on the number of threads. */
	nodalForce.assign(8 * nEl, Vector3r::Zero());
	rdem::groupByKey(nodes, scene->bodies->size(), nodeFirst, nodeSlot);
	/* The elements read their nodes' positions from one compact per-body array, filled in body order once per step,
	   instead of through each node's Body and State (8 pointer chases per element), and the reference positions from
	   another (build takes them from the blocks at once: a body has the same refPos in all its elements). */
	nodeRef.assign(scene->bodies->size(), Vector3r::Zero());
	nodePos.assign(scene->bodies->size(), Vector3r::Zero());
	for (size_t k = 0; k < nodes.size(); ++k)
		nodeRef[size_t(nodes[k])] = refPos[k];
	bonds.assign(12 * nEl, shared_ptr<Interaction>());
	scalesBroken = -1;
	for (size_t e = 0; e < nEl; ++e)
		for (size_t k = 0; k < 12; ++k)
			bonds[12 * e + k]
			        = scene->interactions->find(nodes[8 * e + size_t(rdem::hex8Edges[k][0])], nodes[8 * e + size_t(rdem::hex8Edges[k][1])]);
	LOG_DEBUG(nEl << " Poisson elements share " << stiffness.size() << " distinct stiffness matrices");
}

rdem::Mat24<Real> RdemPoissonEngine::elementStiffness(size_t e) const
{
	rdem::Nodes8<Real> X;
	for (size_t a = 0; a < 8; ++a)
		X[a] = refPos[8 * e + a];
	const Vector3r lo(skin[6 * e], skin[6 * e + 2], skin[6 * e + 4]), hi(skin[6 * e + 1], skin[6 * e + 3], skin[6 * e + 5]);
	return rdem::hex8StiffnessWithSkin<Real>(X, rdem::poissonTensorFromLambda<Real>(lambda[e]), lo, hi);
}

vector<Real> RdemPoissonEngine::elementScales()
{
	scene = Omega::instance().getScene().get();
	if (!prepared()) prepare();
	vector<Real> s(size_t(nElements()), 1);
	// An element one of whose blocks was erased (O.bodies.erase) has lost a node: released, crack or not.
	for (size_t e = 0; e < s.size(); ++e)
		for (size_t a = 0; a < 8; ++a)
			if (!Body::byId(nodes[8 * e + a], scene)) s[e] = 0;
	if (!releaseOnCrack) return s;
	for (size_t e = 0; e < s.size(); ++e)
		for (size_t k = 0; k < 12 && s[e] > 0; ++k) {
			const auto& I = bonds[12 * e + k];
			// A released bond is gone for good: its interaction is dead, or, when prepare() looked the pair up after the
			// blocks touched again (e.g. after O.load), it is a sampled contact without segments.
			const auto* p = I && I->isReal() ? static_cast<RdemPhys*>(I->phys.get()) : nullptr;
			if (!p || p->segState.empty()) {
				s[e] = 0;
				break;
			}
			s[e] = math::min(s[e], Real(p->nIntact()) / Real(p->segState.size()));
		}
	return s;
}

void RdemPoissonEngine::action()
{
	RdemSharedState::of(scene, shared); // checks the engines when they changed
	if (nElements() > 0) hex8Action();
	cellAction();
}

void RdemPoissonEngine::hex8Action()
{
	if (!prepared()) prepare();
	// The scales change only when a spring breaks or a bond is released or erased: recompute them only then.
	const long broken = RdemSharedState::of(scene, shared).brokenSprings(), nIntrs = long(scene->interactions->size());
	if (broken != scalesBroken || nIntrs != scalesIntrs) {
		scales       = elementScales();
		scalesBroken = broken;
		scalesIntrs  = nIntrs;
	}
	const vector<Real>& scale = scales;
	const long          nEl   = long(nElements());
	if (scalePrev.size() != scale.size()) scalePrev = scale;
	const bool trackEnergy = scene->trackEnergy;
	const long nBodies     = long(nodeFirst.size()) - 1;
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(ompThreads))
#endif
	for (long b = 0; b < nBodies; ++b) {
		const auto& body = Body::byId(Body::id_t(b), scene);
		if (body && nodeFirst[size_t(b)] != nodeFirst[size_t(b) + 1]) nodePos[size_t(b)] = body->state->pos; // erased: its elements are released
	}
	Real energy = 0, released = 0; // Σ ½ s uᵀK_p u of the elements; ½ (s_prev - s) uᵀK_p u lost to cracks in this step [J]
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) reduction(realSum : energy, released) num_threads(rdem::threadsFor(ompThreads))
#endif
	for (long e = 0; e < nEl; ++e) {
		const Real s = scale[size_t(e)], sPrev = scalePrev[size_t(e)];
		Vector3r*  F = &nodalForce[8 * size_t(e)];
		if (s <= 0 && (sPrev <= 0 || !trackEnergy)) { // released, and no release energy to book
			std::fill(F, F + 8, Vector3r::Zero());
			continue;
		}
		rdem::Nodes8<Real> X, x;
		for (size_t a = 0; a < 8; ++a) {
			const size_t node = size_t(nodes[8 * size_t(e) + a]);
			X[a]              = nodeRef[node];
			x[a]              = nodePos[node];
		}
		const Matrix3r          R  = corotational ? rdem::hex8Rotation<Real>(X, x) : Matrix3r::Identity();
		const rdem::Vec24<Real> u  = rdem::hex8Displacement<Real>(X, x, corotational ? &R : nullptr);
		const rdem::Vec24<Real> Ku = multiply(stiffness[stiffnessOf[size_t(e)]], u);
		if (trackEnergy) {
			energy += s * u.dot(Ku) / 2;
			released += (sPrev - s) * u.dot(Ku) / 2;
		}
		for (size_t a = 0; a < 8; ++a)
			F[a] = s > 0 ? Vector3r(-s * (R * Ku.segment<3>(3 * long(a)))) : Vector3r::Zero();
	}
	RdemForceAssembler::prepareDirectSums(scene, nBodies);
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(ompThreads))
#endif
	for (long b = 0; b < nBodies; ++b) {
		if (nodeFirst[size_t(b)] == nodeFirst[size_t(b) + 1]) continue;
		Vector3r f = Vector3r::Zero();
		for (size_t k = nodeFirst[size_t(b)]; k < nodeFirst[size_t(b) + 1]; ++k)
			f += nodalForce[nodeSlot[k]];
		scene->forces.addForceUnsynced(Body::id_t(b), f);
	}
	scalePrev = scale;
	if (trackEnergy) {
		scene->energy->add(energy, "rdemPoisson", energyIx, /*reset every step*/ true);
		scene->energy->add(released, "rdemPoissonRelease", releaseIx, /*reset every step*/ false);
	}
}

vector<Real> RdemPoissonEngine::hex8Omega2Bound() const
{
	// Per node of an element: the largest absolute row sum of its 3 rows of K_p [N/m].
	auto nodeBounds = [](const rdem::Mat24<Real>& K) {
		std::array<Real, 8> rows {};
		for (long a = 0; a < 8; ++a)
			for (long d = 0; d < 3; ++d)
				rows[size_t(a)] = math::max(rows[size_t(a)], Real(K.row(3 * a + d).cwiseAbs().sum()));
		return rows;
	};
	vector<std::array<Real, 8>> distinct; // of the distinct matrices, once each (prepared engines)
	if (prepared())
		for (const auto& K : stiffness)
			distinct.push_back(nodeBounds(K));
	Scene*       sc = Omega::instance().getScene().get();
	vector<Real> bound(sc->bodies->size(), 0);
	for (size_t e = 0; e < size_t(nElements()); ++e) {
		const std::array<Real, 8> rows = prepared() ? distinct[stiffnessOf[e]] : nodeBounds(elementStiffness(e));
		for (size_t a = 0; a < 8; ++a)
			bound[size_t(nodes[8 * e + a])] += rows[a];
	}
	for (size_t id = 0; id < bound.size(); ++id) { // row sums [N/m] over the mass: ω² [1/s²]
		const auto& b = Body::byId(Body::id_t(id), sc);
		bound[id]     = (b && bound[id] > 0) ? bound[id] / rdem::inertialMass(*b->state) : Real(0); // inertial mass
	}
	return bound;
}

vector<Real> RdemPoissonEngine::omega2Bound()
{
	vector<Real>       w2 = hex8Omega2Bound();
	const vector<Real> c  = cells.omega2Bound(Omega::instance().getScene().get());
	for (size_t id = 0; id < c.size() && id < w2.size(); ++id)
		w2[id] += c[id];
	return w2;
}

void RdemPoissonEngine::addOmega2Bound(Scene* sc, vector<Real>& omega2)
{
	if (dead) return;
	const vector<Real> P = omega2Bound();
	for (size_t id = 0; id < P.size() && id < omega2.size(); ++id) {
		const auto& b = Body::byId(Body::id_t(id), sc);
		if (b && b->state->blockedDOFs != State::DOF_ALL) omega2[id] += P[id];
	}
}

void RdemPoissonEngine::addStiffness(Scene* sc, const vector<const Interaction*>&, rdem::BlockStiffness<Real>& K, rdem::BlockStiffness<Real>&, Real)
{
	if (dead) return;
	scene = sc;
	if (nElements() > 0) {
		const vector<Real> s = elementScales(); // prepares the matrices
		for (size_t e = 0; e < s.size(); ++e) {
			std::array<long, 8> n;
			for (size_t a = 0; a < 8; ++a)
				n[a] = nodes[8 * e + a];
			K.addElement(n, &stiffness[stiffnessOf[e]], s[e]);
		}
	}
	cells.addStiffness(scene, releaseOnCrack, RdemSharedState::of(scene, shared).brokenSprings(), K);
}

int RdemPoissonEngine::nCells() const
{
	int    n  = 0;
	Scene* sc = Omega::instance().getScene().get();
	for (const auto& b : *sc->bodies)
		if (b)
			if (const auto* st = dynamic_cast<const RdemState*>(b->state.get()))
				if (st->cellVolume > 0) ++n;
	return n;
}

void RdemPoissonEngine::cellAction()
{
	Real energy = 0, released = 0;
	// the ghosts' stresses from their owners on YADE's MPI (RdemGhostExchange sets the sync for this step only)
	RdemCellNetwork::StressSync sync;
	std::swap(sync, RdemSharedState::of(scene, shared).cellStressSync);
	cells.applyForces(scene, releaseOnCrack, energy, released, ompThreads, sync);
	if (scene->trackEnergy && cells.nCells() > 0) {
		scene->energy->add(energy, "rdemPoisson", energyIx, /*reset every step*/ true);
		scene->energy->add(released, "rdemPoissonRelease", releaseIx, /*reset every step*/ false);
	}
}

RdemPoissonEngine* RdemPoissonEngine::of(const Scene* scene) { return rdem::findEngine<RdemPoissonEngine>(scene); }

} // namespace yade
