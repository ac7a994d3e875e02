/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <lib/pyutil/gil.hpp>
#include <pkg/rdem/InertialMass.hpp>
#include <pkg/rdem/OpenMPLoops.hpp>
#include <pkg/rdem/RdemCellNetwork.hpp>
#include <pkg/rdem/RdemForceAssembler.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemRanks.hpp>
#include <pkg/rdem/math/BlockCells.hpp>
#include <pkg/rdem/math/ContactBound.hpp>
#include <pkg/rdem/math/DensityScaling.hpp>
#include <pkg/rdem/math/GroupByKey.hpp>
#include <algorithm>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace yade {

long RdemCellNetwork::generation = 0;

namespace {
	void releaseBonds(vector<shared_ptr<Interaction>>& intr, vector<shared_ptr<IPhys>>& phys)
	{
		// The bonds of erased bodies (O.bodies.erase, or yade.mpy's erasure of other subdomains' bodies) live on here until
		// this rebuild, in the simulation's thread. What they hold may come from Python (an RdemJoint made in a script, held
		// through boost.python's deleter), and releasing that needs the GIL, which this thread does not hold.
		const bool last = std::any_of(intr.begin(), intr.end(), [](const shared_ptr<Interaction>& I) { return I.use_count() == 1; })
		        || std::any_of(phys.begin(), phys.end(), [](const shared_ptr<IPhys>& P) { return P.use_count() == 1; });
		std::optional<gilLock> lock;
		if (last) lock.emplace();
		intr.clear();
		phys.clear();
	}
}

bool RdemCellNetwork::refresh(Scene* scene)
{
	// A scene without cells (the paper's hexahedra, or no build) stays without them until the next build: its
	// interactions, which come and go at nearly every step once contacts form, are then never scanned.
	if (builtGeneration == generation && nCellBlocks == 0) return false;
	const long nB = long(scene->bodies->size()), nI = long(scene->interactions->size());
	/* The network holds the real bonds with cell coefficients, which only RdemPoissonEngine.build gives (a bond made
	   later by utils.createInteraction has none until the next build). It is made again when the bodies change, and,
	   when the container's size changed (the collider's insertions and erasures of contacts change it at nearly every
	   step), if a bond left the container without being released (O.interactions.erase, the erasure of a body), or once
	   the bonds the law released are a quarter of the network's and their cells have seen them. A released bond stays
	   until then with intact fraction 0 (updateIntact), so that it releases the cells of both its blocks (their crack
	   scale drops to 0, and applyForces books the energy) in the step after its release, as a bond whose springs broke
	   one by one does; its terms are zero from then on, and a release costs no rebuild (a cracking building releases
	   bonds at nearly every step). The container keeps the order of the interactions it does not erase, but for the
	   last one, which takes an erased one's place. */
	if (builtGeneration != generation || builtBodies != nB) rebuild(scene);
	else if (seenInteractions != nI) {
		const BondCensus census = bondCensus(scene);
		if (census.erased || (!census.unseen && 4 * census.released > bond.size())) rebuild(scene);
		seenInteractions = nI;
	}
	return nCellBlocks > 0;
}

bool RdemCellNetwork::released(size_t k) const
{
	// reset (then maybe a contact) with every spring broken: the law released it; with springs intact, it was erased
	const Interaction& I    = *intr[k];
	const bool         gone = !I.isReal() || !static_cast<const RdemGeom*>(I.geom.get())->bonded;
	return gone && static_cast<const RdemPhys*>(phys[k].get())->nIntact() == 0;
}

bool RdemCellNetwork::cellsReleased(size_t k) const
{
	const Bond& b    = bond[k];
	const auto  done = [&](size_t i, Real c) { return c == 0 || !hasCell[i] || state[i]->cellScale == 0; };
	return done(b.i1, b.c1) && done(b.i2, b.c2);
}

RdemCellNetwork::BondCensus RdemCellNetwork::bondCensus(Scene* scene) const
{
	// InteractionContainer::erase moves the last interaction into the erased one's place and leaves the erased one's linIx
	auto&      c = *scene->interactions;
	const long n = long(c.size());
	BondCensus census;
	for (size_t k = 0; k < intr.size(); ++k) {
		const shared_ptr<Interaction>& I = intr[k];
		if (released(k)) {
			if (cellsReleased(k)) census.released += 1;
			else
				census.unseen = true;
		} else if (!I->isReal() || !(I->linIx >= 0 && I->linIx < n && c[size_t(I->linIx)] == I))
			census.erased = true;
	}
	return census;
}

