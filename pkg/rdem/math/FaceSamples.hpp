/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The face samples of one block that lie inside another: the sampled contact's test (doc/sphinx/rdemTheory.rst §4).

   Each of the six faces of block X carries the (n+1)×(n+1) points of the trapezoid rule (segmentCentres'
   faceSamplePoints, trapezoidNode); a point is in contact when sampleDepth finds it inside block Y along the direction u
   in which X separates from Y. Only the faces of X that face Y take part (cosine -n_f·u > 0). The points are tested in
   Y's frame, where they are affine in the face's centre and axes (sampleDepthLocal): each face's centre and each of X's
   axes is turned into Y's frame once, each sample costs two scalings and additions and the depth test.

   Units: m, m²; u unit. */
#pragma once

#include <pkg/rdem/math/BlockGeometry.hpp>
#include <pkg/rdem/math/SegmentGrid.hpp>
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace yade {
namespace rdem {

	/// The nodes of the (n+1)-point trapezoid rule (trapezoidNode), made once for the many points of the grids of a
	/// pair of blocks instead of twice per point; up to 9 per edge in place, more on the heap.
	template <class S> class TrapezoidNodes {
	public:
		explicit TrapezoidNodes(int n)
		        : large(n + 1 > int(inPlace) ? std::size_t(n + 1) : 0)
		        , node(large.empty() ? small.data() : large.data())
		{
			for (int i = 0; i <= n; ++i)
				node[i] = trapezoidNode<S>(i, n);
		}
		TrapezoidNodes(const TrapezoidNodes&)                    = delete;
		TrapezoidNodes&         operator=(const TrapezoidNodes&) = delete;
		const TrapezoidNode<S>& operator[](int i) const { return node[i]; }

	private:
		static constexpr std::size_t          inPlace = 10;
		std::array<TrapezoidNode<S>, inPlace> small;
		std::vector<TrapezoidNode<S>>         large;
		TrapezoidNode<S>*                     node;
	};

	/* The part of node i's tributary interval, of the (n+1)-point trapezoid rule on [-h, h] (trapezoidNode: half a
	   segment 2h/n to either side of the node, inward only at an end, length w·2h/n), that lies within [c - r, c + r]
	   (the other block's extent along the same axis), as a fraction in [0, 1] of that interval [-]. h > 0, r >= 0 [m].
	   A contact spring acts per unit contact area (paper §3.1 and eq. 13: springs and dashpots "per unit contact
	   area"); the tributary area of a sample on X's face is in contact only where the other block lies across it. */
	template <class S> S tributaryCover(int i, int n, S h, S c, S r)
	{
		const S x = h * (S(2 * i) / S(n) - 1), half = h / S(n);
		const S lo = i > 0 ? x - half : x, hi = i < n ? x + half : x;
		const S overlap = std::min(hi, c + r) - std::max(lo, c - r);
		return overlap > 0 ? std::min(overlap / (hi - lo), S(1)) : S(0);
	}

	/// A face sample of X found inside Y (faceSamplesInside).
	template <class S> struct FaceSampleHit {
		int                    key;   ///< firstKey + face·(n+1)² + i·(n+1) + j, face = 2k + side (side 1: the +R_X e_k face)
		Eigen::Matrix<S, 3, 1> point; ///< contact point: the sample moved by half its depth along u (global) [m]
		S                      depth; ///< sampleDepth of the sample in Y along u [m]
		S                      area; ///< trapezoid weight × the face's cosine with -u, halved (both blocks are sampled); with clip, times the part of its tributary rectangle across which Y lies (tributaryCover along both face axes) [m²]
	};

	/* The face samples of block X inside block Y along the unit direction u in which X separates from Y, passed to
	   emit(const FaceSampleHit&) in ascending key order. Keys run from firstKey over the six faces of X, (n+1)² each:
	   stable from step to step, for the contact springs' history. With near (a sample certificate: bit key % 64 of word
	   key / 64), only the samples whose bit is set are tested; nullptr: all. The same points, depths and areas, to the
	   bit, as testing every sample of every face of X that faces Y with sampleDepthLocal (tests/unit/test_face_samples.cpp):
	   the faces that cannot reach Y (faceMayEnterLocal) and those turned away from u are skipped before their samples are
	   made, X's axes are turned into Y's frame once per call, and the trapezoid nodes made once (TrapezoidNodes).
	   clip: each sample's area is only the part of its tributary rectangle across which Y lies (tributaryCover; a
	   sample with none is not in contact); false: the whole rectangle (Ig2_RdemBlock_RdemBlock_RdemGeom.clipSampleAreas). */
	template <class S, class Emit>
	void faceSamplesInside(
	        const OrientedBlock<S>&       X,
	        const OrientedBlock<S>&       Y,
	        const Eigen::Matrix<S, 3, 1>& u,
	        int                           n,
	        int                           firstKey,
	        const std::uint64_t*          near,
	        const TrapezoidNodes<S>&      node,
	        bool                          clip,
	        Emit&&                        emit)
	{
		using V                              = Eigen::Matrix<S, 3, 1>;
		const int                    perFace = (n + 1) * (n + 1);
		const Eigen::Matrix<S, 3, 3> toY     = Y.rot.transpose();
		const V                      uq      = toY * u; // u in Y's frame
		// X's axes in Y's frame, each made when a face first needs it.
		V    axisInY[3];
		bool made[3] = { false, false, false };
		auto axis    = [&](int k) -> const V& {
                        if (!made[k]) {
                                const V t  = X.rot.col(k);
                                axisInY[k] = toY * t;
                                made[k]    = true;
                        }
                        return axisInY[k];
		};
		// The samples to test: the set bits of keys [lo, hi) of the certificate, or all of them.
		const int lo = firstKey, hi = lo + 6 * perFace;
		// The first key to test from `key` on (hi if none is left below hi).
		auto next = [&](int key) {
			if (!near) return key < hi ? key : hi;
			while (key < hi) {
				const std::uint64_t bits = near[std::size_t(key) / 64] >> (key % 64);
				if (bits) return key + __builtin_ctzll(bits);
				key = 64 * (key / 64 + 1);
			}
			return hi;
		};
		static constexpr int following[3][2] = { { 1, 2 }, { 2, 0 }, { 0, 1 } }; // (k + 1) % 3, (k + 2) % 3
		for (int key = next(lo); key < hi;) {
			const int face = (key - lo) / perFace, first = lo + face * perFace, end = first + perFace;
			const int k = face / 2, k1 = following[k][0], k2 = following[k][1];
			// The face's outward normal and its cosine with -u: a face turned away from u has no sample in contact.
			const S s      = face % 2 ? 1 : -1;
			const V nf     = s * X.rot.col(k);
			const S cosine = -nf.dot(u);
			if (!(cosine > 0)) {
				key = next(end);
				continue;
			}
			const V  fc = X.pos + X.half[k] * nf;
			const V  qc = toY * (fc - Y.pos); // the face centre in Y's frame
			const V &q1 = axis(k1), &q2 = axis(k2);
			if (!faceMayEnterLocal<S>(Y.half, qc, q1, q2, X.half[k1], X.half[k2])) {
				key = next(end);
				continue;
			}
			const V t1 = X.rot.col(k1), t2 = X.rot.col(k2);
			const S area = segmentArea(X.half[k1], X.half[k2], n); // of a segment of the face [m²]
			// Y's extent along the face's axes, from the face centre: centre -qc·q and half-width Σ h_Y|q| (its projection
			// on each axis; the tributary rectangle of a sample is in contact only across it, tributaryCover)
			const S c1 = -qc.dot(q1), r1 = Y.half.dot(q1.cwiseAbs()), c2 = -qc.dot(q2), r2 = Y.half.dot(q2.cwiseAbs());
			for (; key < end; key = next(key + 1)) {
				const int               i = (key - first) / (n + 1), j = (key - first) % (n + 1);
				const TrapezoidNode<S>& a   = node[i];
				const TrapezoidNode<S>& b   = node[j];
				const S                 sa  = X.half[k1] * a.x;
				const V                 qa  = qc + sa * q1;
				const S                 rb  = X.half[k2] * b.x;
				const auto              hit = sampleDepthLocal<S>(Y.half, qa + rb * q2, uq);
				if (!hit.hit) continue;
				const S cover = clip ? tributaryCover<S>(i, n, X.half[k1], c1, r1) * tributaryCover<S>(j, n, X.half[k2], c2, r2) : S(1);
				if (!(cover > 0)) continue; // on Y's edge with nothing of Y across its tributary area: no contact area
				emit(FaceSampleHit<S> { key, fc + sa * t1 + rb * t2 + (hit.depth / 2) * u, hit.depth, area * a.w * b.w * cosine / 2 * cover });
			}
		}
	}

} // namespace rdem
} // namespace yade
