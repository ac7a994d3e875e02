/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* RdemPoissonEngine::build and its steps: which blocks, their bond graph, whether it is a grid of 2×2×2 groups, then
   the paper's hexahedra (with the consistent formulation's skin and spring weights) or the Poisson cells. The engine's
   step is in RdemPoissonEngine.cpp. */
#include <core/InteractionLoop.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/NumberText.hpp>
#include <pkg/rdem/RdemBlock.hpp>
#include <pkg/rdem/RdemCellStrainUpdater.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemJoint.hpp>
#include <pkg/rdem/RdemMat.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemPoissonEngine.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <pkg/rdem/math/BlockCells.hpp>
#include <pkg/rdem/math/Elasticity.hpp>
#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>

namespace yade {

namespace {
	const Real sameSideCos = 0.99; // two bond normals within ~8° point to the same side of a block

	Body::id_t next(const std::map<Body::id_t, vector<std::pair<Body::id_t, Vector3r>>>& nbr, Body::id_t b, const Vector3r& dir)
	{
		if (b < 0) return -1;
		const auto it = nbr.find(b);
		if (it == nbr.end()) return -1;
		for (const auto& nd : it->second)
			if (nd.second.dot(dir) > sameSideCos) return nd.first;
		return -1;
	}

	/// The block's axis closest to the global direction dir.
	int axisAlong(const Matrix3r& R, const Vector3r& dir)
	{
		int k = 0;
		for (int j = 1; j < 3; ++j)
			if (math::abs(R.col(j).dot(dir)) > math::abs(R.col(k).dot(dir))) k = j;
		return k;
	}

