/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Segments of a face and sample points of a block (paper §3.1, Fig. 2a).

   A face shared by two blocks is cut into n×n equal segments; each carries one restoring spring at its
   centre (the "representative point" of [P] Fig. 2a) with the segment area as weight. For contact between
   blocks that are not bonded, every face of a block is sampled on an (n+1)×(n+1) grid that includes edges and
   corners, with trapezoid-rule weights, so that a face, an edge or a corner that enters another block is
   detected (doc/sphinx/rdemTheory.rst §4). Units: m, m². */
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace yade {
namespace rdem {

	template <class S> struct SurfacePoint {
		Eigen::Matrix<S, 3, 1> pos;    ///< position [m]
		S                      weight; ///< tributary area [m²]
	};

	/// Area of one of the n×n equal segments of a rectangle of half-sizes h1, h2 [m]: 4h1h2/n² [m²].
	template <class S> S segmentArea(S h1, S h2, int n) { return 4 * h1 * h2 / S(n * n); }

	/// Centres and areas of the n×n segments of the rectangle c + s·t1 + r·t2, |s| ≤ h1, |r| ≤ h2 (t1, t2 unit, orthogonal).
	template <class S>
	std::vector<SurfacePoint<S>>
	segmentCentres(const Eigen::Matrix<S, 3, 1>& c, const Eigen::Matrix<S, 3, 1>& t1, const Eigen::Matrix<S, 3, 1>& t2, S h1, S h2, int n)
	{
		std::vector<SurfacePoint<S>> pts;
		pts.reserve(size_t(n * n));
		const S area = segmentArea(h1, h2, n);
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j) {
				const S s = h1 * (S(2 * i + 1) / S(n) - 1), r = h2 * (S(2 * j + 1) / S(n) - 1);
				pts.push_back({ c + s * t1 + r * t2, area });
			}
		return pts;
	}

	/// Node i (0 … n) of the (n+1)-point trapezoid rule on [-1, 1]: its coordinate x = 2i/n - 1 and its weight factor
	/// w (½ at the ends, 1 inside); the rule's weight is w·2/n.
	template <class S> struct TrapezoidNode {
		S x, w;
	};

	template <class S> TrapezoidNode<S> trapezoidNode(int i, int n) { return { S(2 * i) / S(n) - 1, (i == 0 || i == n) ? S(0.5) : S(1) }; }

	/// Trapezoid-rule sample points of the rectangle c + s·t1 + r·t2, |s| ≤ h1, |r| ≤ h2: an (n+1)×(n+1) grid including
	/// edges and corners, point (i, j) at s = h1 x_i, r = h2 x_j (trapezoidNode); weights sum to the rectangle's area
	/// (corner ¼, edge ½, interior 1 times the segment area 4h1h2/n²).
	template <class S>
	std::vector<SurfacePoint<S>>
	faceSamplePoints(const Eigen::Matrix<S, 3, 1>& c, const Eigen::Matrix<S, 3, 1>& t1, const Eigen::Matrix<S, 3, 1>& t2, S h1, S h2, int n)
	{
		std::vector<SurfacePoint<S>> pts;
		pts.reserve(size_t((n + 1) * (n + 1)));
		const S area = segmentArea(h1, h2, n);
		for (int i = 0; i <= n; ++i) {
			const auto a = trapezoidNode<S>(i, n);
			for (int j = 0; j <= n; ++j) {
				const auto b = trapezoidNode<S>(j, n);
				pts.push_back({ c + (h1 * a.x) * t1 + (h2 * b.x) * t2, area * a.w * b.w });
			}
		}
		return pts;
	}

	/// Grid coordinate of segment i of n along one axis of a face: its centre lies s·h from the face centre, s = 2i + 1 - n,
	/// h the segment's half-size along that axis (so that segmentCentres gives c + s h₁t₁ + r h₂t₂).
	template <class S> S segmentCoordinate(int i, int n) { return S(2 * i + 1 - n); }

	/// Grid coordinates (s, r) of segment k = i n + j of a face of n×n segments (segmentCoordinate of i and of j).
	template <class S> Eigen::Matrix<S, 2, 1> segmentCoordinates(std::size_t k, int n)
	{
		return Eigen::Matrix<S, 2, 1>(segmentCoordinate<S>(int(k) / n, n), segmentCoordinate<S>(int(k) % n, n));
	}

	/* Kinematics of the segments of a bonded face (paper eq. 14, §3.1). A segment at grid coordinates (s, r) has one
	   material point in each block, P₁ = x₁ + R₁(c₁ + s a₁ + r b₁) and P₂ = x₂ + R₂(c₂ + s a₂ + r b₂), with c the face
	   centre and a, b the segment half-size vectors along the face's in-plane axes, all in that block's frame, and R the
	   block's rotation (body to global). Both are affine in (s, r), so the relative displacement d = P₂ - P₁ and the
	   offset r₂ = C - x₂ of the segment's current point C = (P₁ + P₂)/2 are too: six matrix-vector products per bond
	   instead of two per segment, and no per-segment point stored. Units m; d is positive (along the normal from block 1
	   to block 2) when the face opens. A rigid motion of the pair gives d = 0 at any rotation. */
	template <class S> struct BondKinematics {
		using V = Eigen::Matrix<S, 3, 1>;
		V d0, da, db; ///< d(s, r) = d0 + s da + r db [m]
		V r0, ra, rb; ///< r₂(s, r) = r0 + s ra + r rb [m]
		/// d = P₂ - P₁ of the segment at grid coordinates (s, r) [m].
		V displacement(S s, S r) const { return d0 + s * da + r * db; }
		/// r₂ = C - x₂ of the segment at grid coordinates (s, r) [m].
		V arm(S s, S r) const { return r0 + s * ra + r * rb; }
	};

	/// BondKinematics of a face for the rotations R1, R2 of the blocks and dx = x₂ - x₁ (see there).
	template <class S>
	BondKinematics<S> bondKinematics(
	        const Eigen::Matrix<S, 3, 3>& R1,
	        const Eigen::Matrix<S, 3, 3>& R2,
	        const Eigen::Matrix<S, 3, 1>& dx,
	        const Eigen::Matrix<S, 3, 1>& c1,
	        const Eigen::Matrix<S, 3, 1>& a1,
	        const Eigen::Matrix<S, 3, 1>& b1,
	        const Eigen::Matrix<S, 3, 1>& c2,
	        const Eigen::Matrix<S, 3, 1>& a2,
	        const Eigen::Matrix<S, 3, 1>& b2)
	{
		using V              = Eigen::Matrix<S, 3, 1>;
		const V           C2 = R2 * c2, A2 = R2 * a2, B2 = R2 * b2; // P₂ - x₂ = C2 + s A2 + r B2
		BondKinematics<S> k;
		k.d0 = dx + C2 - R1 * c1;
		k.da = A2 - R1 * a1;
		k.db = B2 - R1 * b1;
		k.r0 = C2 - k.d0 / 2;
		k.ra = A2 - k.da / 2;
		k.rb = B2 - k.db / 2;
		return k;
	}

} // namespace rdem
} // namespace yade
