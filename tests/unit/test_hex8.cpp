/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/Hex8.hpp, the virtual 8-node hexahedron of the Poisson effect (paper §4.2,
   eqs. 19-21) and its corotational frame.

   Three elements: a unit cube, a 0.02 × 0.03 × 0.04 m box away from the origin, and a distorted (trilinear,
   non-parallelepiped, valid) hexahedron of ~0.03 m. Independent references written here:
     * shape functions as products of 1D linear functions;
     * ∫ ∇N_a dV and the volume from the divergence theorem, as surface integrals over the six bilinear faces with
       3×3 Gauss points (exact: the integrands are polynomials of degree ≤ 2 per face coordinate);
     * for the box, K = ∫ Bᵀ D B dV assembled entry by entry with the explicit diagonal Jacobian.
   Material: E = 30 GPa, ν = 0.2, so λ = 25e9/3 Pa; K entries are O(E·L) ≈ 1e8-1e10 N/m. */
#include <pkg/rdem/math/Hex8.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace {

using rdem_test::Scalar;

namespace rdem = yade::rdem;
using V3     = rdem_test::Vector3;
using M3     = rdem_test::Matrix3;
using V24    = rdem::Vec24<Scalar>;
using M24    = rdem::Mat24<Scalar>;
using M6     = rdem::Matrix6<Scalar>;
using V6     = Eigen::Matrix<Scalar, 6, 1>;
using Nodes  = rdem::Nodes8<Scalar>;
using Grad8  = Eigen::Matrix<Scalar, 3, 8>; // column a: a vector attached to node a

constexpr Scalar E  = 30e9;
constexpr Scalar nu = 0.2;

// ------------------------------------------------------------------------------------------------ elements

// Node a = i + 2j + 4k at origin + (i lx, j ly, k lz).
Nodes boxNodes(const V3& origin, Scalar lx, Scalar ly, Scalar lz)
{
	Nodes X;
	for (int a = 0; a < 8; ++a)
		X[a] = origin + V3((a & 1) * lx, ((a >> 1) & 1) * ly, ((a >> 2) & 1) * lz);
	return X;
}

Nodes unitCube() { return boxNodes(V3::Zero(), 1, 1, 1); }
Nodes box() { return boxNodes(V3(1.0, -2.0, 0.5), 0.02, 0.03, 0.04); }

// A general trilinear hexahedron: every corner of a ~0.03 m cube moved by 1-6 mm; no face is a parallelogram.
Nodes distorted()
{
	return { V3(0.000, 0.000, 0.000), V3(0.030, 0.002, -0.001), V3(-0.003, 0.025, 0.002), V3(0.034, 0.031, 0.004),
		 V3(0.002, -0.001, 0.028), V3(0.029, 0.004, 0.033), V3(0.001, 0.027, 0.030), V3(0.036, 0.030, 0.036) };
}

struct Named {
	const char* name;
	Nodes       X;
};
std::array<Named, 3> elements() { return { { { "unit cube", unitCube() }, { "box", box() }, { "distorted", distorted() } } }; }

V3 centroid(const Nodes& X)
{
	V3 c = V3::Zero();
	for (const V3& p : X)
		c += p / 8;
	return c;
}

Scalar size(const Nodes& X) { return (X[7] - X[0]).norm(); } // a length scale of the element [m]

// The six rigid-body modes of an element: translation along e_i (first) and infinitesimal rotation ω = e_i about the
// centroid, u_a = ω × (X_a - X̄) (second), for i = 0, 1, 2.
std::array<std::pair<V24, V24>, 3> rigidModes(const Nodes& X)
{
	const V3                           c = centroid(X);
	std::array<std::pair<V24, V24>, 3> modes;
	for (int i = 0; i < 3; ++i)
		for (int a = 0; a < 8; ++a) {
			modes[size_t(i)].first.segment<3>(3 * a)  = V3::Unit(i);
			modes[size_t(i)].second.segment<3>(3 * a) = V3::Unit(i).cross(X[size_t(a)] - c);
		}
	return modes;
}

// ------------------------------------------------------------------------------------------------ references

// 1D linear Lagrange functions on [-1, 1]: L_0 = (1-t)/2, L_1 = (1+t)/2, and their derivatives ∓1/2.
Scalar L(int bit, Scalar t) { return bit ? (1 + t) / 2 : (1 - t) / 2; }
Scalar dL(int bit) { return bit ? 0.5 : -0.5; }

// N_a(ξ) = L_i(ξ) L_j(η) L_k(ζ) with a = i + 2j + 4k.
Scalar refN(int a, const V3& xi) { return L(a & 1, xi[0]) * L((a >> 1) & 1, xi[1]) * L((a >> 2) & 1, xi[2]); }
V3     refdN(int a, const V3& xi)
{
	const int i = a & 1, j = (a >> 1) & 1, k = (a >> 2) & 1;
	return V3(dL(i) * L(j, xi[1]) * L(k, xi[2]), L(i, xi[0]) * dL(j) * L(k, xi[2]), L(i, xi[0]) * L(j, xi[1]) * dL(k));
}

// 3-point Gauss-Legendre rule on [-1, 1] (exact to degree 5).
constexpr Scalar gp3[3] = { -0.7745966692414834, 0.0, 0.7745966692414834 };
constexpr Scalar gw3[3] = { 5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0 };

