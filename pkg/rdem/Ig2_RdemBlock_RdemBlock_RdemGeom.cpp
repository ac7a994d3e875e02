/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/Ig2_RdemBlock_RdemBlock_RdemGeom.hpp>
#include <pkg/rdem/NumberText.hpp>
#include <pkg/rdem/RdemPrefetch.hpp>
#include <pkg/rdem/math/BlockGeometry.hpp>
#include <pkg/rdem/math/FacePatch.hpp>
#include <pkg/rdem/math/FaceSamples.hpp>
#include <pkg/rdem/math/SegmentGrid.hpp>
#include <pkg/rdem/math/SeparationBound.hpp>
#include <pkg/rdem/math/SortedKeys.hpp>
#include <limits>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((Ig2_RdemBlock_RdemBlock_RdemGeom)(RdemGap));
CREATE_LOGGER(Ig2_RdemBlock_RdemBlock_RdemGeom);

namespace {
	using Block = rdem::OrientedBlock<Real>;

	Vector3r pointVelocity(const State& s, const Vector3r& centre, const Vector3r& p) { return s.vel + s.angVel.cross(p - centre); }

	/// Distance from a block's centroid to its face whose outward normal is closest to n [m].
	Real faceDistance(const Block& b, const Vector3r& n)
	{
		int k = 0;
		for (int j = 1; j < 3; ++j)
			if (math::abs(b.rot.col(j).dot(n)) > math::abs(b.rot.col(k).dot(n))) k = j;
		return b.half[k];
	}

	/// Overlaps below this are touching, not contact: grid neighbours along an edge or a corner overlap by round-off [m].
	Real touchTolerance(const Block& A, const Block& B) { return rdem::touchTolerance<Real>(A.half, B.half); }

	/// How far outside a block a vertex may lie and still count as on its surface (rdem::facesCross): round-off of the
	/// positions of blocks laid side by side, 1e-6 of the smaller half-extent [m].
	Real faceTouchTolerance(const Block& A, const Block& B) { return 1e-6 * math::min(A.half.minCoeff(), B.half.minCoeff()); }

	/* The samples of block X (which = 0 for body 1, 1 for body 2; keys as in sampleInside, all six faces) that lie less
	   than skin outside block Y (rdem::sampleOutside), marked in near, a sample certificate (RdemGeom::nearSamples: bit
	   `key` set for each such sample): the only ones that can enter Y while the blocks' travels add up to less than skin
	   less rdem::separationMargin. Their points in Y's frame are computed as in sampleInside. */
	void markNearSamples(const Block& X, const Block& Y, int which, int n, Real skin, vector<uint64_t>& near)
	{
		const int      perFace = (n + 1) * (n + 1);
		const Matrix3r toY     = Y.rot.transpose();
		for (int k = 0; k < 3; ++k) {
			const int      k1 = (k + 1) % 3, k2 = (k + 2) % 3;
			const Vector3r q1 = toY * X.rot.col(k1), q2 = toY * X.rot.col(k2);
			for (int side = 0; side < 2; ++side) {
				const Vector3r qc    = toY * (X.pos + X.half[k] * (side ? 1 : -1) * X.rot.col(k) - Y.pos);
				const int      first = (which * 6 + 2 * k + side) * perFace;
				for (int i = 0; i <= n; ++i) {
					const Vector3r qa = qc + X.half[k1] * rdem::trapezoidNode<Real>(i, n).x * q1;
					for (int j = 0; j <= n; ++j) {
						const int key = first + i * (n + 1) + j;
						if (rdem::sampleOutside<Real>(Y.half, qa + X.half[k2] * rdem::trapezoidNode<Real>(j, n).x * q2) < skin)
							near[size_t(key) / 64] |= uint64_t(1) << (size_t(key) % 64);
					}
				}
			}
		}
	}

