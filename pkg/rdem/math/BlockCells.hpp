/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Poisson cells: the Poisson effect of the consistent formulation on any layout of face-bonded rectangular blocks
   (running bond, English bond, bricks cut into blocks that do not line up, T-junctions, mixed sizes; doc/sphinx/rdemTheory.rst §5.4).

   Each block b is a cell. Its normal strain along its axis d is the divergence-theorem average over the cell of the
   normal displacement of its ±d faces, ε_d = (1/V) Σ_faces ±A n·u_f. On a bonded patch (one bond) the face value is
   the point of the bond's face where the two blocks' series springs meet, u_f = u_b(P) + s·d, with d the bond's
   opening vector at the face centre P, u_b(P) the rigid motion of b at P and s = C_b/(C_b + C_c) the share of the
   opening on b's side (C: compliance per area from the centroid to the face, eq. 12). On the free part of a face it
   is u_b(P) extrapolated by ℓ_d times the slope of the bonds along d, Σ β_q (n·d_q)/|s_q| (β_q: area fraction, s_q:
   centroid distance). The rigid motion of b has no flux through its closed surface, so

        ε_d = Σ_q coef_q u_n,q,   coef_q = (A_q/V)(s_q + ℓ_d A_free,d / (A_bonded,d |s_q|)),        (cell strain)

   a weighted sum of the openings u_n,q = n·d_q of the block's bonds along d (positive = opening, m). The openings
   are total measures, so a rigid motion of any size gives ε = 0. Units: m, m², Pa; strains positive in extension.

   Energy W = ½ Σ_b V_b ε_bᵀ (D_b - M_b I) ε_b, D_b the normal block of the isotropic tensor (eq. 18) condensed over
   the axes the cell cannot resolve (σ = 0 there: a block with no bond along an axis, e.g. a one-wythe wall through
   its thickness), M_b the springs' modulus λ+2μ: the springs (diagonal) and the cells add up to D. The cell force
   on bond q is -∂W/∂u_n,q along its normal, at the face centre.

   Exactness (doc/sphinx/rdemTheory.rst §5.4): for a uniform strain the flux of σ_p = (D - M I)ε cancels across every bonded
   face, and what is left on a free face is matched by the springs when the bond q of a block with free area on its
   ±d faces is weighted by w_n = 1 + ℓ_d A_free,d / (|s_q| A_bonded,d) (1.5 for a cube with one free face, as in
   §5.2). A block whose normal translation along d is prescribed (a platen) with bonds on one side only is a half
   cell along d, cut at its centroid plane (as Ω stops there in §5.2); its bonds along the other axes then carry half
   weight. Bonds whose centroids are offset along the face (running bond) need the correction of offsetSlip. */
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <vector>

namespace yade {
namespace rdem {

	/// The axis (0, 1, 2) of the largest component of v: the block axis along a face normal given in the block's frame.
	template <class S> int dominantAxis(const Eigen::Matrix<S, 3, 1>& v)
	{
		using std::abs;
		int k = 0;
		for (int j = 1; j < 3; ++j)
			if (abs(v[j]) > abs(v[k])) k = j;
		return k;
	}

	/// How a cell treats one of its block's axes.
	enum class CellAxis {
		Resolved,  ///< bonds along the axis: the strain comes from their openings (free faces extrapolated)
		Half,      ///< normal translation prescribed and bonds on one side only: the cell stops at the centroid plane
		Condensed, ///< no bond along the axis, or bonds over less than cellMinBondedFraction of a face: its strain is
		           ///< eliminated with σ = 0 (plane stress through a one-wythe wall; a slab piece touching a wall at a corner)
	};

	/* The least bonded area along an axis, as a fraction of one of the block's faces across it, for the cell to resolve the
	   axis [-]. The free part of the ±d faces is extrapolated from the bonds' slopes and weighted onto their springs,
	   w_n - 1 = ℓ_d A_free,d / (|s| A_bonded,d): a bond over a sliver of the face (a 5 × 5 mm corner where a slab piece over a
	   room overlaps the joint of a wall's top brick) would carry the stiffness of the whole face (w_n ≈ 2·10⁴) and the
	   cell's strain, and set the time step of the whole assembly. A block held along d over so little of its section
	   carries the load there locally, not as a uniform strain through its section: σ_dd ≈ 0, as on a free axis, so the
	   axis is condensed and those bonds are plain springs. A quarter of a face is the least overlap of a bond pattern
	   (the quarter lap, doc/sphinx/rdemTheory.rst §5.4); with it, w_n - 1 ≤ 7ℓ_d/|s| from each block. */
	constexpr double cellMinBondedFraction = 0.25;

	/// One bond of a block, as the block's cell sees it.
	template <class S> struct CellBond {
		int axis;     ///< the block's axis (0, 1, 2) along the bond's normal
		int side;     ///< +1: on the block's +axis face; -1: on its -axis face
		S   area;     ///< bonded area [m²]
		S   share;    ///< the block's share of the bond's opening, C_b/(C_b + C_c) (½ between equal blocks)
		S   distance; ///< distance between the two centroids along the normal, |s_q| [m]
	};

