/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/BlockGeometry.hpp: the face shared by two oriented boxes, the depth of a face sample
   point in a block (sampleDepth), the contact normal of a pair (contactFaceAxis), the separating-axis overlap test
   (blocksOverlap) and the contact of two crossing edges (edgeEdgeContact). Blocks are unit cubes or
   boxes with half-extents of 0.2-3 m and coordinates O(1-10) m, so round-off is ~1e-16-1e-15 m; the 1e-12 m (1e-13 m
   after a rigid motion) tolerances leave a margin of ≥ 10² while being far below any geometric offset tested. */
#include <pkg/rdem/math/BlockGeometry.hpp>
#include <pkg/rdem/math/SegmentGrid.hpp>
#include <tests/unit/Random.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace {

using rdem_test::Scalar;

namespace rdem = yade::rdem;
using V3       = rdem_test::Vector3;
using M3       = rdem_test::Matrix3;
using Block    = rdem::OrientedBlock<Scalar>;

constexpr Scalar gapTol   = 1e-6;  // [m], the tolerance passed to findSharedFace
constexpr Scalar angleTol = 1e-6;  // |cos| ≥ 1 - 1e-6, i.e. edges aligned within ~1.4e-3 rad
constexpr Scalar geomTol  = 1e-12; // [m] round-off on O(1) coordinates (see the file header)

Block cube(const V3& pos, const M3& rot = M3::Identity()) { return { pos, rot, V3(0.5, 0.5, 0.5) }; }

M3 rotX(Scalar angle) { return Eigen::AngleAxis<Scalar>(angle, V3::UnitX()).toRotationMatrix(); }

TEST(BlockGeometry, SideBySideCubesShareTheWholeFace)
{
	const auto f = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0)), gapTol, angleTol);
	ASSERT_TRUE(f.found);
	EXPECT_EQ(f.axisA, 0);
	EXPECT_EQ(f.axisB, 0);
	EXPECT_EQ(f.signA, 1.0);  // A's +x face
	EXPECT_EQ(f.signB, -1.0); // B's -x face looks back at A
	EXPECT_NEAR((f.normal - V3::UnitX()).norm(), 0, geomTol);
	EXPECT_NEAR((f.centre - V3(0.5, 0, 0)).norm(), 0, geomTol);
	EXPECT_NEAR(f.gap, 0, geomTol);
	EXPECT_NEAR(f.h1, 0.5, geomTol);
	EXPECT_NEAR(f.h2, 0.5, geomTol);
	// t1, t2 span the face plane, unit and orthogonal to the normal
	EXPECT_NEAR(f.t1.dot(f.normal), 0, geomTol);
	EXPECT_NEAR(f.t2.dot(f.normal), 0, geomTol);
	EXPECT_NEAR(f.t1.dot(f.t2), 0, geomTol);
	EXPECT_NEAR(f.t1.norm(), 1, geomTol);
	EXPECT_NEAR(f.t2.norm(), 1, geomTol);
	// Swapping A and B flips the normal (still from A to B) and keeps the face.
	const auto g = rdem::findSharedFace(cube(V3(1, 0, 0)), cube(V3::Zero()), gapTol, angleTol);
	ASSERT_TRUE(g.found);
	EXPECT_NEAR((g.normal + V3::UnitX()).norm(), 0, geomTol);
	EXPECT_NEAR((g.centre - V3(0.5, 0, 0)).norm(), 0, geomTol);
	// Stacked along z: normal +z, centre on the interface.
	const auto h = rdem::findSharedFace(cube(V3(0, 0, 2)), cube(V3(0, 0, 3)), gapTol, angleTol);
	ASSERT_TRUE(h.found);
	EXPECT_EQ(h.axisA, 2);
	EXPECT_NEAR((h.normal - V3::UnitZ()).norm(), 0, geomTol);
	EXPECT_NEAR((h.centre - V3(0, 0, 2.5)).norm(), 0, geomTol);
}

TEST(BlockGeometry, GapWithinAndBeyondTolerance)
{
	// 1e-9 m apart (< gapTol = 1e-6): still shared, gap reported positive; coordinates of 1 m carry 1e-16 round-off,
	// so the 1e-9 gap is resolved to ~1e-16: check it to 1e-15.
	const auto apart = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1 + 1e-9, 0, 0)), gapTol, angleTol);
	ASSERT_TRUE(apart.found);
	EXPECT_NEAR(apart.gap, 1e-9, 1e-15);
	EXPECT_NEAR((apart.centre - V3(0.5 + 0.5e-9, 0, 0)).norm(), 0, 1e-15); // centre halfway across the gap
	// 1e-9 m interpenetration: found, negative gap.
	const auto over = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1 - 1e-9, 0, 0)), gapTol, angleTol);
	ASSERT_TRUE(over.found);
	EXPECT_NEAR(over.gap, -1e-9, 1e-15);
	// 1e-3 m apart, beyond the tolerance: no shared face; also not found with the looser 1e-4 tolerance.
	EXPECT_FALSE(rdem::findSharedFace(cube(V3::Zero()), cube(V3(1 + 1e-3, 0, 0)), gapTol, angleTol).found);
	EXPECT_FALSE(rdem::findSharedFace<Scalar>(cube(V3::Zero()), cube(V3(1 + 1e-3, 0, 0)), 1e-4, angleTol).found);
	EXPECT_TRUE(rdem::findSharedFace<Scalar>(cube(V3::Zero()), cube(V3(1 + 1e-3, 0, 0)), 2e-3, angleTol).found);
	// Touching only along an edge (offset by a whole face in y): zero overlap area, not a shared face.
	EXPECT_FALSE(rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 1, 0)), gapTol, angleTol).found);
}