	/* Sample points of block X (which = 0 for body 1, 1 for body 2) that entered block Y, appended to geom
	   (rdem::faceSamplesInside). normal is the pair's contact normal from body 1 to body 2 (rdem::contactNormal); X
	   separates from Y along u = -normal (body 1) or +normal (body 2). Sample keys are ((which·6 + face)·(n+1)² + point),
	   ascending, which the law's history and sums follow. With near (a sample certificate, nearSamples), only the samples
	   whose bit is set are tested: the others cannot be inside Y. node: the trapezoid rule of n. */
	void sampleInside(
	        const Block&                      X,
	        const State&                      sx,
	        const Block&                      Y,
	        const State&                      sy,
	        int                               which,
	        int                               n,
	        const Vector3r&                   normal,
	        const rdem::TrapezoidNodes<Real>& node,
	        RdemGeom&                         g,
	        bool                              clip,
	        const vector<uint64_t>*           near)
	{
		const Vector3r u  = which == 0 ? Vector3r(-normal) : normal;
		const State&   s1 = which == 0 ? sx : sy;
		const State&   s2 = which == 0 ? sy : sx;
		const Vector3r x1 = which == 0 ? X.pos : Y.pos;
		const Vector3r x2 = which == 0 ? Y.pos : X.pos;
		rdem::faceSamplesInside<Real>(
		        X, Y, u, n, which * 6 * (n + 1) * (n + 1), near ? near->data() : nullptr, node, clip, [&](const rdem::FaceSampleHit<Real>& hit) {
			        g.sampleKey.push_back(hit.key);
			        g.samplePoint.push_back(hit.point);
			        g.sampleNormal.push_back(normal);
			        g.sampleVel.push_back(pointVelocity(s2, x2, hit.point) - pointVelocity(s1, x1, hit.point));
			        g.sampleDepth.push_back(hit.depth);
			        g.sampleArea.push_back(hit.area);
		        });
	}

	/// Edge-to-edge contact of the pair (rdem::edgeEdgeContact), appended to geom with the key after all face samples.
	/// Its area is that of a corner sample of the smaller block, a quarter of a segment: a penalty for the contact of
	/// two edges, which carries no area of its own.
	void
	edgeInside(const rdem::BlockPair<Real>& pair, const rdem::SeparatingAxes<Real>& sat, const State& s1, const State& s2, Real tol, int n, RdemGeom& g)
	{
		const Block& A   = pair.A;
		const Block& B   = pair.B;
		const auto   hit = rdem::edgeEdgeContact<Real>(pair, sat, tol);
		if (!hit.hit) return;
		Real segArea = std::numeric_limits<Real>::infinity();
		for (const Block* X : { &A, &B })
			for (int k = 0; k < 3; ++k)
				segArea = math::min(segArea, rdem::segmentArea(X->half[(k + 1) % 3], X->half[(k + 2) % 3], n));
		g.sampleKey.push_back(2 * 6 * (n + 1) * (n + 1));
		g.samplePoint.push_back(hit.point);
		g.sampleNormal.push_back(hit.normal);
		g.sampleVel.push_back(pointVelocity(s2, B.pos, hit.point) - pointVelocity(s1, A.pos, hit.point));
		g.sampleDepth.push_back(hit.depth);
		g.sampleArea.push_back(segArea / 4);
	}

	/// Face samples of both blocks inside each other along the pair's contact normal, then the edge-to-edge contact; with
	/// near, only the samples of that certificate (sampleInside). sat: the pair's overlaps on the separating axes.
	void sampleContacts(
	        const rdem::BlockPair<Real>&      pair,
	        const rdem::SeparatingAxes<Real>& sat,
	        const State&                      s1,
	        const State&                      s2,
	        Real                              tol,
	        int                               n,
	        RdemGeom&                         g,
	        bool                              clip,
	        const vector<uint64_t>*           near = nullptr)
	{
		const Block&                     A      = pair.A;
		const Block&                     B      = pair.B;
		const Vector3r                   normal = rdem::contactNormal<Real>(pair, sat);
		const rdem::TrapezoidNodes<Real> node(n);
		sampleInside(A, s1, B, s2, 0, n, normal, node, g, clip, near);
		sampleInside(B, s2, A, s1, 1, n, normal, node, g, clip, near);
		edgeInside(pair, sat, s1, s2, tol, n, g);
	}

	/* The contact points of the last step whose history (RdemPhys::contactShear, contactDashpot, contactOffset, in the
	   same order) passes to the points of a new patch or to samples: where they are now (global) [m], how far each
	   spring is compressed, depth - offset (-1: not in contact) [m], and its tributary area [m²]. What passes is the
	   compression, not the offset: a point taking over at another depth starts with the force per area of the point it
	   replaces (handOver). */
	struct ContactHistory {
		vector<Vector3r> pos;
		vector<Real>     compression;
		vector<Real>     area;
	};

