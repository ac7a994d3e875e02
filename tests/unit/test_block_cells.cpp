/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/BlockCells.hpp, the Poisson cells (doc/theory.md §5.4): the condensed elasticity against
   plane-stress and uniaxial closed forms, the cell strain of uniform strain fields in interior, boundary, running-bond and
   platen blocks (exact: the cell is a divergence-theorem average of an affine field), the spring weights of the free
   faces, and the offset correction of running bond with its gradient against finite differences. */
#include <pkg/rdem/math/BlockCells.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using rdem_test::Scalar;

namespace rdem = yade::rdem;
using Vec3     = Eigen::Matrix<Scalar, 3, 1>;
using Mat3     = Eigen::Matrix<Scalar, 3, 3>;
using Bond     = rdem::CellBond<Scalar>;

constexpr Scalar E = 16.7e9, nu = 0.15; // a clay brick [Pa], [-]

Scalar lambda() { return E * nu / ((1 + nu) * (1 - 2 * nu)); }
Scalar mu() { return E / (2 * (1 + nu)); }
Scalar M() { return lambda() + 2 * mu(); }

/// The cell strain Σ coef u_n of a uniform strain ε (diagonal, block axes): each bond opens by ε_axis times its centroid distance.
Vec3 cellStrainOfUniform(const rdem::CellInput<Scalar>& in, const rdem::Cell<Scalar>& c, const Vec3& eps)
{
	Vec3 out = Vec3::Zero();
	for (size_t q = 0; q < in.bonds.size(); ++q)
		out[in.bonds[q].axis] += c.coef[q] * eps[in.bonds[q].axis] * in.bonds[q].distance;
	return c.condensation * out;
}

rdem::CellInput<Scalar> block(Scalar hx, Scalar hy, Scalar hz)
{
	rdem::CellInput<Scalar> in;
	in.half    = Vec3(hx, hy, hz);
	in.young   = E;
	in.poisson = nu;
	return in;
}

TEST(BlockCells, ElasticityAllAxesIsThePoissonPart)
{
	// Every axis resolved: D - M I is the paper's D_p (eq. 19): λ off the diagonal, 0 on it. Tolerance: a few roundings of
	// O(1e10) Pa values, 1e-15 relative.
	Mat3       C;
	const Mat3 D = rdem::cellElasticity<Scalar>(E, nu, { rdem::CellAxis::Resolved, rdem::CellAxis::Resolved, rdem::CellAxis::Half }, C);
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) {
			EXPECT_NEAR(D(i, j), i == j ? 0.0 : lambda(), 1e-15 * M()) << i << j;
			EXPECT_EQ(C(i, j), i == j ? 1.0 : 0.0);
		}
}

TEST(BlockCells, OneCondensedAxisIsPlaneStress)
{
	// No bond along y (a one-wythe wall): σ_yy = 0 condenses D to plane stress, D11 = E/(1-ν²), D13 = νE/(1-ν²); the
	// cell holds it minus M on the diagonal; ε_yy = -λ/M (ε_xx + ε_zz).
	Mat3         C;
	const Mat3   D  = rdem::cellElasticity<Scalar>(E, nu, { rdem::CellAxis::Resolved, rdem::CellAxis::Condensed, rdem::CellAxis::Resolved }, C);
	const Scalar ps = E / (1 - nu * nu), tol = 1e-14 * M();
	EXPECT_NEAR(D(0, 0), ps - M(), tol);
	EXPECT_NEAR(D(2, 2), ps - M(), tol);
	EXPECT_NEAR(D(0, 2), nu * ps, tol);
	EXPECT_EQ(D(1, 1), 0.0);
	EXPECT_EQ(D(0, 1), 0.0);
	EXPECT_NEAR(C(1, 0), -lambda() / M(), 1e-15);
	EXPECT_NEAR(C(1, 2), -lambda() / M(), 1e-15);
	EXPECT_EQ(C(1, 1), 0.0);
}

TEST(BlockCells, TwoCondensedAxesIsUniaxial)
{
	// A column of blocks: only z has bonds; condensing x and y leaves E (uniaxial stress); ε_xx = ε_yy = -ν ε_zz.
	Mat3       C;
	const Mat3 D = rdem::cellElasticity<Scalar>(E, nu, { rdem::CellAxis::Condensed, rdem::CellAxis::Condensed, rdem::CellAxis::Resolved }, C);
	EXPECT_NEAR(D(2, 2), E - M(), 1e-14 * M());
	EXPECT_NEAR(C(0, 2), -nu, 1e-14);
	EXPECT_NEAR(C(1, 2), -nu, 1e-14);
}