void RdemCellNetwork::rebuild(Scene* scene)
{
	++nRebuilds;
	/* Bonds released whose cells have not dropped yet (updateStrains has not run since) release the cells of both
	   blocks now, as updateStrains would have done, unless a new build defines the cells afresh. */
	vector<Body::id_t> releasedCells;
	if (builtGeneration == generation)
		for (size_t k = 0; k < bond.size(); ++k)
			if (released(k) && !cellsReleased(k)) {
				if (bond[k].c1 != 0) releasedCells.push_back(body[bond[k].i1]);
				if (bond[k].c2 != 0) releasedCells.push_back(body[bond[k].i2]);
			}
	releaseBonds(intr, phys);
	bond.clear();
	body.clear();
	state.clear();
	hasCell.clear();
	std::unordered_map<Body::id_t, size_t> compact;
	auto                                   indexOf = [&](Body::id_t id) {
                const auto it = compact.find(id);
                if (it != compact.end()) return it->second;
                auto* st = static_cast<RdemState*>(Body::byId(id, scene)->state.get());
                compact.emplace(id, body.size());
                body.push_back(id);
                state.push_back(st);
                hasCell.push_back(st->cellVolume > 0);
                return body.size() - 1;
	};
	vector<size_t> blockOfSide;
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		const auto* p = dynamic_cast<const RdemPhys*>(I->phys.get());
		const auto* g = dynamic_cast<const RdemGeom*>(I->geom.get());
		if (!p || !g || !g->bonded || (p->cellCoef1 == 0 && p->cellCoef2 == 0)) continue;
		Bond b { indexOf(I->getId1()),
			 indexOf(I->getId2()),
			 rdem::dominantAxis<Real>(g->segNormal1),
			 rdem::dominantAxis<Real>(g->segNormal2),
			 p->cellCoef1,
			 p->cellCoef2,
			 g->segNormal1,
			 g->segNormal2,
			 g->faceCentre1,
			 g->faceCentre2 };
		bond.push_back(b);
		intr.push_back(I);
		phys.push_back(I->phys);
		blockOfSide.push_back(b.i1);
		blockOfSide.push_back(b.i2);
	}
	vector<size_t> order;
	rdem::groupByKey(blockOfSide, body.size(), first, order);
	/* Each block's sides in the order of the other block's id, not of the interaction container: every sum over a block's
	   bonds then has the same order whatever the container's history (the collider's insertions and erasures reorder it,
	   and so does a rank of YADE's MPI, which holds only some of the bodies), as RdemForceAssembler does for the springs. */
	const auto otherId = [&](size_t side) { return body[side % 2 ? bond[side / 2].i1 : bond[side / 2].i2]; };
	for (size_t i = 0; i + 1 < first.size(); ++i)
		std::sort(order.begin() + long(first[i]), order.begin() + long(first[i + 1]), [&](size_t x, size_t y) { return otherId(x) < otherId(y); });
	sideBond.resize(order.size());
	sideSecond.resize(order.size());
	sideOffset.resize(order.size());
	for (size_t k = 0; k < order.size(); ++k) {
		sideBond[k]   = order[k] / 2;
		sideSecond[k] = order[k] % 2;
		sideOffset[k] = static_cast<const RdemPhys*>(intr[sideBond[k]]->phys.get())->offsetCorrection;
	}
	nCellBlocks = size_t(std::count(hasCell.begin(), hasCell.end(), char(1)));
	opening.assign(bond.size(), 0);
	normal.assign(bond.size(), Vector3r::Zero());
	arm1.assign(bond.size(), Vector3r::Zero());
	arm2.assign(bond.size(), Vector3r::Zero());
	stiffness.resize(body.size());
	condensation.resize(body.size());
	for (size_t i = 0; i < body.size(); ++i) {
		stiffness[i]    = state[i]->cellStiffness;
		condensation[i] = state[i]->cellCondensation;
	}
	intact.assign(bond.size(), 1);
	rot.assign(body.size(), Matrix3r::Identity());
	pos.assign(body.size(), Vector3r::Zero());
	stress.assign(body.size(), Vector3r::Zero());
	elastic.assign(body.size(), Vector3r::Zero());
	booksEnergy.assign(body.size(), 0);
	scalePrev.assign(body.size(), 1);
	for (size_t i = 0; i < body.size(); ++i)
		scalePrev[i] = state[i]->cellScale;
	for (Body::id_t id : releasedCells) { // after scalePrev: applyForces books the energy the drop releases
		const auto it = compact.find(id);
		if (it != compact.end()) state[it->second]->cellScale = 0;
		else if (const auto& b = Body::byId(id, scene)) // left the network with its last bond (its cell's energy unbooked)
			static_cast<RdemState*>(b->state.get())->cellScale = 0;
	}
	builtGeneration  = generation;
	builtBodies      = long(scene->bodies->size());
	seenInteractions = long(scene->interactions->size());
	brokenSeen       = -1;
}