	/// Half-extent of block id along its body axis closest to dir [m].
	Real halfAlong(Scene* scene, Body::id_t id, const Vector3r& dir)
	{
		const Body& b = *Body::byId(id, scene);
		return static_cast<RdemBlock*>(b.shape.get())->extents[axisAlong(b.state->ori.toRotationMatrix(), dir)];
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
	Real dualExtent(Scene* scene, const std::map<Body::id_t, vector<std::pair<Body::id_t, Vector3r>>>& nbr, Body::id_t id, const Vector3r& t)
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

	/// The real bonds among ids, with their geometry and physics.
	template <class F> void forEachBond(Scene* scene, const std::set<Body::id_t>& ids, F f)
	{
		for (const auto& I : *scene->interactions) {
			if (!I->isReal()) continue;
			auto* g = dynamic_cast<RdemGeom*>(I->geom.get());
			auto* p = dynamic_cast<RdemPhys*>(I->phys.get());
			if (!g || !p || g->nSegments() == 0 || !ids.count(I->getId1()) || !ids.count(I->getId2())) continue;
			f(*I, *g, *p);
		}
	}
}

std::set<Body::id_t> RdemPoissonEngine::collectBlocks(const vector<Body::id_t>& idsIn) const
{
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
	return ids;
}

RdemPoissonEngine::Neighbours RdemPoissonEngine::bondedNeighbours(const std::set<Body::id_t>& ids) const
{
	Neighbours nbr; // per block: bonded block and the bond's unit normal (global) pointing to it
	forEachBond(scene, ids, [&](const Interaction& I, const RdemGeom& g, const RdemPhys&) {
		const Vector3r n = Body::byId(I.getId1(), scene)->state->ori * g.segNormal1;
		nbr[I.getId1()].push_back({ I.getId2(), n });
		nbr[I.getId2()].push_back({ I.getId1(), -n });
	});
	return nbr;
}

string RdemPoissonEngine::gridDefect(const Neighbours& nbr) const
{
	for (const auto& bn : nbr)
		for (size_t i = 0; i < bn.second.size(); ++i)
			for (size_t j = i + 1; j < bn.second.size(); ++j)
				if (bn.second[i].second.dot(bn.second[j].second) > sameSideCos) {
					std::ostringstream msg;
					msg << "block " << bn.first << " has two bonded neighbours on one side (blocks " << bn.second[i].first << " and "
					    << bn.second[j].first << ", e.g. running-bond masonry)";
					return msg.str();
				}
	return "";
}

void RdemPoissonEngine::build(const vector<Body::id_t>& idsIn)
{
	scene                                 = Omega::instance().getScene().get();
	const std::set<Body::id_t> ids        = collectBlocks(idsIn);
	const bool                 consistent = Ip2_RdemMat_RdemMat_RdemPhys::formulationOf(scene) == rdem::SpringModulus::Consistent;
	// The paper's springs E/(1-ν²) plus D_p are an indefinite tensor for ν > (3-√5)/2 ≈ 0.382 (doc/sphinx/rdemTheory.rst §5.3): an
	// explicit run would blow up, so refuse it with the way out.
	const Real nuPaperMax = (3 - math::sqrt(Real(5))) / 2;
	if (!consistent)
		for (Body::id_t id : ids) {
			const Real nu = static_cast<RdemMat*>(Body::byId(id, scene)->material.get())->poisson;
			if (nu > nuPaperMax)
				throw std::invalid_argument(
				        "RdemPoissonEngine.build: block " + std::to_string(id) + " has poisson = " + rdem::numberText(nu)
				        + ", above 0.382 where the paper formulation (springs E/(1-nu^2) plus D_p) is not positive definite and a run"
				          " blows up; use the consistent formulation, rdem.engines(formulation='consistent')");
		}
	const Neighbours nbr         = bondedNeighbours(ids);
	const string     defect      = gridDefect(nbr);
	const string     mixed       = materialMix(ids);
	const bool       totalStress = Law2_RdemGeom_RdemPhys_FaceSprings::totalStressOf(scene);
	/* 'auto': cells wherever the hexahedra would be wrong or refused. A hexahedron straddling two materials has one λ for
	   both (Backus 1962), which averages out the lateral push of a soft layer on a stiff one: a stack-bonded brick-mortar
	   prism of 20x20 blocks in plan then expands 44 % more than the layered medium (Backus's closed form), the cells are
	   within 1.7 % (tests/yade/test_prism.py). */
	string why;
	bool   cellsWanted = false;
	if (elements != "auto") {
		cellsWanted = elements == "cells";
		why         = "elements = '" + elements + "'";
	} else if (!defect.empty()) {
		cellsWanted = true;
		why         = defect + ": not a grid of 2x2x2 groups";
	} else if (consistent && !mixed.empty()) {
		cellsWanted = true;
		why         = mixed + ": the hexahedra would blend their lambda, the cells give each block its own";
	} else if (consistent && totalStress) {
		cellsWanted = true;
		why         = "Law2_RdemGeom_RdemPhys_FaceSprings.totalStress needs the Poisson stress of every face, which only the cells give";
	} else
		why = string("a grid of 2x2x2 groups") + (mixed.empty() ? " of one material" : " in the paper's formulation (" + mixed + ")");
	chosen = string(cellsWanted ? "cells" : "hex8") + ": " + why;
	if (!consistent && !cellsWanted && !mixed.empty())
		LOG_WARN(
		        "RdemPoissonEngine.build: " << mixed
		                                    << "; the paper's hexahedra blend their lambda where they straddle two materials, which "
		                                       "averages out the lateral push of a soft layer on a stiff one; the consistent formulation "
		                                       "gives every block its own lambda with Poisson cells");
	if (!cellsWanted && !defect.empty())
		throw std::invalid_argument(
		        "RdemPoissonEngine.build: " + defect
		        + "; the paper's hexahedra need a grid of 2x2x2 groups (one bonded neighbour per face). Poisson cells work on any layout: "
		          "elements='cells' (or 'auto') with the consistent formulation");
	if (!cellsWanted && totalStress)
		throw std::invalid_argument(
		        "RdemPoissonEngine.build: Law2_RdemGeom_RdemPhys_FaceSprings.totalStress needs the Poisson normal stress of every bond, "
		        "which the cells give and the paper's hexahedra do not: elements = 'cells'");
	if (cellsWanted && !consistent)
		throw std::invalid_argument(
		        "RdemPoissonEngine.build: " + (defect.empty() ? string("elements = 'cells'") : defect)
		        + "; Poisson cells, which work on any layout, belong to the consistent formulation (the paper's hexahedra need a grid of 2x2x2 "
		          "groups): "
		          "Ip2_RdemMat_RdemMat_RdemPhys.formulation = 'consistent', e.g. rdem.engines(formulation='consistent')");
	nodes.clear();
	refPos.clear();
	lambda.clear();
	skin.clear();
	clearCells(ids);
	if (cellsWanted) buildCells(ids);
	else
		buildHex8(ids, nbr, consistent);
	RdemCellNetwork::generation++;
	scalePrev.clear(); // the first step takes the current scales
	prepare();
	if (elements == "auto" && cellsWanted && defect.empty()) {
		LOG_WARN("RdemPoissonEngine.build: Poisson cells (elements='auto'): " << why);
	} else {
		LOG_INFO("RdemPoissonEngine.build: " << chosen);
	}
}

string RdemPoissonEngine::materialMix(const std::set<Body::id_t>& ids) const
{
	// Materials count by their elastic constants: two RdemMat of the same E and ν (a platen of the specimen's) are one.
	std::map<std::pair<Real, Real>, std::set<string>> labels; // per (E, ν): the labels (or #index) of its RdemMat
	for (Body::id_t id : ids) {
		const auto& m = *static_cast<RdemMat*>(Body::byId(id, scene)->material.get());
		labels[{ m.young, m.poisson }].insert(m.label.empty() ? "#" + std::to_string(m.id) : m.label);
	}
	if (labels.size() < 2) return "";
	std::ostringstream msg;
	msg << "blocks of " << labels.size() << " materials (";
	for (auto it = labels.begin(); it != labels.end(); ++it) {
		msg << (it == labels.begin() ? "" : "; ") << "E " << double(it->first.first) << " Pa, nu " << double(it->first.second) << ":";
		for (const string& l : it->second)
			msg << " " << l;
	}
	msg << ")";
	return msg.str();
}

void RdemPoissonEngine::buildPy(const py::list& ids)
{
	vector<Body::id_t> v;
	for (long i = 0; i < py::len(ids); ++i)
		v.push_back(py::extract<Body::id_t>(ids[i]));
	build(v);
}

void RdemPoissonEngine::buildHex8(const std::set<Body::id_t>& ids, const Neighbours& nbr, bool consistent)
{
	std::set<std::array<Body::id_t, 8>> seen;
	int                                 incomplete = 0;
	for (Body::id_t b : ids) {
		const Matrix3r                R = Body::byId(b, scene)->state->ori.toRotationMatrix();
		const std::array<Vector3r, 3> e { R.col(0), R.col(1), R.col(2) };
		std::array<Body::id_t, 8>     n;
		n[0] = b;
		n[1] = next(nbr, b, e[0]);
		n[2] = next(nbr, b, e[1]);
		n[4] = next(nbr, b, e[2]);
		if (n[1] < 0 || n[2] < 0 || n[4] < 0) continue; // b is not the (-,-,-) corner of a group
		n[3] = next(nbr, n[1], e[1]);
		n[5] = next(nbr, n[1], e[2]);
		n[6] = next(nbr, n[2], e[2]);
		n[7] = next(nbr, n[3], e[2]);
		// Every one of the 12 edges must be a bond between the nodes found above.
		bool complete = true;
		for (const auto& edge : rdem::hex8Edges) {
			const Body::id_t a = n[size_t(edge[0])], c = n[size_t(edge[1])];
			if (a < 0 || c < 0) {
				complete = false;
				continue;
			}
			const int        bit   = edge[0] ^ edge[1]; // 1, 2 or 4: the axis along which the edge runs
			const Body::id_t found = next(nbr, a, e[bit == 1 ? 0 : (bit == 2 ? 1 : 2)]);
			if (found < 0) complete = false;
			else if (found != c) {
				std::ostringstream msg;
				msg << "RdemPoissonEngine.build: blocks around block " << b << " do not close into a 2x2x2 group (block " << a
				    << " is bonded to " << found << " where the grid expects " << c << ")";
				throw std::invalid_argument(msg.str());
			}
		}
		if (!complete) {
			++incomplete;
			continue;
		}
		std::array<Body::id_t, 8> key = n;
		std::sort(key.begin(), key.end());
		if (seen.insert(key).second) addHex8Element(n, nbr, consistent);
	}
	if (nodes.empty())
		throw std::invalid_argument(
		        "RdemPoissonEngine.build: no 2x2x2 group of bonded blocks among the " + std::to_string(ids.size())
		        + " blocks given (bond them first, e.g. with rdem.bond; for other layouts use Poisson cells, elements='cells', with the consistent "
		          "formulation)");
	setHex8SpringWeights(ids, nbr, consistent);
	LOG_INFO(nElements() << " Poisson elements on " << ids.size() << " blocks (" << incomplete << " groups skipped: a bond missing)");
}

void RdemPoissonEngine::addHex8Element(const std::array<Body::id_t, 8>& n, const Neighbours& nbr, bool consistent)
{
	rdem::Nodes8<Real>                 X;
	std::array<std::array<Real, 3>, 8> parts; // volume, E, ν of each node's block
	for (size_t a = 0; a < 8; ++a) {
		const Body& body = *Body::byId(n[a], scene);
		X[a]             = body.state->pos;
		const auto& m    = *static_cast<RdemMat*>(body.material.get());
		parts[a]         = { 8 * static_cast<RdemBlock*>(body.shape.get())->extents.prod(), m.young, m.poisson };
	}
	if (!rdem::hex8IsValid<Real>(X)) {
		std::ostringstream msg;
		msg << "RdemPoissonEngine.build: the centroids of blocks " << n[0] << "," << n[1] << ",...," << n[7] << " form an inverted or flat hexahedron";
		throw std::invalid_argument(msg.str());
	}
	for (size_t a = 0; a < 8; ++a) {
		nodes.push_back(n[a]);
		refPos.push_back(X[a]);
	}
	lambda.push_back(rdem::layeredLambda<Real>(parts));
	// Skin of the consistent formulation: a side whose four blocks have no neighbour further out and are free along that
	// axis carries a slab as thick as those blocks' half-extent, in units of half the element length.
	const Matrix3r R = Body::byId(n[0], scene)->state->ori.toRotationMatrix();
	for (int d = 0; d < 3; ++d) {
		const Vector3r ed = R.col(d);
		for (int side = 0; side < 2; ++side) {
			const Real sgn   = side ? 1 : -1;
			bool       outer = consistent;
			Real       ell = 0, halfLength = 0;
			for (size_t a = 0; a < 8 && outer; ++a) {
				if (((a >> d) & 1) != size_t(side)) continue;
				outer = next(nbr, n[a], sgn * ed) < 0 && !prescribed(scene, n[a], ed);
				ell += halfAlong(scene, n[a], ed) / 4;
				halfLength += math::abs((X[a ^ (size_t(1) << d)] - X[a]).dot(ed)) / 8;
			}
			skin.push_back(outer ? ell / halfLength : Real(0));
		}
	}
}

void RdemPoissonEngine::setHex8SpringWeights(const std::set<Body::id_t>& ids, const Neighbours& nbr, bool consistent)
{
	// Spring weights of the consistent formulation (doc/sphinx/rdemTheory.rst §5.2); 1 in the paper's.
	forEachBond(scene, ids, [&](const Interaction& I, const RdemGeom& g, RdemPhys& p) {
		p.weightNormal = p.weightShear = 1;
		if (!consistent) return;
		const Body::id_t a = I.getId1(), b = I.getId2();
		const Matrix3r   Ra    = Body::byId(a, scene)->state->ori.toRotationMatrix();
		const Vector3r   nrm   = Ra * g.segNormal1;
		const Real       L     = (Body::byId(b, scene)->state->pos - Body::byId(a, scene)->state->pos).dot(nrm);
		const Real       extA  = (next(nbr, a, -nrm) < 0 && !prescribed(scene, a, nrm)) ? halfAlong(scene, a, nrm) : Real(0);
		const Real       extB  = (next(nbr, b, nrm) < 0 && !prescribed(scene, b, nrm)) ? halfAlong(scene, b, nrm) : Real(0);
		Real             cross = 1;
		for (int k = 0; k < 3; ++k) {
			const Vector3r t = Ra.col(k);
			if (math::abs(t.dot(nrm)) > sameSideCos) continue;
			cross *= (dualExtent(scene, nbr, a, t) / (2 * halfAlong(scene, a, t)) + dualExtent(scene, nbr, b, t) / (2 * halfAlong(scene, b, t)))
			        / 2;
		}
		p.weightNormal = (L + extA + extB) / L * cross;
		p.weightShear  = cross;
	});
}

void RdemPoissonEngine::clearCells(const std::set<Body::id_t>& ids)
{
	for (Body::id_t id : ids)
		if (auto* st = dynamic_cast<RdemState*>(Body::byId(id, scene)->state.get())) {
			st->cellVolume = 0;
			st->cellStiffness.setZero();
			st->cellCondensation.setZero();
			st->strain.setZero();
			st->cellScale = 1;
		}
	forEachBond(scene, ids, [](const Interaction&, const RdemGeom&, RdemPhys& p) {
		p.cellCoef1 = p.cellCoef2 = 0;
		p.offsetCorrection        = false;
		p.weightNormal = p.weightShear = 1;
	});
}

void RdemPoissonEngine::buildCells(const std::set<Body::id_t>& ids)
{
	const long updater = rdem::engineIndex<RdemCellStrainUpdater>(scene), loop = rdem::engineIndex<InteractionLoop>(scene);
	if (updater < 0 || (loop >= 0 && updater > loop))
		throw std::invalid_argument("RdemPoissonEngine.build: Poisson cells need an RdemCellStrainUpdater before the InteractionLoop in O.engines "
		                            "(rdem.engines(formulation='consistent') places it)");
	for (Body::id_t id : ids)
		if (!dynamic_cast<RdemState*>(Body::byId(id, scene)->state.get()))
			throw std::invalid_argument(
			        "RdemPoissonEngine.build: block " + std::to_string(id)
			        + " has no RdemState; make blocks with rdem.block, or give them RdemMat.newAssocState() as state");
	// Every bond seen from each of its blocks (rdem::CellBond): axis, side, area, the block's share of the opening
	// (series compliances with the joint, eq. 12), centroid distance.
	struct Side {
		RdemPhys*  phys;
		Body::id_t body;
		size_t     index; // in its block's input
	};
	std::map<Body::id_t, rdem::CellInput<Real>> input;
	vector<Side>                                sides;
	forEachBond(scene, ids, [&](const Interaction& I, const RdemGeom& g, RdemPhys& p) {
		const auto&    ma   = *static_cast<RdemMat*>(Body::byId(I.getId1(), scene)->material.get());
		const auto&    mb   = *static_cast<RdemMat*>(Body::byId(I.getId2(), scene)->material.get());
		const Vector2r C    = Ip2_RdemMat_RdemMat_RdemPhys::normalCompliances(ma, mb, g, rdem::SpringModulus::Consistent); // the share of each side
		const Real     area = g.segmentArea() * Real(g.nSegments());
		for (int k = 0; k < 2; ++k) {
			const Body::id_t id     = k ? I.getId2() : I.getId1();
			const Vector3r&  normal = k ? g.segNormal2 : g.segNormal1;
			const int        axis   = rdem::dominantAxis<Real>(normal);
			auto&            in     = input[id];
			in.bonds.push_back({ axis, normal[axis] > 0 ? 1 : -1, area, C[k] / C.sum(), g.ell1 + g.ell2 });
			sides.push_back({ &p, id, in.bonds.size() - 1 });
		}
		// The shear springs need the offset correction where the centroids are offset along the face (body 1's frame).
		const State& s1    = *Body::byId(I.getId1(), scene)->state;
		const auto   delta = rdem::alongFace<Real>(s1.ori.conjugate() * (Body::byId(I.getId2(), scene)->state->pos - s1.pos), g.segNormal1);
		p.offsetCorrection = delta.norm() > 1e-9 * math::min(g.ell1, g.ell2);
	});
	std::map<Body::id_t, rdem::Cell<Real>> cell;
	for (auto& in : input) {
		const Body&    b   = *Body::byId(in.first, scene);
		const auto&    mat = *static_cast<RdemMat*>(b.material.get());
		const Matrix3r R   = b.state->ori.toRotationMatrix();
		in.second.half     = static_cast<RdemBlock*>(b.shape.get())->extents;
		in.second.young    = mat.young;
		in.second.poisson  = mat.poisson;
		for (int d = 0; d < 3; ++d)
			in.second.prescribed[size_t(d)] = prescribed(scene, in.first, R.col(d));
		const rdem::Cell<Real> c  = rdem::blockCell<Real>(in.second);
		auto&                  st = *static_cast<RdemState*>(b.state.get());
		st.cellVolume             = c.volume;
		st.cellStiffness          = c.stiffness;
		st.cellCondensation       = c.condensation;
		cell.emplace(in.first, c);
	}
	// Coefficients and spring weights of every bond, from the cells of its two blocks (sides come in pairs: body 1, body 2).
	for (size_t k = 0; k + 1 < sides.size(); k += 2) {
		const Side&             s1 = sides[k];
		const Side&             s2 = sides[k + 1];
		const rdem::Cell<Real>& c1 = cell.at(s1.body);
		const rdem::Cell<Real>& c2 = cell.at(s2.body);
		const auto&             b1 = input.at(s1.body).bonds[s1.index];
		const auto&             b2 = input.at(s2.body).bonds[s2.index];
		RdemPhys&               p  = *s1.phys;
		p.cellCoef1                = c1.coef[s1.index];
		p.cellCoef2                = c2.coef[s2.index];
		const Real lat1 = c1.lateral[size_t(b1.axis)], lat2 = c2.lateral[size_t(b2.axis)];
		p.weightNormal = rdem::cellBondWeightNormal(lat1, lat2, c1.extraWeight[s1.index], c2.extraWeight[s2.index]);
		p.weightShear  = math::min(lat1, lat2);
	}
	LOG_INFO(cell.size() << " Poisson cells on " << ids.size() << " blocks");
}

} // namespace yade