/* Surface integrals over the six faces ξ_d = ±1 of the element: grad.col(a) = ∮ N_a n dS (= ∫ ∇N_a dV by the
   divergence theorem) and volume = (1/3)∮ x·n dS. On a face, n dS = ±(∂x/∂ξ_{d+1} × ∂x/∂ξ_{d+2}) dξ_{d+1} dξ_{d+2}. */
struct SurfaceIntegrals {
	Grad8  grad;
	Scalar volume;
};
SurfaceIntegrals surfaceIntegrals(const Nodes& X)
{
	SurfaceIntegrals out { Grad8::Zero(), 0 };
	for (int d = 0; d < 3; ++d)
		for (int side = -1; side <= 1; side += 2)
			for (int p = 0; p < 3; ++p)
				for (int q = 0; q < 3; ++q) {
					V3 xi;
					xi[d]           = side;
					xi[(d + 1) % 3] = gp3[p];
					xi[(d + 2) % 3] = gp3[q];
					V3 x = V3::Zero(), du = V3::Zero(), dv = V3::Zero();
					for (int a = 0; a < 8; ++a) {
						const V3 g = refdN(a, xi);
						x += refN(a, xi) * X[a];
						du += g[(d + 1) % 3] * X[a];
						dv += g[(d + 2) % 3] * X[a];
					}
					const V3 ndS = side * gw3[p] * gw3[q] * du.cross(dv);
					for (int a = 0; a < 8; ++a)
						out.grad.col(a) += refN(a, xi) * ndS;
					out.volume += x.dot(ndS) / 3;
				}
	return out;
}

// Voigt (xx, yy, zz, yz, zx, xy) with engineering shear, and back to a symmetric tensor for stresses.
V6 strainVoigt(const M3& eps) { return (V6() << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(1, 2), 2 * eps(2, 0), 2 * eps(0, 1)).finished(); }
M3 stressTensor(const V6& s)
{
	M3 sig;
	sig << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
	return sig;
}

// Nodal displacements of the affine field u(x) = G x + t.
V24 affine(const Nodes& X, const M3& G, const V3& t = V3::Zero())
{
	V24 u;
	for (int a = 0; a < 8; ++a)
		u.segment<3>(3 * a) = G * X[a] + t;
	return u;
}

/* Nodal internal forces of a constant stress, by the independent surface integrals: (∫ Bᵀ σ dV)_a = σ ∫ ∇N_a dV. */
V24 constantStressForces(const Nodes& X, const M3& sigma)
{
	const Grad8 g = surfaceIntegrals(X).grad;
	V24         f;
	for (int a = 0; a < 8; ++a)
		f.segment<3>(3 * a) = sigma * g.col(a);
	return f;
}

M3 rotation(Scalar angle, const V3& axis) { return Eigen::AngleAxis<Scalar>(angle, axis.normalized()).toRotationMatrix(); }

// ------------------------------------------------------------------------------------------------ tests

TEST(Hex8, ShapeFunctionsPartitionOfUnityAndKroneckerDelta)
{
	// Tolerance: N_a are products of three O(1) factors, the sum of 8 of them carries ~1e-16 round-off: 1e-15.
	const V3 points[] = { V3::Zero(), V3(0.3, -0.7, 0.1), V3(-1, 0.5, 0.9), V3(0.577, 0.577, -0.577), V3(2.0, -3.0, 0.5) };
	for (const V3& xi : points) {
		const auto N = rdem::hex8ShapeFunctions<Scalar>(xi);
		EXPECT_NEAR(N.sum(), 1.0, 1e-15) << xi.transpose();
		for (int a = 0; a < 8; ++a)
			EXPECT_NEAR(N[a], refN(a, xi), 1e-15) << "a = " << a << " at " << xi.transpose();
	}
	for (int b = 0; b < 8; ++b) {
		// The documented numbering: node b at (2i-1, 2j-1, 2k-1), b = i + 2j + 4k; ±1 are exact.
		const V3 corner(2 * (b & 1) - 1, 2 * ((b >> 1) & 1) - 1, 2 * ((b >> 2) & 1) - 1);
		EXPECT_EQ(rdem::hex8Corner<Scalar>(b), corner) << "b = " << b;
		const auto N = rdem::hex8ShapeFunctions<Scalar>(corner);
		for (int a = 0; a < 8; ++a)
			EXPECT_EQ(N[a], a == b ? 1.0 : 0.0) << "N_" << a << "(corner " << b << ")"; // products of 0, 1, 2 and /8: exact
	}
	// At the centre all N_a = 1/8 exactly.
	EXPECT_EQ(rdem::hex8ShapeFunctions<Scalar>(V3::Zero()), (Eigen::Matrix<Scalar, 8, 1>::Constant(0.125)));
}