void RdemCellNetwork::updateIntact(long brokenSprings)
{
	// Intact fractions change only when a spring breaks or a bond is released: recompute them only then.
	if (brokenSprings == brokenSeen) return;
	brokenSeen = brokenSprings;
	for (size_t k = 0; k < bond.size(); ++k) {
		const auto& p = *static_cast<const RdemPhys*>(phys[k].get()); // also of a released bond: 0 for good
		intact[k]     = Real(p.nIntact()) / Real(p.segState.size());
	}
}

void RdemCellNetwork::updateStrains(Scene* scene, long brokenSprings, int threads)
{
	if (!refresh(scene)) return;
	updateIntact(brokenSprings);
	const long nBlocks = long(body.size()), nBonds = long(bond.size());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(threads))
#endif
	for (long i = 0; i < nBlocks; ++i) {
		rot[size_t(i)] = state[size_t(i)]->ori.toRotationMatrix();
		pos[size_t(i)] = state[size_t(i)]->pos;
	}
	/* Openings at the face centres: u_n = n·d0, d0 = P₂ - P₁ of the centre (rdem::BondKinematics at s = r = 0), along
	   body 1's rotated face normal n = R₁n₁ (the law's mean of both blocks' normals differs from it at second order in
	   their relative rotation, which the opening multiplies); and the moments about both centroids of a unit normal
	   force at the face centre, for applyForces. */
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(threads))
#endif
	for (long k = 0; k < nBonds; ++k) {
		const Bond&     b  = bond[size_t(k)];
		const Matrix3r &R1 = rot[b.i1], &R2 = rot[b.i2];
		const Vector3r  n  = R1 * b.n1;
		const Vector3r  r1 = R1 * b.fc1, r2 = R2 * b.fc2;
		normal[size_t(k)]  = n;
		opening[size_t(k)] = n.dot(pos[b.i2] + r2 - pos[b.i1] - r1);
		arm1[size_t(k)]    = r1.cross(n);
		arm2[size_t(k)]    = r2.cross(n);
	}
	// Per cell: ε_d = Σ c_q u_n,q over its bonds along d, completed by the condensation; the crack scale never increases.
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(threads))
#endif
	for (long i = 0; i < nBlocks; ++i) {
		if (!hasCell[size_t(i)]) continue;
		RdemState& st    = *state[size_t(i)];
		Vector3r   eps   = Vector3r::Zero();
		Real       scale = st.cellScale;
		for (size_t j = first[size_t(i)]; j < first[size_t(i) + 1]; ++j) {
			const Bond& b = bond[sideBond[j]];
			const Real  c = sideSecond[j] ? b.c2 : b.c1;
			if (c == 0) continue; // a sliver on a condensed axis (rdem::cellMinBondedFraction): not part of this cell
			eps[sideSecond[j] ? b.ax2 : b.ax1] += c * opening[sideBond[j]];
			scale = math::min(scale, intact[sideBond[j]]);
		}
		setStrain(size_t(i), eps, scale);
	}
}

void RdemCellNetwork::setStrain(size_t i, const Vector3r& eps, Real scale)
{
	RdemState& st = *state[i];
	st.strain     = condensation[i] * eps;
	st.cellScale  = scale;
	st.cellStress = scale * (stiffness[i] * st.strain);
}

