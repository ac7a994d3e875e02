/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/SeparationBound.hpp: the travel bound of a rigid body against the exact motion of a
   box's vertices, and the separation certificate against blocksOverlap after random and worst-case motions within
   the certified slack. Coordinates are O(1) m, so round-off is ~1e-16-1e-15 m; 1e-12 m tolerances leave ≥ 10³ of
   margin while being far below the offsets tested (≥ 1e-4 m). */
#include <pkg/rdem/math/SeparationBound.hpp>
#include <tests/unit/Random.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace {

namespace rdem = yade::rdem;
using V3       = Eigen::Vector3d;
using Q        = Eigen::Quaterniond;
using Block    = rdem::OrientedBlock<double>;

constexpr double tol = 1e-9; // [m] the touch tolerance passed to blocksOverlap (the functor's 1e-9 of a half-extent)

double uniform(std::mt19937& gen, double lo, double hi) { return rdem_test::uniform(gen, lo, hi); }

Q randomRotation(std::mt19937& gen) { return rdem_test::randomQuaternion<double>(gen); }

V3 randomUnit(std::mt19937& gen)
{
	V3 v(uniform(gen, -1, 1), uniform(gen, -1, 1), uniform(gen, -1, 1));
	return v.normalized();
}

// Largest displacement of the 8 vertices of a box of half-extents h between (x0, q0) and (x1, q1): the largest of any
// of its points, since a point's displacement (x1 - x0) + (R1 - R0) p is affine in p and its norm convex.
double vertexTravel(const V3& h, const V3& x0, const Q& q0, const V3& x1, const Q& q1)
{
	double m = 0;
	for (int v = 0; v < 8; ++v) {
		const V3 p((v & 1) ? h[0] : -h[0], (v & 2) ? h[1] : -h[1], (v & 4) ? h[2] : -h[2]);
		m = std::max(m, ((x1 + q1 * p) - (x0 + q0 * p)).norm());
	}
	return m;
}

Block blockAt(const V3& x, const Q& q, const V3& h) { return Block { x, q.toRotationMatrix(), h }; }

TEST(SeparationBound, TravelOfATranslationIsItsLength)
{
	const Q q = Q(Eigen::AngleAxisd(0.3, V3(1, 2, 3).normalized()));
	EXPECT_NEAR(rdem::rigidTravel<double>(V3(1, 1, 1), q, V3(1.1, 1.2, 1.2), q, 5.0), 0.3, 1e-15);
	// q and -q are the same orientation: no rotation.
	EXPECT_NEAR(rdem::rigidTravel<double>(V3::Zero(), q, V3::Zero(), Q(-q.coeffs()), 5.0), 0.0, 1e-15);
}

TEST(SeparationBound, TravelBoundsEveryVertexAndIsTightForSmallRotations)
{
	// 2000 random motions (rotations of any angle up to π, translations up to 1 m) of random boxes: the bound is never
	// below the exact largest vertex displacement.
	std::mt19937 gen(20261124);
	for (int k = 0; k < 2000; ++k) {
		const V3 h(uniform(gen, 0.1, 1), uniform(gen, 0.1, 1), uniform(gen, 0.1, 1));
		const V3 x0(uniform(gen, -1, 1), uniform(gen, -1, 1), uniform(gen, -1, 1));
		const V3 x1 = x0 + uniform(gen, 0, 1) * randomUnit(gen);
		const Q  q0 = randomRotation(gen), q1 = k % 2 ? randomRotation(gen) : Q(-randomRotation(gen).coeffs());
		EXPECT_GE(rdem::rigidTravel<double>(x0, q0, x1, q1, h.norm()) + 1e-12, vertexTravel(h, x0, q0, x1, q1)) << "motion " << k;
	}
	// A rotation by θ = 1e-3 about an axis normal to a vertex's arm moves that vertex by the chord 2ρ sin(θ/2); the bound
	// 4ρ sin(θ/4) exceeds it by 1/cos(θ/4) - 1 ≈ θ²/32 = 3e-8 relative.
	const V3     h(0.5, 0.5, 0.5);
	const Q      q0    = Q::Identity();
	const Q      q1    = Q(Eigen::AngleAxisd(1e-3, V3(1, -1, 0).normalized()));
	const double exact = vertexTravel(h, V3::Zero(), q0, V3::Zero(), q1);
	EXPECT_NEAR(exact, 2 * h.norm() * std::sin(0.5e-3), 1e-15);
	EXPECT_NEAR(rdem::rigidTravel<double>(V3::Zero(), q0, V3::Zero(), q1, h.norm()) / exact - 1, 0, 1e-7);
}