	/// The history of g's patch for blocks A and B (normal n of this step).
	ContactHistory patchHistory(const RdemGeom& g, const RdemPhys& p, const Block& A, const Block& B, const Vector3r& n)
	{
		const auto     springs = g.patchSprings();
		ContactHistory h;
		for (size_t i = 0; i < springs.size; ++i) {
			const Vector3r P1 = A.pos + A.rot * springs.point1(i), P2 = B.pos + B.rot * springs.point2(i);
			h.pos.push_back((P1 + P2) / 2);
			const Real depth = -(P2 - P1).dot(n);
			h.compression.push_back(
			        i < p.contactOffset.size() && p.contactOffset[i] >= 0 ? math::max(depth - p.contactOffset[i], Real(0)) : Real(-1));
			h.area.push_back(springs.area(i));
		}
		return h;
	}

	/// The history of the last step's samples of g, if the law left it in p (its keys are g's sample keys).
	ContactHistory sampleHistory(const RdemGeom& g, const RdemPhys& p)
	{
		ContactHistory h;
		if (g.sampleKey.empty() || g.sampleKey != p.contactKey) return h;
		h.pos  = g.samplePoint;
		h.area = g.sampleArea;
		for (size_t k = 0; k < g.sampleKey.size(); ++k)
			h.compression.push_back(math::max(g.sampleDepth[k] - p.contactOffset[k], Real(0)));
		return h;
	}

	/* The history `from` (with its arrays still in p) passed to new contact points at `pos` with depths `depth` [m] and
	   tributary areas `area` [m²]: each point in contact takes the shear elongation u_s of the nearest old point that
	   was in contact, and its compression c, at most its own depth. The points' areas differ (a patch's springs carry
	   the patch area, the vertex samples of a small face on a large one half of it, and an edge-to-edge sample a
	   quarter of a segment whatever the overlap), so that the same c and u_s would store another elastic energy,
	   Σ a (w_n k̄_n c² + w_s k̄_s |u_s|²)/2 (eqs. 13, 17): up to 6.7 times the old one when a sliver of a patch goes to
	   the samples (tests/yade/test_persistent_contact.testHandOverMakesNoEnergy). So the new points store what the old ones
	   store in this configuration: where they would store more, c and u_s are scaled down alike; where less, c is
	   scaled up, at most to the point's depth (u_s is kept: a larger one could exceed the friction limit, eq. 17).
	   Going between patch and samples, or re-deriving a patch, thus makes no energy and, unless a depth limits c, loses
	   none; a round trip gives the old springs back. Each old dashpot force is shared among the new points that take it, by area, so that the second
	   half of its step's work (rdem::contactSpringForce) is booked once, not once per new point. Returns the new points'
	   offsets depth - c (-1: no history; the law starts the point at its depth) and replaces p's shear and dashpot
	   arrays by the new points'; `released` is set to the elastic energy the old points stored that the new ones do not
	   (where a depth limits c, or no new point takes an old one's history) [J]. */
	vector<Real>
	handOver(const ContactHistory& from, const vector<Vector3r>& pos, const vector<Real>& depth, const vector<Real>& area, RdemPhys& p, Real& released)
	{
		const vector<int> near = rdem::nearestPoints<Real>(from.pos, pos);
		const Real        kn = p.weightNormal * p.kn, ks = p.weightShear * p.ks;
		vector<Real>      taken(from.pos.size(), Real(0)), compression(pos.size(), Real(-1));
		Real              before = 0, afterN = 0, afterS = 0; // twice the elastic energies of the old and the new points [J]
		for (size_t j = 0; j < from.pos.size(); ++j)
			if (from.compression[j] >= 0)
				before += from.area[j] * (kn * from.compression[j] * from.compression[j] + ks * p.contactShear[j].squaredNorm());
		for (size_t i = 0; i < pos.size(); ++i) {
			const int j = near[i];
			if (j < 0 || !(depth[i] > 0) || !(from.compression[size_t(j)] >= 0)) continue;
			compression[i] = math::min(from.compression[size_t(j)], depth[i]);
			taken[size_t(j)] += area[i];
			afterN += area[i] * kn * compression[i] * compression[i];
			afterS += area[i] * ks * p.contactShear[size_t(j)].squaredNorm();
		}
		const auto       scale  = rdem::handOverScales(before, afterN, afterS); // (compression, shear elongation)
		const Real       scaleN = scale.first, scaleS = scale.second;
		vector<Vector3r> shear(pos.size(), Vector3r::Zero()), dashpot(pos.size(), Vector3r::Zero());
		vector<Real>     offset(pos.size(), Real(-1));
		Real             after = 0; // twice the elastic energy of the new points [J]
		for (size_t i = 0; i < pos.size(); ++i) {
			if (compression[i] < 0) continue;
			const size_t j = size_t(near[i]);
			shear[i]       = scaleS * p.contactShear[j];
			dashpot[i]     = (area[i] / taken[j]) * p.contactDashpot[j];
			const Real c   = math::min(scaleN * compression[i], depth[i]);
			offset[i]      = depth[i] - c;
			after += 2 * rdem::contactSpringEnergy<Real>(area[i] * kn, area[i] * ks, c, shear[i]);
		}
		released = (before - after) / 2;
		p.contactShear.swap(shear);
		p.contactDashpot.swap(dashpot);
		return offset;
	}