TEST(BlockGeometry, PartialOverlapShrinksTheRectangle)
{
	// B shifted by 0.3 in y: A's face spans y ∈ [-0.5, 0.5], B's y ∈ [-0.2, 0.8]: overlap [-0.2, 0.5],
	// half-size 0.35 centred at y = 0.15; z untouched (half-size 0.5, centred at 0).
	const auto f = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0.3, 0)), gapTol, angleTol);
	ASSERT_TRUE(f.found);
	// t1 and t2 are A's y and z axes in some order and sign; read the half-sizes along each.
	const Scalar hy = std::abs(f.t1.y()) > 0.5 ? f.h1 : f.h2, hz = std::abs(f.t1.y()) > 0.5 ? f.h2 : f.h1;
	EXPECT_NEAR(hy, 0.35, geomTol);
	EXPECT_NEAR(hz, 0.5, geomTol);
	EXPECT_NEAR((f.centre - V3(0.5, 0.15, 0)).norm(), 0, geomTol);
	// Shifted in both y (0.3) and z (-0.4): overlap z ∈ [-0.5, 0.1], half 0.3 centred at z = -0.2.
	const auto g = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0.3, -0.4)), gapTol, angleTol);
	ASSERT_TRUE(g.found);
	EXPECT_NEAR(g.h1 * g.h2, 0.35 * 0.3, geomTol); // the area is independent of the t1/t2 order
	EXPECT_NEAR((g.centre - V3(0.5, 0.15, -0.2)).norm(), 0, geomTol);
	// A smaller B entirely inside A's face: the rectangle is B's face (half 0.3 × 0.4), centred on B's axis.
	const Block small { V3(0.5 + 0.2, 0.1, -0.05), M3::Identity(), V3(0.2, 0.3, 0.4) };
	const auto  s = rdem::findSharedFace(cube(V3::Zero()), small, gapTol, angleTol);
	ASSERT_TRUE(s.found);
	EXPECT_NEAR(std::abs(s.t1.y()) > 0.5 ? s.h1 : s.h2, 0.3, geomTol);
	EXPECT_NEAR(std::abs(s.t1.y()) > 0.5 ? s.h2 : s.h1, 0.4, geomTol);
	EXPECT_NEAR((s.centre - V3(0.5, 0.1, -0.05)).norm(), 0, geomTol);
}

TEST(BlockGeometry, RotatedNeighbourWithAlignedEdges)
{
	// B rotated 90° about x: edges still aligned, the shared face is unchanged.
	const auto f = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0), rotX(M_PI / 2)), gapTol, angleTol);
	ASSERT_TRUE(f.found);
	EXPECT_NEAR((f.normal - V3::UnitX()).norm(), 0, geomTol);
	EXPECT_NEAR((f.centre - V3(0.5, 0, 0)).norm(), 0, geomTol);
	EXPECT_NEAR(f.h1, 0.5, geomTol);
	EXPECT_NEAR(f.h2, 0.5, geomTol);
	// A non-cubic B (half-extents 0.5, 0.3, 0.4 along its body axes) rotated 90° about x: its body y axis lies along
	// global z and its body z axis along -y, so the shared rectangle is 0.4 (along y) × 0.3 (along z).
	const Block b { V3(1, 0, 0), rotX(M_PI / 2), V3(0.5, 0.3, 0.4) };
	const auto  g = rdem::findSharedFace(cube(V3::Zero()), b, gapTol, angleTol);
	ASSERT_TRUE(g.found);
	EXPECT_NEAR(std::abs(g.t1.y()) > 0.5 ? g.h1 : g.h2, 0.4, geomTol);
	EXPECT_NEAR(std::abs(g.t1.y()) > 0.5 ? g.h2 : g.h1, 0.3, geomTol);
	EXPECT_NEAR((g.centre - V3(0.5, 0, 0)).norm(), 0, geomTol);
	// B rotated 180° about z (its +x axis points to -x): its +x face now looks at A.
	const auto h
	        = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0), Eigen::AngleAxis<Scalar>(M_PI, V3::UnitZ()).toRotationMatrix()), gapTol, angleTol);
	ASSERT_TRUE(h.found);
	EXPECT_EQ(h.signB, 1.0);
	EXPECT_NEAR((h.centre - V3(0.5, 0, 0)).norm(), 0, geomTol);
}

TEST(BlockGeometry, MisalignedEdgesAreNotShared)
{
	// B rotated 30° about x: the x faces are parallel but the edges are 30° apart (|cos| = 0.87, 0.5 < 1 - 1e-6).
	EXPECT_FALSE(rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0), rotX(M_PI / 6)), gapTol, angleTol).found);
	// A tiny misalignment (1e-4 rad, |cos| = 1 - 5e-9) is within angleTol and still found.
	EXPECT_TRUE(rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0), rotX(1e-4)), gapTol, angleTol).found);
	// Faces not parallel (B tilted 30° about z): not found.
	EXPECT_FALSE(
	        rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0), Eigen::AngleAxis<Scalar>(M_PI / 6, V3::UnitZ()).toRotationMatrix()), gapTol, angleTol)
	                .found);
}

TEST(BlockGeometry, ResultIsCovariantUnderARigidMotion)
{
	// Reference configuration: partial overlap with a non-cubic, 90°-rotated B (the harder case above), then move
	// everything by x -> Q x + t with an arbitrary rotation Q.
	const Block A0 { V3::Zero(), M3::Identity(), V3(0.5, 0.5, 0.5) };
	const Block B0 { V3(1, 0.3, -0.1), rotX(M_PI / 2), V3(0.5, 0.3, 0.4) };
	const M3    Q = Eigen::AngleAxis<Scalar>(1.234, V3(0.3, -0.8, 0.52).normalized()).toRotationMatrix();
	const V3    t(10.0, -3.0, 7.5);
	const Block A { Q * A0.pos + t, Q * A0.rot, A0.half };
	const Block B { Q * B0.pos + t, Q * B0.rot, B0.half };
	const auto  f0 = rdem::findSharedFace(A0, B0, gapTol, angleTol);
	const auto  f  = rdem::findSharedFace(A, B, gapTol, angleTol);
	ASSERT_TRUE(f0.found);
	ASSERT_TRUE(f.found);
	// Reference result by hand: y overlap [-0.5,0.5]∩[0.3-0.4, 0.3+0.4] = [-0.1, 0.5], z overlap [-0.5,0.5]∩[-0.4,0.2].
	EXPECT_NEAR(std::abs(f0.t1.y()) > 0.5 ? f0.h1 : f0.h2, 0.3, geomTol);
	EXPECT_NEAR(std::abs(f0.t1.y()) > 0.5 ? f0.h2 : f0.h1, 0.3, geomTol);
	EXPECT_NEAR((f0.centre - V3(0.5, 0.2, -0.1)).norm(), 0, geomTol);
	// Moved: same axes, sides, sizes and gap; vectors rotated. Coordinates up to ~13 m here: 1e-12 m is still
	// ~10³ ulps.
	EXPECT_EQ(f.axisA, f0.axisA);
	EXPECT_EQ(f.axisB, f0.axisB);
	EXPECT_EQ(f.signA, f0.signA);
	EXPECT_EQ(f.signB, f0.signB);
	EXPECT_NEAR(f.gap, f0.gap, geomTol);
	EXPECT_NEAR(f.h1, f0.h1, geomTol);
	EXPECT_NEAR(f.h2, f0.h2, geomTol);
	EXPECT_NEAR((f.normal - Q * f0.normal).norm(), 0, geomTol);
	EXPECT_NEAR((f.t1 - Q * f0.t1).norm(), 0, geomTol);
	EXPECT_NEAR((f.t2 - Q * f0.t2).norm(), 0, geomTol);
	EXPECT_NEAR((f.centre - (Q * f0.centre + t)).norm(), 0, geomTol);
}

