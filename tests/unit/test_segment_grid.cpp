/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/SegmentGrid.hpp: the n×n segment centres of a face (paper §3.1, Fig. 2a) and the
   (n+1)×(n+1) trapezoid-rule sample points. Faces are tilted in space so that mixing up t1/t2 or h1/h2 shows. */
#include <pkg/rdem/math/SegmentGrid.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace {

using rdem_test::Scalar;

namespace rdem = yade::rdem;
using V3       = rdem_test::Vector3;

// A tilted face: centre c, orthonormal in-plane axes t1, t2 (columns of a rotation), half-sizes 0.3 × 0.2 m.
struct Face {
	V3     c, t1, t2;
	Scalar h1, h2;
};

Face tiltedFace()
{
	const rdem_test::Matrix3 Q = Eigen::AngleAxis<Scalar>(0.7, V3(1, -2, 0.5).normalized()).toRotationMatrix();
	return { V3(1.5, -0.25, 2.0), Q.col(0), Q.col(1), 0.3, 0.2 };
}

// Sizes: face area 4·0.3·0.2 = 0.24 m², coordinates O(1) m. Round-off of sums of at most 16 terms: 1e-14 relative.
constexpr Scalar tol = 1e-14;

TEST(SegmentGrid, CentresTileTheFace)
{
	const Face f = tiltedFace();
	for (int n = 1; n <= 3; ++n) {
		const auto pts = rdem::segmentCentres<Scalar>(f.c, f.t1, f.t2, f.h1, f.h2, n);
		ASSERT_EQ(pts.size(), size_t(n * n));
		Scalar area     = 0;
		V3     centroid = V3::Zero();
		for (const auto& p : pts) {
			// every segment has the same area 0.24/n²; a single division: 1e-15 relative
			EXPECT_NEAR(p.weight, 0.24 / (n * n), 1e-15 * 0.24);
			area += p.weight;
			centroid += p.weight * p.pos;
			// lies in the face plane (normal t1×t2), within the rectangle
			const V3 d = p.pos - f.c;
			EXPECT_NEAR(d.dot(f.t1.cross(f.t2)), 0, tol);
			EXPECT_LT(std::abs(d.dot(f.t1)), f.h1);
			EXPECT_LT(std::abs(d.dot(f.t2)), f.h2);
		}
		EXPECT_NEAR(area, 0.24, tol * 0.24) << "n = " << n;
		centroid /= area;
		EXPECT_NEAR((centroid - f.c).norm(), 0, tol * f.c.norm()) << "n = " << n;
	}
}

TEST(SegmentGrid, CentresForNEquals2ByHand)
{
	// Axis-aligned face at c = (1,2,3), t1 = x, t2 = y, h1 = 0.4, h2 = 0.1: segments of 0.4 × 0.1, centres at
	// c ± 0.2 x ± 0.05 y, in the order (i over t1, j over t2): (-,-), (-,+), (+,-), (+,+); areas 0.04.
	const auto pts = rdem::segmentCentres<Scalar>(V3(1, 2, 3), V3::UnitX(), V3::UnitY(), 0.4, 0.1, 2);
	ASSERT_EQ(pts.size(), 4u);
	const V3 expected[4] = { V3(0.8, 1.95, 3), V3(0.8, 2.05, 3), V3(1.2, 1.95, 3), V3(1.2, 2.05, 3) };
	for (int k = 0; k < 4; ++k) {
		// coordinates O(1) after 3 roundings: 1e-15 absolute [m]
		EXPECT_NEAR((pts[k].pos - expected[k]).norm(), 0, 1e-15 * 4) << "point " << k;
		EXPECT_NEAR(pts[k].weight, 0.04, 1e-15 * 0.04);
	}
	// n = 1: the single centre is the face centre, weight the whole area 4·0.4·0.1 = 0.16.
	const auto one = rdem::segmentCentres<Scalar>(V3(1, 2, 3), V3::UnitX(), V3::UnitY(), 0.4, 0.1, 1);
	ASSERT_EQ(one.size(), 1u);
	EXPECT_EQ(one[0].pos, V3(1, 2, 3)); // s = r = 0 exactly
	EXPECT_NEAR(one[0].weight, 0.16, 1e-15 * 0.16);
}

