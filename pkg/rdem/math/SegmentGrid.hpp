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
   detected (see doc/theory.md, "Contact geometry"). Units: m, m². */
#pragma once

#include <Eigen/Core>
#include <vector>

namespace yade {
namespace rdem {

	template <class S> struct SurfacePoint {
		Eigen::Matrix<S, 3, 1> pos;    ///< position [m]
		S                      weight; ///< tributary area [m²]
	};

	/// Centres and areas of the n×n segments of the rectangle c + s·t1 + r·t2, |s| ≤ h1, |r| ≤ h2 (t1, t2 unit, orthogonal).
	template <class S>
	std::vector<SurfacePoint<S>>
	segmentCentres(const Eigen::Matrix<S, 3, 1>& c, const Eigen::Matrix<S, 3, 1>& t1, const Eigen::Matrix<S, 3, 1>& t2, S h1, S h2, int n)
	{
		std::vector<SurfacePoint<S>> pts;
		pts.reserve(size_t(n * n));
		const S area = 4 * h1 * h2 / S(n * n);
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j) {
				const S s = h1 * (S(2 * i + 1) / S(n) - 1), r = h2 * (S(2 * j + 1) / S(n) - 1);
				pts.push_back({ c + s * t1 + r * t2, area });
			}
		return pts;
	}

	/// Trapezoid-rule sample points of the same rectangle: an (n+1)×(n+1) grid including edges and corners; weights
	/// sum to the rectangle's area (corner ¼, edge ½, interior 1 times the segment area). Written into pts (cleared
	/// first), so that a caller sampling many faces reuses one buffer instead of allocating one per face.
	template <class S>
	void faceSamplePoints(
	        const Eigen::Matrix<S, 3, 1>& c,
	        const Eigen::Matrix<S, 3, 1>& t1,
	        const Eigen::Matrix<S, 3, 1>& t2,
	        S                             h1,
	        S                             h2,
	        int                           n,
	        std::vector<SurfacePoint<S>>& pts)
	{
		pts.clear();
		const S area = 4 * h1 * h2 / S(n * n);
		for (int i = 0; i <= n; ++i)
			for (int j = 0; j <= n; ++j) {
				const S s = h1 * (S(2 * i) / S(n) - 1), r = h2 * (S(2 * j) / S(n) - 1);
				const S w = area * ((i == 0 || i == n) ? S(0.5) : S(1)) * ((j == 0 || j == n) ? S(0.5) : S(1));
				pts.push_back({ c + s * t1 + r * t2, w });
			}
	}

	/// The same, returned as a new vector.
	template <class S>
	std::vector<SurfacePoint<S>>
	faceSamplePoints(const Eigen::Matrix<S, 3, 1>& c, const Eigen::Matrix<S, 3, 1>& t1, const Eigen::Matrix<S, 3, 1>& t2, S h1, S h2, int n)
	{
		std::vector<SurfacePoint<S>> pts;
		pts.reserve(size_t((n + 1) * (n + 1)));
		faceSamplePoints(c, t1, t2, h1, h2, n, pts);
		return pts;
	}

} // namespace rdem
} // namespace yade