TEST(SeparationBound, NoSlackForBlocksThatOverlapOrTouch)
{
	const V3 h(0.5, 0.5, 0.5);
	// Overlapping by 0.1 m along x.
	EXPECT_LT(rdem::separationSlack(rdem::BlockPair<double>(blockAt(V3::Zero(), Q::Identity(), h), blockAt(V3(0.9, 0.2, 0), Q::Identity(), h)), tol), 0);
	// Edge neighbours of a grid, touching along an edge: no certificate (the margin, 1.7e-6 m here, exceeds tol).
	EXPECT_LT(rdem::separationSlack(rdem::BlockPair<double>(blockAt(V3::Zero(), Q::Identity(), h), blockAt(V3(1, 0, 1), Q::Identity(), h)), tol), 0);
}

TEST(SeparationBound, SlackOfAGapIsTheGapLessTheMargin)
{
	// Edge neighbours of a grid under compression along z with lateral expansion: apart by g = 1e-4 m along x (and
	// overlapping along z). The slack is g + tol - 1e-6 (|h_A| + |h_B|).
	const V3     h(0.5, 0.5, 0.5);
	const double g = 1e-4;
	const Block  A = blockAt(V3::Zero(), Q::Identity(), h), B = blockAt(V3(1 + g, 0, 1 - 1e-3), Q::Identity(), h);
	const double slack = rdem::separationSlack(rdem::BlockPair<double>(A, B), tol);
	EXPECT_NEAR(slack, g + tol - 2e-6 * h.norm(), 1e-12);
	// Not vacuous: B moved towards A along x by the slack plus the margin and 2 tol overlaps on every axis.
	const Block closer = blockAt(B.pos - (slack + 2e-6 * h.norm() + 2 * tol) * V3::UnitX(), Q::Identity(), h);
	EXPECT_TRUE(rdem::blocksOverlap(rdem::BlockPair<double>(A, closer), tol));
}

TEST(SeparationBound, EdgeToEdgeGapGetsNoCertificate)
{
	// Two unit cubes with crossed edges: A turned 45° about x (its top edge along x at z = √2/2), B turned 45° about y
	// and lifted so that its lowest edge (along y) is g above A's. Every face axis overlaps (on A's (0, 1, 1)/√2, B's
	// projection reaches down to 1 + g/√2 - 0.854 < 0.5), so only the cross product x × y = z separates them, by g:
	// apart, but no certificate (the face normals give none): tested again at every step.
	const V3                      h(0.5, 0.5, 0.5);
	const double                  g = 1e-3, margin = 2e-6 * h.norm();
	const Block                   A = blockAt(V3::Zero(), Q(Eigen::AngleAxisd(M_PI / 4, V3::UnitX())), h);
	const Q                       qB(Eigen::AngleAxisd(M_PI / 4, V3::UnitY()));
	const Block                   B = blockAt(V3(0, 0, std::sqrt(2.0) + g), qB, h);
	const rdem::BlockPair<double> pair(A, B);
	for (int i = 0; i < 3; ++i) {
		EXPECT_LT(tol - pair.overlapA(i), 0) << "face axis " << i << " of A";
		EXPECT_LT(tol - pair.overlapB(i), 0) << "face axis " << i << " of B";
	}
	EXPECT_FALSE(rdem::blocksOverlap(pair, tol));
	EXPECT_LT(rdem::separationSlack(pair, tol), 0);
	EXPECT_TRUE(rdem::blocksOverlap(rdem::BlockPair<double>(A, blockAt(B.pos - (g + margin + 2 * tol) * V3::UnitZ(), qB, h)), tol)); // not vacuous
}

