/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/InteractionLoop.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/RdemBlock.hpp>
#include <pkg/rdem/RdemForceAssembler.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemMat.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemPoissonEngine.hpp>
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
	/// The 12 edges of the hexahedron: node pairs that differ in one of the bits i, j, k (node a = i + 2j + 4k).
	constexpr int hexEdges[12][2] = { { 0, 1 }, { 2, 3 }, { 4, 5 }, { 6, 7 }, { 0, 2 }, { 1, 3 }, { 4, 6 }, { 5, 7 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
	constexpr Real sameSideCos    = 0.99; // two bond normals within ~8° point to the same side of a block

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

	using Neighbours = std::map<Body::id_t, vector<std::pair<Body::id_t, Vector3r>>>; // per block: bonded block, unit direction

	Body::id_t next(const Neighbours& nbr, Body::id_t b, const Vector3r& dir)
	{
		if (b < 0) return -1;
		const auto it = nbr.find(b);
		if (it == nbr.end()) return -1;
		for (const auto& nd : it->second)
			if (nd.second.dot(dir) > sameSideCos) return nd.first;
		return -1;
	}

	/// Half-extent of block id along its body axis closest to dir [m].
	Real halfAlong(Scene* scene, Body::id_t id, const Vector3r& dir)
	{
		const Body&    b = *Body::byId(id, scene);
		const Matrix3r R = b.state->ori.toRotationMatrix();
		int            k = 0;
		for (int j = 1; j < 3; ++j)
			if (math::abs(R.col(j).dot(dir)) > math::abs(R.col(k).dot(dir))) k = j;
		return static_cast<RdemBlock*>(b.shape.get())->extents[k];
	}

	/// Whether the translation of block id along dir is prescribed (dir along a global axis whose DOF is blocked).
	bool prescribed(Scene* scene, Body::id_t id, const Vector3r& dir)
	{
		const State& s = *Body::byId(id, scene)->state;
		for (int k = 0; k < 3; ++k)
			if (math::abs(dir[k]) > sameSideCos) return (s.blockedDOFs & State::axisDOF(k)) != 0;
		return false;
	}

	/// Extent of the dual cell of block id along the unit direction t: half-way to the neighbouring centroids, to the block's
	/// face where it has no neighbour and is free, to its centroid where it is a platen [m].
	Real dualExtent(Scene* scene, const Neighbours& nbr, Body::id_t id, const Vector3r& t)
	{
		Real ext = 0;
		for (int side = -1; side <= 1; side += 2) {
			const Body::id_t nb = next(nbr, id, side * t);
			if (nb >= 0) ext += math::abs((Body::byId(nb, scene)->state->pos - Body::byId(id, scene)->state->pos).dot(t)) / 2;
			else if (!prescribed(scene, id, t))
				ext += halfAlong(scene, id, t);
		}
		return ext;
	}
}

void RdemPoissonEngine::build(const vector<Body::id_t>& idsIn)
{
	scene = Omega::instance().getScene().get();
	std::set<Body::id_t> ids(idsIn.begin(), idsIn.end());
	if (ids.empty())
		for (const auto& b : *scene->bodies)
			if (b && dynamic_cast<RdemBlock*>(b->shape.get())) ids.insert(b->id);
	for (Body::id_t id : ids) {
		const shared_ptr<Body>& b = Body::byId(id, scene);
		if (!b || !dynamic_cast<RdemBlock*>(b->shape.get()))
			throw std::invalid_argument("RdemPoissonEngine.build: body " + std::to_string(id) + " is not an RdemBlock");
		if (!dynamic_cast<RdemMat*>(b->material.get()))
			throw std::invalid_argument("RdemPoissonEngine.build: body " + std::to_string(id) + " has no RdemMat material");
	}

	for (const auto& e : scene->engines) {
		const auto* loop = dynamic_cast<InteractionLoop*>(e.get());
		if (!loop) continue;
		for (const auto& f : loop->physDispatcher->functors) {
			const auto* ip2 = dynamic_cast<Ip2_RdemMat_RdemMat_RdemPhys*>(f.get());
			if (ip2 && (ip2->springModulus == 1) != consistent)
				throw std::invalid_argument(
				        std::string("RdemPoissonEngine.consistent = ") + (consistent ? "True" : "False")
				        + " needs Ip2_RdemMat_RdemMat_RdemPhys.springModulus = " + (consistent ? "1" : "0")
				        + "; rdem.engines(poisson='paper' or 'consistent') sets both");
		}
	}
	// The paper's springs E/(1-ν²) plus D_p are an indefinite tensor for ν > (3-√5)/2 ≈ 0.382 (doc/theory.md §5.3): an
	// explicit run would blow up, so refuse it with the way out.
	const Real nuPaperMax = (3 - math::sqrt(Real(5))) / 2;
	if (!consistent)
		for (Body::id_t id : ids) {
			const Real nu = static_cast<RdemMat*>(Body::byId(id, scene)->material.get())->poisson;
			if (nu > nuPaperMax)
				throw std::invalid_argument(
				        "RdemPoissonEngine.build: block " + std::to_string(id) + " has poisson = " + std::to_string(nu)
				        + ", above 0.382 where the paper formulation (springs E/(1-nu^2) plus D_p) is not positive definite and a run"
				          " blows up; use the consistent formulation, rdem.engines(poisson='consistent')");
		}

	// Bonded neighbours of every block, with the bond's unit normal (global) pointing to the neighbour.
	Neighbours nbr;
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		const auto* g = dynamic_cast<RdemGeom*>(I->geom.get());
		if (!g || g->nSegments() == 0 || !ids.count(I->getId1()) || !ids.count(I->getId2())) continue;
		const Vector3r n = Body::byId(I->getId1(), scene)->state->ori * g->segNormal1;
		nbr[I->getId1()].push_back({ I->getId2(), n });
		nbr[I->getId2()].push_back({ I->getId1(), -n });
	}
	for (const auto& bn : nbr)
		for (size_t i = 0; i < bn.second.size(); ++i)
			for (size_t j = i + 1; j < bn.second.size(); ++j)
				if (bn.second[i].second.dot(bn.second[j].second) > sameSideCos) {
					std::ostringstream msg;
					msg << "RdemPoissonEngine.build: block " << bn.first << " has two bonded neighbours on one side (blocks " << bn.second[i].first
					    << " and " << bn.second[j].first
					    << "); Poisson elements need blocks on a grid of 2x2x2 groups (one neighbour per face), e.g. not running-bond masonry";
					throw std::invalid_argument(msg.str());
				}

	nodes.clear();
	refPos.clear();
	lambda.clear();
	skin.clear();
	std::set<std::array<Body::id_t, 8>> seen;
	int                                 incomplete = 0;
	for (Body::id_t b : ids) {
		const Matrix3r R = Body::byId(b, scene)->state->ori.toRotationMatrix();
		const Vector3r ex = R.col(0), ey = R.col(1), ez = R.col(2);
		std::array<Body::id_t, 8> n;
		n[0] = b;
		n[1] = next(nbr, b, ex);
		n[2] = next(nbr, b, ey);
		n[4] = next(nbr, b, ez);
		if (n[1] < 0 || n[2] < 0 || n[4] < 0) continue; // b is not the (-,-,-) corner of a group
		n[3] = next(nbr, n[1], ey);
		n[5] = next(nbr, n[1], ez);
		n[6] = next(nbr, n[2], ez);
		n[7] = next(nbr, n[3], ez);
		// Every one of the 12 edges must be a bond between the nodes found above.
		bool complete = true;
		for (const auto& e : hexEdges) {
			const Body::id_t a = n[size_t(e[0])], c = n[size_t(e[1])];
			const int        bit = e[0] ^ e[1];
			const Vector3r   dir = bit == 1 ? ex : (bit == 2 ? ey : ez);
			if (a < 0 || c < 0) {
				complete = false;
				continue;
			}
			const Body::id_t found = next(nbr, a, dir);
			if (found < 0) complete = false;
			else if (found != c) {
				std::ostringstream msg;
				msg << "RdemPoissonEngine.build: blocks around block " << b << " do not close into a 2x2x2 group (block " << a << " is bonded to "
				    << found << " where the grid expects " << c << ")";
				throw std::invalid_argument(msg.str());
			}
		}
		if (!complete) {
			++incomplete;
			continue;
		}
		std::array<Body::id_t, 8> key = n;
		std::sort(key.begin(), key.end());
		if (!seen.insert(key).second) continue;
		rdem::Nodes8<Real>                X;
		std::array<std::array<Real, 3>, 8> parts; // volume, E, ν of each node's block
		for (size_t a = 0; a < 8; ++a) {
			const Body& body = *Body::byId(n[a], scene);
			X[a]             = body.state->pos;
			const auto& m    = *static_cast<RdemMat*>(body.material.get());
			parts[a]         = { 8 * static_cast<RdemBlock*>(body.shape.get())->extents.prod(), m.young, m.poisson };
		}
		const Real lam = rdem::layeredLambda<Real>(parts);
		if (!rdem::hex8IsValid<Real>(X)) {
			std::ostringstream msg;
			msg << "RdemPoissonEngine.build: the centroids of blocks " << n[0] << "," << n[1] << ",...," << n[7] << " form an inverted or flat hexahedron";
			throw std::invalid_argument(msg.str());
		}
		for (size_t a = 0; a < 8; ++a) {
			nodes.push_back(n[a]);
			refPos.push_back(X[a]);
		}
		lambda.push_back(lam);
		// Skin of the consistent formulation: a side whose four blocks have no neighbour further out and are free along
		// that axis carries a slab as thick as those blocks' half-extent, in units of half the element length.
		for (int d = 0; d < 3; ++d) {
			const Vector3r ed = R.col(d);
			for (int side = 0; side < 2; ++side) {
				Real       t     = 0;
				const Real sgn   = side ? 1 : -1;
				bool       outer = consistent;
				Real       ell = 0, halfLength = 0;
				for (size_t a = 0; a < 8 && outer; ++a) {
					if (((a >> d) & 1) != size_t(side)) continue;
					outer = next(nbr, n[a], sgn * ed) < 0 && !prescribed(scene, n[a], ed);
					ell += halfAlong(scene, n[a], ed) / 4;
					halfLength += math::abs((X[a ^ (size_t(1) << d)] - X[a]).dot(ed)) / 8;
				}
				if (outer) t = ell / halfLength;
				skin.push_back(t);
			}
		}
	}
	if (nodes.empty())
		throw std::invalid_argument(
		        "RdemPoissonEngine.build: no 2x2x2 group of bonded blocks among the " + std::to_string(ids.size())
		        + " blocks given (bond them first, e.g. with rdem.bondAll)");
	// Spring weights of the consistent formulation (doc/theory.md §5.2); 1 in the paper's.
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		const auto* g = dynamic_cast<RdemGeom*>(I->geom.get());
		auto*       p = dynamic_cast<RdemPhys*>(I->phys.get());
		if (!g || !p || g->nSegments() == 0 || !ids.count(I->getId1()) || !ids.count(I->getId2())) continue;
		p->weightNormal = p->weightShear = 1;
		if (!consistent) continue;
		const Body::id_t a = I->getId1(), b = I->getId2();
		const Matrix3r   Ra = Body::byId(a, scene)->state->ori.toRotationMatrix();
		const Vector3r   nrm = Ra * g->segNormal1;
		const Real       L   = (Body::byId(b, scene)->state->pos - Body::byId(a, scene)->state->pos).dot(nrm);
		const Real extA = (next(nbr, a, -nrm) < 0 && !prescribed(scene, a, nrm)) ? halfAlong(scene, a, nrm) : Real(0);
		const Real extB = (next(nbr, b, nrm) < 0 && !prescribed(scene, b, nrm)) ? halfAlong(scene, b, nrm) : Real(0);
		Real       cross = 1;
		for (int k = 0; k < 3; ++k) {
			const Vector3r t = Ra.col(k);
			if (math::abs(t.dot(nrm)) > sameSideCos) continue;
			cross *= (dualExtent(scene, nbr, a, t) / (2 * halfAlong(scene, a, t)) + dualExtent(scene, nbr, b, t) / (2 * halfAlong(scene, b, t))) / 2;
		}
		p->weightNormal = (L + extA + extB) / L * cross;
		p->weightShear  = cross;
	}
	scalePrev.clear(); // the first step takes the current scales
	LOG_INFO(nElements() << " Poisson elements on " << ids.size() << " blocks (" << incomplete << " groups skipped: a bond missing)");
	prepare();
}