TEST(BlockCells, InteriorCubeAveragesItsSixBonds)
{
	// A cube of half-size h bonded to six equal cubes: each bond's share is ½ and there is no free face, so
	// coef = A·½/V = 4h²/2/8h³ = 1/(4h); no weight added. A uniform strain gives back exactly that strain.
	const Scalar h  = 0.01;
	auto         in = block(h, h, h);
	for (int d = 0; d < 3; ++d)
		for (int s : { -1, 1 })
			in.bonds.push_back(Bond { d, s, 4 * h * h, 0.5, 2 * h });
	const auto c = rdem::blockCell(in);
	EXPECT_DOUBLE_EQ(c.volume, 8 * h * h * h);
	for (size_t q = 0; q < in.bonds.size(); ++q) {
		EXPECT_NEAR(c.coef[q], 1 / (4 * h), 1e-13 / h);
		EXPECT_EQ(c.extraWeight[q], 0.0);
	}
	const Vec3 eps(1e-4, -2e-5, 3e-5);
	EXPECT_NEAR((cellStrainOfUniform(in, c, eps) - eps).norm(), 0.0, 1e-18);
}

TEST(BlockCells, FreeFaceExtrapolatesAndWeightsTheBond)
{
	// A cube whose +x face is free: the -x bond carries the strain along x alone, coef = (A/2 + h·A·A/(A·2h))/V = 1/(2h),
	// and its spring gets w_n = 1 + h·A/(2h·A) = 1.5 (doc/theory.md §5.2 for cubes).
	const Scalar h  = 0.02;
	auto         in = block(h, h, h);
	in.bonds.push_back(Bond { 0, -1, 4 * h * h, 0.5, 2 * h });
	for (int d = 1; d < 3; ++d)
		for (int s : { -1, 1 })
			in.bonds.push_back(Bond { d, s, 4 * h * h, 0.5, 2 * h });
	const auto c = rdem::blockCell(in);
	EXPECT_NEAR(c.coef[0], 1 / (2 * h), 1e-13 / h);
	EXPECT_NEAR(c.extraWeight[0], 0.5, 1e-15);
	EXPECT_NEAR(rdem::cellBondWeightNormal<Scalar>(c.lateral[0], 1, c.extraWeight[0], 0), 1.5, 1e-15);
	const Vec3 eps(-3e-5, 2e-5, 1e-4);
	EXPECT_NEAR((cellStrainOfUniform(in, c, eps) - eps).norm(), 0.0, 1e-18);
}

TEST(BlockCells, RunningBondBricksAreExact)
{
	// Stretcher 2a × 2b × 2h (a = 0.13, b = 0.06, h = 0.0325 m: a 250×120×55 brick with a 10 mm joint), in running bond:
	// two bricks above and two below, each over half the bed face; two head joints; one wythe (no bond along y).
	const Scalar a = 0.13, b = 0.06, h = 0.0325;
	auto         in = block(a, b, h);
	for (int s : { -1, 1 }) {
		in.bonds.push_back(Bond { 2, s, 2 * a * b, 0.5, 2 * h }); // half bed faces
		in.bonds.push_back(Bond { 2, s, 2 * a * b, 0.5, 2 * h });
		in.bonds.push_back(Bond { 0, s, 4 * b * h, 0.5, 2 * a }); // head joints
	}
	const auto c = rdem::blockCell(in);
	EXPECT_EQ(c.axes[1], rdem::CellAxis::Condensed);
	const Vec3 eps(2e-4, 0, -1e-3);
	Vec3       expected = eps;
	expected[1]         = -lambda() / M() * (eps[0] + eps[2]); // plane stress through the thickness
	EXPECT_NEAR((cellStrainOfUniform(in, c, eps) - expected).norm(), 0.0, 1e-17);
	// The same brick in the top course: its top face is free, and the strain along z is extrapolated from the two bonds
	// below; each gets w_n = 1 + h·(4ab)/(2h·4ab) = 1.5.
	rdem::CellInput<Scalar> top = in;
	top.bonds.erase(top.bonds.begin() + 3, top.bonds.begin() + 5); // the two bonds above
	const auto ct = rdem::blockCell(top);
	EXPECT_NEAR((cellStrainOfUniform(top, ct, eps) - expected).norm(), 0.0, 1e-17);
	EXPECT_NEAR(ct.extraWeight[0], 0.5, 1e-15);
	EXPECT_NEAR(ct.extraWeight[1], 0.5, 1e-15);
	EXPECT_EQ(ct.extraWeight[2], 0.0); // the head joint's axis has no free face
}

