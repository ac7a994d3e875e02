/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Gershgorin terms of the critical time step (doc/sphinx/rdemTheory.rst §6) for one point spring, and their sum over a flush
   contact covering a face, which bounds the contacts a block can still make there. Units: N/m³ (stiffness per area),
   m, m², kg, kg·m², 1/s². */
#pragma once

#include <pkg/rdem/math/SegmentGrid.hpp>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>

namespace yade {
namespace rdem {

	/* Gershgorin row-sum term of one block for a point spring of area A on it: 2(k_t/m + k_r/I_min), with
	   k_t = max(k_n, k_s)A and k_r = A(k_n|r×n|² + k_s(|r|² + (r·n)²)) the trace of the spring's rotational stiffness
	   about the centroid (r the arm from the centroid, n the unit normal, k_n and k_s per area). [1/s²] */
	template <class S> S pointSpringOmega2(const Eigen::Matrix<S, 3, 1>& r, const Eigen::Matrix<S, 3, 1>& n, S area, S kn, S ks, S mass, S inertiaMin)
	{
		const S kt = std::max(kn, ks) * area;
		const S kr = area * (kn * r.cross(n).squaredNorm() + ks * (r.squaredNorm() + r.dot(n) * r.dot(n)));
		return 2 * (kt / mass + kr / inertiaMin);
	}

	/* The same terms summed over a flush contact covering a face normal to body axis k (either side) of a block of
	   half-extents h: its (n+1)×(n+1) trapezoid sample grid, weights summing to the face area, which is what the samples
	   of a flush face-to-face contact add up to (each block's samples carry half the weight, at the same points).
	   k_n, k_s: the contact's stiffnesses per area. [1/s²] */
	template <class S> S faceContactOmega2(const Eigen::Matrix<S, 3, 1>& half, int k, int n, S kn, S ks, S mass, S inertiaMin)
	{
		using V      = Eigen::Matrix<S, 3, 1>;
		const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
		const V   nf  = V::Unit(k);
		S         sum = 0;
		for (const auto& p : faceSamplePoints<S>(half[k] * nf, V::Unit(k1), V::Unit(k2), half[k1], half[k2], n))
			sum += pointSpringOmega2<S>(p.pos, nf, p.weight, kn, ks, mass, inertiaMin);
		return sum;
	}

} // namespace rdem
} // namespace yade