void RdemPoissonEngine::buildPy(const py::list& ids)
{
	vector<Body::id_t> v;
	for (long i = 0; i < py::len(ids); ++i)
		v.push_back(py::extract<Body::id_t>(ids[i]));
	build(v);
}

void RdemPoissonEngine::postLoad(RdemPoissonEngine&)
{
	stiffness.clear();
	stiffnessOf.clear();
	bonds.clear();
	scalesBroken = -1;
}

void RdemPoissonEngine::prepare()
{
	/* Elements of the same shape, size, material and skin share one K_p: a regular grid has a handful of distinct
	   matrices instead of one 4.6 kB matrix per element, and the product K_p·u runs from cache (doc/performance.md).
	   Shapes are compared on node coordinates relative to node 0, rounded to 1e-10 of the element's diagonal, λ to 1e-12 of the largest. */
	const size_t nEl = size_t(nElements());
	stiffness.clear();
	stiffnessOf.assign(nEl, 0);
	std::map<vector<long long>, size_t> distinct;
	const Real lambdaMax = lambda.empty() ? Real(0) : *std::max_element(lambda.begin(), lambda.end());
	for (size_t e = 0; e < nEl; ++e) {
		const Real        q = 1e-10 * (refPos[8 * e + 7] - refPos[8 * e]).norm();
		vector<long long> key;
		for (size_t a = 1; a < 8; ++a)
			for (int d = 0; d < 3; ++d)
				key.push_back(std::llround((refPos[8 * e + a][d] - refPos[8 * e][d]) / q));
		key.push_back(lambdaMax > 0 ? std::llround(lambda[e] / lambdaMax * 1e12) : 0);
		for (size_t f = 0; f < 6; ++f)
			key.push_back(std::llround(skin[6 * e + f] * 1e10));
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
			bonds[12 * e + k] = scene->interactions->find(nodes[8 * e + size_t(hexEdges[k][0])], nodes[8 * e + size_t(hexEdges[k][1])]);
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
	if (!prepared()) prepare();
	// The scales change only when a spring breaks or a bond is released or erased: recompute them only then.
	const long broken = Law2_RdemGeom_RdemPhys_FaceSprings::brokenSprings(scene), nIntrs = long(scene->interactions->size());
	if (broken != scalesBroken || nIntrs != scalesIntrs) {
		scales       = elementScales();
		scalesBroken = broken;
		scalesIntrs  = nIntrs;
	}
	const vector<Real>& scale = scales;
	const long         nEl   = long(nElements());
	if (scalePrev.size() != scale.size()) scalePrev = scale;
	const bool trackEnergy = scene->trackEnergy;
	const long nBodies     = long(nodeFirst.size()) - 1;
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static)
#endif
	for (long b = 0; b < nBodies; ++b) {
		const auto& body = Body::byId(Body::id_t(b), scene);
		if (body && nodeFirst[size_t(b)] != nodeFirst[size_t(b) + 1]) nodePos[size_t(b)] = body->state->pos; // erased: its elements are released
	}
	Real energy = 0, released = 0; // Σ ½ s uᵀK_p u of the elements; ½ (s_prev - s) uᵀK_p u lost to cracks in this step [J]
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) reduction(+ : energy, released)
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
#pragma omp parallel for schedule(static)
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

vector<Real> RdemPoissonEngine::stiffnessBound() const
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
	const Scene* sc = Omega::instance().getScene().get();
	vector<Real> bound(sc->bodies->size(), 0);
	for (size_t e = 0; e < size_t(nElements()); ++e) {
		const std::array<Real, 8> rows = prepared() ? distinct[stiffnessOf[e]] : nodeBounds(elementStiffness(e));
		for (size_t a = 0; a < 8; ++a)
			bound[size_t(nodes[8 * e + a])] += rows[a];
	}
	return bound;
}

} // namespace yade