// ------------------------------------------------------------------------------------------------ sampleDepth

TEST(BlockGeometry, SampleDepthAlongAFaceNormal)
{
	// Y: box at the origin with half-extents (1, 2, 3). A block X on its +x side separates along u = +x; its sample p
	// leaves Y through the +x face (the y and z faces are parallel to u and cannot be left through).
	const Block Y { V3::Zero(), M3::Identity(), V3(1, 2, 3) };
	const V3    u   = V3::UnitX();
	auto        hit = rdem::sampleDepth(Y, V3(0.9, 0.5, 0.2), u);
	ASSERT_TRUE(hit.hit);
	EXPECT_NEAR(hit.depth, 0.1, 1e-15); // 1 - 0.9, one rounding
	// On the plane (depth 0) or outside: no contact.
	EXPECT_FALSE(rdem::sampleDepth(Y, V3(1.0, 0.5, 0.2), u).hit);
	EXPECT_FALSE(rdem::sampleDepth(Y, V3(1.1, 0.5, 0.2), u).hit);
	// Deep points: the distance to the +x face along u, 1 - (-0.8) = 1.8.
	hit = rdem::sampleDepth(Y, V3(-0.8, 0.5, 0.2), u);
	ASSERT_TRUE(hit.hit);
	EXPECT_NEAR(hit.depth, 1.8, 1e-15);
	// The opposite direction leaves through the -x face: 1 + 0.9 = 1.9.
	EXPECT_NEAR(rdem::sampleDepth(Y, V3(0.9, 0.5, 0.2), (-u).eval()).depth, 1.9, 1e-15);
}

TEST(BlockGeometry, SampleDepthRectangleIncludesEdges)
{
	const Block Y { V3::Zero(), M3::Identity(), V3(1, 2, 3) };
	const V3    u = V3::UnitX();
	// On the y edge (|q_y| = h_y = 2) and at a corner (also |q_z| = 3): inside, 0.05 below the +x face.
	EXPECT_NEAR(rdem::sampleDepth(Y, V3(0.95, 2.0, 0.0), u).depth, 0.05, 1e-15);
	EXPECT_NEAR(rdem::sampleDepth(Y, V3(0.95, -2.0, 3.0), u).depth, 0.05, 1e-15);
	// Within the relative tolerance (1e-9 · 2 = 2e-9 m) still in; 1e-6 m beyond the edge, out.
	EXPECT_TRUE(rdem::sampleDepth(Y, V3(0.95, 2.0 + 1e-9, 0.0), u).hit);
	EXPECT_FALSE(rdem::sampleDepth(Y, V3(0.95, 2.0 + 1e-6, 0.0), u).hit);
	EXPECT_FALSE(rdem::sampleDepth(Y, V3(0.95, 0.0, -3.0 - 1e-6), u).hit);
	// A looser tolerance (1e-3 relative: 2e-3 m on y) accepts the 1e-6 m overshoot.
	EXPECT_TRUE(rdem::sampleDepth<Scalar>(Y, V3(0.95, 2.0 + 1e-6, 0.0), u, 1e-3).hit);
}

TEST(BlockGeometry, SampleDepthObliqueIsContinuous)
{
	// u = (1, 1, 0)/√2 leaves Y through +x (after d_x·√2) or +y (after d_y·√2), whichever comes first.
	const Block  Y { V3::Zero(), M3::Identity(), V3(1, 2, 3) };
	const V3     u  = V3(1, 1, 0).normalized();
	const Scalar r2 = std::sqrt(2.0);
	EXPECT_NEAR(rdem::sampleDepth(Y, V3(0.9, 1.7, 0.0), u).depth, 0.1 * r2, 1e-15); // +x first: 0.1√2 < 0.3√2
	EXPECT_NEAR(rdem::sampleDepth(Y, V3(0.5, 1.9, 0.0), u).depth, 0.1 * r2, 1e-15); // +y first: 0.1√2 < 0.5√2
	// Across the switch (d_x = d_y at p = (0.7, 1.7, 0)) the depth is continuous: 0.3√2 within √2 times the shift of p.
	for (const Scalar e : { -1e-7, 0.0, 1e-7 })
		EXPECT_NEAR(rdem::sampleDepth(Y, V3(0.7 + e, 1.7, 0.0), u).depth, 0.3 * r2, 2e-7) << e;
}

TEST(BlockGeometry, SampleDepthOfFlushStackedBlocks)
{
	// Two unit cubes stacked along z (Y below, X on top), X pressed 1e-6 m into Y and separating along u = +z. The
	// samples of X's bottom face, edges and corners included (they lie on the planes of Y's side faces), leave Y
	// through its top face: depth 1e-6 for all.
	const Block  Y = cube(V3::Zero());
	const Scalar z = 0.5 - 1e-6; // bottom face of X
	for (const V3& p : { V3(0, 0, z), V3(0.5, 0, z), V3(0.5, 0.5, z), V3(-0.5, 0.5, z), V3(0.2, -0.5, z) }) {
		const auto hit = rdem::sampleDepth(Y, p, V3::UnitZ().eval());
		ASSERT_TRUE(hit.hit) << p.transpose();
		EXPECT_NEAR(hit.depth, 1e-6, 1e-15) << p.transpose(); // 0.5 - (0.5 - 1e-6): round-off of 0.5, ~1e-16 m
	}
	// Not pressed (flush, z = 0.5): depth 0, no contact.
	EXPECT_FALSE(rdem::sampleDepth(Y, V3(0.5, 0.5, 0.5), V3::UnitZ().eval()).hit);
}

TEST(BlockGeometry, SampleDepthOnTheSurfaceIsZeroWhateverTheOtherFaces)
{
	// Regression (issue 3): a block resting on Y's top face with a corner 0.28 m from Y's +x side; the corner samples of
	// its side faces lie on Y's top plane. Slightly below or above it (within the tolerance), their depth along the
	// pair's normal +z is that distance, never the 0.28 m to Y's +x face (the old nearest-face rule skipped the top
	// face there and jumped to it).
	const Block Y = cube(V3::Zero());
	for (const Scalar dz : { -1e-12, 0.0, 1e-12, 1e-10 })
		EXPECT_LE(rdem::sampleDepth(Y, V3(0.22, 0.1, 0.5 - dz), V3::UnitZ().eval()).depth, std::max<Scalar>(dz, 0.0) + 1e-16) << dz;
}