	/// The history of a patch passed to this step's samples of g (handOver), as the law's sample history in p.
	void handOverToSamples(const ContactHistory& from, const RdemGeom& g, RdemPhys& p, Real& released)
	{
		vector<Real>     offset = handOver(from, g.samplePoint, g.sampleDepth, g.sampleArea, p, released);
		vector<int>      key;
		vector<Vector3r> shear, dashpot;
		vector<Real>     kept;
		for (size_t k = 0; k < offset.size(); ++k) {
			if (offset[k] < 0) continue;
			key.push_back(g.sampleKey[k]); // ascending, as sampleKey
			shear.push_back(p.contactShear[k]);
			dashpot.push_back(p.contactDashpot[k]);
			kept.push_back(offset[k]);
		}
		p.contactKey.swap(key);
		p.contactShear.swap(shear);
		p.contactDashpot.swap(dashpot);
		p.contactOffset.swap(kept);
	}
}

void Ig2_RdemBlock_RdemBlock_RdemGeom::postLoad(Ig2_RdemBlock_RdemBlock_RdemGeom&)
{
	if (!(patchAngleTolerance > 0 && patchAngleTolerance < 1))
		throw std::invalid_argument(
		        "Ig2_RdemBlock_RdemBlock_RdemGeom.patchAngleTolerance = " + rdem::numberText(patchAngleTolerance) + ": must be > 0 and < 1");
	if (!(patchTravelTolerance > 0 && patchTravelTolerance <= 0.1))
		throw std::invalid_argument(
		        "Ig2_RdemBlock_RdemBlock_RdemGeom.patchTravelTolerance = " + rdem::numberText(patchTravelTolerance) + ": must be > 0 and <= 0.1");
	if (segmentsPerEdge < 1)
		throw std::invalid_argument(
		        "Ig2_RdemBlock_RdemBlock_RdemGeom.segmentsPerEdge = " + std::to_string(segmentsPerEdge) + ": must be an integer >= 1");
	if (contactSamplesPerEdge < 0)
		throw std::invalid_argument(
		        "Ig2_RdemBlock_RdemBlock_RdemGeom.contactSamplesPerEdge = " + std::to_string(contactSamplesPerEdge)
		        + ": must be an integer >= 1 (or 0: segmentsPerEdge)");
	if (!(bondGapTolerance >= 0))
		throw std::invalid_argument("Ig2_RdemBlock_RdemBlock_RdemGeom.bondGapTolerance = " + rdem::numberText(bondGapTolerance) + ": must be >= 0");
	if (prefetchDistance < -1)
		throw std::invalid_argument(
		        "Ig2_RdemBlock_RdemBlock_RdemGeom.prefetchDistance = " + std::to_string(prefetchDistance) + ": must be -1 (automatic), 0 (off) or > 0");
}

