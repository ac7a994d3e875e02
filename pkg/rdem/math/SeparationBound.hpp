/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* How long two blocks that are apart stay apart.

   After the first crack the collider hands the geometry functor every pair of blocks whose bounding boxes overlap: in
   a grid, the edge and corner neighbours of every block, about ten pairs per block, nearly all of them apart by a
   strain-sized gap. Instead of the separating-axis test at every step, a pair found apart gets a certificate: the
   slack by which the blocks' projections on one axis must still grow before blocksOverlap can return true. The slack
   is used up by motion only: every point of a rigid body moves at most rigidTravel between two configurations, so the
   test is needed again only once the two blocks' travels since the certificate add up to the slack. The decision of
   blocksOverlap is unchanged, not approximated.

   Units: m; quaternions unit. */
#pragma once

#include <pkg/rdem/math/BlockGeometry.hpp>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace yade {
namespace rdem {

	/* Largest distance a point within rho of a rigid body's reference point moves between the configurations (x0, q0)
	   and (x1, q1) [m]: |x1 - x0| + 2 rho min(|q1 - q0|, |q1 + q0|). The rotation from q0 to q1 by an angle θ ∈ [0, π]
	   moves a point at distance r ≤ rho from the reference point by at most the chord 2 r sin(θ/2), and, with the sign of
	   q1 that makes q0·q1 ≥ 0, |q1 - q0| = 2 sin(θ/4) ≥ sin(θ/2) = 2 sin(θ/4) cos(θ/4). No trigonometric function: this
	   runs for every block at every step of the contact phase. */
	template <class S>
	S rigidTravel(const Eigen::Matrix<S, 3, 1>& x0, const Eigen::Quaternion<S>& q0, const Eigen::Matrix<S, 3, 1>& x1, const Eigen::Quaternion<S>& q1, S rho)
	{
		using std::sqrt;
		const S minus = (q1.coeffs() - q0.coeffs()).squaredNorm(), plus = (q1.coeffs() + q0.coeffs()).squaredNorm();
		return (x1 - x0).norm() + 2 * rho * sqrt(std::min(minus, plus));
	}

	/// Margin kept from a certificate's slack [m]: 1e-6 of the blocks' summed circumradii (see separationSlack), of two
	/// blocks of half-extents hA and hB [m].
	template <class S> S separationMargin(const Eigen::Matrix<S, 3, 1>& hA, const Eigen::Matrix<S, 3, 1>& hB) { return S(1e-6) * (hA.norm() + hB.norm()); }
	template <class S> S separationMargin(const BlockPair<S>& pair) { return separationMargin<S>(pair.A.half, pair.B.half); }

	/* Separation slack of two blocks [m]: over the 3 + 3 face normals a of the blocks, the largest tol - o(a), o(a) the
	   overlap of the blocks' projections on a, less separationMargin. Positive only if blocksOverlap is false. The
	   cross products of edges, which blocksOverlap also tests, give no certificate: a pair apart only along one of them
	   (two edges crossing) is tested again at every step, as without certificates. Measured on a collapsing pile of
	   10³ blocks: the cross products certified no pair that the face normals did not, and cost 15 % of the step
	   (a square root and a division each).

	   Guarantee: if afterwards every point of A moves by at most t_A and every point of B by at most t_B (rigidTravel,
	   summed over steps) with t_A + t_B < slack, blocksOverlap still returns false. Proof: o(a) along the face normal a,
	   now fixed in space, is the least of the two one-sided overlaps max_A p·a - min_B p·a and max_B p·a - min_A p·a;
	   each grows by at most t_A + t_B, so o(a) stays below tol - margin. The overlap along any unit direction is at
	   least the penetration depth of the moved blocks (the distance from the origin to the boundary of the Minkowski
	   difference A - B, if it lies inside), which is attained on a facet normal of that difference, i.e. on one of
	   their 15 axes, so one of them overlaps by less than tol - margin; blocksOverlap skips only the cross products of
	   edges within 1e-9 rad of parallel, whose facets are slivers of width ~1e-9 of an edge, moving the least tested
	   overlap by about 1e-9 of the blocks' size, far inside the margin of 1e-6 (which also covers the round-off, ~1e-16
	   of the coordinates). So blocksOverlap finds an axis with overlap ≤ tol and returns false.

	   faceSeparation gives the slack with the face axis it comes from (the pair's witness, below); separationSlack the
	   slack alone. */
	template <class S> struct FaceSeparation {
		S   slack = -std::numeric_limits<S>::infinity(); ///< separationSlack [m]
		int axis  = -1; ///< the face axis of least overlap (0–2: A's, 3–5: B's, as SeparatingAxes::face), -1 if none is finite
	};
	template <class S> FaceSeparation<S> faceSeparation(const BlockPair<S>& pair, S tol)
	{
		FaceSeparation<S> out;
		S                 best = -std::numeric_limits<S>::infinity();
		for (int i = 0; i < 6; ++i) {
			const S gap = tol - (i < 3 ? pair.overlapA(i) : pair.overlapB(i - 3));
			if (gap > best) {
				best     = gap;
				out.axis = i;
			}
		}
		const S slack = best - separationMargin(pair);
		using std::isfinite;
		out.slack = isfinite(slack) ? slack : -std::numeric_limits<S>::infinity();
		return out;
	}
	template <class S> S separationSlack(const BlockPair<S>& pair, S tol) { return faceSeparation(pair, tol).slack; }