	/// A block and its bonds: what its cell is made of.
	template <class S> struct CellInput {
		Eigen::Matrix<S, 3, 1>   half;           ///< half-extents of the block [m]
		S                        young, poisson; ///< of the block's material [Pa], [-]
		std::array<bool, 3>      prescribed {};  ///< whether the block's translation along each of its axes is prescribed
		std::vector<CellBond<S>> bonds;
	};

	/// The cell of a block (see the file's comment).
	template <class S> struct Cell {
		using Mat3 = Eigen::Matrix<S, 3, 3>;
		std::array<CellAxis, 3> axes {};
		S                       volume       = 0;            ///< V [m³]; 0: no cell (the block has no bond)
		Mat3                    stiffness    = Mat3::Zero(); ///< V (D_cond - M I) on the normal strains [N·m]
		Mat3                    condensation = Mat3::Zero(); ///< ε_all = condensation · ε (condensed axes from the others)
		std::array<S, 3>        lateral {};                  ///< per axis d: the cell's extent fraction across d (½ per half axis; 1 without a cell)
		std::vector<S>          coef;                        ///< per bond: ∂ε_axis/∂u_n [1/m]
		std::vector<S>          extraWeight;                 ///< per bond: this block's addition to the bond's w_n
	};

	/// Normal block of the isotropic elasticity tensor (eq. 18 [P]) condensed over the Condensed axes (σ = 0 there),
	/// minus the springs' modulus M = λ+2μ on the other axes; rows and columns of Condensed axes are zero [Pa]. Also
	/// returns the condensation ε_all = C ε (identity on the other axes).
	template <class S> Eigen::Matrix<S, 3, 3> cellElasticity(S young, S poisson, const std::array<CellAxis, 3>& axes, Eigen::Matrix<S, 3, 3>& condensation)
	{
		using Mat3              = Eigen::Matrix<S, 3, 3>;
		const S          lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson)), mu = young / (2 * (1 + poisson));
		Mat3             D = Mat3::Constant(lambda) + 2 * mu * Mat3::Identity();
		std::vector<int> R, U;
		for (int d = 0; d < 3; ++d)
			(axes[size_t(d)] == CellAxis::Condensed ? U : R).push_back(d);
		Mat3 out     = Mat3::Zero();
		condensation = Mat3::Zero();
		if (R.empty()) return out;
		Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> DUU(U.size(), U.size()), DUR(U.size(), R.size());
		for (size_t i = 0; i < U.size(); ++i) {
			for (size_t j = 0; j < U.size(); ++j)
				DUU(long(i), long(j)) = D(U[i], U[j]);
			for (size_t j = 0; j < R.size(); ++j)
				DUR(long(i), long(j)) = D(U[i], R[j]);
		}
		const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> CUR = U.empty() ? Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>(0, long(R.size()))
		                                                                       : Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>(-DUU.lu().solve(DUR));
		for (size_t i = 0; i < R.size(); ++i) {
			condensation(R[i], R[i]) = 1;
			for (size_t j = 0; j < R.size(); ++j) {
				S v = D(R[i], R[j]);
				for (size_t k = 0; k < U.size(); ++k)
					v += D(R[i], U[k]) * CUR(long(k), long(j));
				out(R[i], R[j]) = v - (i == j ? lambda + 2 * mu : S(0));
			}
		}
		for (size_t k = 0; k < U.size(); ++k)
			for (size_t j = 0; j < R.size(); ++j)
				condensation(U[k], R[j]) = CUR(long(k), long(j));
		return out;
	}

	/// The cell of a block: axes, volume, stiffness, per-bond strain coefficients and spring-weight additions.
	template <class S> Cell<S> blockCell(const CellInput<S>& in)
	{
		Cell<S>            c;
		std::array<int, 3> sides {}; // bit 1: a bond on the -axis face, bit 2: on the +axis face
		std::array<S, 3>   bonded {};
		for (const auto& b : in.bonds) {
			sides[size_t(b.axis)] |= (b.side > 0 ? 2 : 1);
			bonded[size_t(b.axis)] += b.area;
		}
		std::array<S, 3> face {}; // area of one face across each axis [m²]
		for (size_t d = 0; d < 3; ++d)
			face[d] = 4 * in.half[long((d + 1) % 3)] * in.half[long((d + 2) % 3)];
		std::array<S, 3> frac {};
		for (size_t d = 0; d < 3; ++d) {
			if (sides[d] == 0 || bonded[d] < S(cellMinBondedFraction) * face[d]) c.axes[d] = CellAxis::Condensed;
			else
				c.axes[d] = (in.prescribed[d] && sides[d] != 3) ? CellAxis::Half : CellAxis::Resolved;
			frac[d] = c.axes[d] == CellAxis::Half ? S(0.5) : S(1);
		}
		c.coef.assign(in.bonds.size(), 0);
		c.extraWeight.assign(in.bonds.size(), 0);
		for (size_t d = 0; d < 3; ++d)
			c.lateral[d] = frac[(d + 1) % 3] * frac[(d + 2) % 3];
		// no cell (no bond, or slivers only): its bonds are plain springs of weight 1
		if (c.axes[0] == CellAxis::Condensed && c.axes[1] == CellAxis::Condensed && c.axes[2] == CellAxis::Condensed) return c;
		c.volume    = 8 * in.half.prod() * frac[0] * frac[1] * frac[2];
		c.stiffness = c.volume * cellElasticity<S>(in.young, in.poisson, c.axes, c.condensation);
		for (size_t q = 0; q < in.bonds.size(); ++q) {
			const auto&  b   = in.bonds[q];
			const size_t d   = size_t(b.axis);
			const S      lat = c.lateral[d];
			if (c.axes[d] == CellAxis::Condensed) continue; // a sliver: a plain spring, no part of the cell's strain
			S coef = b.area * b.share;
			if (c.axes[d] == CellAxis::Resolved) {
				const S free = face[d] * 2 > bonded[d] ? face[d] * 2 - bonded[d] : S(0); // of both ±d faces [m²]
				coef += in.half[long(d)] * free * b.area / (bonded[d] * b.distance);
				c.extraWeight[q] = lat * in.half[long(d)] * free / (b.distance * bonded[d]);
			}
			c.coef[q] = lat * coef / c.volume;
		}
		return c;
	}

	/// Normal weight w_n of a bond from the cells of its two blocks: the smaller of their lateral fractions (½ across a
	/// platen's half cell) plus each block's extraWeight. The shear weight w_s is that lateral fraction alone.
	template <class S> S cellBondWeightNormal(S lateral1, S lateral2, S extra1, S extra2)
	{
		return (lateral1 < lateral2 ? lateral1 : lateral2) + extra1 + extra2;
	}

	/* Offset correction of the shear springs (doc/sphinx/rdemTheory.rst §5.4). Under the cells' strains each block deforms
	   as E_b = diag(ε_b) in its own frame, so the material of block b at the bonded face's centre p moves by E_b a_b
	   relative to its centroid, a_b = p - x_b. The rigid blocks' shear springs see only the centroids' motion, and two
	   blocks whose centroids are offset along the face (running bond, a course bonded to a beam) slip by the difference
	   even under a uniform strain, which a continuum does not do. The intact shear springs therefore measure
	   d_t - P_t(E₁a₁ - E₂a₂). Under a uniform strain E₁a₁ - E₂a₂ = E(x₂ - x₁) whatever p is; between blocks of unequal
	   length (a brick and a beam) only the face centre gives each block its own share. Arguments: eps1, eps2 the normal
	   strains of the blocks along their own axes; a1 the face centre's offset from body 1's centroid along the face, in
	   body 1's frame, a2 that from body 2's centroid in body 2's frame [m]; R12 = R₁ᵀR₂; n the face normal in body 1's
	   frame. Returns the tangential slip to subtract, in body 1's frame [m]. Zero when a₁ = a₂ = 0 (a grid). */
	template <class S>
	Eigen::Matrix<S, 3, 1> offsetSlip(
	        const Eigen::Matrix<S, 3, 1>& eps1,
	        const Eigen::Matrix<S, 3, 1>& a1,
	        const Eigen::Matrix<S, 3, 3>& R12,
	        const Eigen::Matrix<S, 3, 1>& eps2,
	        const Eigen::Matrix<S, 3, 1>& a2,
	        const Eigen::Matrix<S, 3, 1>& n)
	{
		const Eigen::Matrix<S, 3, 1> c = eps1.cwiseProduct(a1) - R12 * eps2.cwiseProduct(a2);
		return c - c.dot(n) * n;
	}

	/* Gradient of the shear springs' energy ½ Σ k_s w_s A |d_t - c_t|² with respect to the cell strains of the two
	   blocks, given T = Σ k_s w_s A (d_t - c_t) over the intact segments (body-1 frame) [N]: ∂W/∂ε₁ = -T∘a₁ and
	   ∂W/∂ε₂ = (R12ᵀT)∘a₂ [N·m], a₁ and a₂ as in offsetSlip. Added to the cells' stresses, they give the reaction of the
	   correction on the bonds that made the strains, so that the correction is conservative. */
	template <class S>
	void offsetSlipGradient(
	        const Eigen::Matrix<S, 3, 1>& T,
	        const Eigen::Matrix<S, 3, 3>& R12,
	        const Eigen::Matrix<S, 3, 1>& a1,
	        const Eigen::Matrix<S, 3, 1>& a2,
	        Eigen::Matrix<S, 3, 1>&       grad1,
	        Eigen::Matrix<S, 3, 1>&       grad2)
	{
		grad1 = -T.cwiseProduct(a1);
		grad2 = (R12.transpose() * T).cwiseProduct(a2);
	}

	/// The in-plane part of a face centre's offset from a centroid, c - (c·n)n, for offsetSlip's a₁ and a₂ [m].
	template <class S> Eigen::Matrix<S, 3, 1> alongFace(const Eigen::Matrix<S, 3, 1>& centre, const Eigen::Matrix<S, 3, 1>& n)
	{
		return centre - centre.dot(n) * n;
	}

} // namespace rdem
} // namespace yade