bool Ig2_RdemBlock_RdemBlock_RdemGeom::knownApart(
        Interaction& I, const Vector3r& hA, const Vector3r& hB, const State& s1, const State& s2, const Vector3r& shift2)
{
	if (!I.geom || I.geom->getClassIndex() != RdemGap::getClassIndexStatic()) return false;
	auto&                   gap    = static_cast<RdemGap&>(*I.geom);
	const rdem::BodyTravel* travel = shared ? &shared->travel : nullptr; // recorded by RdemContactGate
	// The summed travel of the two blocks if it is recorded for this step, else -1 (asked only for a certificate).
	const auto travelled
	        = [&]() { return travel && travel->currentFor(*scene) ? travel->travel[size_t(I.getId1())] + travel->travel[size_t(I.getId2())] : Real(-1); };
	if (travel && travel->certifies(*scene, gap.epoch, gap.reach, I.getId1(), I.getId2())) {
		skippedTests += 1; // the certificate holds
		return true;
	}
	if (!skipApart || gap.witness < 0) return false;
	const auto verdict = rdem::witnessVerdict<Real>(s1.pos, s1.ori, hA, s2.pos + shift2, s2.ori, hB, gap.witness);
	if (!verdict.apart) return false; // tested in full (findContact)
	witnessTests += 1;
	if (rdem::certifiableSlack<Real>(verdict.slack, hA, hB)) {
		const Real t = travelled();
		if (t >= 0) {
			gap.reach = t + verdict.slack - rdem::separationMargin<Real>(hA, hB);
			gap.epoch = travel->epoch;
		}
	}
	return true;
}

bool Ig2_RdemBlock_RdemBlock_RdemGeom::bond(const Block& A, const Block& B, const shared_ptr<Interaction>& I) const
{
	const Real gapTol = bondGapTolerance * math::min(A.half.minCoeff(), B.half.minCoeff());
	const auto face   = rdem::findSharedFace<Real>(A, B, gapTol, Real(1e-6));
	if (!face.found) return false;
	auto g            = shared_ptr<RdemGeom>(new RdemGeom);
	g->samplesPerEdge = segmentsPerEdge;
	g->bonded         = true;
	g->ell1           = A.half[face.axisA];
	g->ell2           = B.half[face.axisB];
	g->joint          = joint;
	g->segNormal1     = A.rot.transpose() * face.normal;
	g->segNormal2     = -(B.rot.transpose() * face.normal);
	g->faceCentre1    = A.rot.transpose() * (face.centre - A.pos);
	g->faceCentre2    = B.rot.transpose() * (face.centre - B.pos);
	// Segment half-size vectors along t₁ and t₂ = n × t₁ (n: body 1's outward normal), in both body frames.
	const Vector3r u = face.h1 / segmentsPerEdge * face.t1, v = face.h2 / segmentsPerEdge * face.normal.cross(face.t1);
	g->segHalf1u = A.rot.transpose() * u;
	g->segHalf1v = A.rot.transpose() * v;
	g->segHalf2u = B.rot.transpose() * u;
	g->segHalf2v = B.rot.transpose() * v;
	I->geom      = g;
	return true;
}

bool Ig2_RdemBlock_RdemBlock_RdemGeom::findContact(const Block& A, const Block& B, const State& s1, const State& s2, const shared_ptr<Interaction>& I)
{
	const rdem::BlockPair<Real> pair(A, B);
	const Real                  tol = touchTolerance(A, B);
	if (!rdem::blocksOverlap<Real>(pair, tol)) {
		/* Apart: a certificate of how long they stay so (rdem::separationSlack), if the blocks' travel is recorded, and the
		   face axis of least overlap as the witness tested first at the next step, if it separates them (knownApart). */
		if (!skipApart) return false;
		const rdem::BodyTravel*          travel  = shared ? &shared->travel : nullptr;
		const rdem::FaceSeparation<Real> sep     = rdem::faceSeparation<Real>(pair, tol);
		const bool                       certify = travel && travel->currentFor(*scene) && sep.slack > 0;
		const int  witness = sep.axis >= 0 && !((sep.axis < 3 ? pair.overlapA(sep.axis) : pair.overlapB(sep.axis - 3)) > tol) ? sep.axis : -1;
		const bool hasGap  = I->geom && I->geom->getClassIndex() == RdemGap::getClassIndexStatic();
		if (!certify && witness < 0 && !hasGap) return false;
		if (!hasGap) I->geom = shared_ptr<RdemGap>(new RdemGap);
		auto& gap   = static_cast<RdemGap&>(*I->geom);
		gap.witness = witness;
		gap.epoch   = certify ? travel->epoch : -1;
		if (certify) gap.reach = travel->travel[size_t(I->getId1())] + travel->travel[size_t(I->getId2())] + sep.slack;
		return false;
	}
	const bool triedPatch = persistentContacts;
	if (triedPatch) {
		auto g            = shared_ptr<RdemGeom>(new RdemGeom);
		g->samplesPerEdge = contactSamples();
		if (derivePatch(A, B, s1.ori, s2.ori, *g, nullptr)) {
			g->ell1 = faceDistance(A, g->normal);
			g->ell2 = faceDistance(B, g->normal);
			I->geom = g;
			return true;
		}
	}
	const rdem::SeparatingAxes<Real> sat(pair);
	RdemGeom                         probe;
	probe.samplesPerEdge = contactSamples();
	sampleContacts(pair, sat, s1, s2, tol, contactSamples(), probe, clipSampleAreas);
	if (probe.sampleKey.empty() && contactSamples() == 1 && segmentsPerEdge > 1 && rdem::facesCross<Real>(A, B, faceTouchTolerance(A, B))) {
		/* Vertices only, and no vertex of either block in or on the other although they overlap: faces that cross (a beam
		   across a wall). The contact then samples the face grid of segmentsPerEdge for its life; its samples count from
		   the depth at which they enter (δ₀), so the switch adds no energy. Blocks side by side with coincident faces (a
		   course's head joints) have their vertices on each other's edges and keep the vertex samples. */
		probe.samplesPerEdge = segmentsPerEdge;
		sampleContacts(pair, sat, s1, s2, tol, segmentsPerEdge, probe, clipSampleAreas);
	}
	if (probe.sampleKey.empty()) return false;
	auto g  = shared_ptr<RdemGeom>(new RdemGeom(probe));
	g->ell1 = faceDistance(A, probe.sampleNormal[0]);
	g->ell2 = faceDistance(B, probe.sampleNormal[0]);
	if (triedPatch) markDerived(A, B, s1.ori, s2.ori, *g); // no patch here (see go)
	I->geom = g;                                           // replaces a certificate that no longer holds
	return true;                                           // samples of this step are already in place
}