TEST(Hex8, ShapeDerivativesAgainstFiniteDifferences)
{
	// N_a is linear in each coordinate separately, so the central difference has no truncation error; only
	// cancellation, ~1e-16/h = 1e-11 for h = 1e-5: tolerance 1e-10.
	const Scalar h        = 1e-5;
	const V3     points[] = { V3::Zero(), V3(0.3, -0.7, 0.1), V3(-0.9, 0.5, 0.95), V3(0.577, 0.577, -0.577) };
	for (const V3& xi : points) {
		const auto dN = rdem::hex8ShapeDerivatives<Scalar>(xi);
		for (int j = 0; j < 3; ++j) {
			const V3   e  = h * V3::Unit(j);
			const auto fd = ((rdem::hex8ShapeFunctions<Scalar>(xi + e) - rdem::hex8ShapeFunctions<Scalar>(xi - e)) / (2 * h)).eval();
			for (int a = 0; a < 8; ++a) {
				EXPECT_NEAR(dN(j, a), fd[a], 1e-10) << "dN_" << a << "/dxi_" << j << " at " << xi.transpose();
				EXPECT_NEAR(dN(j, a), refdN(a, xi)[j], 1e-15); // against the analytic products: round-off only
			}
		}
		// Σ_a ∂N_a/∂ξ_j = 0 (derivative of the partition of unity); 8 terms of ≤ 0.5: 1e-15.
		for (int j = 0; j < 3; ++j)
			EXPECT_NEAR(dN.row(j).sum(), 0, 1e-15);
	}
}

TEST(Hex8, JacobianOfABoxIsDiagonal)
{
	// For the box, x = X_0 + ((1+ξ) lx/2, (1+η) ly/2, (1+ζ) lz/2): J = diag(0.01, 0.015, 0.02) everywhere.
	// Sums of 8 terms of O(1) coordinates times 1/8: 1e-15 absolute.
	const M3 J = rdem::hex8Jacobian<Scalar>(box(), rdem::hex8ShapeDerivatives<Scalar>(V3(0.3, -0.2, 0.6)));
	EXPECT_NEAR((J - V3(0.01, 0.015, 0.02).asDiagonal().toDenseMatrix()).norm(), 0, 1e-15);
}

TEST(Hex8, VolumeExactForBoxAndDistorted)
{
	// Box: 0.02·0.03·0.04 = 2.4e-5 m³. The box sits at (1, -2, 0.5), so each J entry (≈ 0.01) is a sum of
	// O(1)·O(0.1) terms: ~1e-16·2/0.01 = 2e-14 relative per entry, three per det, eight dets: 1e-13 relative
	// (measured 7e-15).
	EXPECT_NEAR(rdem::hex8Volume(box()), 2.4e-5, 1e-13 * 2.4e-5);
	EXPECT_NEAR(rdem::hex8Volume(unitCube()), 1.0, 1e-14); // no offset: a few ulps, 1e-14
	// Distorted: det J is of degree ≤ 2 in each reference coordinate, so 2-point Gauss is exact; compare with the
	// divergence theorem. Round-off ~1e-16 relative in each, sums of ~50 terms: 1e-13 relative.
	const Scalar V = surfaceIntegrals(distorted()).volume;
	EXPECT_NEAR(rdem::hex8Volume(distorted()), V, 1e-13 * V);
	// The surface-integral reference itself is right on the box (checks the reference, same tolerance).
	EXPECT_NEAR(surfaceIntegrals(box()).volume, 2.4e-5, 1e-13 * 2.4e-5);
	// And the distorted element is not a parallelepiped (otherwise it would test nothing new): face 0-1-3-2 is not a
	// parallelogram by 7 mm in x.
	EXPECT_GT((distorted()[0] + distorted()[3] - distorted()[1] - distorted()[2]).norm(), 5e-3);
}

TEST(Hex8, StiffnessSymmetricAndRigidBodyModesFree)
{
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		ASSERT_TRUE(rdem::hex8IsValid(X));
		for (const M6& D : { rdem::elasticityTensor(E, nu), rdem::poissonTensor(E, nu) }) {
			const M24    K     = rdem::hex8Stiffness(X, D);
			const Scalar normK = K.norm();
			// Round-off: each entry is a sum of 8 Gauss-point products of 6×6×6 terms, ~1e-15 relative each;
			// Bᵀ D B is computed as (Bᵀ D) B, so K - Kᵀ is pure round-off: 1e-14 relative to |K|.
			EXPECT_LE((K - K.transpose()).norm(), 1e-14 * normK);
			// Six rigid-body modes: translations e_i and infinitesimal rotations ω = e_i about the centroid,
			// u_a = ω × (X_a - X̄). K·u is a 24-term sum that cancels to zero: round-off ~24·1e-16 of |K||u|;
			// 1e-13 relative (measured ≤ 8e-16).
			const auto modes = rigidModes(X);
			for (int i = 0; i < 3; ++i) {
				const V24& t = modes[size_t(i)].first;
				const V24& r = modes[size_t(i)].second;
				EXPECT_LE((K * t).norm(), 1e-13 * normK * t.norm()) << "translation " << i;
				EXPECT_LE((K * r).norm(), 1e-13 * normK * r.norm()) << "rotation " << i;
			}
		}
	}
}

TEST(Hex8, FullStiffnessHasRank18)
{
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		const M24                      K = rdem::hex8Stiffness(X, rdem::elasticityTensor(E, nu));
		Eigen::JacobiSVD<M24>          svd(K);
		const Eigen::Matrix<Scalar, 24, 1> s = svd.singularValues(); // descending
		// Six zero singular values (rigid modes) at round-off level: 1e-13 of the largest (measured ≤ 5e-17). The 18
		// others are bounded away from zero: 2×2×2 full integration has no hourglass modes, and the smallest non-zero
		// one is 0.083 (cube), 0.023 (box), 0.064 (distorted) of the largest; 1e-2 catches any spurious zero mode.
		for (int i = 18; i < 24; ++i)
			EXPECT_LE(s[i], 1e-13 * s[0]) << "singular value " << i << ": " << s.transpose();
		EXPECT_GE(s[17], 1e-2 * s[0]) << s.transpose();
		EXPECT_EQ(svd.setThreshold(1e-10).rank(), 18);
	}
}