namespace {
	/// The rows of a table gathered over the ranks (`width` reals per row: a cell's id, the other block's id, then its
	/// terms) in the order of (cell, other block): the order in which one rank sums a cell's bonds.
	vector<size_t> rowsByCellAndBlock(const vector<Real>& all, size_t width)
	{
		vector<size_t> row(all.size() / width);
		std::iota(row.begin(), row.end(), size_t(0));
		std::sort(row.begin(), row.end(), [&](size_t x, size_t y) {
			return std::make_pair(all[x * width], all[x * width + 1]) < std::make_pair(all[y * width], all[y * width + 1]);
		});
		return row;
	}
}

long RdemCellNetwork::reduceMasterStrains(Scene* scene)
{
	/* The terms updateStrains sums for a cell on the master, of the bonds to this rank's own blocks (each bond is on the
	   rank of its other block, and also on ranks that hold that block as a ghost, which do not send it): the cell's
	   id, the other block's id, the axis, c, u_n, the intact fraction, this rank. */
	constexpr size_t width = 7;
	vector<Real>     mine;
	for (size_t i = 0; i < body.size(); ++i) {
		if (!hasCell[i] || !rdem::onMaster(*scene, *Body::byId(body[i], scene))) continue;
		for (size_t j = first[i]; j < first[i + 1]; ++j) {
			const Bond&  b     = bond[sideBond[j]];
			const size_t other = sideSecond[j] ? b.i1 : b.i2;
			const Real   c     = sideSecond[j] ? b.c2 : b.c1;
			if (c == 0 || rdem::notOwned(*scene, *Body::byId(body[other], scene))) continue;
			mine.insert(
			        mine.end(),
			        { Real(body[i]),
			          Real(body[other]),
			          Real(sideSecond[j] ? b.ax2 : b.ax1),
			          c,
			          opening[sideBond[j]],
			          intact[sideBond[j]],
			          Real(rdem::rank(*scene)) });
		}
	}
	const vector<Real> all = rdem::gatherOverRanks(*scene, mine);
	// each cell's terms in the order of the other block's id, as updateStrains sums them on one rank
	const vector<size_t>                   term = rowsByCellAndBlock(all, width);
	const auto                             at   = [&all](size_t t, size_t k) { return all[t * width + k]; };
	std::unordered_map<Body::id_t, size_t> compact;
	for (size_t i = 0; i < body.size(); ++i)
		if (hasCell[i] && rdem::onMaster(*scene, *Body::byId(body[i], scene))) compact.emplace(body[i], i);
	for (size_t t = 0; t < term.size();) {
		const auto cell   = Body::id_t(at(term[t], 0));
		const auto it     = compact.find(cell);
		Vector3r   eps    = Vector3r::Zero();
		Real       scale  = it != compact.end() ? state[it->second]->cellScale : Real(1); // lowered by this rank's part already: min is idempotent
		Real       booker = std::numeric_limits<Real>::max();
		for (; t < term.size() && Body::id_t(at(term[t], 0)) == cell; ++t) {
			eps[int(at(term[t], 2))] += at(term[t], 3) * at(term[t], 4);
			scale  = math::min(scale, at(term[t], 5));
			booker = math::min(booker, at(term[t], 6));
		}
		if (it == compact.end()) continue; // a cell this rank does not hold
		setStrain(it->second, eps, scale);
		booksEnergy[it->second] = booker == Real(rdem::rank(*scene)); // the lowest rank with a part of its bonds
	}
	return long(mine.size() * sizeof(Real));
}

long RdemCellNetwork::reduceMasterStresses(Scene* scene)
{
	// the offset corrections' gradients of the bonds of cells on the master to this rank's own blocks: cell, other block, g
	constexpr size_t width = 5;
	vector<Real>     mine;
	for (size_t i = 0; i < body.size(); ++i) {
		if (!hasCell[i] || !rdem::onMaster(*scene, *Body::byId(body[i], scene))) continue;
		for (size_t j = first[i]; j < first[i + 1]; ++j) {
			if (!sideOffset[j] || intact[sideBond[j]] == 0) continue;
			const Bond&  b     = bond[sideBond[j]];
			const size_t other = sideSecond[j] ? b.i1 : b.i2;
			if (rdem::notOwned(*scene, *Body::byId(body[other], scene))) continue;
			const auto&     p = *static_cast<const RdemPhys*>(phys[sideBond[j]].get());
			const Vector3r& g = sideSecond[j] ? p.offsetGrad2 : p.offsetGrad1;
			mine.insert(mine.end(), { Real(body[i]), Real(body[other]), g[0], g[1], g[2] });
		}
	}
	const vector<Real>   all  = rdem::gatherOverRanks(*scene, mine);
	const vector<size_t> term = rowsByCellAndBlock(all, width);
	const auto           at   = [&all](size_t t, size_t k) { return all[t * width + k]; };
	for (size_t i = 0; i < body.size(); ++i) {
		if (!hasCell[i] || !rdem::onMaster(*scene, *Body::byId(body[i], scene))) continue;
		// the cell's terms (a binary search on the sorted ids), summed as applyForces sums them on one rank
		const Real id = Real(body[i]);
		auto       t  = std::lower_bound(term.begin(), term.end(), id, [&](size_t x, Real v) { return at(x, 0) < v; });
		Vector3r   g  = Vector3r::Zero();
		for (; t != term.end() && at(*t, 0) == id; ++t)
			g += Vector3r(at(*t, 2), at(*t, 3), at(*t, 4));
		stress[i] = fullStress(elastic[i], condensation[i], g);
	}
	return long(mine.size() * sizeof(Real));
}