const vector<uint64_t>* Ig2_RdemBlock_RdemBlock_RdemGeom::nearSamples(const rdem::BlockPair<Real>& pair, const Interaction& I, RdemGeom& g) const
{
	const rdem::BodyTravel* travel = shared ? &shared->travel : nullptr; // recorded by RdemContactGate
	if (!skipApart || !travel || !travel->currentFor(*scene)) return nullptr;
	const int  n = g.samplesPerEdge, words = (2 * 6 * (n + 1) * (n + 1) + 63) / 64;
	const Real t = travel->travel[size_t(I.getId1())] + travel->travel[size_t(I.getId2())];
	if (g.sampleEpoch == travel->epoch && t < g.sampleReach && g.nearSamples.size() == size_t(words)) return &g.nearSamples;
	// A new certificate; this step tests every sample. None for blocks so slender that the skin is within the margin.
	const Real skin = sampleSkin * math::min(pair.A.half.minCoeff(), pair.B.half.minCoeff()), margin = rdem::separationMargin<Real>(pair);
	if (!(skin > margin)) return nullptr;
	g.nearSamples.assign(size_t(words), 0);
	markNearSamples(pair.A, pair.B, 0, n, skin, g.nearSamples);
	markNearSamples(pair.B, pair.A, 1, n, skin, g.nearSamples);
	g.sampleReach = t + skin - margin;
	g.sampleEpoch = travel->epoch;
	return nullptr;
}

bool Ig2_RdemBlock_RdemBlock_RdemGeom::withinPatchTravel(const RdemGeom& g, const State& s1, const State& s2, const Vector3r& shift2) const
{
	if (!(g.patchTravel > 0)) return false;
	const Quaternionr q1c = s1.ori.conjugate();
	const Vector3r    rel = q1c * (s2.pos + shift2 - s1.pos);
	return rdem::rigidTravel<Real>(g.patchRelPos, g.patchRelOri, rel, q1c * s2.ori, g.patchRadius) <= g.patchTravel;
}

void Ig2_RdemBlock_RdemBlock_RdemGeom::markDerived(const Block& A, const Block& B, const Quaternionr& q1, const Quaternionr& q2, RdemGeom& g) const
{
	g.patchRelPos = A.rot.transpose() * (B.pos - A.pos);
	g.patchRelOri = q1.conjugate() * q2;
	g.patchRadius = B.half.norm();
	g.patchTravel = patchTravelTolerance * math::min(A.half.minCoeff(), B.half.minCoeff());
}

void Ig2_RdemBlock_RdemBlock_RdemGeom::releaseSprings(RdemPhys& p, Real energy) const
{
	if (!scene->trackEnergy) return;
	if (p.releasedIter != scene->iter) {
		p.releasedEnergy = 0;
		p.releasedIter   = scene->iter;
	}
	p.releasedEnergy += energy;
}