TEST(Hex8, ConstantStrainPatchTest)
{
	// Arbitrary symmetric strain, plus an arbitrary rigid part (skew W and translation t) that must not matter.
	M3 eps;
	eps << 1.0e-3, 0.4e-3, -0.7e-3, //
	        0.4e-3, -2.0e-3, 0.3e-3, //
	        -0.7e-3, 0.3e-3, 0.5e-3;
	M3 W;
	W << 0, -0.2e-3, 0.1e-3, 0.2e-3, 0, -0.3e-3, -0.1e-3, 0.3e-3, 0;
	const V6  voigt = strainVoigt(eps);
	const M6  D     = rdem::elasticityTensor(E, nu);
	const M3  sigma = stressTensor(D * voigt);
	const Scalar g  = 1 / std::sqrt(3.0);
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		const V24 u  = affine(X, eps);
		const V24 uw = affine(X, eps + W, V3(1e-4, -2e-4, 3e-4));
		// B·u at the 8 Gauss points, the centre and an off-centre point equals the Voigt strain. Round-off: B entries
		// O(1/L), u O(ε·|X|), |X|/L up to 1e2 (offset box): 1e-12 relative to |ε|.
		for (int q = 0; q < 10; ++q) {
			const V3 xi = q < 8 ? V3(g * rdem::hex8Corner<Scalar>(q)) : (q == 8 ? V3::Zero() : V3(0.31, -0.77, 0.12));
			Scalar   detJ = 0;
			const auto B  = rdem::hex8B(X, xi, detJ);
			EXPECT_GT(detJ, 0);
			EXPECT_LE((B * u - voigt).norm(), 1e-12 * voigt.norm()) << "point " << q;
			EXPECT_LE((B * uw - voigt).norm(), 1e-12 * voigt.norm()) << "point " << q << " with rigid part";
		}
		// K u = ∫ Bᵀ D ε dV, by the divergence theorem (surface integrals, independent of B and of 2-point Gauss).
		// Round-off of K·u: u carries the offset position (|X|/L up to 1e2), whose rigid part cancels in 24-term sums:
		// 1e2·24·1e-16 ≈ 3e-13; 1e-12 relative to the force (measured 2e-15).
		const V24 f = constantStressForces(X, sigma);
		EXPECT_LE((rdem::hex8Stiffness(X, D) * u - f).norm(), 1e-12 * f.norm());
		EXPECT_LE((rdem::hex8Stiffness(X, D) * uw - f).norm(), 1e-12 * f.norm());
		// The internal forces of a constant stress are self-equilibrated: Σ_a f_a = σ ∮ n dS = 0.
		V3 sum = V3::Zero();
		for (int a = 0; a < 8; ++a)
			sum += f.segment<3>(3 * a);
		EXPECT_LE(sum.norm(), 1e-13 * f.norm());
	}
}

TEST(Hex8, PoissonStiffnessPushesOutwardUnderVerticalShortening)
{
	// D_p only (eq. 19), u_z = -e z (uniaxial shortening along z, e = 1e-3): σ = D_p ε has σ_xx = σ_yy = -λe,
	// σ_zz = 0; the force on the blocks F = -K_p u points outward in x and y and vanishes in z for a box.
	const Scalar e  = 1e-3;
	const M6     Dp = rdem::poissonTensor(E, nu);
	M3           G  = M3::Zero();
	G(2, 2)         = -e;
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		const V3  c = centroid(X);
		const V24 F = -(rdem::hex8Stiffness(X, Dp) * affine(X, G));
		for (int a = 0; a < 8; ++a) {
			EXPECT_EQ(F[3 * a] > 0, X[a].x() > c.x()) << "F_x at node " << a << " = " << F[3 * a];
			EXPECT_EQ(F[3 * a + 1] > 0, X[a].y() > c.y()) << "F_y at node " << a << " = " << F[3 * a + 1];
		}
		// Magnitude: F_a = -σ ∫∇N_a dV with σ = diag(-λe, -λe, 0) (independent surface integrals); 1e-12 relative
		// as in the patch test.
		const V24 Fref = -constantStressForces(X, stressTensor(Dp * strainVoigt(G)));
		EXPECT_LE((F - Fref).norm(), 1e-12 * Fref.norm());
	}
	// Box by hand: ∫ ∂N_a/∂x dV = ±(ly lz)/4 (the ±x face area over 4 nodes), so F_ax = ±λ e ly lz/4
	// = ±(25e9/3)(1e-3)(0.03·0.04)/4 = ±2500 N; F_ay = ±λ e lx lz/4 = ±5000/3 N; F_az = 0.
	const Nodes X = box();
	const V24   F = -(rdem::hex8Stiffness(X, Dp) * affine(X, G));
	for (int a = 0; a < 8; ++a) {
		const Scalar sx = (a & 1) ? 1 : -1, sy = (a & 2) ? 1 : -1;
		// Round-off of K u relative to the O(2500 N) forces: 1e-12 relative, see the patch test.
		EXPECT_NEAR(F[3 * a], sx * 2500, 1e-12 * 2500) << "node " << a;
		EXPECT_NEAR(F[3 * a + 1], sy * 5000.0 / 3, 1e-12 * 2500) << "node " << a;
		EXPECT_NEAR(F[3 * a + 2], 0, 1e-12 * 2500) << "node " << a;
	}
}

