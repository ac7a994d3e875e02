/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/BlockGeometry.hpp: the face shared by two oriented boxes and the depth of a point
   inside a box. Blocks are unit cubes (or 1 × 0.6 × 0.8 boxes) with coordinates O(1) m, so round-off is ~1e-16 m
   and the 1e-12 m tolerances used below leave a margin of 10⁴ while being far below any geometric offset tested. */
#include <pkg/rdem/math/BlockGeometry.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace {

namespace rdem = yade::rdem;
using V3    = Eigen::Vector3d;
using M3    = Eigen::Matrix3d;
using Block = rdem::OrientedBlock<double>;

constexpr double gapTol   = 1e-6; // [m], the tolerance passed to findSharedFace
constexpr double angleTol = 1e-6; // |cos| ≥ 1 - 1e-6, i.e. edges aligned within ~1.4e-3 rad
constexpr double geomTol  = 1e-12; // [m] round-off on O(1) coordinates (see the file header)

Block cube(const V3& pos, const M3& rot = M3::Identity()) { return { pos, rot, V3(0.5, 0.5, 0.5) }; }

M3 rotX(double angle) { return Eigen::AngleAxisd(angle, V3::UnitX()).toRotationMatrix(); }

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
	EXPECT_FALSE(rdem::findSharedFace(cube(V3::Zero()), cube(V3(1 + 1e-3, 0, 0)), 1e-4, angleTol).found);
	EXPECT_TRUE(rdem::findSharedFace(cube(V3::Zero()), cube(V3(1 + 1e-3, 0, 0)), 2e-3, angleTol).found);
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
	const double hy = std::abs(f.t1.y()) > 0.5 ? f.h1 : f.h2, hz = std::abs(f.t1.y()) > 0.5 ? f.h2 : f.h1;
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
	const auto h = rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0), Eigen::AngleAxisd(M_PI, V3::UnitZ()).toRotationMatrix()),
	                                   gapTol, angleTol);
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
	        rdem::findSharedFace(cube(V3::Zero()), cube(V3(1, 0, 0), Eigen::AngleAxisd(M_PI / 6, V3::UnitZ()).toRotationMatrix()), gapTol, angleTol)
	                .found);
}

TEST(BlockGeometry, ResultIsCovariantUnderARigidMotion)
{
	// Reference configuration: partial overlap with a non-cubic, 90°-rotated B (the harder case above), then move
	// everything by x -> Q x + t with an arbitrary rotation Q.
	const Block           A0 { V3::Zero(), M3::Identity(), V3(0.5, 0.5, 0.5) };
	const Block           B0 { V3(1, 0.3, -0.1), rotX(M_PI / 2), V3(0.5, 0.3, 0.4) };
	const M3              Q = Eigen::AngleAxisd(1.234, V3(0.3, -0.8, 0.52).normalized()).toRotationMatrix();
	const V3              t(10.0, -3.0, 7.5);
	const Block           A { Q * A0.pos + t, Q * A0.rot, A0.half };
	const Block           B { Q * B0.pos + t, Q * B0.rot, B0.half };
	const auto            f0 = rdem::findSharedFace(A0, B0, gapTol, angleTol);
	const auto            f  = rdem::findSharedFace(A, B, gapTol, angleTol);
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

TEST(BlockGeometry, PenetrationDepth)
{
	const Block box { V3::Zero(), M3::Identity(), V3(1, 2, 3) };
	V3          n;
	// Centre: nearest faces are the x faces at distance 1; q_x = 0 >= 0 picks +x.
	EXPECT_EQ(rdem::penetrationDepth(box, V3::Zero().eval(), n), 1.0); // exact: 1 - |0|
	EXPECT_EQ(n, V3::UnitX());
	// Slightly towards -x: depth 0.99 through the -x face (1 - 0.01 has one rounding: 1e-15).
	EXPECT_NEAR(rdem::penetrationDepth(box, V3(-0.01, 0, 0), n), 0.99, 1e-15);
	EXPECT_EQ(n, -V3::UnitX());
	// (0.2, 1.5, 0.1): distances 0.8, 0.5, 2.9: nearest face +y at depth 0.5.
	EXPECT_NEAR(rdem::penetrationDepth(box, V3(0.2, 1.5, 0.1), n), 0.5, 1e-15);
	EXPECT_EQ(n, V3::UnitY());
	// (0.1, -0.3, -2.95): nearest -z face, depth 0.05 (3 - 2.95 rounds at 1e-15 absolute).
	EXPECT_NEAR(rdem::penetrationDepth(box, V3(0.1, -0.3, -2.95), n), 0.05, 1e-15);
	EXPECT_EQ(n, -V3::UnitZ());
	// Outside: (1.5, 0, 0) is 0.5 beyond the +x face: depth -0.5.
	EXPECT_NEAR(rdem::penetrationDepth(box, V3(1.5, 0, 0), n), -0.5, 1e-15);
	EXPECT_EQ(n, V3::UnitX());
	// Outside diagonally beyond a corner: the most negative distance, (1.5, 2.5, 0): -0.5 for both x and y, depth -0.5.
	EXPECT_NEAR(rdem::penetrationDepth(box, V3(1.5, 2.5, 0), n), -0.5, 1e-15);
	EXPECT_NEAR(rdem::penetrationDepth(box, V3(1.5, 3.0, 0), n), -1.0, 1e-15); // y is further out: -1
	EXPECT_EQ(n, V3::UnitY());
	// On the surface: depth 0.
	EXPECT_EQ(rdem::penetrationDepth(box, V3(0, 0, 3), n), 0.0);
}

TEST(BlockGeometry, PenetrationDepthInRotatedBox)
{
	// The same box rotated by Q and moved to c: a point given in body coordinates q maps to c + Q q and must give the
	// same depth, with the normal rotated. Coordinates O(5) m: 1e-14 m round-off.
	const M3    Q = Eigen::AngleAxisd(0.9, V3(1, 2, -1).normalized()).toRotationMatrix();
	const V3    c(2.0, -1.0, 4.0);
	const Block box { c, Q, V3(1, 2, 3) };
	V3          n;
	EXPECT_NEAR(rdem::penetrationDepth(box, (c + Q * V3(0.2, 1.5, 0.1)).eval(), n), 0.5, 1e-14);
	EXPECT_NEAR((n - Q.col(1)).norm(), 0, 1e-14);
	EXPECT_NEAR(rdem::penetrationDepth(box, (c + Q * V3(-0.7, 0.2, 0.3)).eval(), n), 0.3, 1e-14);
	EXPECT_NEAR((n + Q.col(0)).norm(), 0, 1e-14);
	EXPECT_NEAR(rdem::penetrationDepth(box, (c + Q * V3(0.0, 0.0, -3.4)).eval(), n), -0.4, 1e-14);
	EXPECT_NEAR((n + Q.col(2)).norm(), 0, 1e-14);
	// A point at distance 0.5 along the global x axis from the centre is NOT at depth 0.5 (the box is rotated):
	// the body coordinates are Qᵀ(0.5, 0, 0), and the depth is min_k (h_k - |q_k|).
	const V3 q = Q.transpose() * V3(0.5, 0, 0);
	double   expected = 1e9;
	for (int k = 0; k < 3; ++k)
		expected = std::min(expected, box.half[k] - std::abs(q[k]));
	EXPECT_NEAR(rdem::penetrationDepth(box, (c + V3(0.5, 0, 0)).eval(), n), expected, 1e-14);
}

} // namespace
