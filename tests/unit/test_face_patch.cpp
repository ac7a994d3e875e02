/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/FacePatch.hpp: clipping, shoelace areas and centroids against closed forms, the patch of
   two blocks face to face against analytic overlaps, and on random configurations: the spring points' tributary areas
   sum to the patch area and have its first moments, and the patch equals the clip done the other way round (A's face
   clipped by the half-planes of B's projected face). Lengths O(0.1-1) m, a few dozen operations: 1e-12 relative (of
   the areas, m²; of lengths, m) covers round-off. */
#include <pkg/rdem/math/FacePatch.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace {

using rdem_test::Scalar;
namespace rdem = yade::rdem;
using V3       = rdem_test::Vector3;
using M3       = rdem_test::Matrix3;
using P2       = rdem::Point2<Scalar>;
using Poly     = rdem::Polygon2<Scalar>;
using Block    = rdem::OrientedBlock<Scalar>;

constexpr Scalar tol = 1e-12;

Poly square(Scalar h) { return { P2(-h, -h), P2(h, -h), P2(h, h), P2(-h, h) }; }

M3 rotation(Scalar angle, const V3& axis) { return Eigen::AngleAxis<Scalar>(angle, axis.normalized()).toRotationMatrix(); }

TEST(FacePatch, ShoelaceAreaAndCentroid)
{
	// Triangle (0,0), (2,0), (0,1): area 1, centroid (2/3, 1/3); clockwise: area -1.
	const Poly tri { P2(0, 0), P2(2, 0), P2(0, 1) };
	EXPECT_NEAR(rdem::polygonArea<Scalar>(tri), 1, tol);
	EXPECT_NEAR((rdem::polygonCentroid<Scalar>(tri) - P2(Scalar(2) / 3, Scalar(1) / 3)).norm(), 0, tol);
	EXPECT_NEAR(rdem::polygonArea<Scalar>(Poly(tri.rbegin(), tri.rend())), -1, tol);
}

TEST(FacePatch, ClipToBoxIsTheAnalyticOverlap)
{
	// Square of half-size 1 shifted by (0.3, -0.5), clipped by the square of half-size 1: (2-0.3)(2-0.5) = 2.55.
	Poly p = square(1);
	for (auto& q : p)
		q += P2(0.3, -0.5);
	const auto c = rdem::clipToBox<Scalar>(p, P2(-1, -1), P2(1, 1));
	EXPECT_NEAR(rdem::polygonArea<Scalar>(c), 1.7 * 1.5, tol);
	EXPECT_NEAR((rdem::polygonCentroid<Scalar>(c) - P2(0.15, -0.25)).norm(), 0, tol);
	// Apart: empty.
	for (auto& q : p)
		q += P2(3, 0);
	EXPECT_TRUE(rdem::clipToBox<Scalar>(p, P2(-1, -1), P2(1, 1)).empty());
	// The square turned by 45° about its centre: a regular octagon of inradius 1, area 8 tan(π/8) = 8(√2 - 1).
	Poly d;
	for (const auto& q : square(1))
		d.push_back(Eigen::Rotation2D<Scalar>(std::atan(Scalar(1))) * q);
	EXPECT_NEAR(rdem::polygonArea<Scalar>(rdem::clipToBox<Scalar>(d, P2(-1, -1), P2(1, 1))), 8 * (std::sqrt(Scalar(2)) - 1), tol);
}

TEST(FacePatch, PointsOfARectangleAreTheTrapezoidNodes)
{
	// Rectangle [0, 0.4] × [0, 0.2], m = 2: the 3×3 trapezoid nodes, weights cell area × {¼, ½, 1}, cell 0.2 × 0.1.
	const Poly rect { P2(0, 0), P2(0.4, 0), P2(0.4, 0.2), P2(0, 0.2) };
	const auto pts = rdem::patchPoints<Scalar>(rect, 2);
	ASSERT_EQ(pts.size(), 9u);
	for (const auto& q : pts) {
		const int edges = (std::abs(q.pos.x() - 0.2) > 1e-9) + (std::abs(q.pos.y() - 0.1) > 1e-9); // 2: corner, 1: edge, 0: centre
		EXPECT_NEAR(q.area, 0.02 * (edges == 2 ? 0.25 : edges == 1 ? 0.5 : 1), tol) << q.pos.transpose();
	}
}

/// Sum of the areas and of their first moments of the points, against the polygon's.
void expectExactMoments(const Poly& p, int m)
{
	const auto pts  = rdem::patchPoints<Scalar>(p, m);
	const auto area = rdem::polygonArea<Scalar>(p);
	Scalar     sum  = 0;
	P2         mom  = P2::Zero();
	for (const auto& q : pts) {
		EXPECT_GT(q.area, 0);
		sum += q.area;
		mom += q.area * q.pos;
	}
	EXPECT_NEAR(sum, area, tol * area) << "m = " << m;
	EXPECT_NEAR((mom - area * rdem::polygonCentroid<Scalar>(p)).norm(), 0, tol * area) << "m = " << m;
}