bool Ig2_RdemBlock_RdemBlock_RdemGeom::derivePatch(const Block& A, const Block& B, const Quaternionr& q1, const Quaternionr& q2, RdemGeom& g, RdemPhys* p) const
{
	const Real hMin = math::min(A.half.minCoeff(), B.half.minCoeff());
	// Gap tolerance: a tenth of the smaller half-extent, to tell the faces that meet from the others (two faces of a
	// block are 2h apart); the pair overlaps already (blocksOverlap).
	const auto fp = rdem::facePatch<Real>(A, B, contactSamples(), patchAngleTolerance, hMin / 10);
	// A sliver (two grid neighbours that share an edge, strained into each other) is an edge contact: sampled, with
	// its edge-to-edge test. A patch is a face-to-face contact from a hundredth of the smaller face on.
	const int  kA = fp.faceA.k, kB = fp.faceB.k;
	const Real faceA = A.half[(kA + 1) % 3] * A.half[(kA + 2) % 3], faceB = B.half[(kB + 1) % 3] * B.half[(kB + 2) % 3];
	if (!fp.found || fp.area < Real(0.04) * math::min(faceA, faceB)) return false;
	const Vector3r   nA = fp.faceA.normal(A), nB = fp.faceB.normal(B), n = (nA - nB).normalized();
	vector<Vector3r> mid(fp.point1.size());
	vector<Real>     depth(mid.size());
	bool             touching = false;
	for (size_t i = 0; i < mid.size(); ++i) {
		mid[i]   = (fp.point1[i] + fp.point2[i]) / 2;
		depth[i] = -(fp.point2[i] - fp.point1[i]).dot(n);
		touching = touching || depth[i] > 0;
	}
	// A new contact none of whose springs overlaps (blocks side by side, within the touch tolerance) is not made: the law
	// would erase it at once, and the pair would be found and made again at every step (as a sampled contact is not made
	// without a sample inside).
	if (!p && !touching) return false;
	if (p) {
		// The history of the old patch, or of the last step's samples, passed to the new springs (handOver).
		const ContactHistory from     = g.nPatch() > 0 && p->contactKey.empty() && p->contactOffset.size() == g.nPatch()
		            ? patchHistory(g, *p, A, B, (A.rot * g.segNormal1 - B.rot * g.segNormal2).normalized())
		            : sampleHistory(g, *p);
		Real                 released = 0;
		vector<Real>         offset   = handOver(from, mid, depth, fp.pointArea, *p, released);
		releaseSprings(*p, released);
		p->contactKey.clear();
		p->contactOffset.swap(offset);
	}
	g.patch.clear();
	for (size_t i = 0; i < mid.size(); ++i)
		rdem::PatchSprings<Real>::append(
		        g.patch, A.rot.transpose() * (fp.point1[i] - A.pos), B.rot.transpose() * (fp.point2[i] - B.pos), fp.pointArea[i]);
	g.patchArea  = fp.area;
	g.segNormal1 = A.rot.transpose() * nA;
	g.segNormal2 = B.rot.transpose() * nB;
	g.normal     = n;
	markDerived(A, B, q1, q2, g);
	g.clearSamples();
	return true;
}