// Reference B of a box lx × ly × lz written out entry by entry: J = diag(lx, ly, lz)/2 everywhere, so
// ∂N_a/∂x = (2/lx) ∂N_a/∂ξ etc.
Eigen::Matrix<Scalar, 6, 24> boxB(Scalar lx, Scalar ly, Scalar lz, const V3& xi)
{
	Eigen::Matrix<Scalar, 6, 24> B = Eigen::Matrix<Scalar, 6, 24>::Zero();
	for (int a = 0; a < 8; ++a) {
		const Scalar si = (a & 1) ? 1 : -1, sj = (a & 2) ? 1 : -1, sk = (a & 4) ? 1 : -1;
		const Scalar dx = (2 / lx) * si * (1 + sj * xi[1]) * (1 + sk * xi[2]) / 8;
		const Scalar dy = (2 / ly) * (1 + si * xi[0]) * sj * (1 + sk * xi[2]) / 8;
		const Scalar dz = (2 / lz) * (1 + si * xi[0]) * (1 + sj * xi[1]) * sk / 8;
		// rows: εxx = ∂ux/∂x, εyy, εzz, γyz = ∂uy/∂z + ∂uz/∂y, γzx = ∂uz/∂x + ∂ux/∂z, γxy = ∂ux/∂y + ∂uy/∂x
		B(0, 3 * a)     = dx;
		B(1, 3 * a + 1) = dy;
		B(2, 3 * a + 2) = dz;
		B(3, 3 * a + 1) = dz;
		B(3, 3 * a + 2) = dy;
		B(4, 3 * a + 2) = dx;
		B(4, 3 * a)     = dz;
		B(5, 3 * a)     = dy;
		B(5, 3 * a + 1) = dx;
	}
	return B;
}

TEST(Hex8, BoxPoissonStiffnessAgainstDenseReference)
{
	// Slow reference for a box lx × ly × lz: J = diag(lx, ly, lz)/2 at every point, so ∂N_a/∂x = (2/lx) ∂N_a/∂ξ etc.,
	// det J = lx ly lz / 8; B built entry by entry and K = Σ_q Bᵀ D B det J assembled with explicit loops.
	const Scalar lx = 0.02, ly = 0.03, lz = 0.04, detJ = lx * ly * lz / 8, g = 1 / std::sqrt(3.0);
	for (const M6& D : { rdem::poissonTensor(E, nu), rdem::elasticityTensor(E, nu) }) {
		M24 Kref = M24::Zero();
		for (int q = 0; q < 8; ++q) {
			const V3                           xi((q & 1) ? g : -g, (q & 2) ? g : -g, (q & 4) ? g : -g);
			const Eigen::Matrix<Scalar, 6, 24> B = boxB(lx, ly, lz, xi);
			for (int r = 0; r < 24; ++r)
				for (int c = 0; c < 24; ++c) {
					Scalar s = 0;
					for (int m = 0; m < 6; ++m)
						for (int n = 0; n < 6; ++n)
							s += B(m, r) * D(m, n) * B(n, c);
					Kref(r, c) += s * detJ;
				}
		}
		const M24 K = rdem::hex8Stiffness(box(), D);
		// Round-off: both are sums of 8×36 products of O(1e10·1e2·1e2·1e-6) terms in a different order; entries can
		// cancel, so compare in the Frobenius norm: 1e-12 relative.
		EXPECT_LE((K - Kref).norm(), 1e-12 * Kref.norm());
		// Entry-wise as well, relative to the largest entry.
		EXPECT_LE((K - Kref).cwiseAbs().maxCoeff(), 1e-12 * Kref.cwiseAbs().maxCoeff());
	}
	// One entry by hand. In local coordinates x ∈ [0, lx] etc., N_0 = (1 - x/lx)(1 - y/ly)(1 - z/lz). The (u_0x, u_0y)
	// entry couples ε_xx = ∂N_0/∂x u_0x with ε_yy = ∂N_0/∂y u_0y through D(0,1) = λ (and, for the full D, γ_xy through
	// μ), so K(0,1) = (λ [+ μ]) ∫ ∂N_0/∂x ∂N_0/∂y dV = (λ [+ μ]) (lx/2)(ly/2)(lz/3)/(lx ly) = (λ [+ μ]) lz/12
	// = 2.78e7 N/m for D_p. The integrand has degree 2 in z, integrated exactly by 2-point Gauss; round-off 1e-13.
	const Scalar lambda = 25e9 / 3, mu = 12.5e9;
	EXPECT_NEAR(rdem::hex8Stiffness(box(), rdem::poissonTensor(E, nu))(0, 1), lambda * lz / 12, 1e-13 * lambda * lz / 12);
	EXPECT_NEAR(rdem::hex8Stiffness(box(), rdem::elasticityTensor(E, nu))(0, 1), (lambda + mu) * lz / 12, 1e-13 * (lambda + mu) * lz / 12);
}