TEST(FacePatch, PointsOfAnyPatchHaveItsAreaAndFirstMoments)
{
	Poly d;
	for (const auto& q : square(1))
		d.push_back(Eigen::Rotation2D<Scalar>(0.3) * q + P2(0.2, 0.1));
	const auto oct = rdem::clipToBox<Scalar>(d, P2(-1, -1), P2(1, 1));
	for (int m = 1; m <= 5; ++m)
		expectExactMoments(oct, m);
	// m = 1: the whole patch is one cut cell, whose area goes to its vertices (cutCellPoints), not to one point: a patch
	// must resist a moment.
	EXPECT_EQ(rdem::patchPoints<Scalar>(oct, 1).size(), oct.size());
}

Block block(const V3& pos, const M3& rot, const V3& half) { return Block { pos, rot, half }; }

TEST(FacePatch, StackedBlocksOffsetAndOverlapping)
{
	// A: 0.4 × 0.2 × 0.1 m at the origin; B: 0.2 × 0.2 × 0.1 m on top, shifted by (0.15, 0.05), sunk 1 µm into A.
	const V3    hA(0.2, 0.1, 0.05), hB(0.1, 0.1, 0.05);
	const Block A  = block(V3::Zero(), M3::Identity(), hA);
	const Block B  = block(V3(0.15, 0.05, 0.1 - 1e-6), M3::Identity(), hB);
	const auto  fp = rdem::facePatch<Scalar>(A, B, 2, 1e-6, 1e-3);
	ASSERT_TRUE(fp.found);
	EXPECT_EQ(fp.faceA.k, 2);
	EXPECT_EQ(fp.faceA.s, 1);
	EXPECT_EQ(fp.faceB.k, 2);
	EXPECT_EQ(fp.faceB.s, -1);
	EXPECT_NEAR(fp.gap, -1e-6, tol);
	// Overlap in x: [0.05, 0.2], in y: [-0.05, 0.1]: 0.15 × 0.15.
	EXPECT_NEAR(fp.area, 0.0225, tol * 0.0225);
	Scalar sum = 0;
	for (size_t i = 0; i < fp.point1.size(); ++i) {
		sum += fp.pointArea[i];
		EXPECT_NEAR(fp.point1[i].z(), 0.05, tol);
		EXPECT_NEAR(fp.point2[i].z(), 0.05 - 1e-6, tol);
		EXPECT_NEAR((fp.point2[i] - fp.point1[i]).head<2>().norm(), 0, tol);
	}
	EXPECT_NEAR(sum, 0.0225, tol * 0.0225);
	EXPECT_EQ(fp.point1.size(), 9u); // an aligned rectangle: the 3×3 trapezoid nodes
}

TEST(FacePatch, NotFaceToFace)
{
	const V3    h(0.1, 0.1, 0.1);
	const Block A = block(V3::Zero(), M3::Identity(), h);
	// Tilted by 0.01 rad about x: 1 - cos = 5e-5 beyond an angle tolerance of 1e-5, within one of 1e-4.
	const Block B = block(V3(0, 0, 0.2), rotation(0.01, V3::UnitX()), h);
	EXPECT_FALSE(rdem::facePatch<Scalar>(A, B, 2, 1e-5, 1e-3).found);
	EXPECT_TRUE(rdem::facePatch<Scalar>(A, B, 2, 1e-4, 1e-3).found);
	// Face to face but 2 mm apart, beyond a gap tolerance of 1 mm.
	EXPECT_FALSE(rdem::facePatch<Scalar>(A, block(V3(0, 0, 0.202), M3::Identity(), h), 2, 1e-5, 1e-3).found);
	// Side by side along x, not touching in the face plane (0.05 m apart in y beyond the faces).
	EXPECT_FALSE(rdem::facePatch<Scalar>(A, block(V3(0, 0.25, 0.2), M3::Identity(), h), 2, 1e-5, 1e-3).found);
}

/// A's face rectangle clipped by the half-planes of B's face projected on A's face plane: the patch computed the other
/// way round.
Scalar reverseClipArea(const Block& A, const Block& B, const rdem::BlockFace<Scalar>& fa, const rdem::BlockFace<Scalar>& fb)
{
	const int k = fa.k, k1 = (k + 1) % 3, k2 = (k + 2) % 3, j = fb.k, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
	const V3  cA = fa.centre(A), cB = fb.centre(B), t1 = A.rot.col(k1), t2 = A.rot.col(k2);
	Poly      quad;
	for (const auto& c : { P2(-1, -1), P2(1, -1), P2(1, 1), P2(-1, 1) }) {
		const V3 x = cB - cA + c.x() * B.half[j1] * B.rot.col(j1) + c.y() * B.half[j2] * B.rot.col(j2);
		quad.push_back(P2(x.dot(t1), x.dot(t2)));
	}
	if (rdem::polygonArea<Scalar>(quad) < 0) std::reverse(quad.begin(), quad.end());
	Poly rect = square(1);
	for (auto& q : rect)
		q = q.cwiseProduct(P2(A.half[k1], A.half[k2]));
	for (size_t i = 0; i < 4 && !rect.empty(); ++i) { // inside of a counter-clockwise edge PQ: (Q - P)⊥ · (x - P) ≥ 0
		const P2 P = quad[i], Q = quad[(i + 1) % 4], a(Q.y() - P.y(), P.x() - Q.x());
		rect = rdem::clipHalfPlane<Scalar>(rect, a, a.dot(P));
	}
	return rect.size() >= 3 ? rdem::polygonArea<Scalar>(rect) : Scalar(0);
}