TEST(BlockGeometry, SampleDepthIsCovariantUnderARigidMotion)
{
	// The oblique case above, moved by x -> Q x + t (Y, p and u): same depths. Coordinates O(10) m: 1e-13 m budget.
	const M3     Q = Eigen::AngleAxis<Scalar>(0.9, V3(1, 2, -1).normalized()).toRotationMatrix();
	const V3     t(2.0, -1.0, 4.0);
	const Block  Y { t, Q, V3(1, 2, 3) };
	const V3     u  = Q * V3(1, 1, 0).normalized();
	const Scalar r2 = std::sqrt(2.0);
	EXPECT_NEAR(rdem::sampleDepth(Y, (Q * V3(0.9, 1.7, 0.0) + t).eval(), u).depth, 0.1 * r2, 1e-13);
	EXPECT_NEAR(rdem::sampleDepth(Y, (Q * V3(0.5, 1.9, 0.0) + t).eval(), u).depth, 0.1 * r2, 1e-13);
}

// ------------------------------------------------------------------------------------------------ faceMayEnter

TEST(BlockGeometry, FaceMayEnterCullsOnlyFacesOutsideTheSlabs)
{
	const Block Y { V3(0, 0, 0), M3::Identity(), V3(1, 2, 3) };
	// A unit square face in the plane x = 1.5, fully beyond Y's x slab: culled; in x = 0.9: kept.
	EXPECT_FALSE(rdem::faceMayEnter<Scalar>(Y, V3(1.5, 0, 0), V3(0, 1, 0), V3(0, 0, 1), 0.5, 0.5));
	EXPECT_TRUE(rdem::faceMayEnter<Scalar>(Y, V3(0.9, 0, 0), V3(0, 1, 0), V3(0, 0, 1), 0.5, 0.5));
	// Touching Y's face plane x = 1 exactly (round-off margin): kept, as sampleDepth counts points on the face as inside.
	EXPECT_TRUE(rdem::faceMayEnter<Scalar>(Y, V3(1.0, 0, 0), V3(0, 1, 0), V3(0, 0, 1), 0.5, 0.5));
	// A face tilted by 45° about z whose centre is beyond the slab but whose corner reaches into it: kept.
	const V3 t1 = V3(1, 1, 0).normalized();
	EXPECT_TRUE(rdem::faceMayEnter<Scalar>(Y, V3(1.5, 0, 0), t1, V3(0, 0, 1), 1.0, 0.5));  // reach along x: 0.707 > 0.5
	EXPECT_FALSE(rdem::faceMayEnter<Scalar>(Y, V3(1.8, 0, 0), t1, V3(0, 0, 1), 1.0, 0.5)); // 1.8 - 0.707 > 1
}

TEST(BlockGeometry, FaceMayEnterNeverCullsAFaceWithAHit)
{
	// Random blocks and faces: whenever a sample point of the face hits Y (sampleDepth, any direction), the face is not culled.
	std::mt19937                           rng(7);
	std::uniform_real_distribution<Scalar> u(-1, 1);
	int                                    hits = 0;
	for (int trial = 0; trial < 20000; ++trial) {
		const M3     Q = Eigen::AngleAxis<Scalar>(3 * u(rng), V3(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
		const Block  Y { V3(0, 0, 0), Q, V3(1 + 0.5 * u(rng), 1 + 0.5 * u(rng), 1 + 0.5 * u(rng)) };
		const M3     R  = Eigen::AngleAxis<Scalar>(3 * u(rng), V3(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
		const V3     c  = 2.5 * V3(u(rng), u(rng), u(rng));
		const Scalar h1 = 0.6 + 0.4 * u(rng), h2 = 0.6 + 0.4 * u(rng);
		const bool   kept = rdem::faceMayEnter(Y, c, V3(R.col(0)), V3(R.col(1)), h1, h2);
		for (int i = -2; i <= 2; ++i)
			for (int j = -2; j <= 2; ++j) {
				const V3 p = c + R.col(0) * (h1 * i / 2.0) + R.col(1) * (h2 * j / 2.0);
				for (const V3& dir : { V3(R.col(2)), V3(-R.col(2)), V3(Q.col(0)), V3(-Q.col(1)) })
					if (rdem::sampleDepth(Y, p, dir).hit) {
						++hits;
						ASSERT_TRUE(kept) << "trial " << trial;
					}
			}
	}
	EXPECT_GT(hits, 1000); // the trials do exercise hits
}

// ------------------------------------------------------------------------------------------------ blocksOverlap

// Independent separating-axis check from the 8 vertices of each block: the overlap of the vertex projections onto
// the axis [m] (negative: a gap).
Scalar overlapAlong(const Block& A, const Block& B, const V3& axis)
{
	const V3 a   = axis.normalized();
	Scalar   loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
	for (int v = 0; v < 8; ++v) {
		const V3     s((v & 1) ? 1 : -1, (v & 2) ? 1 : -1, (v & 4) ? 1 : -1);
		const Scalar pA = (A.pos + A.rot * s.cwiseProduct(A.half)).dot(a), pB = (B.pos + B.rot * s.cwiseProduct(B.half)).dot(a);
		loA = std::min(loA, pA);
		hiA = std::max(hiA, pA);
		loB = std::min(loB, pB);
		hiB = std::max(hiB, pB);
	}
	return std::min(hiA, hiB) - std::max(loA, loB);
}
bool separatedAlong(const Block& A, const Block& B, const V3& axis, Scalar tol) { return overlapAlong(A, B, axis) <= tol; }

// A block with a random rotation, half-extents in [0.2, 1] m and its centre in [-spread, spread]³ m, drawn from gen
// (std::mt19937 is fully specified; the mapping to [0, 1) is done here, so a seed gives the same blocks everywhere).
Block randomBlock(std::mt19937& gen, Scalar spread)
{
	const auto uniform = [&gen](Scalar lo, Scalar hi) { return rdem_test::uniform(gen, lo, hi); };
	const auto q       = rdem_test::randomQuaternion<Scalar>(gen);
	return Block { V3(uniform(-spread, spread), uniform(-spread, spread), uniform(-spread, spread)),
		       q.toRotationMatrix(),
		       V3(uniform(0.2, 1), uniform(0.2, 1), uniform(0.2, 1)) };
}

// Smallest vertex-projection overlap over the 15 separating-axis candidates; > 0 iff the boxes intersect (SAT).
Scalar minOverlap15(const Block& A, const Block& B)
{
	Scalar m = 1e300;
	for (int i = 0; i < 3; ++i) {
		m = std::min({ m, overlapAlong(A, B, A.rot.col(i)), overlapAlong(A, B, B.rot.col(i)) });
		for (int j = 0; j < 3; ++j) {
			const V3 a = A.rot.col(i).cross(B.rot.col(j));
			if (a.norm() > 1e-6) m = std::min(m, overlapAlong(A, B, a));
		}
	}
	return m;
}

TEST(BlockGeometry, BlockPairProjectionsEqualTheWorldFrameOnes)
{
	// The A-frame table (C = R_Aᵀ R_B, t = R_Aᵀ(x_B - x_A)) gives the projection overlaps along the 15 SAT axes that
	// projectionOverlap computes in global coordinates, for 50 random pairs (general rotations, unequal half-extents,
	// B's centre in [-2, 2]³ m): agreement to 1e-13 m (round-off of O(1) coordinates, ~1e-15 m, with margin).
	std::mt19937 gen(20261122);
	for (int k = 0; k < 50; ++k) {
		const Block                   A = randomBlock(gen, 0.5), B = randomBlock(gen, 2.0);
		const rdem::BlockPair<Scalar> pair(A, B);
		for (int i = 0; i < 3; ++i) {
			EXPECT_NEAR(pair.overlapA(i), rdem::projectionOverlap(A, B, V3(A.rot.col(i))), 1e-13);
			EXPECT_NEAR(pair.overlapB(i), rdem::projectionOverlap(A, B, V3(B.rot.col(i))), 1e-13);
			EXPECT_NEAR(pair.offsetB(i), (B.pos - A.pos).dot(B.rot.col(i)), 1e-13);
			for (int j = 0; j < 3; ++j) {
				const V3 axis = A.rot.col(i).cross(B.rot.col(j));
				EXPECT_NEAR(pair.crossLength(i, j), axis.norm(), 1e-13);
				EXPECT_NEAR(
				        pair.crossOverlapScaled(i, j) / pair.crossLength(i, j), rdem::projectionOverlap(A, B, V3(axis.normalized())), 1e-12);
			}
		}
	}
	// Aligned blocks: the cross products of parallel edges have length exactly 0, which blocksOverlap skips.
	const rdem::BlockPair<Scalar> aligned(cube(V3::Zero()), cube(V3(0.9, 0.3, 0)));
	for (int i = 0; i < 3; ++i)
		EXPECT_EQ(aligned.crossLength(i, i), 0);
	EXPECT_DOUBLE_EQ(aligned.overlapA(0), 0.1);
	EXPECT_DOUBLE_EQ(aligned.overlapA(1), 0.7);
}

TEST(BlockGeometry, BlocksOverlapFaceToFace)
{
	const Scalar tol = 1e-9; // [m]
	// Unit cubes along x: centres 0.9 apart overlap by 0.1; 1.0 apart touch (overlap 0, not > tol); 1.1 apart.
	EXPECT_TRUE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(0.9, 0, 0)), tol));
	EXPECT_FALSE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(1.0, 0, 0)), tol));
	EXPECT_FALSE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(1.1, 0, 0)), tol));
	// Overlap 1e-6 > tol = 1e-9: true; with tol = 1e-5 the same pair counts as touching.
	EXPECT_TRUE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(1 - 1e-6, 0, 0)), tol));
	EXPECT_FALSE(rdem::blocksOverlap<Scalar>(cube(V3::Zero()), cube(V3(1 - 1e-6, 0, 0)), 1e-5));
	// The overlap must exceed tol strictly: centres 0.75 apart overlap by exactly 0.25 (exact in binary).
	EXPECT_FALSE(rdem::blocksOverlap<Scalar>(cube(V3::Zero()), cube(V3(0.75, 0, 0)), 0.25));
	EXPECT_TRUE(rdem::blocksOverlap<Scalar>(cube(V3::Zero()), cube(V3(0.75, 0, 0)), 0.2499));
	// Grid neighbours along an edge (offset (1, 1, 0)) and a corner (1, 1, 1): touching only.
	EXPECT_FALSE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(1, 1, 0)), tol));
	EXPECT_FALSE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(1, 1, 1)), tol));
	// Rotated B (45° about z) whose corner pokes 0.05 m into A's +x face: centre at 0.5 + √2/2 - 0.05.
	const Scalar x = 0.5 + std::sqrt(0.5) - 0.05;
	EXPECT_TRUE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(x, 0, 0), Eigen::AngleAxis<Scalar>(M_PI / 4, V3::UnitZ()).toRotationMatrix()), tol));
	EXPECT_FALSE(rdem::blocksOverlap(cube(V3::Zero()), cube(V3(x + 0.1, 0, 0), Eigen::AngleAxis<Scalar>(M_PI / 4, V3::UnitZ()).toRotationMatrix()), tol));
}