// Segment k = i n + j sits at (s_i, s_j), s_i = 2i + 1 - n: row-major, as RdemPhys::segState is indexed.
TEST(SegmentGrid, CoordinatesOfSegmentIndex)
{
	const auto c = rdem::segmentCoordinates<Scalar>(5, 3); // i = 1, j = 2
	EXPECT_EQ(c[0], Scalar(0));
	EXPECT_EQ(c[1], Scalar(2));
	const auto first = rdem::segmentCoordinates<Scalar>(0, 2), last = rdem::segmentCoordinates<Scalar>(3, 2);
	EXPECT_EQ(first[0], Scalar(-1));
	EXPECT_EQ(first[1], Scalar(-1));
	EXPECT_EQ(last[0], Scalar(1));
	EXPECT_EQ(last[1], Scalar(1));
}

TEST(SegmentGrid, SamplePointsTrapezoidWeights)
{
	const Face f = tiltedFace();
	for (int n = 1; n <= 4; ++n) {
		const auto pts = rdem::faceSamplePoints<Scalar>(f.c, f.t1, f.t2, f.h1, f.h2, n);
		ASSERT_EQ(pts.size(), size_t((n + 1) * (n + 1)));
		const Scalar segment = 0.24 / (n * n);
		Scalar       sum     = 0;
		for (const auto& p : pts) {
			const V3     d = p.pos - f.c;
			const Scalar s = d.dot(f.t1) / f.h1, r = d.dot(f.t2) / f.h2; // in [-1, 1]
			const bool   edgeS = std::abs(std::abs(s) - 1) < 1e-12, edgeR = std::abs(std::abs(r) - 1) < 1e-12;
			// corner ¼, edge ½, interior 1 segment area; one product: 1e-15 relative
			const Scalar factor = edgeS && edgeR ? 0.25 : (edgeS || edgeR ? 0.5 : 1.0);
			EXPECT_NEAR(p.weight, factor * segment, 1e-15 * segment) << "n = " << n << " s = " << s << " r = " << r;
			EXPECT_LE(std::abs(s), 1 + 1e-12);
			EXPECT_LE(std::abs(r), 1 + 1e-12);
			sum += p.weight;
		}
		EXPECT_NEAR(sum, 0.24, tol * 0.24) << "n = " << n;
	}
	// n = 2 on an axis-aligned face of 2 × 2: weights 0.25 (corners), 0.5 (edge midpoints), 1 (centre), sum 4.
	const auto pts = rdem::faceSamplePoints<Scalar>(V3::Zero(), V3::UnitX(), V3::UnitY(), 1.0, 1.0, 2);
	ASSERT_EQ(pts.size(), 9u);
	const Scalar expected[9] = { 0.25, 0.5, 0.25, 0.5, 1.0, 0.5, 0.25, 0.5, 0.25 };
	for (int k = 0; k < 9; ++k)
		EXPECT_EQ(pts[k].weight, expected[k]) << "point " << k; // products of 1, 0.5: exact
	EXPECT_EQ(pts[0].pos, V3(-1, -1, 0));
	EXPECT_EQ(pts[4].pos, V3(0, 0, 0));
	EXPECT_EQ(pts[8].pos, V3(1, 1, 0));
}