TEST(FacePatch, RandomFaceToFaceConfigurations)
{
	std::mt19937                           gen(25);
	std::uniform_real_distribution<Scalar> u(-1, 1);
	int                                    found = 0;
	for (int trial = 0; trial < 500; ++trial) {
		const M3    RA = rotation(3 * u(gen), V3(u(gen), u(gen), u(gen)));
		const V3    hA(0.1 + 0.05 * u(gen), 0.1 + 0.05 * u(gen), 0.1 + 0.05 * u(gen));
		const V3    hB(0.1 + 0.05 * u(gen), 0.1 + 0.05 * u(gen), 0.1 + 0.05 * u(gen));
		const Block A = block(V3(u(gen), u(gen), u(gen)), RA, hA);
		// B on A's face +z (A's frame), yawed, shifted in plane, overlapping or apart by up to 10 µm, tilted by up to 1e-3 rad.
		const int k           = trial % 3;
		const M3  yaw         = rotation(3 * u(gen), V3::Unit(k));
		const M3  tilt        = rotation(1e-3 * u(gen), V3::Unit((k + 1) % 3));
		const M3  RB          = RA * tilt * yaw;
		V3        off         = 0.15 * V3(u(gen), u(gen), u(gen));
		off[k]                = hA[k] + hB[k] + 1e-5 * u(gen);
		const Block  B        = block(A.pos + RA * off, RB, hB);
		const auto   fp       = rdem::facePatch<Scalar>(A, B, 1 + trial % 4, 1e-6, 1e-3);
		const Scalar expected = reverseClipArea(A, B, { k, 1 }, { k, -1 }); // A's face +k, B's face -k
		if (!fp.found) {
			EXPECT_LT(expected, 1e-12) << "trial " << trial; // missed only if the faces do not overlap
			continue;
		}
		++found;
		EXPECT_EQ(fp.faceA.k, k);
		EXPECT_NEAR(fp.area, expected, tol * 0.1) << "trial " << trial;
		Scalar sum = 0;
		V3     mom = V3::Zero();
		for (size_t i = 0; i < fp.point1.size(); ++i) {
			sum += fp.pointArea[i];
			mom += fp.pointArea[i] * fp.point1[i];
			// P2 lies on B's face plane, straight along A's normal from P1.
			EXPECT_NEAR((fp.point2[i] - fp.faceB.centre(B)).dot(fp.faceB.normal(B)), 0, tol) << "trial " << trial;
			EXPECT_NEAR((fp.point2[i] - fp.point1[i]).cross(fp.faceA.normal(A)).norm(), 0, tol) << "trial " << trial;
		}
		EXPECT_NEAR(sum, fp.area, tol * 0.1);
		const auto c2 = rdem::polygonCentroid<Scalar>(fp.polygon);
		const V3   c3 = fp.faceA.centre(A) + c2.x() * RA.col((k + 1) % 3) + c2.y() * RA.col((k + 2) % 3);
		EXPECT_NEAR((mom - fp.area * c3).norm(), 0, tol * 0.1) << "trial " << trial;
	}
	EXPECT_GT(found, 300); // most configurations overlap
}

} // namespace

TEST(FacePatch, HandOverScalesKeepTheElasticEnergy)
{
	// new springs that would store more (a sliver patch handed to vertex samples: 6.67 times) are scaled down alike;
	// ones that would store less get their compressions scaled up with the shear kept; either way the scaled energy,
	// scaleN² afterN + scaleS² afterS, is the old one (to round-off)
	const Scalar cases[][3] = { { 1.0, 5.0, 1.67 }, { 6.0, 1.0, 0.5 }, { 2.0, 2.0, 0.0 }, { 3.0, 0.0, 3.0 }, { 1e-9, 4e-9, 2e-9 } };
	for (const auto& c : cases) {
		const auto s = rdem::handOverScales<Scalar>(c[0], c[1], c[2]);
		EXPECT_NEAR(double(s.first * s.first * c[1] + s.second * s.second * c[2]), double(c[0]), 1e-14 * double(c[0])) << c[0] << ' ' << c[1];
		if (c[1] + c[2] > c[0]) EXPECT_EQ(s.first, s.second); // down alike
		else
			EXPECT_EQ(s.second, Scalar(1)); // the shear kept
	}
	// without a compressed new spring nothing is scaled up (the energy is not restored: there is nothing to hold it)
	const auto none = rdem::handOverScales<Scalar>(2.0, 0.0, 1.0);
	EXPECT_EQ(none.first, Scalar(1));
	EXPECT_EQ(none.second, Scalar(1));
}