TEST(BlockCells, DifferentMaterialsSplitTheOpeningBySeriesCompliance)
{
	// A brick between two soft mortar blocks along z: the face point where the series springs meet is C_b/(C_b + C_m) of
	// the opening from the brick's side. For a layered field with the strain ε_b in the brick and ε_m in the mortar, the
	// openings are ε_b h_b + ε_m h_m, and if the stresses M ε are continuous (M_b ε_b = M_m ε_m) the face point is exact,
	// so the brick's cell sees ε_b.
	const Scalar hb = 0.025, hm = 0.005, Mb = M(), Mm = 2.4e9;
	const Scalar Cb = hb / Mb, Cm = hm / Mm, share = Cb / (Cb + Cm);
	auto         in = block(0.05, 0.05, hb);
	for (int s : { -1, 1 })
		in.bonds.push_back(Bond { 2, s, 0.01, share, hb + hm });
	const auto   c    = rdem::blockCell(in);
	const Scalar epsB = 1e-4, epsM = epsB * Mb / Mm, opening = epsB * hb + epsM * hm;
	EXPECT_NEAR((c.coef[0] + c.coef[1]) * opening, epsB, 1e-15);
}

TEST(BlockCells, PlatenIsAHalfCell)
{
	// A top platen cube prescribed along z, bonded below only: a half cell (V/2), coef of the bond below = A·½/(V/2) =
	// 1/(2h) as if the cell stopped at the centroid plane; its bonds along x and y have lateral ½ and so weight ½.
	const Scalar h  = 0.01;
	auto         in = block(h, h, h);
	in.prescribed   = { false, false, true };
	in.bonds.push_back(Bond { 2, -1, 4 * h * h, 0.5, 2 * h });
	for (int d = 0; d < 2; ++d)
		for (int s : { -1, 1 })
			in.bonds.push_back(Bond { d, s, 4 * h * h, 0.5, 2 * h });
	const auto c = rdem::blockCell(in);
	EXPECT_EQ(c.axes[2], rdem::CellAxis::Half);
	EXPECT_DOUBLE_EQ(c.volume, 4 * h * h * h);
	EXPECT_NEAR(c.coef[0], 1 / (2 * h), 1e-13 / h);
	EXPECT_EQ(c.extraWeight[0], 0.0);
	EXPECT_EQ(c.lateral[0], 0.5);
	EXPECT_EQ(c.lateral[2], 1.0);
	EXPECT_EQ(rdem::cellBondWeightNormal<Scalar>(c.lateral[0], 0.5, 0, 0), 0.5);
	const Vec3 eps(1e-5, 1e-5, -1e-4);
	EXPECT_NEAR((cellStrainOfUniform(in, c, eps) - eps).norm(), 0.0, 1e-18);
}