TEST(SegmentGrid, TrapezoidRuleIntegratesLinearAndBilinearExactly)
{
	const Face f = tiltedFace();
	// f(x) = a + g·x is linear in space, hence linear in (s, r) on the face: ∫ f dA = area · f(centre).
	const Scalar a = 0.7;
	const V3     g(2.0, -1.5, 0.25);
	const Scalar exact = 0.24 * (a + g.dot(f.c));
	// A bilinear function of the face coordinates, f = (x-c)·t1 · (x-c)·t2 = s·r, integrates to 0.
	for (int n = 1; n <= 5; ++n) {
		Scalar linear = 0, bilinear = 0, midpointLinear = 0;
		for (const auto& p : rdem::faceSamplePoints<Scalar>(f.c, f.t1, f.t2, f.h1, f.h2, n)) {
			linear += p.weight * (a + g.dot(p.pos));
			const V3 d = p.pos - f.c;
			bilinear += p.weight * d.dot(f.t1) * d.dot(f.t2);
		}
		for (const auto& p : rdem::segmentCentres<Scalar>(f.c, f.t1, f.t2, f.h1, f.h2, n))
			midpointLinear += p.weight * (a + g.dot(p.pos));
		// |f| ≤ ~6 over the face: sums of ≤ 36 terms, 1e-14 relative to the integral (≈ 0.65)
		EXPECT_NEAR(linear, exact, tol * 6) << "n = " << n;
		EXPECT_NEAR(midpointLinear, exact, tol * 6) << "n = " << n;
		// (x-c)·t1 (x-c)·t2 = s·r is odd in s: integral 0; |f| ≤ 0.06, 1e-14 relative
		EXPECT_NEAR(bilinear, 0, tol * 0.06) << "n = " << n;
	}
	// The trapezoid rule is NOT exact for s², and must show exactly its known error: ∫ s² dA = (2h1³/3)·2h2 = 0.0072.
	for (int n = 1; n <= 3; ++n) {
		Scalar q = 0;
		for (const auto& p : rdem::faceSamplePoints<Scalar>(f.c, f.t1, f.t2, f.h1, f.h2, n)) {
			const Scalar s = (p.pos - f.c).dot(f.t1);
			q += p.weight * s * s;
		}
		// Composite trapezoid error for s² on [-h, h] with step H = 2h/n: (2h)·H²/6; times the other extent 2h2.
		const Scalar H = 2 * f.h1 / n, expected = 0.0072 + 2 * f.h2 * (2 * f.h1) * H * H / 6;
		EXPECT_NEAR(q, expected, tol * expected) << "n = " << n; // round-off only, 1e-14 relative
	}
}

TEST(SegmentGrid, TrapezoidNodesOnMinusOneToOne)
{
	// n = 2: nodes -1, 0, 1 with factors ½, 1, ½ (exact in binary); for every n the weights w·2/n sum to the length 2
	// and the rule integrates x exactly (0, by symmetry).
	const Scalar x[] = { -1, 0, 1 }, w[] = { 0.5, 1, 0.5 };
	for (int i = 0; i <= 2; ++i) {
		EXPECT_EQ(rdem::trapezoidNode<Scalar>(i, 2).x, x[i]);
		EXPECT_EQ(rdem::trapezoidNode<Scalar>(i, 2).w, w[i]);
	}
	for (int n = 1; n <= 6; ++n) {
		Scalar length = 0, moment = 0;
		for (int i = 0; i <= n; ++i) {
			const auto node = rdem::trapezoidNode<Scalar>(i, n);
			length += node.w * 2 / n;
			moment += node.w * 2 / n * node.x;
		}
		EXPECT_NEAR(length, 2, 1e-15) << "n = " << n;
		EXPECT_NEAR(moment, 0, 1e-15) << "n = " << n;
	}
}

// A bonded face in the frames of its two blocks, made from the face in global coordinates at bonding time.
struct BondedFace {
	rdem_test::Matrix3 R1, R2; // rotations of the blocks at bonding (body to global)
	V3                 x1, x2; // their centroids [m]
	V3                 c1, a1, b1, c2, a2, b2;
};

BondedFace bondedFace()
{
	const Face f = tiltedFace();
	BondedFace b;
	const int  n = 2;
	b.R1         = Eigen::AngleAxis<Scalar>(0.3, V3(0, 1, 1).normalized()).toRotationMatrix();
	b.R2         = Eigen::AngleAxis<Scalar>(-1.1, V3(2, -1, 0.3).normalized()).toRotationMatrix();
	b.x1         = f.c - 0.2 * f.t1.cross(f.t2);
	b.x2         = f.c + 0.3 * f.t1.cross(f.t2);
	const V3 a = f.h1 / n * f.t1, c = f.h2 / n * f.t2; // segment half-size vectors (global)
	b.c1 = b.R1.transpose() * (f.c - b.x1);
	b.a1 = b.R1.transpose() * a;
	b.b1 = b.R1.transpose() * c;
	b.c2 = b.R2.transpose() * (f.c - b.x2);
	b.a2 = b.R2.transpose() * a;
	b.b2 = b.R2.transpose() * c;
	return b;
}

