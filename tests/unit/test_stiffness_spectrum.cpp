/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/StiffnessSpectrum.hpp: the block stiffness K against closed forms (a chain of springs,
   a block on a grounded face, rigid motions), cells against their definition, the mass normalisation, and the Lanczos
   estimate of λ_max against a dense eigen-solve of the same operator. Tolerances: entries are sums of a few dozen
   products of O(1) numbers, 1e-12 relative covers their round-off; eigenvalues of the dense solver are accurate to
   ~1e-14·‖A‖. */
#include <pkg/rdem/math/StiffnessSpectrum.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>

namespace {

namespace rdem = yade::rdem;
using V3       = Eigen::Vector3d;
using M3       = Eigen::Matrix3d;
using MX       = Eigen::MatrixXd;
using VX       = Eigen::VectorXd;

/// A = P S K S P as a dense matrix.
MX normalised(const rdem::BlockStiffness<double>& K, const std::vector<rdem::BodyScale<double>>& scale)
{
	MX A = K.dense();
	for (long c = 0; c < A.cols(); ++c)
		rdem::scaleDofs(scale, A.col(c).data());
	MX At = A.transpose();
	for (long c = 0; c < At.cols(); ++c)
		rdem::scaleDofs(scale, At.col(c).data());
	return At.transpose();
}

double largestDense(const MX& A) { return Eigen::SelfAdjointEigenSolver<MX>(A, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff(); }

rdem::LargestEigenvalue<double> lanczos(const MX& A, std::vector<double>& start, int maxSteps = 60, double tol = 1e-10)
{
	std::vector<char> mask(size_t(A.rows()), 1);
	for (long i = 0; i < A.rows(); ++i)
		mask[size_t(i)] = A.row(i).norm() > 0;
	auto apply = [&](const double* x, double* y) { Eigen::Map<VX>(y, A.rows()) = A * Eigen::Map<const VX>(x, A.rows()); };
	return rdem::lanczosLargest<double>(apply, size_t(A.rows()), mask, start, 2, maxSteps, tol, 0.1);
}

/// A bonded grid nx × ny × nz of cubes of half-size h (centres 2h apart), each shared face carrying 2×2 point springs
/// at its segment centres (k_n, k_s per spring), as RdemTimeStepper assembles a bond.
rdem::BlockStiffness<double> grid(int nx, int ny, int nz, double h, double kn, double ks, std::vector<V3>& centres)
{
	centres.clear();
	for (int k = 0; k < nz; ++k)
		for (int j = 0; j < ny; ++j)
			for (int i = 0; i < nx; ++i)
				centres.push_back(2 * h * V3(i, j, k));
	rdem::BlockStiffness<double> K(centres.size());
	for (size_t a = 0; a < centres.size(); ++a)
		for (size_t b = a + 1; b < centres.size(); ++b) {
			const V3 d = centres[b] - centres[a];
			if (std::abs(d.norm() - 2 * h) > 1e-12) continue;
			const V3 n  = d.normalized();
			const V3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
			K.beginPair(long(a), long(b));
			for (int s : { -1, 1 })
				for (int r : { -1, 1 }) {
					const V3 p = centres[a] + h * n + 0.5 * h * (s * t1 + r * t2); // segment centre, global
					K.addPointSpring(long(a), long(b), p - centres[a], p - centres[b], n, kn, ks);
				}
			K.endPair();
		}
	return K;
}

std::vector<rdem::BodyScale<double>> cubes(size_t n, double m, double h, unsigned blocked = 0)
{
	const double I = m * (2 * h) * (2 * h) / 6; // cube of side 2h
	return std::vector<rdem::BodyScale<double>>(n, rdem::bodyScale<double>(m, V3::Constant(I), M3::Identity(), blocked));
}

TEST(StiffnessSpectrum, ChainOfNormalSpringsHasTheClosedFormSpectrum)
{
	// N masses on a line between two walls, normal springs k at the centroids (zero arms), shear springs 0: the
	// longitudinal eigenvalues are (2k/m)(1 - cos(jπ/(N+1))), j = 1..N; the largest 2k/m(1 + cos(π/(N+1))).
	const int                    N = 7;
	const double                 k = 3.0, m = 2.0;
	rdem::BlockStiffness<double> K(N);
	K.addPointSpring(0, -1, V3::Zero(), V3::Zero(), V3::UnitX(), k, 0);
	K.addPointSpring(N - 1, -1, V3::Zero(), V3::Zero(), V3::UnitX(), k, 0);
	for (long b = 0; b + 1 < N; ++b) {
		K.beginPair(b, b + 1);
		K.addPointSpring(b, b + 1, V3::Zero(), V3::Zero(), V3::UnitX(), k, 0);
		K.endPair();
	}
	const auto scale = cubes(N, m, 0.1);
	const MX   A     = normalised(K, scale);
	EXPECT_NEAR(largestDense(A), 2 * k / m * (1 + std::cos(M_PI / (N + 1))), 1e-12);
	std::vector<double> start;
	const auto          est = lanczos(A, start);
	EXPECT_NEAR(est.ritz, 2 * k / m * (1 + std::cos(M_PI / (N + 1))), 1e-10);
}

TEST(StiffnessSpectrum, BlockOnAGroundedFace)
{
	// A cube of half-size h on 4 grounded springs at (±h/2, ±h/2, -h) (its bottom face's 2×2 segment centres), normal z.
	// Vertical translation: 4k_n/m exactly (the moment arms cancel). Rocking about x: θ·I = -Σ k_n y² θ - coupled
	// sliding; a pure shear-free check: with k_s = 0 the rocking stiffness is Σ k_n y² = k_n h², I = m(2h)²/6.
	const double                 h = 0.5, m = 3.0, kn = 10.0;
	rdem::BlockStiffness<double> K(1);
	for (int s : { -1, 1 })
		for (int r : { -1, 1 })
			K.addPointSpring(0, -1, V3(0.5 * h * s, 0.5 * h * r, -h), V3::Zero(), V3::UnitZ(), kn, 0);
	const MX     Kd = K.dense();
	const double I  = m * 4 * h * h / 6;
	EXPECT_NEAR(Kd(2, 2), 4 * kn, 1e-12);
	EXPECT_NEAR(Kd(3, 3), kn * h * h, 1e-12); // Σ k_n y² = 4 k_n h²/4
	EXPECT_NEAR(Kd(4, 4), kn * h * h, 1e-12);
	EXPECT_NEAR(Kd(2, 3), 0, 1e-12); // symmetric arms: no translation-rotation coupling
	const MX A = normalised(K, cubes(1, m, h));
	EXPECT_NEAR(A(2, 2), 4 * kn / m, 1e-12);
	EXPECT_NEAR(A(3, 3), kn * h * h / I, 1e-12);
}

TEST(StiffnessSpectrum, PairSumsMatchTheSpringsOneByOne)
{
	// A pair's blocks are made from the moments of its springs' arms (BlockStiffness::endPair); here against the
	// definition written out spring by spring: d = J(r2) x2 - J(r1) x1, J(r) = [I, -[r]×], energy ½ dᵀK_s d, for 16
	// springs at random common points with random normals and stiffnesses, bodies at random centroids. The entries are
	// sums of 16 products of O(1) numbers: 1e-12 relative covers their round-off.
	std::srand(7);
	const V3   c1 = V3::Random(), c2 = c1 + V3(1.0, 0.3, -0.2);
	MX         ref = MX::Zero(12, 12);
	const auto J   = [](const V3& r) {
                Eigen::Matrix<double, 3, 6> j;
                j << M3::Identity(), -(M3() << 0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0).finished();
                return j;
	};
	rdem::BlockStiffness<double> K(2);
	K.beginPair(0, 1);
	for (int i = 0; i < 16; ++i) {
		const V3     p  = (c1 + c2) / 2 + 0.4 * V3::Random();
		const V3     n  = V3::Random().normalized();
		const double kn = 2 + std::abs(V3::Random()[0]), ks = 1 + std::abs(V3::Random()[0]);
		K.addPointSpring(0, 1, p - c1, p - c2, n, kn, ks);
		const M3                     Ks = kn * n * n.transpose() + ks * (M3::Identity() - n * n.transpose());
		Eigen::Matrix<double, 3, 12> Jd;
		Jd << -J(p - c1), J(p - c2);
		ref += Jd.transpose() * Ks * Jd;
	}
	K.endPair();
	EXPECT_LT((K.dense() - ref).norm(), 1e-12 * ref.norm());
	// The protocol: springs of a pair sit at common points, inside beginPair ... endPair.
	rdem::BlockStiffness<double> L(2);
	L.beginPair(0, 1);
	L.addPointSpring(0, 1, V3(0.1, 0, 0), V3(-0.9, 0, 0), V3::UnitX(), 1, 1);
	EXPECT_THROW(L.addPointSpring(0, 1, V3(0.1, 0.2, 0), V3(-0.9, 0, 0), V3::UnitX(), 1, 1), std::logic_error);
	std::vector<double> x(12, 1), y(12);
	EXPECT_THROW(L.multiply(x.data(), y.data()), std::logic_error);
	EXPECT_THROW(L.beginPair(0, 1), std::logic_error);
	L.endPair();
	EXPECT_THROW(L.endPair(), std::logic_error);
}

TEST(StiffnessSpectrum, GridIsSymmetricAndFreeOfRigidMotions)
{
	std::vector<V3> c;
	const auto      K  = grid(3, 2, 2, 0.01, 5e9, 2e9, c);
	const MX        Kd = K.dense();
	EXPECT_LT((Kd - Kd.transpose()).norm(), 1e-12 * Kd.norm());
	// rigid motion x_b = (t + ω×c_b, ω): every spring's d vanishes, so K x = 0
	const V3 t(1, -2, 0.5), w(30, 10, -20);
	VX       x(6 * long(c.size()));
	for (size_t b = 0; b < c.size(); ++b) {
		x.segment<3>(6 * long(b))     = t + w.cross(c[b]);
		x.segment<3>(6 * long(b) + 3) = w;
	}
	EXPECT_LT((Kd * x).norm(), 1e-12 * Kd.norm() * x.norm());
	// positive semi-definite: its smallest eigenvalue is round-off
	EXPECT_GT(Eigen::SelfAdjointEigenSolver<MX>(Kd, Eigen::EigenvaluesOnly).eigenvalues().minCoeff(), -1e-10 * Kd.norm());
}

TEST(StiffnessSpectrum, BlockedDofsAndRotatedInertia)
{
	// scaleDofs with a rotated body: S_r = R diag(I)^-½ Rᵀ, so S_r² = R diag(I)⁻¹ Rᵀ; blocked DOFs give zero.
	const M3                             R = Eigen::AngleAxisd(0.7, V3(1, 2, 3).normalized()).toRotationMatrix();
	const V3                             I(1, 4, 9);
	const rdem::BodyScale<double>        s = rdem::bodyScale<double>(16, I, R, /*blocked y and rz*/ 2u | 32u);
	std::vector<rdem::BodyScale<double>> scale { s };
	std::vector<double>                  x { 1, 1, 1, 0, 0, 0 };
	rdem::scaleDofs(scale, x.data());
	EXPECT_DOUBLE_EQ(x[0], 0.25);
	EXPECT_DOUBLE_EQ(x[1], 0);
	EXPECT_DOUBLE_EQ(x[2], 0.25);
	const M3 Sr2 = s.invSqrtInertia * s.invSqrtInertia;
	EXPECT_LT((Sr2 - R * I.cwiseInverse().asDiagonal() * R.transpose()).norm(), 1e-14);
	std::vector<double> r { 0, 0, 0, 1, 0, 1 };
	rdem::scaleDofs(scale, r.data());
	EXPECT_NEAR(r[3], s.invSqrtInertia(0, 0), 1e-15); // rz blocked before: only rx's column
	EXPECT_DOUBLE_EQ(r[5], 0);                        // and after
	// no mass: fixed
	EXPECT_FALSE(rdem::bodyScale<double>(0, I, R, 0).free[0]);
}

TEST(StiffnessSpectrum, CellIsItsDefinition)
{
	// Two openings on a cell: ε = (c₀ u₀, 0, c₁ u₁), energy ½ εᵀKε, so K_cell = Gᵀ K G with the rows G_d = Σ c ∂u_n/∂x.
	rdem::BlockStiffness<double> K(3);
	const V3                     n0 = V3::UnitX(), n1 = V3::UnitZ(), a01(0, 0.2, -0.1), a02(0.3, 0, 0.1), a11(0.05, 0.1, 0), a12(0, -0.2, 0.4);
	const size_t                 q0 = K.addOpening(0, 1, n0, a01, a02), q1 = K.addOpening(0, 2, n1, a11, a12);
	M3                           Kc;
	Kc << 4, 1, 0.5, 1, 3, 0.2, 0.5, 0.2, 2;
	K.addCell(Kc, { { q0, 0, 2.0 }, { q1, 2, -1.5 } });
	MX G = MX::Zero(3, 18);
	G.block<1, 3>(0, 6) += 2.0 * n0.transpose(); // body 1 translation
	G.block<1, 3>(0, 9) += 2.0 * a02.transpose();
	G.block<1, 3>(0, 0) -= 2.0 * n0.transpose();
	G.block<1, 3>(0, 3) -= 2.0 * a01.transpose();
	G.block<1, 3>(2, 12) += -1.5 * n1.transpose();
	G.block<1, 3>(2, 15) += -1.5 * a12.transpose();
	G.block<1, 3>(2, 0) -= -1.5 * n1.transpose();
	G.block<1, 3>(2, 3) -= -1.5 * a11.transpose();
	EXPECT_LT((K.dense() - G.transpose() * Kc * G).norm(), 1e-12 * Kc.norm());
}

TEST(StiffnessSpectrum, OffsetShearCompletesTheShearSpringsEnergy)
{
	// Two cells (body 0: openings q0 along x and q1 along z; body 1: q0) and a bond 0-1 whose shear springs k measure
	// P(d - c), c = A₁ε₀ - A₂ε₁: its point spring plus addOffsetShear must be the Hessian of
	// E = ½ε₀ᵀK₀ε₀ + ½ε₁ᵀK₁ε₁ + ½k|P(d - c)|², written here from its definition. E is quadratic, so its Hessian by
	// polarisation, H_ij = (E(e_i + e_j) - E(e_i - e_j) - E(-e_i + e_j) + E(-e_i - e_j))/4, is exact up to round-off.
	rdem::BlockStiffness<double> K(3);
	const V3                     n0 = V3::UnitX(), n1 = V3::UnitZ(), a01(0, 0.2, -0.1), a02(0.3, 0, 0.1), a11(0.05, 0.1, 0), a12(0, -0.2, 0.4);
	const V3                     r1(0.1, -0.05, 0.2), r2(-0.6, 0.02, -0.2), n = V3(0.1, 0.2, 1).normalized();
	const double                 k = 3.0, c00 = 2.0, c01 = -1.5, c10 = 0.7;
	M3                           K0, K1, A1, A2;
	K0 << 4, 1, 0.5, 1, 3, 0.2, 0.5, 0.2, 2;
	K1 << 2, 0.3, 0, 0.3, 5, 0.1, 0, 0.1, 1;
	A1 << 0.1, 0, 0.02, 0, 0.05, 0, 0.01, 0, 0.2;
	A2 << 0.6, 0.01, 0, 0, 0.03, 0, 0, 0.02, 0.1;
	const size_t q0 = K.addOpening(0, 1, n0, a01, a02), q1 = K.addOpening(0, 2, n1, a11, a12);
	const size_t cell0 = K.addCell(K0, { { q0, 0, c00 }, { q1, 2, c01 } }), cell1 = K.addCell(K1, { { q0, 0, c10 } });
	K.beginPair(0, 1);
	K.addPointSpring(0, 1, r1, r2, n, 0, k);
	K.endPair();
	K.addOffsetShear(0, 1, r1, r2, n, k, long(cell0), A1, long(cell1), A2);
	const auto at = [](const VX& x, long b, const V3& r) -> V3 { return x.segment<3>(6 * b) + V3(x.segment<3>(6 * b + 3)).cross(r); };
	const auto E  = [&](const VX& x) {
                const double u0 = n0.dot(V3(x.segment<3>(6) - x.segment<3>(0))) + a02.dot(V3(x.segment<3>(9))) - a01.dot(V3(x.segment<3>(3)));
                const double u1 = n1.dot(V3(x.segment<3>(12) - x.segment<3>(0))) + a12.dot(V3(x.segment<3>(15))) - a11.dot(V3(x.segment<3>(3)));
                const V3     e0(c00 * u0, 0, c01 * u1), e1(c10 * u0, 0, 0);
                const M3     P = M3::Identity() - n * n.transpose();
                const V3     s = P * (at(x, 1, r2) - at(x, 0, r1) - (A1 * e0 - A2 * e1));
                return 0.5 * e0.dot(K0 * e0) + 0.5 * e1.dot(K1 * e1) + 0.5 * k * s.squaredNorm();
	};
	MX H(18, 18);
	for (long i = 0; i < 18; ++i)
		for (long j = 0; j < 18; ++j) {
			const VX ei = VX::Unit(18, i), ej = VX::Unit(18, j);
			H(i, j) = (E(ei + ej) - E(ei - ej) - E(-ei + ej) + E(-ei - ej)) / 4;
		}
	EXPECT_LT((K.dense() - H).norm(), 1e-12 * H.norm());
	// Without the offset term K is that of the cells and the spring alone: the term is not zero.
	rdem::BlockStiffness<double> plain(3);
	const size_t                 p0 = plain.addOpening(0, 1, n0, a01, a02), p1 = plain.addOpening(0, 2, n1, a11, a12);
	plain.addCell(K0, { { p0, 0, c00 }, { p1, 2, c01 } });
	plain.addCell(K1, { { p0, 0, c10 } });
	plain.beginPair(0, 1);
	plain.addPointSpring(0, 1, r1, r2, n, 0, k);
	plain.endPair();
	EXPECT_GT((K.dense() - plain.dense()).norm(), 1e-3 * H.norm());
}

TEST(StiffnessSpectrum, ElementAddsItsMatrixOnTranslations)
{
	// A random symmetric K_p on 8 bodies, scale ½: the dense K is ½ K_p on the translation rows and columns, 0 elsewhere.
	Eigen::Matrix<double, 24, 24> Kp = Eigen::Matrix<double, 24, 24>::Random();
	Kp                               = (Kp + Kp.transpose()).eval();
	rdem::BlockStiffness<double> K(9);
	const std::array<long, 8>    nodes { 8, 1, 2, 3, 4, 5, 6, 7 };
	K.addElement(nodes, &Kp, 0.5);
	const MX Kd = K.dense();
	for (int a = 0; a < 8; ++a)
		for (int b = 0; b < 8; ++b)
			for (int i = 0; i < 3; ++i)
				for (int j = 0; j < 3; ++j)
					EXPECT_DOUBLE_EQ(Kd(6 * nodes[size_t(a)] + i, 6 * nodes[size_t(b)] + j), 0.5 * Kp(3 * a + i, 3 * b + j));
	EXPECT_EQ(Kd.row(0).norm(), 0);         // body 0 has no element: nothing
	EXPECT_EQ(Kd.row(6 * 8 + 3).norm(), 0); // rotations: nothing
}

TEST(StiffnessSpectrum, LanczosMatchesDenseSolveOnAGridWithElementAndFixedBlocks)
{
	// 3×3×2 bonded cubes of the paper's size and stiffness order, the bottom layer fixed, plus one Poisson element of
	// positive semi-definite K_p on 8 of them: the estimate θ + r bounds λ_max from above within the tolerance 1e-6
	// asked for, and θ alone is within it from below.
	std::vector<V3>               c;
	auto                          K  = grid(3, 3, 2, 0.01, 1.5e12 * 1e-4, 6e11 * 1e-4, c);
	Eigen::Matrix<double, 24, 24> B  = Eigen::Matrix<double, 24, 24>::Random();
	Eigen::Matrix<double, 24, 24> Kp = 1e7 * B * B.transpose();
	K.addElement({ 0, 1, 3, 4, 9, 10, 12, 13 }, &Kp, 1.0);
	auto scale = cubes(c.size(), 2300 * 8e-6, 0.01);
	for (size_t b = 0; b < 9; ++b)
		scale[b] = rdem::bodyScale<double>(2300 * 8e-6, V3::Constant(1e-6), M3::Identity(), 63u);
	const MX            A     = normalised(K, scale);
	const double        exact = largestDense(A);
	std::vector<double> start;
	const auto          est = lanczos(A, start, 108, 1e-6);
	EXPECT_LE(est.ritz, exact * (1 + 1e-12));
	EXPECT_GE(est.upper(), exact * (1 - 1e-12));
	EXPECT_LT(est.upper(), exact * (1 + 2e-6));
	EXPECT_LT(est.steps, 54); // fewer than the 54 free DOFs, after which the Krylov space is the whole space
	// the returned Ritz vector is the top eigenvector: its Rayleigh quotient is λ_max
	const VX v = Eigen::Map<VX>(start.data(), A.rows());
	EXPECT_NEAR(v.dot(A * v) / v.squaredNorm(), exact, 1e-6 * exact);
}

TEST(StiffnessSpectrum, WarmStartConvergesInFewSteps)
{
	// After a cold start, a slightly stiffer system (k_n × 1.01) starting from the old Ritz vector converges to 1e-4 in
	// a few steps; a cold start needs several times more.
	std::vector<V3>     c;
	const auto          K0    = grid(4, 4, 3, 0.01, 1.0, 0.4, c);
	const auto          K1    = grid(4, 4, 3, 0.01, 1.01, 0.4, c);
	const auto          scale = cubes(c.size(), 1.0, 0.01);
	const MX            A0 = normalised(K0, scale), A1 = normalised(K1, scale);
	std::vector<double> warm, cold;
	lanczos(A0, warm, 200, 1e-8);
	const auto   w     = lanczos(A1, warm, 200, 1e-4);
	const auto   k     = lanczos(A1, cold, 200, 1e-4);
	const double exact = largestDense(A1);
	EXPECT_GE(w.upper(), exact * (1 - 1e-12));
	EXPECT_LT(w.upper(), exact * (1 + 2e-4));
	EXPECT_GE(k.upper(), exact * (1 - 1e-12));
	EXPECT_LT(w.steps, k.steps);
	std::printf("warm start: %d steps, cold: %d steps (288 DOFs)\n", w.steps, k.steps);
}

TEST(StiffnessSpectrum, NoStiffnessGivesZero)
{
	rdem::BlockStiffness<double> K(2);
	const MX                     A = normalised(K, cubes(2, 1, 1));
	std::vector<double>          start;
	const auto                   est = lanczos(A, start);
	EXPECT_EQ(est.upper(), 0);
}

/// Spectral radius of the leapfrog step with velocity-lagged dashpots, state (x_n, v_{n-1/2}), for M = I.
double amplificationRadius(const MX& K, const MX& C, double dt)
{
	const long n = K.rows();
	const MX   I = MX::Identity(n, n);
	MX         G(2 * n, 2 * n);
	G << I - dt * dt * K, dt * (I - dt * C), -dt * K, I - dt * C;
	return G.eigenvalues().cwiseAbs().maxCoeff();
}

TEST(StiffnessSpectrum, DampedStepOfOneOscillatorIsBelytschkos)
{
	// (2/ω)(√(1+ζ²) - ζ) [Belytschko2000]; and the leapfrog step is stable just below it, unstable just above
	const double omega = 3.0;
	for (double zeta : { 0.0, 0.1, 0.5, 1.0, 3.0 }) {
		const double dt = rdem::dampedCriticalStep(omega * omega, 2 * zeta * omega);
		EXPECT_NEAR(dt, 2 / omega * (std::sqrt(1 + zeta * zeta) - zeta), 1e-14) << zeta;
		const MX K = MX::Constant(1, 1, omega * omega), C = MX::Constant(1, 1, 2 * zeta * omega);
		EXPECT_LE(amplificationRadius(K, C, 0.999 * dt), 1 + 1e-12) << zeta;
		EXPECT_GT(amplificationRadius(K, C, 1.001 * dt), 1 + 1e-6) << zeta;
	}
	EXPECT_EQ(rdem::dampedCriticalStep(0.0, 0.0), std::numeric_limits<double>::infinity());
	EXPECT_DOUBLE_EQ(rdem::dampedCriticalStep(0.0, 4.0), 0.5); // dashpots alone: Δt ≤ 2/λ_C
}

TEST(StiffnessSpectrum, CriticallyDampedStepIsSqrtTwoMinusOneOfTheUndamped)
{
	// a critical dashpot (ζ = 1) on the mode of the undamped limit 2/ω: (√2 - 1)·2/ω, and the one-oscillator leapfrog
	// with that dashpot is stable just below it and unstable just above
	for (double undamped : { 1e-7, 3.2e-6, 0.5 }) {
		const double dt = rdem::criticallyDampedStep(undamped);
		EXPECT_NEAR(dt / undamped, std::sqrt(2.0) - 1, 1e-14) << undamped;
		const double omega = 2 / undamped;
		const MX     K = MX::Constant(1, 1, omega * omega), C = MX::Constant(1, 1, 2 * omega);
		EXPECT_LE(amplificationRadius(K * undamped * undamped, C * undamped, 0.999 * dt / undamped), 1 + 1e-12) << undamped;
		EXPECT_GT(amplificationRadius(K * undamped * undamped, C * undamped, 1.001 * dt / undamped), 1 + 1e-6) << undamped;
	}
	EXPECT_EQ(rdem::criticallyDampedStep(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
}

TEST(StiffnessSpectrum, DampedStepIsALowerBoundOfTheLimitOfCoupledSystems)
{
	// random positive semi-definite K and C (C of rank 2: dashpots at a few points): stable at the bound, and the
	// true limit (scanned in steps of 0.5 %) is at most 1.5 times the bound on these systems
	std::srand(11);
	for (int trial = 0; trial < 40; ++trial) {
		const MX     A = MX::Random(6, 6), B = MX::Random(6, 2) * (1 + trial % 4);
		const MX     K = A * A.transpose(), C = B * B.transpose();
		const auto   lambda = [](const MX& X) { return Eigen::SelfAdjointEigenSolver<MX>(X).eigenvalues().maxCoeff(); };
		const double dt     = rdem::dampedCriticalStep(lambda(K), lambda(C));
		EXPECT_LE(amplificationRadius(K, C, dt), 1 + 1e-9) << trial;
		EXPECT_LE(lambda(dt * dt * K + 2 * dt * C), 4 + 1e-9) << trial;
		double limit = dt;
		while (amplificationRadius(K, C, limit * 1.005) <= 1 + 1e-9)
			limit *= 1.005;
		EXPECT_LT(limit, 1.5 * dt) << trial;
	}
}

TEST(StiffnessSpectrum, DampedStepOfIsTheRootOfTheDampedLimit)
{
	/* dampedCriticalStepOf against the exact root of λ_max(Δt²K + 2ΔtC) = 4 (bisected on dense eigenvalues to 1e-12) on
	   random coupled systems where the stiffest and the most damped modes differ (C of rank 2, dashpots at a few
	   points): not above the root (the leapfrog's amplification at it has radius ≤ 1), and within 2·tol of it (the
	   bracket it stops on; tol = 1e-3, the stepper's lanczosTolerance); and far above the bound dampedCriticalStep on
	   some of them. */
	std::srand(17);
	const double tol    = 1e-3;
	double       gained = 1;
	for (int trial = 0; trial < 40; ++trial) {
		const MX   A = MX::Random(30, 30), B = MX::Random(30, 2) * (0.5 + trial % 4);
		const MX   K = A * A.transpose(), C = B * B.transpose();
		const auto lambda = [](const MX& X) { return Eigen::SelfAdjointEigenSolver<MX>(X, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff(); };
		double     lo = 0, hi = 2 / std::sqrt(lambda(K));
		while (hi - lo > 1e-12 * hi) {
			const double mid                                    = (lo + hi) / 2;
			(lambda(mid * mid * K + 2 * mid * C) > 4 ? hi : lo) = mid;
		}
		const auto applyOf = [](const MX& X) {
			return [&X](const double* x, double* y) {
				Eigen::Map<Eigen::VectorXd>(y, X.rows()) = X * Eigen::Map<const Eigen::VectorXd>(x, X.rows());
			};
		};
		std::vector<double>     start;
		const std::vector<char> mask(30, 1);
		const auto              d = rdem::dampedCriticalStepOf<double>(applyOf(K), applyOf(C), 30, mask, start, lambda(K), lambda(C), 60, tol, 8);
		EXPECT_LE(d.step, lo * (1 + 1e-9)) << trial;
		EXPECT_GT(d.step, (1 - 2 * tol) * lo) << trial;
		EXPECT_GE(d.upper, lo * (1 - 1e-9)) << trial;
		EXPECT_LE(amplificationRadius(K, C, d.step), 1 + 1e-9) << trial;
		EXPECT_LE(d.rounds, 8) << trial;
		// with `enough` below the root: a lower bound at least that, found in no more rounds
		std::vector<double> start2;
		const auto e = rdem::dampedCriticalStepOf<double>(applyOf(K), applyOf(C), 30, mask, start2, lambda(K), lambda(C), 60, tol, 8, 0.9 * lo);
		EXPECT_LE(e.step, lo * (1 + 1e-9)) << trial;
		EXPECT_GE(e.step, 0.9 * lo) << trial;
		EXPECT_LE(e.rounds, d.rounds) << trial;
		gained = std::max(gained, d.step / rdem::dampedCriticalStep(lambda(K), lambda(C)));
	}
	EXPECT_GT(gained, 1.2); // the bound is far below the root where the modes differ
	// no dashpots: 2/ω; no stiffness: 2/λ_C
	std::vector<double>     start;
	const std::vector<char> mask(1, 1);
	const auto              none = [](const double*, double* y) { y[0] = 0; };
	const auto              one  = [](const double* x, double* y) { y[0] = 4 * x[0]; };
	EXPECT_DOUBLE_EQ(rdem::dampedCriticalStepOf<double>(one, none, 1, mask, start, 4.0, 0.0, 60, tol, 8).step, 1.0);
	EXPECT_DOUBLE_EQ(rdem::dampedCriticalStepOf<double>(none, one, 1, mask, start, 0.0, 4.0, 60, tol, 8).step, 0.5);
}

TEST(StiffnessSpectrum, DampedStepOfBothIsTheSameToTheBit)
{
	/* RdemTimeStepper's form of the damped root: P S x made once for K and C (dampedCriticalStepOfBoth), and C with
	   dashpots on one pair only, so that most of its diagonal blocks are zero (multiply skips them): the same step,
	   bracket, rounds, Lanczos steps and Ritz vector, to the bit, as the two products made apart (dampedCriticalStepOf). */
	std::vector<V3>                      centres;
	const auto                           K = grid(3, 3, 2, 0.05, 2e8, 1e8, centres);
	rdem::BlockStiffness<double>         C(centres.size());
	std::vector<rdem::BodyScale<double>> scale;
	for (size_t b = 0; b < centres.size(); ++b) // unequal masses and rotated inertias; body 4 fixed, body 7 without rz
		scale.push_back(rdem::bodyScale<double>(
		        2 + 0.3 * double(b),
		        V3(1e-3, 2e-3, 1.5e-3),
		        Eigen::AngleAxisd(0.1 * double(b), V3(1, 2, 3).normalized()).toRotationMatrix(),
		        b == 4           ? 63u
		                : b == 7 ? 32u
		                         : 0u));
	C.beginPair(0, 1);
	C.addPointSpring(0, 1, V3(0.05, 0.02, 0.01), V3(-0.05, 0.02, 0.01), V3::UnitX(), 3e5, 1e5);
	C.addPointSpring(0, 1, V3(0.05, -0.02, 0.01), V3(-0.05, -0.02, 0.01), V3::UnitX(), 3e5, 1e5);
	C.endPair();
	rdem::NormalisedOperators<double> ops(scale); // what RdemTimeStepper multiplies by
	const size_t                      n    = ops.size();
	const std::vector<char>           mask = ops.mask();
	const auto          normalisedOf       = [&](const rdem::BlockStiffness<double>& X) { return [&](const double* x, double* y) { ops.apply(X, x, y); }; };
	const auto          both               = [&](const double* x, double* kx, double* cx) { ops.applyBoth(K, C, x, kx, cx); };
	std::vector<double> s0, s1, s2;
	const auto          lk = rdem::lanczosLargest<double>(normalisedOf(K), n, mask, s0, 2, 60, 1e-3, 0.1);
	const auto          lc = rdem::lanczosLargest<double>(normalisedOf(C), n, mask, s1, 2, 60, 1e-3, 0.1);
	for (size_t i = 0; i < n; ++i)
		s0[i] += s1[i];
	s1               = s0;
	s2               = s0;
	const auto apart = rdem::dampedCriticalStepOf<double>(normalisedOf(K), normalisedOf(C), n, mask, s1, lk.upper(), lc.upper(), 60, 1e-3, 8);
	const auto one   = rdem::dampedCriticalStepOfBoth<double>(both, normalisedOf(K), n, mask, s2, lk.upper(), lc.upper(), 60, 1e-3, 8);
	EXPECT_GT(apart.rounds, 0); // the root was searched
	EXPECT_EQ(one.step, apart.step);
	EXPECT_EQ(one.upper, apart.upper);
	EXPECT_EQ(one.rounds, apart.rounds);
	EXPECT_EQ(one.steps, apart.steps);
	EXPECT_TRUE(s1 == s2);
	EXPECT_LT(apart.step, rdem::dampedCriticalStep(lk.upper(), 0.0)); // the dashpots lower the step
}

} // namespace