TEST(BlockGeometry, BlocksOverlapNeedsTheEdgeAxes)
{
	// B = unit cube rotated by Rx(45°)·Rz(45°), centred at t·(1, 1, 0)/√2. The 6 face normals stop separating the
	// pair only beyond t = 1.5858, but an edge-edge axis separates it from t = 1.4142 on (found numerically, proved
	// below from the vertices). At t = 1.5 a face-normals-only test would wrongly report an overlap.
	const Scalar tol = 1e-9;
	const M3     RB  = (Eigen::AngleAxis<Scalar>(M_PI / 4, V3::UnitX()) * Eigen::AngleAxis<Scalar>(M_PI / 4, V3::UnitZ())).toRotationMatrix();
	const Block  A   = cube(V3::Zero());
	for (const Scalar t : { 1.3, 1.5 }) {
		SCOPED_TRACE("t = " + std::to_string(t));
		const Block B             = cube(t * V3(1, 1, 0).normalized(), RB);
		bool        faceSeparated = false, edgeSeparated = false;
		for (int i = 0; i < 3; ++i) {
			faceSeparated |= separatedAlong(A, B, A.rot.col(i), tol) || separatedAlong(A, B, B.rot.col(i), tol);
			for (int j = 0; j < 3; ++j) {
				const V3 a = A.rot.col(i).cross(B.rot.col(j));
				if (a.norm() > 1e-6) edgeSeparated |= separatedAlong(A, B, a, tol);
			}
		}
		EXPECT_FALSE(faceSeparated); // the case really needs the edge axes
		// By the separating-axis theorem (complete for boxes with these 15 axes): overlap iff no axis separates.
		EXPECT_EQ(edgeSeparated, t > 1.4142);
		EXPECT_EQ(rdem::blocksOverlap(A, B, tol), !edgeSeparated);
	}
}

TEST(BlockGeometry, BlocksOverlapAgreesWithAVertexBasedSeparatingAxisTest)
{
	// 400 pairs of boxes with general rotations, unequal half-extents in [0.2, 1] m and B's centre in [-2, 2]³ m,
	// from a fixed-seed generator (randomBlock). The reference projects the 16 vertices on the 15 SAT axes. Pairs
	// within 1e-9 m of the threshold are skipped: the two computations round differently (~1e-15 m), so only those
	// could legitimately disagree.
	std::mt19937 gen(20260122);
	const Scalar tol         = 1e-3;
	int          overlapping = 0, apart = 0;
	for (int k = 0; k < 400; ++k) {
		const Block  A = randomBlock(gen, 0.0), B = randomBlock(gen, 2.0);
		const Scalar m = minOverlap15(A, B);
		if (std::abs(m - tol) < 1e-9) continue;
		const bool expected = m > tol;
		EXPECT_EQ(rdem::blocksOverlap(A, B, tol), expected) << "pair " << k << ": min overlap " << m;
		(expected ? overlapping : apart)++;
	}
	// Both outcomes are well represented, so the comparison tests something either way.
	EXPECT_GE(overlapping, 50);
	EXPECT_GE(apart, 50);
}