	/* Grid neighbours that touch along an edge or at a corner (overlap 0 on one face axis, up to the strain of their
	   contacts) are apart for blocksOverlap but get no certificate: their slack, tol less an overlap of about 0, is
	   below the margin. In a dense pack (a dry-stacked cube, a wall) they are most of the collider's pairs, and every
	   step tested them with both rotation matrices, C = R_Aᵀ R_B and the overlaps. The axis that separated a pair in
	   one step is tested first in the next (a witness of separation: the separating plane of the last step, Rabbitz
	   1994 [Rabbitz1994]_): its overlap alone, from the two blocks' positions and orientations (faceAxisOverlap), decides
	   the pair apart while it stays below tol by more than the round-off between it and BlockPair's value of the same
	   overlap (faceAxisRoundOff): blocksOverlap, which tests every face axis before the edge cross products and returns
	   false at the first one whose overlap is not above tol, then returns false too. Otherwise the pair is tested in
	   full again. */

	/* Overlap of the projections of blocks A and B (centroids xA, xB [m], unit orientations qA, qB, half-extents hA, hB
	   [m]) on the face axis `axis` (0–2: A's axis a_i, 3–5: B's b_j) [m]: BlockPair::overlapA(i), overlapB(j) without the
	   two rotation matrices and C. Along a_i: h_Ai + Σ_j |(R_Bᵀ a_i)_j| h_Bj - |a_i·(xB - xA)|, and alike along b_j; a_i is
	   column i of R_A from the quaternion's components, R_Bᵀ a_i the rotation by B's conjugate quaternion
	   (v + w t + u × t with t = 2 u × v, u = -q_B's vector part, w its scalar part), written out so that it inlines. */
	template <class S>
	S faceAxisOverlap(
	        const Eigen::Matrix<S, 3, 1>& xA,
	        const Eigen::Quaternion<S>&   qA,
	        const Eigen::Matrix<S, 3, 1>& hA,
	        const Eigen::Matrix<S, 3, 1>& xB,
	        const Eigen::Quaternion<S>&   qB,
	        const Eigen::Matrix<S, 3, 1>& hB,
	        int                           axis)
	{
		using std::abs;
		const bool                  onA = axis < 3;
		const int                   i   = onA ? axis : axis - 3;
		const Eigen::Quaternion<S>& qX  = onA ? qA : qB;
		const Eigen::Quaternion<S>& qY  = onA ? qB : qA;
		const S                     w = qX.w(), x = qX.x(), y = qX.y(), z = qX.z();
		S                           a0, a1, a2; // column i of R_X
		if (i == 0) {
			a0 = 1 - 2 * (y * y + z * z);
			a1 = 2 * (x * y + w * z);
			a2 = 2 * (x * z - w * y);
		} else if (i == 1) {
			a0 = 2 * (x * y - w * z);
			a1 = 1 - 2 * (x * x + z * z);
			a2 = 2 * (y * z + w * x);
		} else {
			a0 = 2 * (x * z + w * y);
			a1 = 2 * (y * z - w * x);
			a2 = 1 - 2 * (x * x + y * y);
		}
		const S u0 = -qY.x(), u1 = -qY.y(), u2 = -qY.z(), qw = qY.w();
		const S t0 = 2 * (u1 * a2 - u2 * a1), t1 = 2 * (u2 * a0 - u0 * a2), t2 = 2 * (u0 * a1 - u1 * a0);
		const S v0 = a0 + qw * t0 + (u1 * t2 - u2 * t1), v1 = a1 + qw * t1 + (u2 * t0 - u0 * t2), v2 = a2 + qw * t2 + (u0 * t1 - u1 * t0);
		const Eigen::Matrix<S, 3, 1>& hX = onA ? hA : hB;
		const Eigen::Matrix<S, 3, 1>& hY = onA ? hB : hA;
		return hX[i] + (abs(v0) * hY[0] + abs(v1) * hY[1] + abs(v2) * hY[2]) - abs(a0 * (xB[0] - xA[0]) + a1 * (xB[1] - xA[1]) + a2 * (xB[2] - xA[2]));
	}

