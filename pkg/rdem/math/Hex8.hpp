/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The virtual 8-node hexahedron of the Poisson effect (paper §4.2, eqs. 20-21) and its corotational frame.

   Nodes are the centroids of 2×2×2 neighbouring blocks. Node a = i + 2j + 4k (i, j, k ∈ {0, 1}) sits at
   the reference-cube corner (ξ, η, ζ) = (2i-1, 2j-1, 2k-1): x runs fastest. Displacement vector
   u = (u_0x, u_0y, u_0z, u_1x, ...), 24 entries [m]; forces in the same order [N].

   Trilinear shape functions N_a = (1+ξ_a ξ)(1+η_a η)(1+ζ_a ζ)/8 (Zienkiewicz & Taylor, The Finite Element
   Method, vol. 1, §8.5); strain-displacement matrix B (6×24) in Voigt order (xx, yy, zz, yz, zx, xy) with
   engineering shear strains; K = ∫ Bᵀ D B dV by 2×2×2 Gauss-Legendre quadrature, which is exact for a
   parallelepiped and the standard full integration otherwise.

   Sign convention: K u is the element's internal (resisting) force; the force applied to the blocks is
   F = -K u. With D = D_p (eq. 19), shortening along z gives outward forces along x and y. */
#pragma once

#include <pkg/rdem/math/Elasticity.hpp>
#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <array>
#include <utility>
#include <cmath>

namespace yade {
namespace rdem {

	template <class S> using Vec3    = Eigen::Matrix<S, 3, 1>;
	template <class S> using Mat3    = Eigen::Matrix<S, 3, 3>;
	template <class S> using Vec24   = Eigen::Matrix<S, 24, 1>;
	template <class S> using Mat24   = Eigen::Matrix<S, 24, 24>;
	template <class S> using Mat6x24 = Eigen::Matrix<S, 6, 24>;
	template <class S> using Nodes8  = std::array<Vec3<S>, 8>;