bool Ig2_RdemBlock_RdemBlock_RdemGeom::go(
        const shared_ptr<Shape>&       shape1,
        const shared_ptr<Shape>&       shape2,
        const State&                   state1,
        const State&                   state2,
        const Vector3r&                shift2,
        const bool&                    force,
        const shared_ptr<Interaction>& I)
{
	// The first functor of every interaction: asks for the data of the interactions that follow (RdemPrefetch.hpp).
	if (const int distance = rdem::prefetchDistanceFor(prefetchDistance, scene->interactions->size()))
		rdem::prefetchInteractionsAhead(*scene, *I, distance);
	// A real interaction has the RdemGeom this functor made; a potential one has no geometry or an RdemGap.
	if (I->phys && static_cast<RdemGeom*>(I->geom.get())->bonded) {
		// bonded: this step's face normal and segment kinematics (paper eq. 14), from the blocks' states
		static_cast<RdemGeom*>(I->geom.get())
		        ->updateBond(state1.ori.toRotationMatrix(), state2.ori.toRotationMatrix(), state2.pos + shift2 - state1.pos);
		return true;
	}
	if (!I->phys && !force
	    && knownApart(*I, static_cast<RdemBlock*>(shape1.get())->extents, static_cast<RdemBlock*>(shape2.get())->extents, state1, state2, shift2))
		return false;
	// A face-to-face contact whose blocks have not moved enough to change its patch: its springs are in place.
	if (I->phys && static_cast<RdemGeom*>(I->geom.get())->nPatch() > 0
	    && withinPatchTravel(*static_cast<RdemGeom*>(I->geom.get()), state1, state2, shift2)) {
		RdemGeom& g = *static_cast<RdemGeom*>(I->geom.get());
		g.normal    = (state1.ori * g.segNormal1 - state2.ori * g.segNormal2).normalized();
		return true;
	}
	const Block A { state1.pos, state1.ori.toRotationMatrix(), static_cast<RdemBlock*>(shape1.get())->extents };
	const Block B { state2.pos + shift2, state2.ori.toRotationMatrix(), static_cast<RdemBlock*>(shape2.get())->extents };
	if (!I->phys) return force ? bond(A, B, I) : findContact(A, B, state1, state2, I);

	// A real contact needs every separating axis's overlap when it overlaps (normal, edge-to-edge test): computed once.
	const rdem::BlockPair<Real>      pair(A, B);
	const rdem::SeparatingAxes<Real> sat(pair);
	const Real                       tol     = touchTolerance(A, B);
	RdemGeom&                        g       = *static_cast<RdemGeom*>(I->geom.get());
	RdemPhys&                        p       = *static_cast<RdemPhys*>(I->phys.get());
	const bool                       overlap = rdem::blocksOverlap<Real>(sat, tol);
	/* A sampled contact whose faces were found not to meet face to face (two grid neighbours along an edge, blocks tilted
	   against each other) is not tested again before the blocks have moved by patchTravel relative to each other since:
	   the same tolerance as a patch's, by which the patch found later lags (markDerived). */
	const bool tried = overlap && persistentContacts && !(g.nPatch() == 0 && withinPatchTravel(g, state1, state2, shift2));
	if (tried && derivePatch(A, B, state1.ori, state2.ori, g, &p)) return true;
	// Sampled: a patch whose faces no longer meet hands its history to the samples.
	const ContactHistory from = g.nPatch() > 0 && p.contactKey.empty() && p.contactOffset.size() == g.nPatch()
	        ? patchHistory(g, p, A, B, (A.rot * g.segNormal1 - B.rot * g.segNormal2).normalized())
	        : ContactHistory();
	/* The last step's samples, whose history the law kept in p (RdemPhys::contactKey, contactOffset, contactShear), are
	   set aside (swapped: no copy) while g is sampled again, so that a sample this step drops while it is loaded books
	   the elastic energy the law gave its spring in the last step (rdem::contactSpringForce): a point that slides past
	   the edge of the other block's face takes its spring with it. */
	struct LastSamples {
		vector<int>  key;
		vector<Real> depth, area;
	};
	static thread_local LastSamples last; // one thread-local object: one look-up of the thread's storage
	const bool                      sampled = scene->trackEnergy && g.nPatch() == 0 && !g.sampleKey.empty() && g.sampleKey == p.contactKey;
	if (sampled) {
		last.key.swap(g.sampleKey);
		last.depth.swap(g.sampleDepth);
		last.area.swap(g.sampleArea);
	}
	if (g.nPatch() > 0) g.clearPatch(); // and the configuration it was derived in
	if (tried) markDerived(A, B, state1.ori, state2.ori, g);
	g.clearSamples();
	if (overlap) sampleContacts(pair, sat, state1, state2, tol, g.samplesPerEdge, g, clipSampleAreas, nearSamples(pair, *I, g));
	if (sampled && g.sampleKey != last.key) // the same samples as in the last step (most steps): none dropped
		releaseSprings(p, rdem::sumOfDropped(last.key, g.sampleKey.data(), g.sampleKey.size(), [&](size_t j) {
			               return rdem::contactSpringEnergy<Real>(
			                       p.kn * (p.weightNormal * last.area[j]),
			                       p.ks * (p.weightShear * last.area[j]),
			                       math::max(last.depth[j] - p.contactOffset[j], Real(0)),
			                       p.contactShear[j]);
		               }));
	if (!from.pos.empty()) {
		Real released = 0;
		handOverToSamples(from, g, p, released);
		releaseSprings(p, released);
	}
	return true; // a real interaction stays; the law erases it when no sample is in contact
}

} // namespace yade