TEST(SeparationBound, AFaceAxisThatCertifiesGivesItsOwnSlack)
{
	// B turned by 0.1 rad and 0.2 m beyond A's +x face: A's x axis separates them (B reaches about 0.06 m further
	// along x than unturned): the slack is the largest over the face normals.
	const V3     h(0.5, 0.5, 0.5);
	const double g = 0.2;
	const Block  A = blockAt(V3::Zero(), Q::Identity(), h), B = blockAt(V3(1 + g, 0.3, -0.2), Q(Eigen::AngleAxisd(0.1, V3(1, 2, 3).normalized())), h);
	const rdem::BlockPair<double> pair(A, B);
	double                        face = -1e9;
	for (int i = 0; i < 3; ++i)
		face = std::max(face, std::max(tol - pair.overlapA(i), tol - pair.overlapB(i)));
	EXPECT_GT(face, 0);
	EXPECT_EQ(rdem::separationSlack(pair, tol), face - 1e-6 * (A.half.norm() + B.half.norm()));
}

/// A block with its centre in [-c, c]³ m, a random rotation and half-extents in [0.2, 1] m.
Block randomBlock(std::mt19937& gen, double c)
{
	return Block { V3(uniform(gen, -c, c), uniform(gen, -c, c), uniform(gen, -c, c)),
		       randomRotation(gen).toRotationMatrix(),
		       V3(uniform(gen, 0.2, 1), uniform(gen, 0.2, 1), uniform(gen, 0.2, 1)) };
}

// Moves a block rigidly: its centre by `shift`, its orientation by q, about its centre.
Block moved(const Block& b, const V3& shift, const Q& q) { return Block { b.pos + shift, q.toRotationMatrix() * b.rot, b.half }; }

TEST(SeparationBound, CertifiedPairsStayApartUnderAnyMotionWithinTheSlack)
{
	// Random pairs (general rotations, half-extents 0.2-1 m, B's centre in [-2, 2]³ m). For every pair with a
	// certificate: (1) 20 random rigid motions of both blocks whose travels add up to a random fraction of the slack;
	// (2) the worst translations: B towards A along each of the 15 test axes, and A towards B, by 0.999 of the slack.
	// blocksOverlap must stay false every time.
	std::mt19937 gen(17);
	int          certified = 0;
	for (int k = 0; k < 4000; ++k) {
		const Block                   A = randomBlock(gen, 0.5);
		const Block                   B = randomBlock(gen, 2);
		const rdem::BlockPair<double> pair(A, B);
		const double                  slack = rdem::separationSlack(pair, tol);
		if (!(slack > 0)) continue;
		++certified;
		ASSERT_FALSE(rdem::blocksOverlap(pair, tol)) << "pair " << k;
		for (int m = 0; m < 20; ++m) {
			// Rotation angles and shifts drawn, then scaled so that travel(A) + travel(B) = f · slack.
			const Q qa      = Q(Eigen::AngleAxisd(uniform(gen, 0, 0.5), randomUnit(gen))),
			        qb      = Q(Eigen::AngleAxisd(uniform(gen, 0, 0.5), randomUnit(gen)));
			const V3     sa = uniform(gen, 0, 1) * randomUnit(gen), sb = uniform(gen, 0, 1) * randomUnit(gen);
			const double ta = rdem::rigidTravel<double>(V3::Zero(), Q::Identity(), sa, qa, A.half.norm());
			const double tb = rdem::rigidTravel<double>(V3::Zero(), Q::Identity(), sb, qb, B.half.norm());
			const double f  = uniform(gen, 0, 0.99) * slack / (ta + tb);
			/* Rotation angles and shifts scaled by f: a travel grows by at most 1/f · sin(fθ/4)/sin(θ/4) ≤ (θ/4)/sin(θ/4) ≤
			   1.0027 times f for θ ≤ 0.5, so the motion stays within 0.99 · 1.0027 < 1 of the slack (asserted below). */
			const Eigen::AngleAxisd aa(qa), ab(qb);
			const Block             A2 = moved(A, f * sa, Q(Eigen::AngleAxisd(f * aa.angle(), aa.axis())));
			const Block             B2 = moved(B, f * sb, Q(Eigen::AngleAxisd(f * ab.angle(), ab.axis())));
			ASSERT_LT(
			        rdem::rigidTravel<double>(A.pos, Q(A.rot), A2.pos, Q(A2.rot), A.half.norm())
			                + rdem::rigidTravel<double>(B.pos, Q(B.rot), B2.pos, Q(B2.rot), B.half.norm()),
			        slack);
			EXPECT_FALSE(rdem::blocksOverlap(rdem::BlockPair<double>(A2, B2), tol)) << "pair " << k << ", motion " << m;
		}
		for (int i = 0; i < 15; ++i) {
			V3 axis = i < 3 ? V3(A.rot.col(i)) : i < 6 ? V3(B.rot.col(i - 3)) : V3(A.rot.col((i - 6) / 3).cross(B.rot.col((i - 6) % 3)));
			if (axis.norm() < 1e-6) continue;
			axis.normalize();
			if (axis.dot(B.pos - A.pos) < 0) axis = -axis; // from A to B
			const double d = 0.999 * slack;
			EXPECT_FALSE(rdem::blocksOverlap(rdem::BlockPair<double>(A, moved(B, -d * axis, Q::Identity())), tol))
			        << "pair " << k << ", axis " << i;
			EXPECT_FALSE(rdem::blocksOverlap(rdem::BlockPair<double>(moved(A, d * axis, Q::Identity()), B), tol)) << "pair " << k << ", axis " << i;
		}
	}
	EXPECT_GT(certified, 1000); // the trials do exercise certificates
}

} // namespace