void RdemCellNetwork::applyForces(Scene* scene, bool releaseOnCrack, Real& energy, Real& released, int threads, const StressSync& sync)
{
	if (!refresh(scene)) {
		if (sync) { // the sync is collective on YADE's MPI: a rank without cells takes part with none
			vector<Vector3r> none;
			sync(vector<Body::id_t>(), none);
		}
		return;
	}
	const long nBlocks     = long(body.size());
	const bool trackEnergy = scene->trackEnergy;
	Real       e = 0, rel = 0;
	/* 1. Per cell: ∂W/∂ε = s K ε (K = V(D - M I), RdemState::cellStiffness) plus the reaction of the offset correction
	      of its bonds' shear springs (RdemPhys::offsetGrad, written by the law), mapped to the axes with bonds by the
	      condensation (RdemState::cellCondensation). */
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) reduction(realSum : e, rel) num_threads(rdem::threadsFor(threads))
#endif
	for (long i = 0; i < nBlocks; ++i) {
		if (!hasCell[size_t(i)]) {
			stress[size_t(i)] = Vector3r::Zero();
			continue;
		}
		const RdemState& st   = *state[size_t(i)];
		const Real       s    = releaseOnCrack ? st.cellScale : Real(1);
		const Vector3r   Ke   = stiffness[size_t(i)] * st.strain;
		Vector3r         grad = Vector3r::Zero();
		for (size_t j = first[size_t(i)]; j < first[size_t(i) + 1]; ++j) {
			// a released bond has intact 0 (and a fully broken one no intact shear spring: its gradients are zero)
			if (!sideOffset[j] || intact[sideBond[j]] == 0) continue;
			const auto& p = *static_cast<const RdemPhys*>(phys[sideBond[j]].get());
			grad += sideSecond[j] ? p.offsetGrad2 : p.offsetGrad1;
		}
		elastic[size_t(i)] = s * Ke;
		stress[size_t(i)]  = fullStress(elastic[size_t(i)], condensation[size_t(i)], grad);
		// a ghost's cell: its owner's energy; a cell on the master (YADE's MPI): one rank's with a part of its bonds
		const auto books = [&]() {
			const Body& bi = *Body::byId(body[size_t(i)], scene);
			return rdem::onMaster(*scene, bi) ? booksEnergy[size_t(i)] != 0 : !rdem::isGhost(*scene, bi);
		};
		if (trackEnergy && books()) {
			e += s * st.strain.dot(Ke) / 2;
			rel += (scalePrev[size_t(i)] - s) * st.strain.dot(Ke) / 2;
		}
		scalePrev[size_t(i)] = s;
	}
	energy += e;
	released += rel;
	if (sync) sync(body, stress); // YADE's MPI: the ghosts' from their owners
	/* 2. Per block: the normal force -∂W/∂u_n = -(c₁∂W/∂ε₁ + c₂∂W/∂ε₂) of each of its bonds, on body 2 along the bond's
	      normal and on body 1 against it, at the face centre; summed block by block in the fixed order of the lists. */
	RdemForceAssembler::prepareDirectSums(scene, long(scene->bodies->size()));
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static) num_threads(rdem::threadsFor(threads))
#endif
	for (long i = 0; i < nBlocks; ++i) {
		if (first[size_t(i)] == first[size_t(i) + 1]) continue;
		Vector3r f = Vector3r::Zero(), t = Vector3r::Zero();
		for (size_t j = first[size_t(i)]; j < first[size_t(i) + 1]; ++j) {
			const size_t k = sideBond[j];
			if (intact[k] == 0 && !intr[k]->isReal()) continue; // released
			const Bond& b  = bond[k];
			const Real  F  = -(b.c1 * stress[b.i1][b.ax1] + b.c2 * stress[b.i2][b.ax2]);
			const Real  Fb = sideSecond[j] ? F : -F; // along the normal, on this block
			f += Fb * normal[k];
			t += Fb * (sideSecond[j] ? arm2[k] : arm1[k]);
		}
		scene->forces.addForceUnsynced(body[size_t(i)], f);
		scene->forces.addTorqueUnsynced(body[size_t(i)], t);
	}
}