TEST(Hex8, StiffnessWithSkinZeroWeightsIsTheElementStiffness)
{
	// All skin weights 0: the 2×2×2 rule of hex8Stiffness, summed in another order: round-off only, 1e-14 relative
	// (as for the symmetry of K).
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		for (const M6& D : { rdem::elasticityTensor(E, nu), rdem::poissonTensor(E, nu) }) {
			const M24 K = rdem::hex8Stiffness(X, D);
			EXPECT_LE((rdem::hex8StiffnessWithSkin<Scalar>(X, D, V3::Zero(), V3::Zero()) - K).norm(), 1e-14 * K.norm());
		}
	}
}

TEST(Hex8, StiffnessWithSkinOfABox)
{
	// Box lx × ly × lz with skins of thickness ℓ beyond four of its faces: weight t = ℓ/(half length) per face.
	const Scalar lx = 0.02, ly = 0.03, lz = 0.04;
	const Scalar lxLo = 0.004, lxHi = 0.007, lyHi = 0.005, lzLo = 0.002; // [m]
	const V3     lo(lxLo / (lx / 2), 0, lzLo / (lz / 2)), hi(lxHi / (lx / 2), lyHi / (ly / 2), 0);
	const Nodes  X = box();
	for (const M6& D : { rdem::elasticityTensor(E, nu), rdem::poissonTensor(E, nu) }) {
		const M24 Ks = rdem::hex8StiffnessWithSkin<Scalar>(X, D, lo, hi);
		// Symmetric, and rigid-body modes stay free (B·u = 0 at the skin points too); same budgets as for K.
		EXPECT_LE((Ks - Ks.transpose()).norm(), 1e-14 * Ks.norm());
		const V3   c     = centroid(X);
		const auto modes = rigidModes(X);
		for (int i = 0; i < 3; ++i) {
			const V24& t = modes[size_t(i)].first;
			const V24& r = modes[size_t(i)].second;
			EXPECT_LE((Ks * t).norm(), 1e-13 * Ks.norm() * t.norm());
			EXPECT_LE((Ks * r).norm(), 1e-13 * Ks.norm() * r.norm());
		}
		// Uniform strain: B u = ε at every point, inside and in the skin, so uᵀ K u = εᵀ D ε times the volume of the
		// box grown by its skins, (lx + ℓx⁻ + ℓx⁺)(ly + ℓy⁺)(lz + ℓz⁻): the slabs, the edge prisms and corner blocks
		// (products of weights) all count once. The field is taken about the centroid, u = ε(X - X̄), so that the
		// quadratic form is not dominated by a translation of the 1 m offset box (a rigid mode, checked above):
		// round-off of a 24×24 quadratic form, 1e-12 relative (measured below 5e-14).
		const Scalar Vext = (lx + lxLo + lxHi) * (ly + lyHi) * (lz + lzLo);
		M3           eps;
		eps << 1.0e-3, 0.4e-3, -0.7e-3, //
		        0.4e-3, -2.0e-3, 0.3e-3, //
		        -0.7e-3, 0.3e-3, 0.5e-3;
		for (const M3& e : { eps, M3(V3(0, 0, -1e-3).asDiagonal()), M3(V3(1e-3, 0, 0).asDiagonal()) }) {
			const V24    u      = affine(X, e, -e * c);
			const V6     v      = strainVoigt(e);
			const Scalar energy = v.dot(D * v) * Vext;
			EXPECT_NEAR(u.dot(Ks * u), energy, 1e-12 * std::abs(energy)) << "ε =\n" << e;
		}
		// Entry by entry against the reference B of the box: K_skin = K + Σ over the skin points (ξ on a skinned face,
		// the other coordinates on the ±1/√3 or skinned-face points) of w Bᵀ D B det J, w the product of the 1-D
		// weights; det J = lx ly lz/8. 1e-12 relative, as for the dense reference.
		const Scalar g = 1 / std::sqrt(3.0), detJ = lx * ly * lz / 8;
		const std::array<std::pair<Scalar, Scalar>, 4> rx { { { -g, 1 }, { g, 1 }, { -1, lo[0] }, { 1, hi[0] } } };
		const std::array<std::pair<Scalar, Scalar>, 4> ry { { { -g, 1 }, { g, 1 }, { -1, lo[1] }, { 1, hi[1] } } };
		const std::array<std::pair<Scalar, Scalar>, 4> rz { { { -g, 1 }, { g, 1 }, { -1, lo[2] }, { 1, hi[2] } } };
		M24 Kref = M24::Zero();
		for (const auto& [x, wx] : rx)
			for (const auto& [y, wy] : ry)
				for (const auto& [z, wz] : rz) {
					const auto B = boxB(lx, ly, lz, V3(x, y, z));
					Kref += (wx * wy * wz * detJ) * (B.transpose() * D * B);
				}
		EXPECT_LE((Ks - Kref).norm(), 1e-12 * Kref.norm());
		// The skins change K by more than 10 % of |K| here, so the comparisons above are not dominated by the bare K.
		EXPECT_GT((Ks - rdem::hex8Stiffness(X, D)).norm(), 0.1 * rdem::hex8Stiffness(X, D).norm());
	}
}