TEST(SegmentGrid, SegmentCoordinatesAreTheCentresOfSegmentCentres)
{
	// segmentCentres puts segment (i, j) at c + s h t1 + r h' t2 with h, h' the segment half-sizes: same grid, to round-off.
	const Face f = tiltedFace();
	for (int n = 1; n <= 4; ++n) {
		const auto pts = rdem::segmentCentres<Scalar>(f.c, f.t1, f.t2, f.h1, f.h2, n);
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j) {
				const V3 p = f.c + rdem::segmentCoordinate<Scalar>(i, n) * f.h1 / n * f.t1
				        + rdem::segmentCoordinate<Scalar>(j, n) * f.h2 / n * f.t2;
				EXPECT_NEAR((pts[size_t(i * n + j)].pos - p).norm(), 0, tol * f.c.norm()) << "n = " << n << ", i = " << i << ", j = " << j;
			}
	}
	EXPECT_EQ(rdem::segmentCoordinate<Scalar>(0, 2), -1);
	EXPECT_EQ(rdem::segmentCoordinate<Scalar>(1, 2), 1);
	EXPECT_EQ(rdem::segmentCoordinate<Scalar>(1, 3), 0);
}

TEST(SegmentGrid, BondKinematicsEqualsTheMaterialPointsMovedOneByOne)
{
	// Blocks moved and rotated independently: d = P₂ - P₁ and r₂ = (P₁ + P₂)/2 - x₂ of each segment, computed from its
	// two material points one by one, against the affine form. Coordinates O(1) m, a few products: 1e-14 m.
	const BondedFace         b  = bondedFace();
	const rdem_test::Matrix3 R1 = Eigen::AngleAxis<Scalar>(0.05, V3(1, 0, 0)).toRotationMatrix() * b.R1;
	const rdem_test::Matrix3 R2 = Eigen::AngleAxis<Scalar>(-0.08, V3(0.2, 1, 0.4).normalized()).toRotationMatrix() * b.R2;
	const V3                 x1 = b.x1 + V3(0.01, -0.02, 0.005), x2 = b.x2 + V3(-0.003, 0.004, 0.02);
	const auto               kin = rdem::bondKinematics<Scalar>(R1, R2, x2 - x1, b.c1, b.a1, b.b1, b.c2, b.a2, b.b2);
	for (Scalar s : { -1.0, 1.0, 0.0, 0.5 })
		for (Scalar r : { -1.0, 1.0, -0.25 }) {
			const V3 P1 = x1 + R1 * (b.c1 + s * b.a1 + r * b.b1), P2 = x2 + R2 * (b.c2 + s * b.a2 + r * b.b2);
			EXPECT_NEAR((kin.displacement(s, r) - (P2 - P1)).norm(), 0, 1e-14) << "s = " << s << ", r = " << r;
			EXPECT_NEAR((kin.arm(s, r) - ((P1 + P2) / 2 - x2)).norm(), 0, 1e-14) << "s = " << s << ", r = " << r;
		}
	// The points have moved apart by centimetres: the test would see a sign or axis mix-up.
	EXPECT_GT(kin.displacement(1, -1).norm(), 1e-3);
}

TEST(SegmentGrid, BondKinematicsOfARigidMotionIsZero)
{
	// The pair rotated by 1 rad and moved as one body: every segment's d is zero to round-off (1e-15 relative of
	// coordinates O(1) m), and r₂ is the common material point's offset from x₂.
	const BondedFace         b  = bondedFace();
	const rdem_test::Matrix3 Q  = Eigen::AngleAxis<Scalar>(1.0, V3(1, 2, 3).normalized()).toRotationMatrix();
	const V3                 u  = V3(0.5, -1, 2);
	const V3                 x1 = Q * b.x1 + u, x2 = Q * b.x2 + u;
	const auto               kin = rdem::bondKinematics<Scalar>(Q * b.R1, Q * b.R2, x2 - x1, b.c1, b.a1, b.b1, b.c2, b.a2, b.b2);
	for (Scalar s : { -1.0, 1.0 })
		for (Scalar r : { -1.0, 1.0 }) {
			EXPECT_NEAR(kin.displacement(s, r).norm(), 0, 1e-14) << "s = " << s << ", r = " << r;
			const V3 P = x1 + Q * b.R1 * (b.c1 + s * b.a1 + r * b.b1);
			EXPECT_NEAR((kin.arm(s, r) - (P - x2)).norm(), 0, 1e-14) << "s = " << s << ", r = " << r;
		}
}

} // namespace