TEST(SeparationBound, SampleOutsideIsTheDistanceBeyondTheGrownBox)
{
	const V3 h(0.5, 0.25, 0.125);
	EXPECT_NEAR(rdem::sampleOutside<double>(h, V3(0.7, 0, 0)), 0.2 - 0.5e-9, 1e-15);
	EXPECT_NEAR(rdem::sampleOutside<double>(h, V3(0.1, -0.35, 0.2)), 0.1 - 0.25e-9, 1e-15); // the largest over the axes
	EXPECT_LT(rdem::sampleOutside<double>(h, V3(0.1, 0.1, 0.1)), 0);                        // inside
}

TEST(SeparationBound, ASampleOutsideByMoreThanTheTravelsStaysOutside)
{
	/* Random blocks Y (general rotations, half-extents 0.2-1 m) and sample points p of another block X (at distance up
	   to ρ_X = |h_X| from X's centre) that lie outside Y: after 20 random rigid motions of X and Y whose travels add up
	   to less than sampleOutside less separationMargin, sampleDepthLocal (along a random direction) never finds p
	   inside the moved Y. Points and motions are drawn so that many lie within a few travels of Y's surface. */
	std::mt19937 gen(2026);
	int          tested = 0;
	for (int k = 0; k < 3000; ++k) {
		const Block  Y = randomBlock(gen, 0.5);
		const V3     hX(uniform(gen, 0.2, 1), uniform(gen, 0.2, 1), uniform(gen, 0.2, 1));
		const V3     xX = Y.pos + Y.rot * V3(uniform(gen, -1.5, 1.5), uniform(gen, -1.5, 1.5), uniform(gen, -1.5, 1.5));
		const Q      qX = randomRotation(gen);
		const V3     local(uniform(gen, -hX[0], hX[0]), uniform(gen, -hX[1], hX[1]), uniform(gen, -hX[2], hX[2])); // p in X's frame
		const V3     p   = xX + qX * local;
		const double out = rdem::sampleOutside<double>(Y.half, Y.rot.transpose() * (p - Y.pos));
		if (!(out > 0)) continue;
		const double margin = 1e-6 * (hX.norm() + Y.half.norm());
		if (!(out > margin)) continue;
		++tested;
		for (int m = 0; m < 20; ++m) {
			const Q qa      = Q(Eigen::AngleAxisd(uniform(gen, 0, 0.5), randomUnit(gen))),
			        qb      = Q(Eigen::AngleAxisd(uniform(gen, 0, 0.5), randomUnit(gen)));
			const V3     sa = uniform(gen, 0, 1) * randomUnit(gen), sb = uniform(gen, 0, 1) * randomUnit(gen);
			const double ta = rdem::rigidTravel<double>(V3::Zero(), Q::Identity(), sa, qa, hX.norm());
			const double tb = rdem::rigidTravel<double>(V3::Zero(), Q::Identity(), sb, qb, Y.half.norm());
			const double f  = uniform(gen, 0, 0.99) * (out - margin) / (ta + tb);
			// Scaled as in CertifiedPairsStayApartUnderAnyMotionWithinTheSlack (a travel grows by at most 1.0027 f).
			const Eigen::AngleAxisd aa(qa), ab(qb);
			const Q                 ra(Eigen::AngleAxisd(f * aa.angle(), aa.axis())), rb(Eigen::AngleAxisd(f * ab.angle(), ab.axis()));
			const V3                p2 = xX + f * sa + ra * (qX * local);
			const Block             Y2 = moved(Y, f * sb, rb);
			ASSERT_LT(
			        rdem::rigidTravel<double>(xX, qX, xX + f * sa, ra * qX, hX.norm())
			                + rdem::rigidTravel<double>(Y.pos, Q(Y.rot), Y2.pos, Q(Y2.rot), Y.half.norm()),
			        out - margin);
			EXPECT_FALSE(rdem::sampleDepthLocal<double>(Y2.half, Y2.rot.transpose() * (p2 - Y2.pos), Y2.rot.transpose() * randomUnit(gen)).hit)
			        << "point " << k << ", motion " << m;
		}
	}
	EXPECT_GT(tested, 1000);
}

