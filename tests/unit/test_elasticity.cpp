/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/Elasticity.hpp: Lamé constants, eqs. (11)-(13), (18), (19) of the paper
   (shared/reference/paper-poisson-effect-refined-dem.txt) and the compliance of eq. (4).
   Reference values are worked out by hand in the comments (E = 30 GPa, ν = 0.2, a concrete-like material). */
#include <pkg/rdem/math/Elasticity.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <vector>

namespace {

using rdem_test::Scalar;

using yade::rdem::Matrix6;
using yade::rdem::SpringModulus;
using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
namespace rdem = yade::rdem;

constexpr Scalar E  = 30e9; // [Pa]
constexpr Scalar nu = 0.2;

// Relative closeness of two 6×6 matrices in the Frobenius norm.
::testing::AssertionResult matricesClose(const Matrix6<Scalar>& actual, const Matrix6<Scalar>& expected, Scalar relTol)
{
	const Scalar err = (actual - expected).norm(), scale = expected.norm();
	if (err <= relTol * scale) return ::testing::AssertionSuccess();
	return ::testing::AssertionFailure() << "|A - B| = " << err << " > " << relTol << " * |B| = " << relTol * scale << "\nA =\n"
	                                     << actual << "\nB =\n"
	                                     << expected;
}

TEST(Elasticity, LameConstantsAgainstHandValues)
{
	// λ = Eν/((1+ν)(1-2ν)) = 30e9·0.2/(1.2·0.6) = 25e9/3; μ = E/(2(1+ν)) = 30e9/2.4 = 12.5e9;
	// M = λ+2μ = E(1-ν)/((1+ν)(1-2ν)) = 30e9·0.8/0.72 = 100e9/3.
	// Tolerance: a handful of Scalar operations, each rounding at 1.1e-16 relative: 1e-15 relative.
	EXPECT_NEAR(rdem::lameLambda(E, nu), 25e9 / 3, 1e-15 * 25e9 / 3);
	EXPECT_NEAR(rdem::shearModulus(E, nu), 12.5e9, 1e-15 * 12.5e9);
	EXPECT_NEAR(rdem::springNormalModulus(E, nu, SpringModulus::Consistent), 100e9 / 3, 1e-15 * 100e9 / 3);
	// Paper modulus of eq. (8): E/(1-ν²) = 30e9/0.96 = 31.25e9.
	EXPECT_NEAR(rdem::springNormalModulus(E, nu, SpringModulus::Paper), 31.25e9, 1e-15 * 31.25e9);
	// ν = 0 : λ = 0 exactly and μ = E/2, M = E (uncoupled); exact in floating point.
	EXPECT_EQ(rdem::lameLambda<Scalar>(E, 0.0), 0.0);
	EXPECT_EQ(rdem::shearModulus<Scalar>(E, 0.0), E / 2);
	EXPECT_EQ(rdem::springNormalModulus<Scalar>(E, 0.0, SpringModulus::Consistent), E);
}

TEST(Elasticity, Eq11StiffnessPerArea)
{
	const Scalar ell = 0.01; // [m]
	// k_n(Paper) = E/((1-ν²)ℓ) = 31.25e9/0.01 = 3.125e12; k_n(Consistent) = (λ+2μ)/ℓ = (100e9/3)/0.01 = 1e13/3;
	// k_s = E/(2(1+ν)ℓ) = 12.5e9/0.01 = 1.25e12 [N/m³].
	// Tolerance: a handful of roundings, 1e-15 relative.
	EXPECT_NEAR(rdem::normalStiffnessPerArea(E, nu, ell, SpringModulus::Paper), 3.125e12, 1e-15 * 3.125e12);
	EXPECT_NEAR(rdem::normalStiffnessPerArea(E, nu, ell, SpringModulus::Consistent), 1e13 / 3, 1e-15 * 1e13 / 3);
	EXPECT_NEAR(rdem::shearStiffnessPerArea(E, nu, ell), 1.25e12, 1e-15 * 1.25e12);
	// k ∝ 1/ℓ: halving ℓ doubles k (exact: division by a power-of-two multiple is exact up to one rounding).
	EXPECT_NEAR(rdem::shearStiffnessPerArea(E, nu, ell / 2), 2.5e12, 1e-15 * 2.5e12);
}

TEST(Elasticity, Eq12SeriesOfIdenticalSpringsIsHalf)
{
	const Scalar k = rdem::normalStiffnessPerArea<Scalar>(E, nu, 0.01, SpringModulus::Paper);
	// 1/(1/k + 1/k) = k/2; three roundings: 1e-15 relative.
	EXPECT_NEAR(rdem::seriesStiffness(k, k), k / 2, 1e-15 * k);
	// A much stiffer partner leaves the softer spring: 1/(1/k + 1/(1e6 k)) = k/(1+1e-6).
	EXPECT_NEAR(rdem::seriesStiffness(k, 1e6 * k), k / (1 + 1e-6), 1e-15 * k);
}

TEST(Elasticity, Eq12SeriesOfDifferentMaterials)
{
	// A: E = 30 GPa, ν = 0.2, ℓ = 0.01 m; B: E = 3 GPa, ν = 0.1, ℓ = 0.005 m.
	const Scalar EA = 30e9, nuA = 0.2, ellA = 0.01, EB = 3e9, nuB = 0.1, ellB = 0.005;
	// Eq. (12) with the per-block moduli of eq. (11): k̄_n = 1/(ℓ_A/(E_A/(1-ν_A²)) + ℓ_B/(E_B/(1-ν_B²))).
	// By hand: ℓ_A(1-ν_A²)/E_A = 0.01·0.96/30e9 = 3.2e-13, ℓ_B(1-ν_B²)/E_B = 0.005·0.99/3e9 = 1.65e-12,
	// so k̄_n = 1/1.97e-12 ≈ 5.076e11 N/m³.
	// (The paper prints ℓ_A/(E_A(1-ν_A²)), which contradicts its own eq. (11); the header follows eq. (11).)
	const Scalar kA = rdem::normalStiffnessPerArea(EA, nuA, ellA, SpringModulus::Paper);
	const Scalar kB = rdem::normalStiffnessPerArea(EB, nuB, ellB, SpringModulus::Paper);
	const Scalar kn = rdem::seriesStiffness(kA, kB);
	// Tolerance: ~10 roundings along each path, 1e-14 relative.
	EXPECT_NEAR(kn, 1 / (ellA / (EA / (1 - nuA * nuA)) + ellB / (EB / (1 - nuB * nuB))), 1e-14 * kn);
	EXPECT_NEAR(kn, 1 / 1.97e-12, 1e-14 * kn);
	// Shear: ℓ_A·2(1+ν_A)/E_A = 0.01·2.4/30e9 = 8e-13, ℓ_B·2(1+ν_B)/E_B = 0.005·2.2/3e9 = 11e-12/3,
	// k̄_s = 1/(8e-13 + 11e-12/3) = 3/13.4e-12.
	const Scalar ks = rdem::seriesStiffness(rdem::shearStiffnessPerArea(EA, nuA, ellA), rdem::shearStiffnessPerArea(EB, nuB, ellB));
	EXPECT_NEAR(ks, 3 / 13.4e-12, 1e-14 * ks); // same round-off budget as above
	// Series is symmetric in A and B (the sum 1/kA + 1/kB commutes exactly).
	EXPECT_EQ(rdem::seriesStiffness(kA, kB), rdem::seriesStiffness(kB, kA));
}

TEST(Elasticity, Eq13Damping)
{
	// m_ave = ρ_A ℓ_A + ρ_B ℓ_B = 2400·0.01 + 1800·0.005 = 24 + 9 = 33 kg/m².
	// Tolerance: two products and a sum, 1e-15 relative.
	EXPECT_NEAR(rdem::equivalentMassPerArea(2400.0, 0.01, 1800.0, 0.005), 33.0, 1e-15 * 33);
	// c = 2h√(m k): with m = 4, k = 9, h = 1 (critical) c = 2·6 = 12; h = 0.25 gives 3. All exact in binary.
	EXPECT_EQ(rdem::dampingPerArea(1.0, 4.0, 9.0), 12.0);
	EXPECT_EQ(rdem::dampingPerArea(0.25, 4.0, 9.0), 3.0);
	// Realistic: h = 1, m = 33 kg/m², k = 1/1.97e-12 N/m³: c = 2√(33/1.97e-12) ≈ 8.186e6 N·s/m³.
	const Scalar c = rdem::dampingPerArea(1.0, 33.0, 1 / 1.97e-12);
	EXPECT_NEAR(c, 2 * std::sqrt(33 / 1.97e-12), 1e-15 * c); // a few roundings, 1e-15 relative
	// Critical damping of one unit of area: the characteristic polynomial m s² + c s + k has a Scalar root, c² = 4mk.
	EXPECT_NEAR(c * c, 4 * 33 / 1.97e-12, 1e-14 * c * c); // squaring doubles the relative round-off: 1e-14
	EXPECT_EQ(rdem::dampingPerArea(0.0, 33.0, 1e12), 0.0);  // h = 0: no dashpot, exactly
}

// Eq. (18) written as printed in the paper: E(1-ν)/((1+ν)(1-2ν)) times a dimensionless matrix.
Matrix6<Scalar> paperEq18(Scalar e, Scalar n)
{
	const Scalar    f = e * (1 - n) / ((1 + n) * (1 - 2 * n)), o = n / (1 - n), s = (1 - 2 * n) / (2 * (1 - n));
	Matrix6<Scalar> D;
	D << 1, o, o, 0, 0, 0, //
	        o, 1, o, 0, 0, 0, //
	        o, o, 1, 0, 0, 0, //
	        0, 0, 0, s, 0, 0, //
	        0, 0, 0, 0, s, 0, //
	        0, 0, 0, 0, 0, s;
	return f * D;
}

TEST(Elasticity, Eq18TensorEqualsStandardIsotropicMatrix)
{
	const Matrix6<Scalar> D = rdem::elasticityTensor(E, nu);
	// Entry by entry against the hand values: λ+2μ = 100e9/3 on the normal diagonal, λ = 25e9/3 off it,
	// μ = 12.5e9 on the shear diagonal, zero elsewhere. Tolerance: a few roundings, 1e-15 relative.
	for (int i = 0; i < 6; ++i)
		for (int j = 0; j < 6; ++j) {
			const Scalar expected = (i < 3 && j < 3) ? (i == j ? 100e9 / 3 : 25e9 / 3) : (i == j ? 12.5e9 : 0.0);
			EXPECT_NEAR(D(i, j), expected, 1e-15 * 100e9 / 3) << "D(" << i << "," << j << ")";
		}
	// The paper's factored form of eq. (18), evaluated independently; ~10 roundings: 1e-14 relative.
	EXPECT_TRUE(matricesClose(D, paperEq18(E, nu), 1e-14));
	// And for another ν, including the auxetic range.
	EXPECT_TRUE(matricesClose(rdem::elasticityTensor<Scalar>(7e9, 0.35), paperEq18(7e9, 0.35), 1e-14));
	EXPECT_TRUE(matricesClose(rdem::elasticityTensor<Scalar>(7e9, -0.3), paperEq18(7e9, -0.3), 1e-14));
}

TEST(Elasticity, Eq18StressesOfUniaxialStrainAndStress)
{
	const Matrix6<Scalar> D = rdem::elasticityTensor(E, nu);
	const Scalar          e = 1e-3;
	// Uniaxial strain ε = (e,0,0,0,0,0): σ = ((λ+2μ)e, λe, λe, 0, 0, 0) = (100e6/3, 25e6/3, 25e6/3, 0, 0, 0) Pa.
	Vector6 eps = Vector6::Zero();
	eps[0]      = e;
	const auto sig                     = (D * eps).eval();
	const Scalar tol                   = 1e-15 * 100e6 / 3; // a few roundings on the largest stress
	EXPECT_NEAR(sig[0], 100e6 / 3, tol);
	EXPECT_NEAR(sig[1], 25e6 / 3, tol);
	EXPECT_NEAR(sig[2], 25e6 / 3, tol);
	for (int i = 3; i < 6; ++i)
		EXPECT_EQ(sig[i], 0.0); // zero entries times strain: exact
	// Uniaxial stress s along y: ε = (-νs/E, s/E, -νs/E, 0,0,0) gives σ = (0, s, 0, 0,0,0).
	const Scalar s = 5e6;
	eps << -nu * s / E, s / E, -nu * s / E, 0, 0, 0;
	const auto sig2 = (D * eps).eval();
	// Cancellation of terms of size (λ+2μ)·s/E ≈ 1.1 s: round-off 1e-15·s per entry, 1e-14 relative to s.
	EXPECT_NEAR(sig2[0], 0, 1e-14 * s);
	EXPECT_NEAR(sig2[1], s, 1e-14 * s);
	EXPECT_NEAR(sig2[2], 0, 1e-14 * s);
	// Pure engineering shear γ_zx = 2e-3: τ_zx = μγ = 12.5e9·2e-3 = 25e6 Pa.
	eps.setZero();
	eps[4] = 2e-3;
	EXPECT_NEAR((D * eps)[4], 25e6, 1e-15 * 25e6); // one product after μ: 1e-15
}

TEST(Elasticity, Eq19PoissonTensorIsOffDiagonalPart)
{
	const Matrix6<Scalar> D  = rdem::elasticityTensor(E, nu);
	const Matrix6<Scalar> Dp = rdem::poissonTensor(E, nu);
	Matrix6<Scalar>       offDiagonal = D;
	offDiagonal.diagonal().setZero();
	// Same λ computation on both sides, so exact equality is expected.
	EXPECT_EQ(Dp, offDiagonal);
	// Hand value of the off-diagonal entries: λ = 25e9/3; 1e-15 relative as above.
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			EXPECT_NEAR(Dp(i, j), i == j ? 0.0 : 25e9 / 3, 1e-15 * 25e9 / 3);
	EXPECT_EQ(Dp.bottomRows<3>().norm(), 0.0);
	EXPECT_EQ(Dp.rightCols<3>().norm(), 0.0);
	// Against the paper's printed form of eq. (19): the factored eq. (18) with its diagonal removed; 1e-14 relative.
	Matrix6<Scalar> paper = paperEq18(E, nu);
	paper.diagonal().setZero();
	EXPECT_TRUE(matricesClose(Dp, paper, 1e-14));
}

TEST(Elasticity, InverseOfEq18IsComplianceOfEq4)
{
	const Matrix6<Scalar> C = rdem::elasticityTensor(E, nu).inverse();
	// Eq. (4): C = (1/E)[[1,-ν,-ν],[-ν,1,-ν],[-ν,-ν,1]] ⊕ (2(1+ν)/E) I₃.
	// 1/E = 3.333e-11, -ν/E = -6.667e-12, 2(1+ν)/E = 8e-11 [1/Pa].
	Matrix6<Scalar> expected = Matrix6<Scalar>::Zero();
	for (int i = 0; i < 3; ++i) {
		for (int j = 0; j < 3; ++j)
			expected(i, j) = i == j ? 1 / E : -nu / E;
		expected(i + 3, i + 3) = 2 * (1 + nu) / E;
	}
	// D has eigenvalues 3λ+2μ = 50e9, 2μ = 25e9 (twice), μ = 12.5e9 (three times): condition number 4, so LU
	// inversion loses at most a few ulps: 1e-14 relative.
	EXPECT_TRUE(matricesClose(C, expected, 1e-14));
	EXPECT_NEAR(C(0, 0), 1 / E, 1e-14 / E);
	EXPECT_NEAR(C(0, 1), -nu / E, 1e-14 / E);
	EXPECT_NEAR(C(5, 5), 8e-11, 1e-14 * 8e-11);
}

TEST(Elasticity, LayeredLambdaOfOneMaterialIsLambda)
{
	// Four blocks of 8 cm³ and four of 1 cm³, one material: λ = 8.333e9 Pa, whatever the volumes.
	std::vector<std::array<Scalar, 3>> parts;
	for (int a = 0; a < 8; ++a)
		parts.push_back({ a < 4 ? 8e-6 : 1e-6, E, nu });
	EXPECT_NEAR(rdem::layeredLambda<Scalar>(parts), rdem::lameLambda(E, nu), 1e-15 * rdem::lameLambda(E, nu));
}

TEST(Elasticity, LayeredLambdaOfEqualNuIsHarmonicMean)
{
	// Brick (E, volume 16 cm³) and mortar (E/100, 3.2 cm³), both ν = 0.2: λ/M = 1/4 for both, so
	// <λ/M>/<1/M> = 1/<1/λ> (volume-weighted): λ_b = 8.333e9, λ_m = 8.333e7 Pa,
	// λ_e = (4·16 + 4·3.2) / (4·16/λ_b + 4·3.2/λ_m) = 76.8 / (64 + 1280) λ_b = 0.057143 λ_b = 4.7619e8 Pa.
	const Scalar                       lb = rdem::lameLambda(E, nu);
	std::vector<std::array<Scalar, 3>> parts;
	for (int a = 0; a < 4; ++a) {
		parts.push_back({ 16e-6, E, nu });
		parts.push_back({ 3.2e-6, E / 100, nu });
	}
	EXPECT_NEAR(rdem::layeredLambda<Scalar>(parts), 76.8 / 1344 * lb, 1e-14 * lb);
}

TEST(Elasticity, LayeredLambdaIsBackusC13)
{
	// Two equal layers, E = 30 GPa ν = 0.2 (λ = 8.333e9, M = 33.333e9) and E = 30 GPa ν = 0.4 (λ = 42.857e9,
	// M = 64.286e9): <λ/M> = (0.25 + 0.66667)/2 = 0.45833, <1/M> = (3e-11 + 1.5556e-11)/2 = 2.2778e-11,
	// λ_e = 2.0122e10 Pa (between the two λ, not their mean 2.5595e10).
	const std::vector<std::array<Scalar, 3>> parts { { 1, E, 0.2 }, { 1, E, 0.4 } };
	const Scalar                             l1 = rdem::lameLambda<Scalar>(E, 0.2), l2 = rdem::lameLambda<Scalar>(E, 0.4);
	const Scalar                             M1 = l1 + 2 * rdem::shearModulus<Scalar>(E, 0.2), M2 = l2 + 2 * rdem::shearModulus<Scalar>(E, 0.4);
	EXPECT_NEAR(rdem::layeredLambda<Scalar>(parts), (l1 / M1 + l2 / M2) / (1 / M1 + 1 / M2), 1e-14 * l2);
	EXPECT_NEAR(rdem::layeredLambda<Scalar>(parts), 2.0122e10, 1e6);
}

TEST(Elasticity, Eq12WithAMortarJointInSeries)
{
	// Two 250×120×55 mm bricks (E = 16.7 GPa, ν = 0.15) with a 10 mm joint of mortar (E = 2 GPa, ν = 0.25), interface
	// model: each block reaches the joint's mid-plane, ℓ = 27.5 + 5 = 32.5 mm along the height. In series: brick 27.5 mm,
	// mortar 10 mm, brick 27.5 mm, so 1/k_n = 0.055/M_b + 0.01/M_m (and likewise with G). Tolerance 1e-15 relative.
	const Scalar Eb = 16.7e9, nub = 0.15, Em = 2e9, num = 0.25, ell = 0.0325, t = 0.01;
	for (auto m : { SpringModulus::Paper, SpringModulus::Consistent }) {
		const Scalar Mb = rdem::springNormalModulus(Eb, nub, m), Mm = rdem::springNormalModulus(Em, num, m);
		const Scalar k  = 1 / (2 * rdem::bondSideCompliance(Mb, ell, Mm, t));
		EXPECT_NEAR(k, 1 / (0.055 / Mb + 0.01 / Mm), 1e-15 * k);
	}
	const Scalar Gb = rdem::shearModulus(Eb, nub), Gm = rdem::shearModulus(Em, num);
	const Scalar ks = 1 / (2 * rdem::bondSideCompliance(Gb, ell, Gm, t));
	EXPECT_NEAR(ks, 1 / (0.055 / Gb + 0.01 / Gm), 1e-15 * ks);
	// No joint: ℓ/M, eq. (11) inverted (exact division).
	EXPECT_EQ(rdem::bondSideCompliance<Scalar>(Eb, ell, Em, 0.0), ell / Eb);
}

} // namespace