	/// The 12 edges of the hexahedron: node pairs that differ in one of the bits i, j, k (node a = i + 2j + 4k).
	constexpr int hex8Edges[12][2] = { { 0, 1 }, { 2, 3 }, { 4, 5 }, { 6, 7 }, { 0, 2 }, { 1, 3 }, { 4, 6 }, { 5, 7 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };

	/// Reference-cube coordinates (ξ_a, η_a, ζ_a) of node a ∈ [0, 8).
	template <class S> Vec3<S> hex8Corner(int a) { return Vec3<S>(S(2 * (a & 1) - 1), S((a & 2) - 1), S((a & 4) / 2 - 1)); }

	/// Trilinear shape functions N_a(ξ) at a point of the reference cube.
	template <class S> Eigen::Matrix<S, 8, 1> hex8ShapeFunctions(const Vec3<S>& xi)
	{
		Eigen::Matrix<S, 8, 1> N;
		for (int a = 0; a < 8; ++a) {
			const Vec3<S> c = hex8Corner<S>(a);
			N[a]            = (1 + c[0] * xi[0]) * (1 + c[1] * xi[1]) * (1 + c[2] * xi[2]) / 8;
		}
		return N;
	}

	/// Derivatives ∂N_a/∂ξ_j of the shape functions, row j, column a.
	template <class S> Eigen::Matrix<S, 3, 8> hex8ShapeDerivatives(const Vec3<S>& xi)
	{
		Eigen::Matrix<S, 3, 8> dN;
		for (int a = 0; a < 8; ++a) {
			const Vec3<S> c = hex8Corner<S>(a);
			const Vec3<S> f(1 + c[0] * xi[0], 1 + c[1] * xi[1], 1 + c[2] * xi[2]);
			dN(0, a) = c[0] * f[1] * f[2] / 8;
			dN(1, a) = f[0] * c[1] * f[2] / 8;
			dN(2, a) = f[0] * f[1] * c[2] / 8;
		}
		return dN;
	}

	/// Jacobian J_ij = ∂x_j/∂ξ_i of the map from the reference cube to the element with nodes X.
	template <class S> Mat3<S> hex8Jacobian(const Nodes8<S>& X, const Eigen::Matrix<S, 3, 8>& dN)
	{
		Mat3<S> J = Mat3<S>::Zero();
		for (int a = 0; a < 8; ++a)
			J += dN.col(a) * X[a].transpose();
		return J;
	}

	/// Strain-displacement matrix B at ξ, ε = B u (Voigt, engineering shear); also returns det J through detJ.
	template <class S> Mat6x24<S> hex8B(const Nodes8<S>& X, const Vec3<S>& xi, S& detJ)
	{
		const Eigen::Matrix<S, 3, 8> dN = hex8ShapeDerivatives<S>(xi);
		const Mat3<S>                J  = hex8Jacobian<S>(X, dN);
		detJ                            = J.determinant();
		const Eigen::Matrix<S, 3, 8> dNdx = J.inverse() * dN; // ∂N_a/∂x_j, row j
		Mat6x24<S>                   B    = Mat6x24<S>::Zero();
		for (int a = 0; a < 8; ++a) {
			const S dx = dNdx(0, a), dy = dNdx(1, a), dz = dNdx(2, a);
			const int c = 3 * a;
			B(0, c)     = dx;
			B(1, c + 1) = dy;
			B(2, c + 2) = dz;
			B(3, c + 1) = dz; // γ_yz = ∂u_y/∂z + ∂u_z/∂y
			B(3, c + 2) = dy;
			B(4, c)     = dz; // γ_zx = ∂u_z/∂x + ∂u_x/∂z
			B(4, c + 2) = dx;
			B(5, c)     = dy; // γ_xy = ∂u_x/∂y + ∂u_y/∂x
			B(5, c + 1) = dx;
		}
		return B;
	}

	/// Eq. (21) [P]: K = ∫ Bᵀ D B dV by 2×2×2 Gauss-Legendre quadrature (points ±1/√3, weights 1).
	/// With D = D_p (eq. 19) this is the paper's K_p. Callers check the geometry first with hex8IsValid.
	template <class S> Mat24<S> hex8Stiffness(const Nodes8<S>& X, const Matrix6<S>& D)
	{
		using std::sqrt;
		const S  g = 1 / sqrt(S(3));
		Mat24<S> K = Mat24<S>::Zero();
		for (int q = 0; q < 8; ++q) {
			const Vec3<S>    xi = g * hex8Corner<S>(q);
			S                detJ;
			const Mat6x24<S> B = hex8B<S>(X, xi, detJ);
			K.noalias() += B.transpose() * D * B * detJ;
		}
		return K;
	}

	/* K over the element extended by a skin (consistent formulation, doc/sphinx/rdemTheory.rst §5.2): along each axis d the 1-D rule is
	   the two Gauss points ±1/√3 (weight 1) plus the end point ξ_d = -1 with weight skinLo[d] and ξ_d = +1 with weight
	   skinHi[d] (left out when 0). A weight t = ℓ/(half the element length along d) integrates the strain of the element's
	   face over a slab of thickness ℓ beyond it: the strain of the skin is that of the nearest point of the element
	   (B(clamp(ξ))). With all weights 0 this is hex8Stiffness. */
	template <class S> Mat24<S> hex8StiffnessWithSkin(const Nodes8<S>& X, const Matrix6<S>& D, const Vec3<S>& skinLo, const Vec3<S>& skinHi)
	{
		using std::sqrt;
		const S g = 1 / sqrt(S(3));
		std::array<std::array<std::pair<S, S>, 4>, 3> rule; // per axis: (ξ, weight) points, unused ones weight 0
		for (int d = 0; d < 3; ++d)
			rule[size_t(d)] = { { { -g, S(1) }, { g, S(1) }, { S(-1), skinLo[d] }, { S(1), skinHi[d] } } };
		Mat24<S> K = Mat24<S>::Zero();
		for (const auto& px : rule[0])
			for (const auto& py : rule[1])
				for (const auto& pz : rule[2]) {
					const S w = px.second * py.second * pz.second;
					if (w == 0) continue;
					S                detJ;
					const Mat6x24<S> B = hex8B<S>(X, Vec3<S>(px.first, py.first, pz.first), detJ);
					K.noalias() += B.transpose() * D * B * (w * detJ);
				}
		return K;
	}

	/// True when det J > 0 at the 8 Gauss points and the centre, i.e. the nodes are numbered as documented above and
	/// the element is not inverted or degenerate.
	template <class S> bool hex8IsValid(const Nodes8<S>& X)
	{
		using std::sqrt;
		const S g = 1 / sqrt(S(3));
		for (int q = 0; q < 9; ++q) {
			const Vec3<S> xi = q < 8 ? Vec3<S>(g * hex8Corner<S>(q)) : Vec3<S>(Vec3<S>::Zero());
			// Scale-free: det J over the product of the row norms of J is in [-1, 1] (Hadamard's inequality); a flat
			// element gives round-off of either sign, so require more than that.
			const Mat3<S> J = hex8Jacobian<S>(X, hex8ShapeDerivatives<S>(xi));
			if (!(J.determinant() > S(1e-8) * J.row(0).norm() * J.row(1).norm() * J.row(2).norm())) return false;
		}
		return true;
	}

	/// Volume of the element, ∫ dV by the same quadrature [m³].
	template <class S> S hex8Volume(const Nodes8<S>& X)
	{
		using std::sqrt;
		const S g = 1 / sqrt(S(3));
		S       V = 0;
		for (int q = 0; q < 8; ++q)
			V += hex8Jacobian<S>(X, hex8ShapeDerivatives<S>(Vec3<S>(g * hex8Corner<S>(q)))).determinant();
		return V;
	}

	/* Corotational frame (Felippa & Haugen, CMAME 194 (2005) 2285; Chrono's ChElementHexaCorot_8): the rotation R of
	   the element is the rotation factor of the polar decomposition F = R U of the deformation gradient at the
	   element centre, F = Σ_a x_a ⊗ ∇_X N_a(0). The local displacement is u_a = Rᵀ(x_a - x̄) - (X_a - X̄)
	   with x̄, X̄ the node means, so a rigid motion gives u = 0 exactly; local forces K u are rotated back by R. */
	/* Rotation factor R of the polar decomposition F = R U (U symmetric positive definite), for det F > 0: Higham's
	   scaled Newton iteration R ← (ζR + R⁻ᵀ/ζ)/2, ζ = |det R|^(-1/3) (N. J. Higham, Functions of Matrices, SIAM 2008,
	   §8.6), which converges quadratically and, for the near-rotations of an element, in 3-5 steps; stopped when R
	   changes by less than 1e-14 (Frobenius, R is O(1)). Flat or inverted F (det F ≤ 0) or no convergence in 30 steps:
	   the SVD, with the sign fix that keeps det R = +1. */
	template <class S> Mat3<S> polarRotation(const Mat3<S>& F)
	{
		using std::abs;
		using std::cbrt;
		if (F.determinant() > 0) {
			Mat3<S> R = F;
			for (int it = 0; it < 30; ++it) {
				const S       zeta = 1 / cbrt(abs(R.determinant()));
				const Mat3<S> next = (zeta * R + R.inverse().transpose() / zeta) / 2;
				const S       step = (next - R).norm();
				R                  = next;
				if (step < S(1e-14)) return R;
			}
		}
		Eigen::JacobiSVD<Mat3<S>> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
		Mat3<S>                   W = Mat3<S>::Identity();
		W(2, 2)                     = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? S(-1) : S(1);
		return svd.matrixU() * W * svd.matrixV().transpose();
	}

	template <class S> Mat3<S> hex8Rotation(const Nodes8<S>& X, const Nodes8<S>& x)
	{
		const Eigen::Matrix<S, 3, 8> dN   = hex8ShapeDerivatives<S>(Vec3<S>::Zero());
		const Eigen::Matrix<S, 3, 8> dNdX = hex8Jacobian<S>(X, dN).inverse() * dN;
		Mat3<S>                      F    = Mat3<S>::Zero();
		for (int a = 0; a < 8; ++a)
			F += x[a] * dNdX.col(a).transpose();
		return polarRotation<S>(F);
	}

	/// Element displacement vector u (24) from reference nodes X and current nodes x: small-strain u_a = x_a - X_a, or,
	/// with a rotation R (corotational), u_a = Rᵀ(x_a - x̄) - (X_a - X̄).
	template <class S> Vec24<S> hex8Displacement(const Nodes8<S>& X, const Nodes8<S>& x, const Mat3<S>* R)
	{
		Vec24<S> u;
		if (!R) {
			for (int a = 0; a < 8; ++a)
				u.template segment<3>(3 * a) = x[a] - X[a];
			return u;
		}
		Vec3<S> xMean = Vec3<S>::Zero(), XMean = Vec3<S>::Zero();
		for (int a = 0; a < 8; ++a) {
			xMean += x[a] / 8;
			XMean += X[a] / 8;
		}
		for (int a = 0; a < 8; ++a)
			u.template segment<3>(3 * a) = R->transpose() * (x[a] - xMean) - (X[a] - XMean);
		return u;
	}

} // namespace rdem
} // namespace yade