// Whether A and B overlap by more than tol (blocksOverlap of the pair, with its early return), after checking that the
// table of the pair's 15 overlaps holds BlockPair's values to the bit and blocksOverlap from it decides the same.
bool overlapCheckedAgainstTheTable(const Block& A, const Block& B, Scalar tol)
{
	const rdem::BlockPair<Scalar>      pair(A, B);
	const rdem::SeparatingAxes<Scalar> sat(pair);
	for (int i = 0; i < 3; ++i) {
		EXPECT_EQ(sat.face[i], pair.overlapA(i));
		EXPECT_EQ(sat.face[i + 3], pair.overlapB(i));
		for (int j = 0; j < 3; ++j) {
			EXPECT_EQ(sat.crossLength[3 * i + j], pair.crossLength(i, j));
			EXPECT_EQ(sat.crossScaled[3 * i + j], pair.crossOverlapScaled(i, j));
		}
	}
	const bool overlap = rdem::blocksOverlap<Scalar>(pair, tol);
	EXPECT_EQ(rdem::blocksOverlap<Scalar>(sat, tol), overlap);
	return overlap;
}

TEST(BlockGeometry, SeparatingAxesTableGivesTheSameDecisionsToTheBit)
{
	// The table of a pair's 15 overlaps (SeparatingAxes), made once for a sampled contact, holds BlockPair's values to the
	// bit, and blocksOverlap from it (no early return) decides as blocksOverlap from the pair (early return at the first
	// separating axis), on 400 random pairs (general rotations, both outcomes) and on 400 grid neighbours of a wall: blocks
	// of 0.25 × 0.12 × 0.055 m half-extents offset across an edge, a corner or a face, strained into each other or apart by
	// up to 1e-6 m and turned by up to 1e-4 rad (the pairs of tests/yade that are sampled every step). The
	// tolerance is the functor's 1e-9 of the smaller half-extent; pairs on the threshold are included: the decisions must
	// agree exactly, since both compare the same numbers.
	std::mt19937 gen(20261127);
	auto         uniform     = [&gen](Scalar lo, Scalar hi) { return lo + (hi - lo) * (gen() / 4294967296.0); };
	int          overlapping = 0, apart = 0;
	for (int k = 0; k < 400; ++k) {
		const Block A = randomBlock(gen, 0.0), B = randomBlock(gen, 2.0);
		(overlapCheckedAgainstTheTable(A, B, 1e-3) ? overlapping : apart)++;
	}
	const V3 h(0.25, 0.12, 0.055);
	for (int k = 0; k < 400; ++k) {
		V3 offset, strain, axis;
		for (int i = 0; i < 3; ++i) // -1, 0 or 1 block along each axis; along the course also half a block
			offset[i] = 2 * h[i] * (int(gen() % 3) - 1) / (i == 0 && gen() % 2 ? 2 : 1);
		for (int i = 0; i < 3; ++i)
			strain[i] = uniform(-1e-6, 1e-6);
		for (int i = 0; i < 3; ++i)
			axis[i] = uniform(-1, 1);
		const Scalar angle = uniform(0, 1e-4);
		const Block  A { V3(0.3, -0.2, 1.1), M3::Identity(), h };
		const Block  B { A.pos + offset + strain, Eigen::AngleAxis<Scalar>(angle, axis.normalized()).toRotationMatrix(), h };
		(overlapCheckedAgainstTheTable(A, B, 1e-9 * h.minCoeff()) ? overlapping : apart)++;
	}
	EXPECT_GE(overlapping, 100);
	EXPECT_GE(apart, 100);
}

// ------------------------------------------------------------------------------------------------ contactFaceAxis

TEST(BlockGeometry, ContactFaceAxisOfStackedBlocks)
{
	// X on Y, pressed 1e-6 m in and shifted sideways by 0.3 and 0.2 (lateral overlaps 0.7 and 0.8 are larger): the
	// normal is +z from Y to X (-z from X to Y), the overlap 1e-6 (round-off of O(1) coordinates, ~1e-16 m).
	const Block Y = cube(V3::Zero()), X = cube(V3(0.3, 0.2, 1 - 1e-6));
	auto        axis = rdem::contactFaceAxis(Y, X);
	EXPECT_NEAR(axis.overlap, 1e-6, 1e-15);
	EXPECT_NEAR((axis.normal - V3::UnitZ()).norm(), 0, 1e-15);
	axis = rdem::contactFaceAxis(X, Y);
	EXPECT_NEAR((axis.normal + V3::UnitZ()).norm(), 0, 1e-15);
	// Shifted by 1 - 1e-7 in x: the lateral overlap 1e-7 is now the smallest, the normal turns to +x.
	axis = rdem::contactFaceAxis(Y, cube(V3(1 - 1e-7, 0.2, 1 - 1e-6)));
	EXPECT_NEAR(axis.overlap, 1e-7, 1e-15);
	EXPECT_NEAR((axis.normal - V3::UnitX()).norm(), 0, 1e-15);
}

TEST(BlockGeometry, ContactFaceAxisIsContinuousAcrossATie)
{
	// Two unit cubes touching along parallel edges (z), overlapping by ox in x and oy = 1e-3 in y. With a blend of 0.1
	// (wider than the default 1e-2, to resolve it with steps of 1e-6): below ox = oy/1.1 the normal is +x, above
	// 1.1·oy it is +y, at ox = oy it is (1, 1, 0)/√2, and it turns
	// continuously in between: the weight of the other axis changes by at most Δox·max(ox, oy)/(0.1·min(ox, oy)²)
	// ≤ 1.4e-2 per step Δox = 1e-6 over ox = 0.85-1.15 oy, and the normal turns by no more than that (a jump would be
	// π/4 rad).
	const Block  Y        = cube(V3::Zero());
	const Scalar oy       = 1e-3;
	auto         normalAt = [&](Scalar ox) { return rdem::contactFaceAxis<Scalar>(Y, cube(V3(1 - ox, 1 - oy, 0)), 0.1).normal; };
	EXPECT_NEAR((normalAt(0.9 * oy) - V3::UnitX()).norm(), 0, 1e-12);
	EXPECT_NEAR((normalAt(1.2 * oy) - V3::UnitY()).norm(), 0, 1e-12);
	EXPECT_NEAR((normalAt(oy) - V3(1, 1, 0).normalized()).norm(), 0, 1e-9); // overlaps equal up to round-off of 1 - 1e-3
	Scalar worst = 0;
	for (Scalar ox = 0.85 * oy; ox < 1.15 * oy; ox += 1e-6)
		worst = std::max(worst, (normalAt(ox + 1e-6) - normalAt(ox)).norm());
	EXPECT_LT(worst, 1.5e-2);
}

