/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/CrackDisplay.hpp, what the 3D view draws: segment marks by failure mode, segment quads
   (their centres must be the material points the law uses, rdem::bondKinematics), the hexahedron edges drawn for a Poisson element, and colours. */
#include <pkg/rdem/math/CrackDisplay.hpp>
#include <pkg/rdem/math/Hex8.hpp>
#include <pkg/rdem/math/SegmentGrid.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <set>

namespace {

using rdem_test::Scalar;

namespace rdem = yade::rdem;
using V3       = rdem_test::Vector3;
using rdem::SegmentMark;
using rdem::SegmentState;

// Coordinates O(1) m, sums of at most 4 terms: round-off below 1e-15 m.
constexpr Scalar tol = 1e-14;

TEST(CrackDisplay, MarkIsWhatBrokeTheSegment)
{
	EXPECT_EQ(rdem::segmentMark<Scalar>(int(SegmentState::Intact), 0), SegmentMark::None);
	EXPECT_EQ(rdem::segmentMark<Scalar>(int(SegmentState::BrokenTension), 0), SegmentMark::Tension);
	EXPECT_EQ(rdem::segmentMark<Scalar>(int(SegmentState::BrokenShear), 0), SegmentMark::Shear);
	// crushed (κ > 0) but intact: crushing; crushed then broken: what broke it
	EXPECT_EQ(rdem::segmentMark<Scalar>(int(SegmentState::Intact), 1e-6), SegmentMark::Crushing);
	EXPECT_EQ(rdem::segmentMark<Scalar>(int(SegmentState::BrokenShear), 1e-6), SegmentMark::Shear);
	EXPECT_EQ(rdem::segmentMark<Scalar>(int(SegmentState::BrokenTension), 1e-6), SegmentMark::Tension);
}

TEST(CrackDisplay, ContactIsABrokenSegmentInCompression)
{
	EXPECT_TRUE(rdem::segmentInContact<Scalar>(int(SegmentState::BrokenTension), -1e5));
	EXPECT_TRUE(rdem::segmentInContact<Scalar>(int(SegmentState::BrokenShear), -1));
	EXPECT_FALSE(rdem::segmentInContact<Scalar>(int(SegmentState::BrokenTension), 0)); // apart: the law writes σ = 0
	EXPECT_FALSE(rdem::segmentInContact<Scalar>(int(SegmentState::Intact), -1e6));     // an intact spring is no contact
}

// A tilted 2×2-segment face of half-sizes 0.3 × 0.2 m: the four quads (fill 1) tile it exactly, each centred on the
// material point P₁ of rdem::bondKinematics, and fill 0.5 halves each side about that centre.
TEST(CrackDisplay, QuadsTileTheFaceAndSitOnTheMaterialPoints)
{
	const rdem_test::Matrix3 Q = Eigen::AngleAxis<Scalar>(0.7, V3(1, -2, 0.5).normalized()).toRotationMatrix();
	const V3                 c(1.5, -0.25, 2.0);
	const int                n = 2;
	const V3                 a = 0.3 / n * Q.col(0), b = 0.2 / n * Q.col(1);
	// Body 1 at x1 with rotation R1, body 2 anywhere: P₁ = x1 + R1 (c + s a + r b) = x1 + R1 quad centre.
	const rdem_test::Matrix3 R1 = Eigen::AngleAxis<Scalar>(-0.4, V3(0.2, 1, 0.3).normalized()).toRotationMatrix();
	const V3                 x1(0.1, 0.2, -0.3), x2(0.4, -0.1, 0.2);
	const auto               kin  = rdem::bondKinematics<Scalar>(R1, R1, x2 - x1, c, a, b, c, a, b);
	Scalar                   area = 0;
	for (int i = 0; i < n; ++i)
		for (int j = 0; j < n; ++j) {
			const Scalar s = rdem::segmentCoordinate<Scalar>(i, n), r = rdem::segmentCoordinate<Scalar>(j, n);
			const auto   q      = rdem::segmentQuad<Scalar>(c, a, b, s, r, 1);
			const V3     centre = (q[0] + q[1] + q[2] + q[3]) / 4;
			// P₁ = P₂ - d, P₂ = x2 + R1(c + s a + r b) since both bodies share the face and rotation here
			const V3 P1 = x2 + R1 * (c + s * a + r * b) - kin.displacement(s, r);
			EXPECT_LT((x1 + R1 * centre - P1).norm(), tol);
			area += ((q[1] - q[0]).cross(q[3] - q[0])).norm();
			for (const V3& p : q) { // every corner lies on the face: |t1·(p-c)| ≤ 0.3, |t2·(p-c)| ≤ 0.2, n·(p-c) = 0
				EXPECT_LE(std::abs(Q.col(0).dot(p - c)), 0.3 + tol);
				EXPECT_LE(std::abs(Q.col(1).dot(p - c)), 0.2 + tol);
				EXPECT_LT(std::abs(Q.col(2).dot(p - c)), tol);
			}
			const auto h = rdem::segmentQuad<Scalar>(c, a, b, s, r, 0.5);
			EXPECT_LT(((h[2] - h[0]) - (q[2] - q[0]) / 2).norm(), tol);
			EXPECT_LT(((h[0] + h[2]) / 2 - centre).norm(), tol);
		}
	EXPECT_NEAR(area, 4 * 0.3 * 0.2, tol); // the quads cover the face once
}

TEST(CrackDisplay, HexEdgesJoinNodesThatDifferInOneIndex)
{
	// rdem::hex8Edges (Hex8.hpp) is what GlExtra_RdemPoissonElements draws
	std::set<std::pair<int, int>> distinct;
	int                           degree[8] = {};
	for (const auto& e : rdem::hex8Edges) {
		ASSERT_LT(e[0], e[1]);
		const int diff = e[0] ^ e[1];
		EXPECT_TRUE(diff == 1 || diff == 2 || diff == 4) << e[0] << "-" << e[1];
		distinct.insert({ e[0], e[1] });
		++degree[e[0]];
		++degree[e[1]];
	}
	EXPECT_EQ(distinct.size(), 12u);
	for (int d : degree)
		EXPECT_EQ(d, 3);
}

TEST(CrackDisplay, ElementColourBlendsAndClamps)
{
	const V3 intact(0.2, 0.8, 1), released(0.5, 0.5, 0.5);
	EXPECT_LT((rdem::elementColour<Scalar>(1, intact, released) - intact).norm(), tol);
	EXPECT_LT((rdem::elementColour<Scalar>(0, intact, released) - released).norm(), tol);
	EXPECT_LT((rdem::elementColour<Scalar>(0.25, intact, released) - V3(0.425, 0.575, 0.625)).norm(), tol);
	EXPECT_LT((rdem::elementColour<Scalar>(2, intact, released) - intact).norm(), tol);
	EXPECT_LT((rdem::elementColour<Scalar>(-1, intact, released) - released).norm(), tol);
}

} // namespace
