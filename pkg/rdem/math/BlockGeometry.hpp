/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Geometry of rectangular blocks (oriented boxes): the face two blocks share, and how deep a point lies inside a block.

   A block is its centroid x, its rotation R (columns = body axes in global coordinates) and its half-extents h [m]. */
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace yade {
namespace rdem {

	template <class S> struct OrientedBlock {
		Eigen::Matrix<S, 3, 1> pos;  ///< centroid [m]
		Eigen::Matrix<S, 3, 3> rot;  ///< body-to-global rotation
		Eigen::Matrix<S, 3, 1> half; ///< half-extents along the body axes [m]
	};

	/// The rectangle two blocks share, expressed in global coordinates.
	template <class S> struct SharedFace {
		bool                   found = false;
		int                    axisA = -1, axisB = -1; ///< body axis of A (B) normal to the face
		S                      signA = 0, signB = 0;   ///< side of that axis: the face normal of A is signA·R_A e_axisA
		S                      gap = 0;                ///< distance between the two face planes along the normal, >0 apart [m]
		Eigen::Matrix<S, 3, 1> centre, normal, t1, t2; ///< normal points from A to B; t1, t2 unit, in-plane
		S                      h1 = 0, h2 = 0;         ///< half-sizes of the shared rectangle along t1, t2 [m]
	};

	/* Find the face of A that faces a parallel face of B across a plane gap |gap| ≤ gapTol with an in-plane overlap
	   of positive area. Faces must be parallel and their edges aligned (within angleTol, as |cos| ≥ 1-angleTol). */
	template <class S> SharedFace<S> findSharedFace(const OrientedBlock<S>& A, const OrientedBlock<S>& B, S gapTol, S angleTol)
	{
		using std::abs;
		using std::max;
		using std::min;
		using V = Eigen::Matrix<S, 3, 1>;
		SharedFace<S> best;
		for (int k = 0; k < 3; ++k) {
			for (int sa = -1; sa <= 1; sa += 2) {
				const V n = S(sa) * A.rot.col(k);
				int     m = -1;
				for (int j = 0; j < 3; ++j)
					if (abs(B.rot.col(j).dot(n)) >= 1 - angleTol) m = j;
				if (m < 0) continue;
				const S sb  = B.rot.col(m).dot(n) > 0 ? S(-1) : S(1); // B's face looks back at A
				const V cA  = A.pos + A.half[k] * n;
				const V cB  = B.pos + sb * B.half[m] * B.rot.col(m);
				const S gap = (cB - cA).dot(n);
				if (abs(gap) > gapTol) continue;
				const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
				const V   t1 = A.rot.col(k1), t2 = A.rot.col(k2);
				// Half-extents of B's face along t1 and t2: the B axis parallel to each.
				S hB1 = -1, hB2 = -1;
				for (int j = 0; j < 3; ++j) {
					if (j == m) continue;
					if (abs(B.rot.col(j).dot(t1)) >= 1 - angleTol) hB1 = B.half[j];
					if (abs(B.rot.col(j).dot(t2)) >= 1 - angleTol) hB2 = B.half[j];
				}
				if (hB1 < 0 || hB2 < 0) continue; // faces parallel but edges not aligned
				const S o1 = (cB - cA).dot(t1), o2 = (cB - cA).dot(t2);
				const S lo1 = max(-A.half[k1], o1 - hB1), hi1 = min(A.half[k1], o1 + hB1);
				const S lo2 = max(-A.half[k2], o2 - hB2), hi2 = min(A.half[k2], o2 + hB2);
				if (!(hi1 > lo1 && hi2 > lo2)) continue;
				if (best.found && abs(gap) >= abs(best.gap)) continue;
				best.found  = true;
				best.axisA  = k;
				best.axisB  = m;
				best.signA  = S(sa);
				best.signB  = sb;
				best.gap    = gap;
				best.normal = n;
				best.t1     = t1;
				best.t2     = t2;
				best.h1     = (hi1 - lo1) / 2;
				best.h2     = (hi2 - lo2) / 2;
				best.centre = cA + (gap / 2) * n + ((lo1 + hi1) / 2) * t1 + ((lo2 + hi2) / 2) * t2;
			}
		}
		return best;
	}

	/// Overlap of the projections of two blocks on the unit axis a [m] (negative if they are apart along a).
	template <class S> S projectionOverlap(const OrientedBlock<S>& A, const OrientedBlock<S>& B, const Eigen::Matrix<S, 3, 1>& a)
	{
		using std::abs;
		S rA = 0, rB = 0;
		for (int j = 0; j < 3; ++j) {
			rA += A.half[j] * abs(A.rot.col(j).dot(a));
			rB += B.half[j] * abs(B.rot.col(j).dot(a));
		}
		return rA + rB - abs((B.pos - A.pos).dot(a));
	}

	/* Two blocks seen from A's frame (Gottschalk, Lin & Manocha, SIGGRAPH 1996): C = R_Aᵀ R_B (C_ij = a_i·b_j), its
	   absolute values, and t = R_Aᵀ(x_B - x_A) [m]. The projections of both blocks on the 15 axes of the separating-axis
	   test (a_i, b_j, a_i × b_j) are sums of half-extents times |C_ij|; made once per pair and step and shared by
	   blocksOverlap, contactFaceAxis and edgeEdgeContact, instead of projecting both blocks' six axes on each candidate
	   axis in each of them. Holds references to A and B: a local of the caller. */
	template <class S> struct BlockPair {
		const OrientedBlock<S>& A;
		const OrientedBlock<S>& B;
		Eigen::Matrix<S, 3, 3>  C, absC;
		Eigen::Matrix<S, 3, 1>  t;

		BlockPair(const OrientedBlock<S>& a, const OrientedBlock<S>& b)
		        : A(a)
		        , B(b)
		        , C(a.rot.transpose() * b.rot)
		        , absC(C.cwiseAbs())
		        , t(a.rot.transpose() * (b.pos - a.pos))
		{
		}
		/// Overlap of the projections along a_i [m], negative if apart; B lies on the +a_i side if t_i > 0.
		S overlapA(int i) const
		{
			using std::abs;
			return A.half[i] + absC.row(i).dot(B.half) - abs(t[i]);
		}
		/// (x_B - x_A)·b_j [m].
		S offsetB(int j) const { return C.col(j).dot(t); }
		/// Overlap of the projections along b_j [m].
		S overlapB(int j) const
		{
			using std::abs;
			return absC.col(j).dot(A.half) + B.half[j] - abs(offsetB(j));
		}
		/// |a_i × b_j|, from its components 0, -C_(i+2)j, C_(i+1)j along a_i, a_(i+1), a_(i+2) (no cancellation when the
		/// edges are parallel).
		S crossLength(int i, int j) const
		{
			using std::sqrt;
			const S u = C((i + 1) % 3, j), v = C((i + 2) % 3, j);
			return sqrt(u * u + v * v);
		}
		/// Overlap of the projections along the unit axis (a_i × b_j)/|a_i × b_j|, times |a_i × b_j| [m].
		S crossOverlapScaled(int i, int j) const
		{
			using std::abs;
			const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
			const S   rA = A.half[i1] * absC(i2, j) + A.half[i2] * absC(i1, j);
			const S   rB = B.half[j1] * absC(i, j2) + B.half[j2] * absC(i, j1);
			return rA + rB - abs(t[i2] * C(i1, j) - t[i1] * C(i2, j));
		}
	};

	/* The projection overlaps of a pair on all 15 axes of the separating-axis test, each computed once by BlockPair's
	   formulas: a sampled contact needs every one of them in each step, for the overlap test (blocksOverlap), the pair's
	   normal (contactFaceAxis) and the edge-to-edge contact (edgeEdgeContact), which computed them again each (with a
	   square root per edge pair). The functions given this table do the same operations on the same numbers as those
	   given the BlockPair alone, so their results are the same to the bit (tests/unit/test_block_geometry.cpp). */
	template <class S> struct SeparatingAxes {
		S face[6];        ///< overlapA(i) for i < 3, overlapB(i - 3) for i ≥ 3 [m]
		S crossLength[9]; ///< crossLength(i, j) at 3i + j
		S crossScaled[9]; ///< crossOverlapScaled(i, j) at 3i + j [m]

		explicit SeparatingAxes(const BlockPair<S>& pair)
		{
			for (int i = 0; i < 3; ++i) {
				face[i]     = pair.overlapA(i);
				face[i + 3] = pair.overlapB(i);
				for (int j = 0; j < 3; ++j) {
					crossLength[3 * i + j] = pair.crossLength(i, j);
					crossScaled[3 * i + j] = pair.crossOverlapScaled(i, j);
				}
			}
		}
	};

	/// The contact normal of two overlapping blocks (see contactFaceAxis).
	template <class S> struct FaceAxis {
		S                      overlap = 0;                              ///< overlap of the projections along the normal [m]
		Eigen::Matrix<S, 3, 1> normal  = Eigen::Matrix<S, 3, 1>::Zero(); ///< unit, from A to B
	};

	/* Contact normal of two overlapping blocks, from the face normals of A and B along which their projections overlap
	   least (the minimum-translation axis of the separating-axis test restricted to face axes; Gottschalk, Lin & Manocha
	   1996; ODE's dBoxBox). Two convex blocks touch over one connected region with one normal, used for the whole pair;
	   sample depths along it are of the order of the overlap (see sampleDepth). To keep the normal, and with it the
	   forces, continuous where two axes overlap almost equally (the two parallel face normals of blocks in flush contact,
	   the x and y faces of two blocks touching along parallel edges), it is the normalised sum of the face normals
	   (turned from A to B) weighted by w_i = max(0, 1 - (o_i - o_min)/(blend·o_min)): only the least overlapped one
	   unless another is within the fraction blend of it. The default 1 % blends the faces of aligned blocks (their
	   overlaps differ by round-off) and keeps the band between perpendicular axes narrow, where the turning normal
	   acts as a transverse stiffness of order k_nA/blend that the time step does not include. For blocks that overlap (o_min > 0); oriented from A to B.
	   contactNormal gives the normal alone (what the sampled contact needs), contactFaceAxis with the overlap along it. */
	template <class S> Eigen::Matrix<S, 3, 1> contactNormal(const BlockPair<S>& pair, const SeparatingAxes<S>& sat, S blend = S(1e-2))
	{
		using V = Eigen::Matrix<S, 3, 1>;
		V        axes[6];
		const S* overlaps = sat.face;
		S        least    = std::numeric_limits<S>::infinity();
		for (int i = 0; i < 6; ++i) {
			const V a = (i < 3 ? pair.A : pair.B).rot.col(i % 3);
			axes[i]   = (i < 3 ? pair.t[i] : pair.offsetB(i - 3)) >= 0 ? a : V(-a);
			least     = std::min(least, overlaps[i]);
		}
		V       sum  = V::Zero();
		const S band = blend * least;
		for (int i = 0; i < 6; ++i)
			sum += (band > 0 ? std::max(S(0), 1 - (overlaps[i] - least) / band) : S(overlaps[i] == least)) * axes[i];
		return sum.normalized();
	}

	/// The contact normal (contactNormal) with the overlap of the blocks' projections along it.
	template <class S> FaceAxis<S> contactFaceAxis(const BlockPair<S>& pair, const SeparatingAxes<S>& sat, S blend = S(1e-2))
	{
		FaceAxis<S> axis;
		axis.normal  = contactNormal(pair, sat, blend);
		axis.overlap = projectionOverlap(pair.A, pair.B, axis.normal);
		return axis;
	}

	template <class S> FaceAxis<S> contactFaceAxis(const BlockPair<S>& pair, S blend = S(1e-2))
	{
		return contactFaceAxis(pair, SeparatingAxes<S>(pair), blend);
	}

	template <class S> FaceAxis<S> contactFaceAxis(const OrientedBlock<S>& A, const OrientedBlock<S>& B, S blend = S(1e-2))
	{
		return contactFaceAxis(BlockPair<S>(A, B), blend);
	}

	/// How deep a sample point lies inside a block along a direction (see sampleDepth).
	template <class S> struct SampleHit {
		bool hit   = false;
		S    depth = 0; ///< distance the point travels along u before it leaves Y [m]
	};

	/* Depth of a sample point p (of another block) inside block Y along the unit direction u in which p's block
	   separates from Y: the distance d_f/a_f from p along u to the plane of a face of Y that u leaves through
	   (a_f = n_f·u, d_f = h_k - s q_k the distance behind the plane), least over those faces. p is inside Y when
	   d_f ≥ -tol·h_k for every face (edges and faces included). Faces within about 6° of parallel to u (a_f ≤ g = 0.1)
	   are side faces that u does not leave through; between g and 2g a face's distance is scaled by g/(a_f - g), from 1
	   to infinity, so that the depth stays continuous in p and in u. Without that (pure ray exit), a point close to a
	   side face of Y would report its tiny distance to that face as soon as u tilts a little towards it while its
	   block is deep in Y: a blind spot that let a tilted corner sink 1 % of the block in and come back with its full
	   depth when the pair's normal turned to a face axis of the other block (0.12 J in one step for a 2 cm cube). For
	   a face normal u of Y, the depth is the distance behind that face, also for the edge samples of a flush stacked
	   block, which lie on Y's side planes. No hit outside Y or at a depth below tol·min h_k, where a sample only
	   touches (edge and corner samples of aligned blocks lie on each other's faces, where the sign of a zero depth is
	   round-off). sampleDepthLocal takes p and u in Y's frame, q = R_Yᵀ(p - x_Y) and u_q = R_Yᵀu, with Y's half-extents:
	   a caller sampling a face's grid transforms u once per pair and the face's centre and axes once per face (the grid
	   points are affine in them) instead of two matrix-vector products per point. */
	template <class S>
	SampleHit<S> sampleDepthLocal(
	        const Eigen::Matrix<S, 3, 1>& half, const Eigen::Matrix<S, 3, 1>& q, const Eigen::Matrix<S, 3, 1>& uq, S tol = S(1e-9), S grazing = S(0.1))
	{
		S            depth = std::numeric_limits<S>::infinity();
		SampleHit<S> best;
		for (int k = 0; k < 3; ++k) {
			for (int s = -1; s <= 1; s += 2) {
				const S d = half[k] - S(s) * q[k];
				if (d < -tol * half[k]) return best; // outside
				const S a = S(s) * uq[k];
				if (a <= grazing) continue; // a side face for u
				const S toPlane = std::max(d, S(0)) / a;
				depth           = std::min(depth, a >= 2 * grazing ? toPlane : toPlane * grazing / (a - grazing));
			}
		}
		using std::isfinite;
		if (!(depth > tol * half.minCoeff()) || !isfinite(depth)) return best;
		best.hit   = true;
		best.depth = depth;
		return best;
	}

	/// sampleDepth for a point p and direction u in global coordinates.
	template <class S>
	SampleHit<S>
	sampleDepth(const OrientedBlock<S>& Y, const Eigen::Matrix<S, 3, 1>& p, const Eigen::Matrix<S, 3, 1>& u, S tol = S(1e-9), S grazing = S(0.1))
	{
		return sampleDepthLocal<S>(Y.half, Y.rot.transpose() * (p - Y.pos), Y.rot.transpose() * u, tol, grazing);
	}

	/* Whether a rectangular face (centre c, unit in-plane axes t1, t2, half-sizes h1, h2 [m]) can have a point inside
	   block Y in the sense of sampleDepth: false only if, along one of Y's axes k, the face's extent
	   |t1_k| h1 + |t2_k| h2 around c lies entirely beyond Y's slab |q_k| ≤ h_k (1 + tol), with the margin 1e-9·h_k for
	   round-off. A cheap cull before the (n+1)² sample points of the face are made and tested.
	   faceMayEnterLocal takes the face in Y's frame, q_c = R_Yᵀ(c - x_Y), q_t1 = R_Yᵀt1, q_t2 = R_Yᵀt2 (see sampleDepth). */
	template <class S>
	bool faceMayEnterLocal(
	        const Eigen::Matrix<S, 3, 1>& half,
	        const Eigen::Matrix<S, 3, 1>& qc,
	        const Eigen::Matrix<S, 3, 1>& qt1,
	        const Eigen::Matrix<S, 3, 1>& qt2,
	        S                             h1,
	        S                             h2,
	        S                             tol = S(1e-9))
	{
		using std::abs;
		for (int k = 0; k < 3; ++k)
			if (abs(qc[k]) - (abs(qt1[k]) * h1 + abs(qt2[k]) * h2) > half[k] * (1 + tol + S(1e-9))) return false;
		return true;
	}

	/// faceMayEnter for a face in global coordinates.
	template <class S>
	bool faceMayEnter(
	        const OrientedBlock<S>&       Y,
	        const Eigen::Matrix<S, 3, 1>& c,
	        const Eigen::Matrix<S, 3, 1>& t1,
	        const Eigen::Matrix<S, 3, 1>& t2,
	        S                             h1,
	        S                             h2,
	        S                             tol = S(1e-9))
	{
		return faceMayEnterLocal<S>(Y.half, Y.rot.transpose() * (c - Y.pos), Y.rot.transpose() * t1, Y.rot.transpose() * t2, h1, h2, tol);
	}

	/* The decision of the separating-axis test (blocksOverlap) from the projections' overlaps on its 15 axes [m]:
	   face(i) on the face normals (i < 3: A's, else B's), and for the 9 edge cross products k = 3i + j their length
	   length(k) and scaled overlap scaled(k) (BlockPair::crossLength, crossOverlapScaled). Each is asked for only until an
	   axis separates the blocks, in the same order whatever supplies them (a BlockPair computing them, or a
	   SeparatingAxes table), so that both give the same decision. */
	template <class S, class Face, class Length, class Scaled> bool projectionsOverlap(Face face, Length length, Scaled scaled, S tol)
	{
		for (int i = 0; i < 3; ++i)
			if (!(face(i) > tol) || !(face(i + 3) > tol)) return false;
		for (int k = 0; k < 9; ++k) {
			const S len = length(k);
			if (len < S(1e-9)) continue; // parallel edges: the face axes already cover this direction
			if (!(scaled(k) > tol * len)) return false;
		}
		return true;
	}

	/* Separating-axis test of two oriented blocks (Gottschalk, Lin & Manocha, SIGGRAPH 1996): true if their projections
	   overlap by more than tol [m] on all 15 candidate axes (3 + 3 face normals, 9 edge cross products; see BlockPair).
	   Blocks that are apart or only touch (grid neighbours along an edge) return false, usually at the first face axis. */
	template <class S> bool blocksOverlap(const BlockPair<S>& pair, S tol)
	{
		return projectionsOverlap<S>(
		        [&](int i) { return i < 3 ? pair.overlapA(i) : pair.overlapB(i - 3); },
		        [&](int k) { return pair.crossLength(k / 3, k % 3); },
		        [&](int k) { return pair.crossOverlapScaled(k / 3, k % 3); },
		        tol);
	}

	template <class S> bool blocksOverlap(const OrientedBlock<S>& A, const OrientedBlock<S>& B, S tol) { return blocksOverlap(BlockPair<S>(A, B), tol); }

	/// blocksOverlap from the pair's table of overlaps (the same decision on the same numbers: for a pair that needs the
	/// table anyway).
	template <class S> bool blocksOverlap(const SeparatingAxes<S>& sat, S tol)
	{
		return projectionsOverlap<S>(
		        [&](int i) { return sat.face[i]; }, [&](int k) { return sat.crossLength[k]; }, [&](int k) { return sat.crossScaled[k]; }, tol);
	}

	/// An edge of one block crossing an edge of the other (see edgeEdgeContact).
	template <class S> struct EdgeHit {
		bool                   hit    = false;
		S                      depth  = 0;                              ///< overlap along the normal [m]
		Eigen::Matrix<S, 3, 1> point  = Eigen::Matrix<S, 3, 1>::Zero(); ///< mid-point of the two edges' closest points
		Eigen::Matrix<S, 3, 1> normal = Eigen::Matrix<S, 3, 1>::Zero(); ///< unit, from A to B
	};

	/* Edge-to-edge contact, which face samples cannot see: two crossing edges can sink into each other with no sample
	   point of either block inside the other. Following the separating-axis test (Gottschalk et al. 1996; the contact
	   generation of ODE's dBoxBox), if the axis of least overlap is the cross product of an edge direction of A and one of
	   B, and its overlap is clearly smaller than that of every face axis (margin 0.95), the contact is at the closest
	   points of A's edge farthest along that axis and B's edge farthest against it, if both lie within their edges. */
	template <class S> EdgeHit<S> edgeEdgeContact(const BlockPair<S>& pair, const SeparatingAxes<S>& sat, S tol)
	{
		using std::abs;
		using V                         = Eigen::Matrix<S, 3, 1>;
		const OrientedBlock<S>& A       = pair.A;
		const OrientedBlock<S>& B       = pair.B;
		S                       faceMin = std::numeric_limits<S>::infinity();
		for (int i = 0; i < 3; ++i)
			faceMin = std::min(faceMin, std::min(sat.face[i], sat.face[i + 3]));
		EdgeHit<S> hit;
		if (!(faceMin > tol)) return hit;
		int i0 = -1, j0 = -1;
		S   best = faceMin, bestLength = 0;
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j) {
				const S len = sat.crossLength[3 * i + j];
				if (len < S(1e-6)) continue;
				const S o = sat.crossScaled[3 * i + j] / len;
				if (!(o > tol)) return hit; // separated along this axis
				if (o < S(0.95) * best) {
					best       = o;
					bestLength = len;
					i0         = i;
					j0         = j;
				}
			}
		if (i0 < 0) return hit;
		V axis = A.rot.col(i0).cross(B.rot.col(j0)) / bestLength;
		if (axis.dot(B.pos - A.pos) < 0) axis = -axis; // from A to B
		V pA = A.pos, pB = B.pos;
		for (int k = 0; k < 3; ++k) {
			if (k != i0) pA += (A.rot.col(k).dot(axis) > 0 ? S(1) : S(-1)) * A.half[k] * A.rot.col(k);
			if (k != j0) pB -= (B.rot.col(k).dot(axis) > 0 ? S(1) : S(-1)) * B.half[k] * B.rot.col(k);
		}
		// Closest points of the lines pA + s·ea and pB + t·eb.
		const V ea = A.rot.col(i0), eb = B.rot.col(j0), w = pA - pB;
		const S b = ea.dot(eb), den = 1 - b * b;
		const S sA = (b * eb.dot(w) - ea.dot(w)) / den, tB = (eb.dot(w) - b * ea.dot(w)) / den;
		if (abs(sA) > A.half[i0] || abs(tB) > B.half[j0]) return hit;
		hit.hit    = true;
		hit.depth  = best;
		hit.normal = axis;
		hit.point  = (pA + sA * ea + pB + tB * eb) / 2;
		return hit;
	}

	template <class S> EdgeHit<S> edgeEdgeContact(const BlockPair<S>& pair, S tol) { return edgeEdgeContact(pair, SeparatingAxes<S>(pair), tol); }

	template <class S> EdgeHit<S> edgeEdgeContact(const OrientedBlock<S>& A, const OrientedBlock<S>& B, S tol)
	{
		return edgeEdgeContact(BlockPair<S>(A, B), tol);
	}

	/* Whether a vertex of A lies in B or on its surface, within tol [m] (B's box grown by tol on every side). Two blocks
	   that overlap although no vertex of either is in or on the other have faces that cross (a beam laid across a wall):
	   vertex samples cannot see that contact. Side-by-side blocks whose faces coincide (the head joints of a course) have
	   their vertices on each other's edges, so they count as touching at the vertices, not as crossing. */
	template <class S> bool vertexInOrOn(const OrientedBlock<S>& A, const OrientedBlock<S>& B, S tol)
	{
		using std::abs;
		const Eigen::Matrix<S, 3, 3> toB = B.rot.transpose();
		for (int corner = 0; corner < 8; ++corner) {
			Eigen::Matrix<S, 3, 1> v = A.pos;
			for (int k = 0; k < 3; ++k)
				v += S((corner >> k) & 1 ? 1 : -1) * A.half[k] * A.rot.col(k);
			const Eigen::Matrix<S, 3, 1> q = toB * (v - B.pos);
			if (abs(q[0]) <= B.half[0] + tol && abs(q[1]) <= B.half[1] + tol && abs(q[2]) <= B.half[2] + tol) return true;
		}
		return false;
	}

	/// Faces that cross: no vertex of either block in or on the other (vertexInOrOn), although the blocks overlap.
	template <class S> bool facesCross(const OrientedBlock<S>& A, const OrientedBlock<S>& B, S tol)
	{
		return !vertexInOrOn(A, B, tol) && !vertexInOrOn(B, A, tol);
	}

} // namespace rdem
} // namespace yade