// How far B must move along the unit axis a (turned to point from A to B) to clear A, from the 8 vertices of each: the
// highest vertex projection of A minus the lowest of B [m].
Scalar penetrationAlong(const Block& A, const Block& B, const V3& axis)
{
	const V3 a  = (B.pos - A.pos).dot(axis) >= 0 ? axis.normalized() : V3(-axis.normalized());
	Scalar   hi = -1e300, lo = 1e300;
	for (int v = 0; v < 8; ++v) {
		const V3 s((v & 1) ? 1 : -1, (v & 2) ? 1 : -1, (v & 4) ? 1 : -1);
		hi = std::max(hi, (A.pos + A.rot * s.cwiseProduct(A.half)).dot(a));
		lo = std::min(lo, (B.pos + B.rot * s.cwiseProduct(B.half)).dot(a));
	}
	return hi - lo;
}

TEST(BlockGeometry, ContactFaceAxisAgreesWithVertexProjections)
{
	// Random pairs that overlap on every face axis: the normal points from A to B; where no other face axis is within
	// 10 % of the least overlapped one (almost always for random orientations) it is that axis, with the least
	// penetration computed from the vertices; the reported overlap is the vertex penetration along the normal; every
	// face sample point of one block inside the other is at most that deep along it (sampleDepth).
	std::mt19937                           rng(7);
	std::uniform_real_distribution<Scalar> U(-1, 1);
	int                                    tested = 0, single = 0;
	Scalar                                 worstRatio = 0;
	for (int trial = 0; trial < 2000; ++trial) {
		const M3    RA = Eigen::Quaternion<Scalar>(U(rng), U(rng), U(rng), U(rng)).normalized().toRotationMatrix();
		const M3    RB = Eigen::Quaternion<Scalar>(U(rng), U(rng), U(rng), U(rng)).normalized().toRotationMatrix();
		const Block A { V3::Zero(), RA, V3(0.5, 0.3 + 0.2 * U(rng), 0.6) };
		const Block B { V3(U(rng), U(rng), U(rng)), RB, V3(0.4, 0.5, 0.3 + 0.1 * U(rng)) };
		Scalar      least = 1e300, second = 1e300;
		V3          leastAxis;
		for (int i = 0; i < 6; ++i) {
			const V3     a = (i < 3 ? A : B).rot.col(i % 3);
			const Scalar o = penetrationAlong(A, B, a);
			if (o < least) {
				second    = least;
				least     = o;
				leastAxis = (B.pos - A.pos).dot(a) >= 0 ? a : V3(-a);
			} else
				second = std::min(second, o);
		}
		if (!(least > 0)) continue;
		++tested;
		const auto axis = rdem::contactFaceAxis(A, B);
		EXPECT_GE(axis.normal.dot(B.pos - A.pos), 0);
		EXPECT_NEAR(axis.normal.norm(), 1, 1e-15);
		EXPECT_NEAR(axis.overlap, penetrationAlong(A, B, axis.normal), 1e-12);
		if (second > 1.1 * least) {
			++single;
			EXPECT_NEAR((axis.normal - leastAxis).norm(), 0, 1e-12);
			EXPECT_NEAR(axis.overlap, least, 1e-12);
		}
		for (int which = 0; which < 2; ++which) {
			const Block& X = which ? B : A;
			const Block& Y = which ? A : B;
			const V3     u = which ? axis.normal : V3(-axis.normal);
			for (int k = 0; k < 3; ++k) {
				const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
				for (const Scalar s : { -1.0, 1.0 }) {
					const V3 c = X.pos + s * X.half[k] * X.rot.col(k);
					for (const auto& p : rdem::faceSamplePoints<Scalar>(c, X.rot.col(k1), X.rot.col(k2), X.half[k1], X.half[k2], 4)) {
						const auto hit = rdem::sampleDepth(Y, p.pos, u);
						if (hit.hit) worstRatio = std::max(worstRatio, hit.depth / axis.overlap);
					}
				}
			}
		}
	}
	EXPECT_GT(tested, 200);        // enough overlapping pairs among the draws
	EXPECT_GT(single, tested / 2); // and most of them with a clear least overlapped axis
	// the scaling of grazing faces in sampleDepth can raise a depth a little above the pair's overlap: 1.0047 measured
	EXPECT_LT(worstRatio, 1.05);
}

// ------------------------------------------------------------------------------------------------ edgeEdgeContact

// Two unit cubes whose edges cross at right angles, sunk d into each other: A turned 45° about x (its top is an edge
// along x at z = √2/2), B turned 45° about y (its bottom is an edge along y), B's centre at (0, 0, √2 - d).
struct CrossedEdges {
	Block A, B;
};
CrossedEdges crossedEdges(Scalar d)
{
	const M3 RA = rotX(M_PI / 4), RB = Eigen::AngleAxis<Scalar>(M_PI / 4, V3::UnitY()).toRotationMatrix();
	return { cube(V3::Zero(), RA), cube(V3(0, 0, std::sqrt(Scalar(2)) - d), RB) };
}

TEST(BlockGeometry, EdgeEdgeContactOfCrossedEdges)
{
	// The least overlapped axis is x × y = z, overlap d, far below every face axis (their overlaps are ~0.7 m): the
	// contact is at the crossing, the mid-point of the two edges' closest points (0, 0, √2/2 - d/2), normal +z (A to B),
	// depth d, which is also the penetration of the vertex projections along z.
	for (const Scalar d : { 1e-6, 1e-3, 0.01 }) {
		SCOPED_TRACE("d = " + std::to_string(d));
		const auto c   = crossedEdges(d);
		const auto hit = rdem::edgeEdgeContact<Scalar>(c.A, c.B, 1e-9);
		ASSERT_TRUE(hit.hit);
		EXPECT_NEAR((hit.normal - V3::UnitZ()).norm(), 0, geomTol);
		EXPECT_NEAR(hit.depth, d, geomTol);
		EXPECT_NEAR(hit.depth, overlapAlong(c.A, c.B, V3::UnitZ()), geomTol);
		EXPECT_NEAR((hit.point - V3(0, 0, std::sqrt(0.5) - d / 2)).norm(), 0, geomTol);
		// from B to A: the same contact point and depth, the normal reversed
		const auto back = rdem::edgeEdgeContact<Scalar>(c.B, c.A, 1e-9);
		ASSERT_TRUE(back.hit);
		EXPECT_NEAR((back.normal + V3::UnitZ()).norm(), 0, geomTol);
		EXPECT_NEAR(back.depth, d, geomTol);
		EXPECT_NEAR((back.point - hit.point).norm(), 0, geomTol);
	}
	// Crossing off the centre: B moved by (0.3, -0.2, 0) crosses A's edge at x = 0.3, 0.2 from the middle of its own
	// (both within the edges' half-length 0.5).
	auto c = crossedEdges(0.01);
	c.B.pos += V3(0.3, -0.2, 0);
	const auto hit = rdem::edgeEdgeContact<Scalar>(c.A, c.B, 1e-9);
	ASSERT_TRUE(hit.hit);
	EXPECT_NEAR((hit.point - V3(0.3, 0, std::sqrt(0.5) - 0.005)).norm(), 0, geomTol); // B's edge at x = 0.3, A's at y = 0
	EXPECT_NEAR(hit.depth, 0.01, geomTol);
}