Real RdemCellNetwork::offsetShearStiffness(size_t k) const
{
	const auto& p = *static_cast<const RdemPhys*>(phys[k].get());
	if (!p.offsetCorrection || intact[k] == 0 || !intr[k]->isReal()) return 0;
	const auto& g = *static_cast<const RdemGeom*>(intr[k]->geom.get());
	return intact[k] * Real(g.nSegments()) * p.weightShear * p.ks * g.segmentArea();
}

vector<Real> RdemCellNetwork::omega2Bound(Scene* scene)
{
	/* The cells' stiffness on the bond openings is K_qr = Σ_b s_b c_bq K_b(d_q, d_r) c_br over the cells b the two bonds
	   share. Each bond q is bounded like a normal spring of stiffness κ_q = Σ_r |K_qr| at its face centre, with the
	   Gershgorin terms 2κ(1/m + |r×n|²/I_min) of each of its free blocks (as RdemTimeStepper does for springs) [1/s²]. */
	vector<Real> w2(scene->bodies->size(), 0);
	if (!refresh(scene)) return w2;
	vector<Vector3r> row(body.size(), Vector3r::Zero()); // per cell and axis d: Σ_r |K(d, d_r)| |c_r|
	for (size_t i = 0; i < body.size(); ++i) {
		if (!hasCell[i]) continue;
		const RdemState& st = *state[i];
		for (size_t j = first[i]; j < first[i + 1]; ++j) {
			const Bond& b = bond[sideBond[j]];
			const int   a = sideSecond[j] ? b.ax2 : b.ax1;
			const Real  c = math::abs(sideSecond[j] ? b.c2 : b.c1);
			for (int d = 0; d < 3; ++d)
				row[i][d] += math::abs(st.cellStiffness(d, a)) * c;
		}
		row[i] *= st.cellScale;
	}
	/* The offset correction of the intact shear springs (addStiffness), bounded by -k(Pd)·(Pc) + ½k|Pc|² ≤ ½k|Pd|² + k|Pc|²
	   and |Pc|² ≤ 2|s₁a₁∘ε₁|² + 2|s₂a₂∘ε₂|²: a shear spring k at the face centre, and on each cell the diagonal stiffness
	   4k s²(a∘a) on its strains. */
	vector<Vector3r> offsetDiag(body.size(), Vector3r::Zero());
	for (size_t k = 0; k < bond.size(); ++k) {
		const Real kShear = offsetShearStiffness(k);
		if (kShear == 0) continue;
		const Bond& b = bond[k];
		for (int side = 0; side < 2; ++side) {
			const size_t i = side ? b.i2 : b.i1;
			const Real   s = state[i]->cellScale;
			offsetDiag[i] += 4 * kShear * s * s * rdem::alongFace<Real>(side ? b.fc2 : b.fc1, side ? b.n2 : b.n1).cwiseAbs2();
			const State& st = *state[i];
			if (st.blockedDOFs == State::DOF_ALL) continue;
			w2[size_t(body[i])] += rdem::pointSpringOmega2<Real>(
			        st.ori * (side ? b.fc2 : b.fc1),
			        st.ori * (side ? b.n2 : b.n1),
			        1,
			        0,
			        kShear,
			        rdem::inertialMass(st), // inertial (density scaling)
			        rdem::inertialMinInertia(st));
		}
	}
	for (size_t i = 0; i < body.size(); ++i)
		if (hasCell[i])
			for (size_t j = first[i]; j < first[i + 1]; ++j) {
				const Bond& b = bond[sideBond[j]];
				const int   a = sideSecond[j] ? b.ax2 : b.ax1;
				row[i][a] += offsetDiag[i][a] * math::abs(sideSecond[j] ? b.c2 : b.c1);
			}
	for (size_t k = 0; k < bond.size(); ++k) {
		const Bond& b     = bond[k];
		const Real  kappa = math::abs(b.c1) * row[b.i1][b.ax1] + math::abs(b.c2) * row[b.i2][b.ax2];
		for (int side = 0; side < 2; ++side) {
			const State& s = *state[side ? b.i2 : b.i1];
			if (s.blockedDOFs == State::DOF_ALL) continue;
			const Vector3r r = s.ori * (side ? b.fc2 : b.fc1);
			const Vector3r n = s.ori * (side ? b.n2 : b.n1);
			const Real     f = rdem::inertialFactor(s.densityScaling); // inertial mass and inertia (density scaling)
			w2[size_t(body[side ? b.i2 : b.i1])] += 2 * kappa * (1 / (s.mass * f) + r.cross(n).squaredNorm() / (s.inertia.minCoeff() * f));
		}
	}
	return w2;
}