TEST(SeparationBound, FaceAxisOverlapIsBlockPairsWithinItsRoundOffBound)
{
	// Random pairs (general rotations, half-extents 0.2-1 m, centres in [-50, 50]³ m, so that |x| sets the round-off):
	// faceAxisOverlap on each of the 6 face axes against BlockPair::overlapA/overlapB. The difference is round-off,
	// measured here at most a few 1e-15 of the bound's sum; the bound (faceAxisRoundOff, 1e-12 of it) must hold with a
	// factor of 100 to spare. faceSeparation's axis is the face axis of least overlap.
	std::mt19937 gen(20261127);
	double       worst = 0; // largest |difference| / bound
	for (int k = 0; k < 4000; ++k) {
		const double c = k % 2 ? 50 : 0.5;
		const V3     xA(uniform(gen, -c, c), uniform(gen, -c, c), uniform(gen, -c, c));
		const V3     xB = xA + V3(uniform(gen, -2, 2), uniform(gen, -2, 2), uniform(gen, -2, 2));
		const Q      qA = randomRotation(gen), qB = randomRotation(gen);
		const V3     hA(uniform(gen, 0.2, 1), uniform(gen, 0.2, 1), uniform(gen, 0.2, 1)),
		        hB(uniform(gen, 0.2, 1), uniform(gen, 0.2, 1), uniform(gen, 0.2, 1));
		const Block                   A = blockAt(xA, qA, hA), B = blockAt(xB, qB, hB);
		const rdem::BlockPair<double> pair(A, B);
		const double                  bound = rdem::faceAxisRoundOff<double>(xA, hA, xB, hB);
		double                        least = 1e300;
		for (int axis = 0; axis < 6; ++axis) {
			const double o = axis < 3 ? pair.overlapA(axis) : pair.overlapB(axis - 3);
			worst          = std::max(worst, std::abs(rdem::faceAxisOverlap<double>(xA, qA, hA, xB, qB, hB, axis) - o) / bound);
			least          = std::min(least, o);
		}
		const int axis = rdem::faceSeparation(pair, tol).axis;
		EXPECT_EQ(axis < 3 ? pair.overlapA(axis) : pair.overlapB(axis - 3), least) << "pair " << k;
	}
	EXPECT_LT(worst, 1e-2);
	EXPECT_GT(worst, 0); // not vacuous: the two formulas do round differently
}