TEST(Hex8, IsValidRejectsInvertedAndFlatElements)
{
	for (const auto& [name, X] : elements())
		EXPECT_TRUE(rdem::hex8IsValid(X)) << name;
	for (const auto& [name, X0] : elements()) {
		SCOPED_TRACE(name);
		// Two nodes swapped (0 ↔ 1): the element folds over itself, det J < 0 near node 0.
		Nodes X = X0;
		std::swap(X[0], X[1]);
		EXPECT_FALSE(rdem::hex8IsValid(X));
		// Mirrored numbering (every x pair swapped): left-handed, det J < 0 everywhere.
		Nodes M;
		for (int a = 0; a < 8; ++a)
			M[a] = X0[a ^ 1];
		EXPECT_FALSE(rdem::hex8IsValid(M));
		// Flat: all nodes projected onto the plane z = 0. The third column of J, Σ_a ∂N_a/∂ξ_i z_a, is then exactly
		// zero, so det J = 0 exactly, independently of round-off.
		Nodes P = X0;
		for (V3& p : P)
			p.z() = 0;
		EXPECT_FALSE(rdem::hex8IsValid(P));
	}
}

TEST(Hex8, IsValidRejectsFlatElementsInTiltedPlanes)
{
	// The distorted element projected onto its z = 0 plane (zero volume, a valid quadrilateral in plan) and then
	// rotated into 200 tilted planes. Exactly degenerate: every one must be rejected.
	int accepted = 0;
	for (int s = 0; s < 200; ++s) {
		const M3 Q = rotation(0.037 * s + 0.1, V3(1, -2, 3 + 0.1 * s));
		Nodes    X = distorted();
		for (V3& p : X)
			p = Q * V3(p.x(), p.y(), 0);
		accepted += rdem::hex8IsValid(X);
		// Sanity check of the case itself: zero volume up to round-off (1e-12 relative to L³ ≈ 2.7e-5 m³).
		EXPECT_LE(std::abs(rdem::hex8Volume(X)), 1e-12 * 2.7e-5);
	}
	EXPECT_EQ(accepted, 0) << "flat elements accepted by hex8IsValid";
	// A reproducible single case, accepted by the current header (det J ≈ +1e-23..4e-22 at all 9 points).
	Nodes X = distorted();
	for (V3& p : X)
		p = rotation(0.037 * 37 + 0.1, V3(1, -2, 3 + 0.1 * 37)) * V3(p.x(), p.y(), 0);
	EXPECT_FALSE(rdem::hex8IsValid(X));
}

TEST(Hex8, CorotationalFrameOfARigidRotation)
{
	const M3 R = rotation(M_PI / 4, V3(1, 2, 3)); // 45° about an arbitrary axis
	const V3 t(0.5, -0.2, 0.1);
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		Nodes x;
		for (int a = 0; a < 8; ++a)
			x[a] = R * X[a] + t;
		// F = R exactly for an affine motion; the 3×3 SVD is backward stable: 1e-12 on O(1) entries.
		const M3 Rc = rdem::hex8Rotation(X, x);
		EXPECT_LE((Rc - R).cwiseAbs().maxCoeff(), 1e-12);
		// Corotational displacement of a rigid motion: zero up to round-off on positions up to ~2.5 m: 1e-12 L.
		const V24 u = rdem::hex8Displacement(X, x, &Rc);
		EXPECT_LE(u.cwiseAbs().maxCoeff(), 1e-12 * size(X));
		// Small strain (no R): u = (R - I)X + t is of the order of the element and the offset, far from zero.
		const V24 uSmall = rdem::hex8Displacement<Scalar>(X, x, nullptr);
		for (int a = 0; a < 8; ++a)
			EXPECT_LE((uSmall.segment<3>(3 * a) - (x[a] - X[a])).norm(), 1e-15 * (1 + X[a].norm())); // one subtraction
		EXPECT_GT(uSmall.norm(), 0.1 * size(X));
	}
}

TEST(Hex8, SmallStrainPoissonForceOfARigidRotationIsSpurious)
{
	// A 45° rigid rotation treated with small strains: u = (R - I) X, whose symmetric part is the spurious strain
	// ε = (cos45° - 1)(I - n nᵀ) ≈ -0.29 (I - n nᵀ). K_p u is then σ_p(ε) ∫∇N dV (patch test), ~10² times the force
	// of a real 0.1 % shortening, though a rigid motion must give none. This is why the plugin uses hex8Rotation.
	const Nodes  X     = box();
	const V3     n     = V3(1, 2, 3).normalized();
	const M3     R     = rotation(M_PI / 4, n);
	const M6     Dp    = rdem::poissonTensor(E, nu);
	const M24    Kp    = rdem::hex8Stiffness(X, Dp);
	const V24    uRot  = affine(X, R - M3::Identity(), V3(0.5, -0.2, 0.1));
	const M3     epsR  = (std::cos(M_PI / 4) - 1) * (M3::Identity() - n * n.transpose());
	const V24    fRot  = Kp * uRot;
	const V24    fRef  = constantStressForces(X, stressTensor(Dp * strainVoigt(epsR)));
	EXPECT_LE((fRot - fRef).norm(), 1e-12 * fRef.norm()); // as in the patch test (measured 2e-16)
	M3 G    = M3::Zero();
	G(2, 2) = -1e-3;
	const Scalar ratio = fRot.norm() / (Kp * affine(X, G)).norm();
	RecordProperty("KpRotation45_over_Kp0p1percentStrain", std::to_string(ratio));
	// By hand, for n = (1,2,3)/√14: ε_ii = (cos45° - 1)(1 - n_i²) = (-0.272, -0.209, -0.105), and D_p gives
	// σ_ii = λ(tr ε - ε_ii) = -λ(0.314, 0.377, 0.481), against σ = -λ(1e-3, 1e-3, 0) for the 0.1 % shortening. With
	// ∫∇N_a dV = (±3e-4, ±2e-4, ±1.5e-4) m² on the box, |f_rot|/|f_0.1%| = √((0.314²·9 + 0.377²·4 + 0.481²·2.25)/
	// (1e-6·13)) ≈ 390 (389.72 printed as the test property). Checked against the independent surface-integral
	// forces to round-off (1e-12 relative, as above) and against the hand estimate to its 3 digits.
	const Scalar predicted = fRef.norm() / constantStressForces(X, stressTensor(Dp * strainVoigt(G))).norm();
	EXPECT_NEAR(ratio, predicted, 1e-12 * predicted);
	EXPECT_NEAR(ratio, 390, 1.0);
	// Corotational: with R the same motion gives zero displacement, hence zero force.
	Nodes x;
	for (int a = 0; a < 8; ++a)
		x[a] = R * X[a] + V3(0.5, -0.2, 0.1);
	const M3 Rc = rdem::hex8Rotation(X, x);
	EXPECT_LE((Kp * rdem::hex8Displacement(X, x, &Rc)).norm(), 1e-9 * (Kp * affine(X, G)).norm()); // ≤ 1e-12 L of u
}