void RdemCellNetwork::addStiffness(Scene* scene, bool releaseOnCrack, long brokenSprings, rdem::BlockStiffness<Real>& K)
{
	if (!refresh(scene)) return;
	updateIntact(brokenSprings);
	// the openings u_n = n·(P₂ - P₁) at the face centres, as updateStrains, linearised: gradients n and r×n
	vector<size_t> openingOf(bond.size());
	for (size_t k = 0; k < bond.size(); ++k) {
		const Bond&    b  = bond[k];
		const Matrix3r R1 = state[b.i1]->ori.toRotationMatrix(), R2 = state[b.i2]->ori.toRotationMatrix();
		const Vector3r n = R1 * b.n1;
		openingOf[k]     = K.addOpening(body[b.i1], body[b.i2], n, (R1 * b.fc1).cross(n), (R2 * b.fc2).cross(n));
	}
	vector<long> cellOf(body.size(), -1);
	for (size_t i = 0; i < body.size(); ++i) {
		const Real s = releaseOnCrack ? state[i]->cellScale : Real(1);
		if (!hasCell[i] || !(s > 0)) continue;
		vector<std::tuple<size_t, int, Real>> terms;
		for (size_t j = first[i]; j < first[i + 1]; ++j) {
			const Bond& b = bond[sideBond[j]];
			terms.emplace_back(openingOf[sideBond[j]], sideSecond[j] ? b.ax2 : b.ax1, sideSecond[j] ? b.c2 : b.c1);
		}
		// W = ½ s strainᵀ K strain with strain = C ε (the condensation), so ½ εᵀ (s CᵀKC) ε
		cellOf[i] = long(K.addCell(s * condensation[i].transpose() * stiffness[i] * condensation[i], terms));
	}
	/* The offset correction of the intact shear springs (rdem::offsetSlip, as the law applies it): the slip
	   c = s₁R₁diag(a₁)C₁ε₁ - s₂R₂diag(a₂)C₂ε₂ at the face centre, a_b its offset from block b's centroid along the face,
	   s_b the crack scale and C_b the condensation. Its lever is a block's length; for a course bonded to a long beam, the
	   beam's, which can set the step. */
	for (size_t k = 0; k < bond.size(); ++k) {
		const Real kShear = offsetShearStiffness(k);
		if (kShear == 0) continue;
		const Bond&    b  = bond[k];
		const Matrix3r R1 = state[b.i1]->ori.toRotationMatrix(), R2 = state[b.i2]->ori.toRotationMatrix();
		const auto     lever = [&](size_t i, const Matrix3r& R, const Vector3r& fc, const Vector3r& n) -> Matrix3r {
                        return state[i]->cellScale * R * rdem::alongFace<Real>(fc, n).asDiagonal() * condensation[i];
		};
		K.addOffsetShear(
		        body[b.i1],
		        body[b.i2],
		        R1 * b.fc1,
		        R2 * b.fc2,
		        R1 * b.n1,
		        kShear,
		        cellOf[b.i1],
		        lever(b.i1, R1, b.fc1, b.n1),
		        cellOf[b.i2],
		        lever(b.i2, R2, b.fc2, b.n2));
	}
}

} // namespace yade