TEST(BlockCells, SliverAlongAnAxisIsNotPartOfTheCell)
{
	// A roof slab piece over a room (0.565 × 0.579 × 0.15 m, the big house of scripts/building.py): bonded to slab pieces
	// on its four sides, and on its -z face only at a 5 × 5 mm corner where a wall's top brick reaches into the joint.
	// Extrapolated from that sliver, its free ±z faces would weight the sliver's spring by
	// w_n - 1 = ℓ_z A_free/(|s| A_bonded) = 0.075·(2·0.327 - 2.5e-5)/(0.1·2.5e-5) ≈ 2·10⁴. Below a quarter of a face the
	// axis is condensed instead (σ_zz = 0, plane stress): the sliver is a plain spring (coef 0, no extra weight) and the
	// cell is the slab's plane-stress cell, exact for any uniform in-plane strain.
	const Scalar hx = 0.2825, hy = 0.28945, hz = 0.075, sliver = 0.005 * 0.005;
	auto         in = block(hx, hy, hz);
	// the brick's half height; share: the slab's side of the opening (one material)
	const Scalar hb = 0.03;
	in.bonds.push_back(Bond { 2, -1, sliver, hz / (hz + hb), hz + hb });
	for (int s : { -1, 1 }) {
		in.bonds.push_back(Bond { 0, s, 4 * hy * hz, 0.5, 2 * hx });
		in.bonds.push_back(Bond { 1, s, 4 * hx * hz, 0.5, 2 * hy });
	}
	const auto c = rdem::blockCell(in);
	EXPECT_EQ(c.axes[2], rdem::CellAxis::Condensed);
	EXPECT_EQ(c.coef[0], 0.0);
	EXPECT_EQ(c.extraWeight[0], 0.0);
	Mat3       C;
	const Mat3 D = c.volume * rdem::cellElasticity<Scalar>(E, nu, { rdem::CellAxis::Resolved, rdem::CellAxis::Resolved, rdem::CellAxis::Condensed }, C);
	EXPECT_NEAR((c.stiffness - D).norm(), 0.0, 1e-15 * D.norm());
	// a uniform in-plane strain: the cell measures it exactly (each bond opens by ε_axis |s|), and the condensation gives
	// the plane-stress ε_zz = -λ/M (ε_xx + ε_yy)
	const Vec3 eps(2e-5, -1e-5, 0);
	Vec3       expected = eps;
	expected[2]         = -lambda() / M() * (eps[0] + eps[1]);
	EXPECT_NEAR((cellStrainOfUniform(in, c, eps) - expected).norm(), 0.0, 1e-18);
	// the same piece on a quarter of its bottom face (the least overlap of a bond pattern): resolved, and the weight its
	// free faces give the bond is the bound of cellMinBondedFraction, w_n - 1 = ℓ_z (2 - ¼)/(¼ |s|) = 7 ℓ_z/|s|
	in.bonds[0].area = rdem::cellMinBondedFraction * 4 * hx * hy;
	const auto q     = rdem::blockCell(in);
	EXPECT_EQ(q.axes[2], rdem::CellAxis::Resolved);
	EXPECT_NEAR(q.extraWeight[0], 7 * hz / (hz + hb), 1e-14);
	const Vec3 eps3(2e-5, -1e-5, 3e-5);
	EXPECT_NEAR((cellStrainOfUniform(in, q, eps3) - eps3).norm(), 0.0, 1e-18);
	// a block held by a sliver only has no cell, and its bond keeps the plain spring's weight (lateral 1, no extra)
	auto only = block(hx, hy, hz);
	only.bonds.push_back(Bond { 2, -1, sliver, hz / (hz + hb), hz + hb });
	const auto n = rdem::blockCell(only);
	EXPECT_EQ(n.volume, 0.0);
	EXPECT_EQ(n.coef[0], 0.0);
	EXPECT_EQ(rdem::cellBondWeightNormal<Scalar>(n.lateral[2], 1, n.extraWeight[0], 0), 1.0);
}

TEST(BlockCells, BlockWithoutBondsHasNoCell)
{
	const auto c = rdem::blockCell(block(0.01, 0.01, 0.01));
	EXPECT_EQ(c.volume, 0.0);
	EXPECT_TRUE(c.coef.empty());
}

TEST(BlockCells, OffsetSlipOfRunningBond)
{
	// Bed joint (n = z) between bricks offset by half a brick along x, the face centre midway: a uniform strain makes
	// them translate apart by ε_xx δ_x along the face, which the correction takes out; the normal part is dropped.
	// Exact arithmetic: 1e-20 m.
	const Vec3 delta(0.13, 0.0, 0.0), n(0, 0, 1), eps(2e-4, -1e-4, -1e-3);
	const Vec3 slip = rdem::offsetSlip<Scalar>(eps, Vec3(delta / 2), Mat3::Identity(), eps, Vec3(-delta / 2), n);
	EXPECT_NEAR((slip - Vec3(2e-4 * 0.13, 0, 0)).norm(), 0.0, 1e-20);
	// No offset (a grid): no correction.
	EXPECT_EQ(rdem::offsetSlip<Scalar>(eps, Vec3::Zero(), Mat3::Identity(), eps, Vec3::Zero(), n).norm(), 0.0);
}