TEST(SeparationBound, AWitnessBelowTheToleranceMeansBlocksOverlapIsFalse)
{
	// Grid neighbours of a dry stack, 2 cm blocks near (0.3, 0.2, 0.1) m: edge neighbours (along x and z) pressed
	// into each other along z by d, with x touching (overlap e along x, from -1e-10 to 2e-11 m, tol = 1e-11 m), turned
	// by up to 1e-10 rad (a turn of 1e-6 rad would widen their projections by 1e-8 m, far beyond tol). Where the witness (faceSeparation's axis) is below tol less the round-off bound,
	// blocksOverlap is false; a witness above tol means the full test decides.
	std::mt19937 gen(5);
	const V3     h(0.01, 0.01, 0.01);
	const double tolGrid = 1e-9 * 0.01;
	int          decided = 0;
	for (int k = 0; k < 2000; ++k) {
		const V3     xA(0.3, 0.2, 0.1);
		const double e = uniform(gen, -1e-10, 2e-11), d = uniform(gen, 0, 1e-7);
		const V3     xB = xA + V3(0.02 - e, uniform(gen, -1e-8, 1e-8), 0.02 - d);
		const Q      qA(Eigen::AngleAxisd(uniform(gen, 0, 1e-10), randomUnit(gen))), qB(Eigen::AngleAxisd(uniform(gen, 0, 1e-10), randomUnit(gen)));
		const rdem::BlockPair<double> pair(blockAt(xA, qA, h), blockAt(xB, qB, h));
		const int                     axis = rdem::faceSeparation(pair, tolGrid).axis;
		const auto                    v    = rdem::witnessVerdict<double>(xA, qA, h, xB, qB, h, axis);
		const double                  o    = rdem::faceAxisOverlap<double>(xA, qA, h, xB, qB, h, axis);
		EXPECT_EQ(v.slack, tolGrid - o - rdem::faceAxisRoundOff<double>(xA, h, xB, h)) << "pair " << k;
		if (v.apart) {
			++decided;
			EXPECT_FALSE(rdem::blocksOverlap(pair, tolGrid)) << "pair " << k;
			EXPECT_FALSE(rdem::certifiableSlack<double>(v.slack, h, h)) << "touching pairs make no certificate, pair " << k;
		}
	}
	EXPECT_GT(decided, 1500); // most pairs touch within the tolerance and are decided by the witness (91 % of e)
}

TEST(SeparationBound, AWitnessGapMakesACertificateOnlyBeyondTheMargin)
{
	// Two 2 cm blocks side by side along x, turned together by a random rotation, with a gap g between their faces:
	// the witness axis (A's x axis) is apart with the slack tol + g less the round-off bound (faceAxisOverlap is -g
	// to round-off, ~1e-17 m here), and the slack makes a certificate once it exceeds separationMargin, 1e-6 of the
	// half-extents' norms (3.5e-8 m), not below it. A gap of -2 tol (pressed together) is not apart.
	std::mt19937 gen(11);
	const V3     h(0.01, 0.01, 0.01);
	const double tolGrid = rdem::touchTolerance<double>(h, h), margin = rdem::separationMargin<double>(h, h);
	EXPECT_EQ(tolGrid, 1e-9 * 0.01);
	for (int k = 0; k < 200; ++k) {
		const Q      q = randomRotation(gen);
		const V3     xA(uniform(gen, -1, 1), uniform(gen, -1, 1), uniform(gen, -1, 1));
		const double g   = k % 4 == 0 ? -2 * tolGrid : std::pow(10.0, uniform(gen, -10, -5));
		const V3     xB  = xA + q * V3(0.02 + g, 0, 0);
		const auto   v   = rdem::witnessVerdict<double>(xA, q, h, xB, q, h, 0);
		const double eps = rdem::faceAxisRoundOff<double>(xA, h, xB, h);
		EXPECT_NEAR(v.slack, tolGrid + g - eps, 1e-15) << "gap " << g;
		EXPECT_EQ(v.apart, g > 0) << "gap " << g;
		if (std::abs(v.slack - margin) > 1e-15) {
			EXPECT_EQ(rdem::certifiableSlack<double>(v.slack, h, h), v.slack > margin) << "gap " << g;
		}
	}
}
