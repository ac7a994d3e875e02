/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Face-to-face contact of two blocks as a patch of contact springs (doc/sphinx/rdemTheory.rst §4.3).

   Two blocks whose faces meet face to face (outward normals antiparallel within a tolerance, a small gap or overlap
   between the face planes) touch over the intersection of the two faces: a convex polygon, found once by clipping B's
   face, projected orthogonally onto A's face plane, against A's face rectangle ([SutherlandHodgman1974], doc/references.bib:
   one pass per half-plane of the rectangle), its area by the shoelace formula. The patch carries the contact
   springs of eqs. (13) and (17) of the paper [P] at fixed material points of both blocks, as a bond carries its
   segments' springs, instead of points sampled again at every step (SegmentGrid.hpp, BlockGeometry.hpp).

   Spring points. The bounding rectangle of the patch in A's face frame is cut into m×m cells, and each cell is clipped
   to the patch. A full cell gives a quarter of its area to each of its four corners (the trapezoid rule; shared
   corners are merged), a cut cell its area to its vertices. The points are thus the (m+1)×(m+1) trapezoid nodes of
   the sampled contacts wherever the patch is a rectangle aligned with A's face (grid neighbours, joints of a wall,
   stacked blocks), and for any patch the tributary areas sum to the patch area exactly and have its first moments
   exactly: a normal stress field that is affine over the patch gives the exact resultant force and moment.

   Coordinates: A's face frame has its origin at the centre of A's face, axes t1 = R_A e_{k+1}, t2 = R_A e_{k+2} and
   outward normal n_A = s_A R_A e_k (k the face's body axis, s_A its side). Units: m, m². Polygons are counter-clockwise
   in (t1, t2). */
#pragma once

#include <pkg/rdem/math/BlockGeometry.hpp>
#include <pkg/rdem/math/SegmentGrid.hpp>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace yade {
namespace rdem {

	template <class S> using Point2   = Eigen::Matrix<S, 2, 1>;
	template <class S> using Polygon2 = std::vector<Point2<S>>;

	/// The part of the convex polygon p with a·x ≤ c (Sutherland-Hodgman, one half-plane); empty if none.
	template <class S> Polygon2<S> clipHalfPlane(const Polygon2<S>& p, const Point2<S>& a, S c)
	{
		Polygon2<S>  out;
		const size_t n = p.size();
		out.reserve(n + 1);
		for (size_t i = 0; i < n; ++i) {
			const Point2<S>& P  = p[i];
			const Point2<S>& Q  = p[(i + 1) % n];
			const S          dp = a.dot(P) - c, dq = a.dot(Q) - c;
			if (dp <= 0) out.push_back(P);
			if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) out.push_back(P + (dp / (dp - dq)) * (Q - P)); // the edge crosses the line
		}
		return out;
	}

	/// The part of the convex polygon p inside the axis-aligned rectangle lo ≤ x ≤ hi.
	template <class S> Polygon2<S> clipToBox(Polygon2<S> p, const Point2<S>& lo, const Point2<S>& hi)
	{
		for (int d = 0; d < 2 && !p.empty(); ++d) {
			const Point2<S> e = Point2<S>::Unit(d);
			p                 = clipHalfPlane<S>(p, e, hi[d]);
			if (!p.empty()) p = clipHalfPlane<S>(p, Point2<S>(-e), -lo[d]);
		}
		return p;
	}

	/// Signed area of a polygon by the shoelace formula, positive counter-clockwise [m²].
	template <class S> S polygonArea(const Polygon2<S>& p)
	{
		S twice = 0;
		for (size_t i = 0, n = p.size(); i < n; ++i) {
			const Point2<S>& P = p[i];
			const Point2<S>& Q = p[(i + 1) % n];
			twice += P.x() * Q.y() - Q.x() * P.y();
		}
		return twice / 2;
	}

	/// Centroid of a polygon of nonzero area (the shoelace formula's first moments) [m].
	template <class S> Point2<S> polygonCentroid(const Polygon2<S>& p)
	{
		S         twice = 0;
		Point2<S> m     = Point2<S>::Zero();
		for (size_t i = 0, n = p.size(); i < n; ++i) {
			const Point2<S>& P     = p[i];
			const Point2<S>& Q     = p[(i + 1) % n];
			const S          cross = P.x() * Q.y() - Q.x() * P.y();
			twice += cross;
			m += cross * (P + Q);
		}
		return m / (3 * twice);
	}

	/// A spring point of a patch in A's face frame and its tributary area [m, m²].
	template <class S> struct PatchPoint {
		Point2<S> pos;
		S         area;
	};

	/* Spring points of a cell cut by the patch's edge, the convex polygon q of area a: its vertices v_k (repeated ones
	   dropped), with the weights w_k = a/N + (v_k - v̄)·μ, S μ = a (c - v̄), v̄ the vertices' mean, c the centroid and
	   S = Σ (v_k - v̄)(v_k - v̄)ᵀ: the least-norm weights with Σ w_k = a and Σ w_k v_k = a c, so that the piece has its
	   area and first moments exactly and, unlike a single point at the centroid, a moment stiffness (a patch of one cut
	   cell, m = 1, would otherwise be a single spring). For a rectangle they are a/4 at each corner. Where a weight would
	   not be positive (a sliver), the centroid takes the whole area. Appended to out. */
	template <class S> void cutCellPoints(const Polygon2<S>& q, S a, std::vector<PatchPoint<S>>& out)
	{
		Polygon2<S> v;
		S           size = 0;
		for (size_t i = 1; i < q.size(); ++i)
			size = std::max(size, (q[i] - q[0]).norm());
		for (const auto& x : q)
			if (v.empty() || (x - v.back()).norm() > S(1e-9) * size) v.push_back(x);
		while (v.size() > 1 && (v.front() - v.back()).norm() <= S(1e-9) * size)
			v.pop_back();
		const Point2<S> c = polygonCentroid<S>(q);
		if (v.size() >= 3) {
			Point2<S> mean = Point2<S>::Zero();
			for (const auto& x : v)
				mean += x / S(v.size());
			Eigen::Matrix<S, 2, 2> M = Eigen::Matrix<S, 2, 2>::Zero();
			for (const auto& x : v)
				M += (x - mean) * (x - mean).transpose();
			const S det = M.determinant();
			if (det > S(1e-12) * M.trace() * M.trace()) {
				const Point2<S> mu = M.inverse() * (a * (c - mean));
				std::vector<S>  w;
				bool            positive = true;
				for (const auto& x : v) {
					w.push_back(a / S(v.size()) + (x - mean).dot(mu));
					positive = positive && w.back() > 0;
				}
				if (positive) {
					for (size_t k = 0; k < v.size(); ++k)
						out.push_back({ v[k], w[k] });
					return;
				}
			}
		}
		out.push_back({ c, a });
	}

	/* Spring points of the convex patch polygon p (counter-clockwise, nonzero area) on an m×m grid of cells over its
	   bounding rectangle (see the header): trapezoid nodes of the full cells, vertices of the cut ones (cutCellPoints). The areas sum
	   to polygonArea(p) and their first moments to the patch's, up to round-off. Cells cut to less than 1e-12 of a
	   cell's area are dropped (slivers of round-off). */
	template <class S> std::vector<PatchPoint<S>> patchPoints(const Polygon2<S>& p, int m)
	{
		using std::abs;
		Point2<S> lo = p[0], hi = p[0];
		for (const auto& q : p) {
			lo = lo.cwiseMin(q);
			hi = hi.cwiseMax(q);
		}
		const Point2<S>            cell     = (hi - lo) / S(m);
		const S                    cellArea = cell.x() * cell.y();
		std::vector<S>             node(size_t((m + 1) * (m + 1)), S(0)); // trapezoid weights of the grid nodes
		std::vector<PatchPoint<S>> out;
		for (int i = 0; i < m; ++i)
			for (int j = 0; j < m; ++j) {
				const Point2<S> a = lo + Point2<S>(S(i) * cell.x(), S(j) * cell.y());
				const Point2<S> b = i + 1 == m && j + 1 == m
				        ? hi
				        : Point2<S>(i + 1 == m ? hi.x() : a.x() + cell.x(), j + 1 == m ? hi.y() : a.y() + cell.y());
				const auto piece = clipToBox<S>(p, a, b);
				if (piece.size() < 3) continue;
				const S area = polygonArea<S>(piece);
				if (!(area > S(1e-12) * cellArea)) continue;
				if (abs(area - (b - a).prod()) <= S(1e-12) * cellArea) { // a full cell: its corners
					for (int di = 0; di < 2; ++di)
						for (int dj = 0; dj < 2; ++dj)
							node[size_t((i + di) * (m + 1) + j + dj)] += area / 4;
				} else
					cutCellPoints<S>(piece, area, out);
			}
		for (int i = 0; i <= m; ++i)
			for (int j = 0; j <= m; ++j) {
				const S w = node[size_t(i * (m + 1) + j)];
				if (w > 0)
					out.push_back({ Point2<S>(i == m ? hi.x() : lo.x() + S(i) * cell.x(), j == m ? hi.y() : lo.y() + S(j) * cell.y()), w });
			}
		return out;
	}

	/// One face of a block: body axis k, side s (outward normal s R e_k).
	template <class S> struct BlockFace {
		int                    k = -1;
		S                      s = 0;
		Eigen::Matrix<S, 3, 1> normal(const OrientedBlock<S>& b) const { return s * b.rot.col(k); }
		Eigen::Matrix<S, 3, 1> centre(const OrientedBlock<S>& b) const { return b.pos + s * b.half[k] * b.rot.col(k); }
	};

	/* A face-to-face contact of blocks A and B: the faces, the patch polygon in A's face frame, its area, and the spring
	   points, in global coordinates on A's face plane (P1) and, along A's normal, on B's face plane (P2). */
	template <class S> struct FacePatch {
		bool                                found = false;
		BlockFace<S>                        faceA, faceB;
		S                                   gap  = 0; ///< distance of B's face centre from A's face plane along n_A, > 0 apart [m]
		S                                   area = 0; ///< patch area in A's face plane [m²]
		Polygon2<S>                         polygon;  ///< in A's face frame, counter-clockwise
		std::vector<Eigen::Matrix<S, 3, 1>> point1, point2;
		std::vector<S>                      pointArea;
	};

	/* Whether faces of A and B meet face to face and, if so, their patch with m×m cells (patchPoints). Faces meet when
	   their outward normals are antiparallel within angleTol (n_A·n_B ≤ -(1 - angleTol), i.e. an angle below
	   √(2 angleTol) rad), the centre of B's face lies within gapTol of A's face plane (either side) [m], and their
	   projections on A's face plane overlap with a positive area; of several such pairs (only in degenerate cases), the
	   one with the smallest |gap|. */
	template <class S> FacePatch<S> facePatch(const OrientedBlock<S>& A, const OrientedBlock<S>& B, int m, S angleTol, S gapTol)
	{
		using std::abs;
		using V = Eigen::Matrix<S, 3, 1>;
		FacePatch<S> best;
		for (int k = 0; k < 3; ++k)
			for (int sa = -1; sa <= 1; sa += 2) {
				const BlockFace<S> fa { k, S(sa) };
				const V            nA = fa.normal(A);
				int                j  = 0; // B's axis most parallel to n_A
				for (int c = 1; c < 3; ++c)
					if (abs(B.rot.col(c).dot(nA)) > abs(B.rot.col(j).dot(nA))) j = c;
				const S            cj = B.rot.col(j).dot(nA);
				const BlockFace<S> fb { j, cj > 0 ? S(-1) : S(1) };
				if (!(abs(cj) >= 1 - angleTol)) continue;
				const V cA = fa.centre(A), cB = fb.centre(B);
				const S gap = (cB - cA).dot(nA);
				if (!(abs(gap) <= gapTol) || (best.found && abs(gap) >= abs(best.gap))) continue;
				const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
				const V   t1 = A.rot.col(k1), t2 = A.rot.col(k2);
				// B's face corners, projected on A's face plane, counter-clockwise in (t1, t2).
				const int   j1 = (j + 1) % 3, j2 = (j + 2) % 3;
				const V     u = B.half[j1] * B.rot.col(j1), v = B.half[j2] * B.rot.col(j2);
				Polygon2<S> quad;
				for (const auto& c : { Point2<S>(-1, -1), Point2<S>(1, -1), Point2<S>(1, 1), Point2<S>(-1, 1) }) {
					const V corner = cB - cA + c.x() * u + c.y() * v;
					quad.push_back(Point2<S>(corner.dot(t1), corner.dot(t2)));
				}
				if (polygonArea<S>(quad) < 0) std::reverse(quad.begin(), quad.end());
				auto    poly = clipToBox<S>(quad, Point2<S>(-A.half[k1], -A.half[k2]), Point2<S>(A.half[k1], A.half[k2]));
				const S area = poly.size() >= 3 ? polygonArea<S>(poly) : S(0);
				if (!(area > 0)) continue;
				best.found   = true;
				best.faceA   = fa;
				best.faceB   = fb;
				best.gap     = gap;
				best.area    = area;
				best.polygon = std::move(poly);
			}
		if (!best.found) return best;
		const int k = best.faceA.k, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
		const V   t1 = A.rot.col(k1), t2 = A.rot.col(k2), nA = best.faceA.normal(A), nB = best.faceB.normal(B);
		const V   cA = best.faceA.centre(A), cB = best.faceB.centre(B);
		for (const auto& q : patchPoints<S>(best.polygon, m)) {
			const V P = cA + q.pos.x() * t1 + q.pos.y() * t2;
			best.point1.push_back(P);
			best.point2.push_back(P + ((cB - P).dot(nB) / nA.dot(nB)) * nA); // along n_A onto B's face plane
			best.pointArea.push_back(q.area);
		}
		return best;
	}

	/* The springs of a face-to-face contact as the law reads them at every step: one contiguous array of 7 numbers per
	   spring, its material point in body 1's frame (3, relative to the centroid), in body 2's frame (3) and its
	   tributary area, so that a contact's springs take one pass over adjacent memory (a quarter of a 64-byte line per
	   number triple in double). The only way in: the law, the geometry functor and the time stepper go through it. */
	template <class S> struct PatchSprings {
		static constexpr int stride = 7;
		static_assert(sizeof(Eigen::Matrix<S, 3, 1>) == 3 * sizeof(S), "a Vector3 must be three packed scalars for PatchSprings' layout");
		const S* data;
		size_t   size;
		PatchSprings(const std::vector<S>& v)
		        : data(v.data())
		        , size(v.size() / stride)
		{
		}
		Eigen::Map<const Eigen::Matrix<S, 3, 1>> point1(size_t i) const { return Eigen::Map<const Eigen::Matrix<S, 3, 1>>(data + stride * i); }
		Eigen::Map<const Eigen::Matrix<S, 3, 1>> point2(size_t i) const { return Eigen::Map<const Eigen::Matrix<S, 3, 1>>(data + stride * i + 3); }
		S                                        area(size_t i) const { return data[stride * i + 6]; }
		/// Appends a spring with material points p1 (body 1's frame), p2 (body 2's frame) [m] and area [m²] to v.
		static void append(std::vector<S>& v, const Eigen::Matrix<S, 3, 1>& p1, const Eigen::Matrix<S, 3, 1>& p2, S a)
		{
			v.insert(v.end(), { p1[0], p1[1], p1[2], p2[0], p2[1], p2[2], a });
		}
	};

	/// For each point of `to`, the index of the nearest point of `from` (-1 if `from` is empty): how a contact's spring
	/// history passes to the springs of a patch derived again, or between sampled points and a patch.
	template <class S> std::vector<int> nearestPoints(const std::vector<Eigen::Matrix<S, 3, 1>>& from, const std::vector<Eigen::Matrix<S, 3, 1>>& to)
	{
		std::vector<int> out(to.size(), -1);
		for (size_t i = 0; i < to.size(); ++i) {
			S best = std::numeric_limits<S>::infinity();
			for (size_t j = 0; j < from.size(); ++j) {
				const S d = (from[j] - to[i]).squaredNorm();
				if (d < best) {
					best   = d;
					out[i] = int(j);
				}
			}
		}
		return out;
	}

	/// Scale factors (of the compressions, of the shear elongations) that make the springs taking over a contact's
	/// history store the elastic energy the old ones stored: twice the old energy `before` and the new springs' normal and
	/// shear parts `afterN`, `afterS` as they would be with the history passed unscaled [J], each Σ a k̄ x² (eqs. 13, 17).
	/// Where the new springs would store more, both are scaled down alike, √(before/(afterN + afterS)); where less, the
	/// shear is kept (a larger elongation could pass the friction limit, eq. 17) and the compressions are scaled up,
	/// √((before − afterS)/afterN), 1 without a compressed new spring. The caller caps a compression at its depth.
	template <class S> std::pair<S, S> handOverScales(S before, S afterN, S afterS)
	{
		using std::sqrt;
		if (afterN + afterS > before) {
			const S down = sqrt(before / (afterN + afterS));
			return { down, down };
		}
		return { afterN > 0 ? sqrt((before - afterS) / afterN) : S(1), S(1) };
	}

} // namespace rdem
} // namespace yade