	/* Bound on the difference between faceAxisOverlap and BlockPair's value of the same overlap [m]: 1e-12 of
	   |xA|∞ + |xB|∞ + Σ hA + Σ hB. Both sum a few products of unit vectors' components (round-off ~1e-16 each) with
	   half-extents and with xB - xA (itself within an ulp of |x|, ~1e-16 |x|), so they differ by a few 1e-16 of that
	   sum; the bound leaves a factor of more than 10³ (tests/unit/test_separation_bound.cpp measures the difference). */
	template <class S>
	S
	faceAxisRoundOff(const Eigen::Matrix<S, 3, 1>& xA, const Eigen::Matrix<S, 3, 1>& hA, const Eigen::Matrix<S, 3, 1>& xB, const Eigen::Matrix<S, 3, 1>& hB)
	{
		return S(1e-12) * (xA.cwiseAbs().maxCoeff() + xB.cwiseAbs().maxCoeff() + hA.sum() + hB.sum());
	}

	/// Overlaps below this are touching, not contact: grid neighbours along an edge or a corner overlap by round-off [m].
	template <class S> S touchTolerance(const Eigen::Matrix<S, 3, 1>& hA, const Eigen::Matrix<S, 3, 1>& hB)
	{
		return S(1e-9) * std::min(hA.minCoeff(), hB.minCoeff());
	}

	/// What the witness axis of a pair found apart says in a later step: whether the blocks are still apart along it,
	/// and the slack it leaves [m].
	template <class S> struct WitnessVerdict {
		bool apart;
		S    slack;
	};

	/* The witness test for blocks at xA, qA and xB, qB with half-extents hA, hB and witness axis `axis` (0–5, as
	   faceAxisOverlap): apart if the overlap along the axis is below the touch tolerance by more than the round-off
	   (faceAxisRoundOff), which makes it the decision blocksOverlap would take; the slack tol - o - eps is left on the
	   axis. One function for the geometry functor (Ig2_RdemBlock_RdemBlock_RdemGeom) and RdemInteractionLoop. */
	template <class S>
	WitnessVerdict<S> witnessVerdict(
	        const Eigen::Matrix<S, 3, 1>& xA,
	        const Eigen::Quaternion<S>&   qA,
	        const Eigen::Matrix<S, 3, 1>& hA,
	        const Eigen::Matrix<S, 3, 1>& xB,
	        const Eigen::Quaternion<S>&   qB,
	        const Eigen::Matrix<S, 3, 1>& hB,
	        int                           axis)
	{
		const S tol = touchTolerance<S>(hA, hB);
		const S o   = faceAxisOverlap<S>(xA, qA, hA, xB, qB, hB, axis);
		const S eps = faceAxisRoundOff<S>(xA, hA, xB, hB);
		return { o <= tol - eps, tol - o - eps };
	}

	/// Whether the slack of a witness verdict makes a certificate (RdemGap::reach), for blocks of half-extents hA, hB: it
	/// exceeds separationMargin (its square roots only where it may: the margin is at least 1e-6 of the largest half-extents).
	template <class S> bool certifiableSlack(S slack, const Eigen::Matrix<S, 3, 1>& hA, const Eigen::Matrix<S, 3, 1>& hB)
	{
		return slack > S(1e-6) * (hA.maxCoeff() + hB.maxCoeff()) && slack > separationMargin<S>(hA, hB);
	}

	/* How far a point q, given in block Y's frame (q = R_Yᵀ(p - x_Y)), lies outside the region in which sampleDepthLocal can
	   find it inside Y, Y's box grown by tol·h_k along each axis k (its slab test |q_k| ≤ (1 + tol) h_k): the largest
	   |q_k| - (1 + tol) h_k [m]; ≤ 0 where the point may be inside. The sample certificate of a sampled contact
	   (Ig2_RdemBlock_RdemBlock_RdemGeom, RdemGeom::nearSamples) keeps the samples of a pair's two blocks less than a skin
	   outside the other block, and tests only those while the blocks' travels add up to less than the skin less
	   separationMargin.

	   Guarantee: if afterwards the point moves by at most t_X (it is a material point of block X, within X's
	   circumradius of its centroid: rigidTravel) and every point of Y's grown box by at most t_Y, with
	   t_X + t_Y < sampleOutside - margin, sampleDepthLocal does not find it inside Y. Proof: along Y's axis k at the
	   time of the certificate, now fixed in space, the point's coordinate has moved by at most t_X and the grown box's
	   extent has grown by at most t_Y, so the point lies outside the moved grown box, and so beyond one of its slabs;
	   the margin covers the round-off of the coordinates (~1e-16 of them) and the grown box's points lying up to 1e-9
	   beyond the circumradius that rigidTravel is given. */
	template <class S> S sampleOutside(const Eigen::Matrix<S, 3, 1>& half, const Eigen::Matrix<S, 3, 1>& q, S tol = S(1e-9))
	{
		using std::abs;
		S out = -std::numeric_limits<S>::infinity();
		for (int k = 0; k < 3; ++k)
			out = std::max(out, abs(q[k]) - (1 + tol) * half[k]);
		return out;
	}

} // namespace rdem
} // namespace yade