TEST(BlockGeometry, EdgeEdgeContactIsCovariantUnderARigidMotion)
{
	// The same crossing after a rotation Q and a translation t of both blocks: point Q p + t, normal Q n, same depth.
	const auto  c0 = crossedEdges(0.01);
	const auto  h0 = rdem::edgeEdgeContact<Scalar>(c0.A, c0.B, 1e-9);
	const M3    Q  = Eigen::AngleAxis<Scalar>(1.1, V3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
	const V3    t(2.5, -1.0, 7.0);
	const Block A { Q * c0.A.pos + t, Q * c0.A.rot, c0.A.half }, B { Q * c0.B.pos + t, Q * c0.B.rot, c0.B.half };
	const auto  h = rdem::edgeEdgeContact<Scalar>(A, B, 1e-9);
	ASSERT_TRUE(h0.hit);
	ASSERT_TRUE(h.hit);
	EXPECT_NEAR(h.depth, h0.depth, 1e-13);
	EXPECT_NEAR((h.normal - Q * h0.normal).norm(), 0, 1e-13);
	EXPECT_NEAR((h.point - (Q * h0.point + t)).norm(), 0, 1e-13);
}

TEST(BlockGeometry, EdgeEdgeContactOnlyWhereFacesCannotSee)
{
	const Scalar tol = 1e-9;
	// Face to face (stacked cubes overlapping 0.1 m): the least overlap is a face axis, no edge contact.
	EXPECT_FALSE(rdem::edgeEdgeContact<Scalar>(cube(V3::Zero()), cube(V3(0, 0, 0.9)), tol).hit);
	// A corner in a face (B turned 45° about z and x, its lowest corner 0.05 m into A's top): a face axis is the least,
	// the face samples see the corner.
	const M3 R
	        = (Eigen::AngleAxis<Scalar>(std::atan(std::sqrt(Scalar(2))), V3::UnitX()) * Eigen::AngleAxis<Scalar>(M_PI / 4, V3::UnitZ())).toRotationMatrix();
	const Block B = cube(V3(0, 0, 0.5 + std::sqrt(0.75) - 0.05), R);
	EXPECT_FALSE(rdem::edgeEdgeContact<Scalar>(cube(V3::Zero()), B, tol).hit);
	// Apart (the crossed edges 0.01 m from touching) or only touching: nothing.
	EXPECT_FALSE(rdem::edgeEdgeContact<Scalar>(crossedEdges(-0.01).A, crossedEdges(-0.01).B, tol).hit);
	EXPECT_FALSE(rdem::edgeEdgeContact<Scalar>(crossedEdges(0).A, crossedEdges(0).B, tol).hit);
	// The crossing beyond the end of A's edge (B moved 0.6 m along x, A's edge ends at 0.5): B's edge passes the end
	// of A's and no edge pair crosses, so the least overlapped axis gives no point within both edges.
	auto c = crossedEdges(0.01);
	c.B.pos += V3(0.6, 0, 0);
	EXPECT_FALSE(rdem::edgeEdgeContact<Scalar>(c.A, c.B, tol).hit);
}

// ------------------------------------------------------------------------------------------------ facesCross

// Two beams 2 × 0.2 × 0.2 m laid across each other (one along x, the other along y on top of it, sunk d): they overlap,
// yet no vertex of either is in the other: faces that cross, which vertex samples cannot see.
TEST(BlockGeometry, CrossedBeamsHaveFacesThatCross)
{
	const V3 half(1, 0.1, 0.1);
	for (const Scalar d : { 1e-6, 1e-3 }) {
		SCOPED_TRACE("d = " + std::to_string(d));
		const Block A { V3::Zero(), M3::Identity(), half };
		const Block B { V3(0, 0, 0.2 - d), Eigen::AngleAxis<Scalar>(M_PI / 2, V3::UnitZ()).toRotationMatrix(), half };
		ASSERT_TRUE(rdem::blocksOverlap<Scalar>(A, B, 1e-9));
		EXPECT_FALSE(rdem::vertexInOrOn<Scalar>(A, B, 1e-9));
		EXPECT_FALSE(rdem::vertexInOrOn<Scalar>(B, A, 1e-9));
		EXPECT_TRUE(rdem::facesCross<Scalar>(A, B, 1e-9));
	}
}

// Side by side with coincident faces, pressed 1e-6 m into each other (a course's head joint), and a cube standing
// on a larger block: vertices lie on (or in) the other block, so the faces do not cross. The coincident vertices lie on
// B's edges to round-off, within the tolerance; 1e-3 m apart sideways, A's vertices leave B and B's leave A.
TEST(BlockGeometry, CoincidentOrRestingFacesDoNotCross)
{
	const Block A = cube(V3::Zero());
	EXPECT_FALSE(rdem::facesCross<Scalar>(A, cube(V3(1 - 1e-6, 0, 0)), 1e-9));
	EXPECT_FALSE(rdem::facesCross<Scalar>(A, cube(V3(1 - 1e-6, 1e-12, -1e-12)), 1e-9));
	EXPECT_FALSE(rdem::facesCross<Scalar>(A, Block { V3(0, 0, -1 + 1e-6), M3::Identity(), V3(2, 2, 0.5) }, 1e-9));
	EXPECT_TRUE(rdem::vertexInOrOn<Scalar>(A, cube(V3(1 - 1e-6, 1e-3, 0)), 1e-9)); // A's +y corners reach into B
	EXPECT_TRUE(rdem::vertexInOrOn<Scalar>(cube(V3(1 - 1e-6, 1e-3, 0)), A, 1e-9));
}


} // namespace