TEST(BlockCells, OffsetSlipOfABrickOnABeam)
{
	// A brick (half-length 0.125 m) bonded to a beam of 1.55 m whose centroid is 0.6 m away along x: the face centre is
	// the brick's, a₁ = 0, and a₂ = (-0.6, 0, 0) from the beam's centroid. A uniform strain gives ε_xx (x₂ - x₁), the
	// face-centre choice does not matter; a strain of the brick alone gives no slip at all (its material at the face
	// centre is its centroid's), whereas half the centroid offset would give ε_xx · 0.3 m. Exact arithmetic: 1e-20 m.
	const Vec3 a1(0, 0.04, 0), a2(-0.6, 0.04, 0), n(0, 0, 1), eps(2e-4, -1e-4, -1e-3), zero = Vec3::Zero();
	const Vec3 uniform = rdem::offsetSlip<Scalar>(eps, a1, Mat3::Identity(), eps, a2, n);
	EXPECT_NEAR((uniform - Vec3(2e-4 * 0.6, 0, 0)).norm(), 0.0, 1e-20);
	const Vec3 brickOnly = rdem::offsetSlip<Scalar>(Vec3(2e-4, 0, 0), a1, Mat3::Identity(), zero, a2, n);
	EXPECT_EQ(brickOnly.norm(), 0.0);
	const Vec3 beamOnly = rdem::offsetSlip<Scalar>(zero, a1, Mat3::Identity(), Vec3(2e-4, 0, 0), a2, n);
	EXPECT_NEAR((beamOnly - Vec3(2e-4 * 0.6, 0, 0)).norm(), 0.0, 1e-20);
}

TEST(BlockCells, OffsetSlipHonoursTheBlocksFrames)
{
	// Body 2 turned by 90° about z (a header next to a stretcher): its x axis is body 1's y. Its strains along its own
	// axes (ε_y, ε_x, ε_z) are body 1's (ε_x, ε_y, ε_z), and its offset in its own frame is R12ᵀ of body 1's, so the
	// slip equals that of two blocks with equal frames.
	Mat3 R12;
	R12 << 0, -1, 0, 1, 0, 0, 0, 0, 1;
	const Vec3 eps1(2e-4, -5e-5, -1e-3), eps2(-5e-5, 2e-4, -1e-3), a1(0.05, 0.03, 0), a2(-0.02, 0.01, 0), n(0, 0, 1);
	const Vec3 a = rdem::offsetSlip<Scalar>(eps1, a1, R12, eps2, Vec3(R12.transpose() * a2), n);
	const Vec3 b = rdem::offsetSlip<Scalar>(eps1, a1, Mat3::Identity(), eps1, a2, n);
	EXPECT_NEAR((a - b).norm(), 0.0, 1e-20);
}

TEST(BlockCells, OffsetSlipGradientIsTheEnergyDerivative)
{
	// W(ε₁, ε₂) = ½ k |d_t - slip(ε₁, ε₂)|² for a fixed tangential elongation d_t; T = k (d_t - slip). The analytic
	// gradient must match central differences (W is quadratic: exact up to round-off; step 1e-9 of the strain).
	Mat3 R12;
	R12 << 0, -1, 0, 1, 0, 0, 0, 0, 1;
	const Vec3   a1(0.05, 0.03, 0), a2(-0.6, 0.02, 0), n(0, 0, 1), dt(3e-6, -1e-6, 0);
	const Scalar k = 7e9;
	const Vec3   eps1(2e-4, -5e-5, -1e-3), eps2(-6e-5, 1e-4, -8e-4);
	auto         W = [&](const Vec3& e1, const Vec3& e2) { return 0.5 * k * (dt - rdem::offsetSlip<Scalar>(e1, a1, R12, e2, a2, n)).squaredNorm(); };
	const Vec3   T = k * (dt - rdem::offsetSlip<Scalar>(eps1, a1, R12, eps2, a2, n));
	Vec3         g1, g2;
	rdem::offsetSlipGradient<Scalar>(T, R12, a1, a2, g1, g2);
	const Scalar step = 1e-9;
	for (int d = 0; d < 3; ++d) {
		Vec3 e = Vec3::Zero();
		e[d]   = step;
		EXPECT_NEAR(g1[d], (W(eps1 + e, eps2) - W(eps1 - e, eps2)) / (2 * step), 1e-6 * k * 1e-6) << d;
		EXPECT_NEAR(g2[d], (W(eps1, eps2 + e) - W(eps1, eps2 - e)) / (2 * step), 1e-6 * k * 1e-6) << d;
	}
	EXPECT_NE(g1.norm(), 0.0);
	EXPECT_NE(g2.norm(), 0.0);
}

TEST(BlockCells, AlongFaceDropsTheNormalPart)
{
	const Vec3 n(0, 0, 1), c(0.1, -0.2, 0.06);
	EXPECT_EQ(rdem::alongFace<Scalar>(c, n), Vec3(0.1, -0.2, 0));
}

} // namespace