TEST(Hex8, CorotationalFrameOfAnInvertedElementIsAProperRotation)
{
	// x = R M X with M = diag(1.1, 1.0, -0.5): the element is squashed through itself along z (det F < 0). The
	// closest proper rotation to F = R M is R (flip the sign of the smallest singular value), not the reflection
	// R diag(1, 1, -1) that U Vᵀ alone would give.
	const M3 R = rotation(0.6, V3(2, -1, 1));
	const M3 M = V3(1.1, 1.0, -0.5).asDiagonal();
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		Nodes x;
		for (int a = 0; a < 8; ++a)
			x[a] = R * (M * X[a]);
		const M3 Rc = rdem::hex8Rotation(X, x);
		EXPECT_NEAR(Rc.determinant(), 1.0, 1e-12);        // a rotation, not a reflection (round-off of the SVD)
		EXPECT_LE((Rc - R).cwiseAbs().maxCoeff(), 1e-12); // singular values 1.1, 1, 0.5 well separated: 1e-12
	}
}

TEST(Hex8, CorotationalDisplacementOfStretchPlusRotationIsTheStretch)
{
	// x = R U X + t with U symmetric positive definite (a 1-5 % stretch): F = R U, polar factor R, and
	// u_a = Rᵀ(x_a - x̄) - (X_a - X̄) = (U - I)(X_a - X̄).
	M3 U;
	U << 1.03, 0.01, -0.02, //
	        0.01, 0.98, 0.015, //
	        -0.02, 0.015, 1.05;
	const M3 R = rotation(0.8, V3(-0.4, 1.0, 0.3));
	const V3 t(-0.3, 0.7, 0.2);
	for (const auto& [name, X] : elements()) {
		SCOPED_TRACE(name);
		Nodes x;
		for (int a = 0; a < 8; ++a)
			x[a] = R * (U * X[a]) + t;
		const M3 Rc = rdem::hex8Rotation(X, x);
		EXPECT_LE((Rc - R).cwiseAbs().maxCoeff(), 1e-12); // SVD of an O(1) well-conditioned 3×3: 1e-12
		const V24 u = rdem::hex8Displacement(X, x, &Rc);
		const V3  c = centroid(X);
		for (int a = 0; a < 8; ++a)
			// ≤ 1e-12 error in R times positions of up to ~2.5 m: 1e-12·(1 + |X|) absolute [m] (the stretch is 1e-4-1e-2 m)
			EXPECT_LE((u.segment<3>(3 * a) - (U - M3::Identity()) * (X[a] - c)).norm(), 1e-12 * (1 + X[a].norm())) << "node " << a;
	}
}

TEST(Hex8, PolarRotationOfStretchedRotationsAndItsFallback)
{
	// F = R U, U symmetric positive definite with stretches up to ±40 %, and large rotations: the scaled Newton iteration
	// returns R to 1e-12 (an O(1) well-conditioned 3×3; it stops when R changes by < 1e-14). A reflection (det F < 0)
	// takes the SVD route and still returns a proper rotation.
	for (int k = 0; k < 20; ++k) {
		const M3 R = rotation(0.3 * k, V3(std::sin(k + 1.0), std::cos(2.0 * k), 0.5));
		const M3 Q = rotation(0.7 * k + 0.2, V3(1.0, 0.3 * k, -0.5));
		const V3 stretch(1 + 0.4 * std::sin(3.0 * k), 1 + 0.3 * std::cos(5.0 * k), 1 - 0.35 * std::sin(7.0 * k));
		const M3 U = Q * stretch.asDiagonal() * Q.transpose();
		EXPECT_LE((rdem::polarRotation<Scalar>(R * U) - R).cwiseAbs().maxCoeff(), 1e-12) << "case " << k;
	}
	M3 reflect = M3::Identity();
	reflect(2, 2) = -1;
	const M3 Rr = rdem::polarRotation<Scalar>(reflect * rotation(0.4, V3(0, 1, 1)));
	EXPECT_NEAR(Rr.determinant(), 1.0, 1e-12);
	EXPECT_LE((Rr.transpose() * Rr - M3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
}

} // namespace
