/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/FaceSamples.hpp: the face samples of one block inside another (faceSamplesInside), the
   sampled contact's test, against the full test of every sample of every face that faces the other block, one point
   at a time, with no face culled (faceMayEnterLocal) and no axis or node shared between points. Both compute each
   number by the same operations on the same numbers, so they must agree to the bit: the keys, points, depths and
   areas are compared with EXPECT_EQ. What the comparison checks is that the shortcuts (faces culled before their
   samples are made, X's axes turned into Y's frame once, the trapezoid nodes made once, the certificate's bits
   visited) leave out no sample in contact and change no number. */
#include <pkg/rdem/math/FaceSamples.hpp>
#include <tests/unit/Random.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using rdem_test::Scalar;

namespace rdem = yade::rdem;
using V3       = rdem_test::Vector3;
using M3       = rdem_test::Matrix3;
using Block    = rdem::OrientedBlock<Scalar>;
using Hit      = rdem::FaceSampleHit<Scalar>;

Scalar uniform(std::mt19937& gen, Scalar lo, Scalar hi) { return rdem_test::uniform(gen, lo, hi); }

M3 randomRotation(std::mt19937& gen) { return rdem_test::randomQuaternion<Scalar>(gen).toRotationMatrix(); }

/* The full test: every sample (i, j) of every face of X whose outward normal n_f has -n_f·u > 0, with its point made
   in Y's frame from that face's centre and axes (sampleDepthLocal), kept if its bit is set in near (nullptr: all). */
std::vector<Hit> everySample(const Block& X, const Block& Y, const V3& u, int n, int firstKey, const std::uint64_t* near, bool clip)
{
	std::vector<Hit> hits;
	const int        perFace = (n + 1) * (n + 1);
	const M3         toY     = Y.rot.transpose();
	const V3         uq      = toY * u;
	for (int face = 0; face < 6; ++face) {
		const int    k = face / 2, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
		const Scalar s      = face % 2 ? 1 : -1;
		const V3     nf     = s * X.rot.col(k);
		const Scalar cosine = -nf.dot(u);
		if (!(cosine > 0)) continue;
		const V3     t1 = X.rot.col(k1), t2 = X.rot.col(k2);
		const V3     q1 = toY * t1, q2 = toY * t2;
		const V3     fc   = X.pos + X.half[k] * nf;
		const V3     qc   = toY * (fc - Y.pos);
		const Scalar area = rdem::segmentArea(X.half[k1], X.half[k2], n);
		const Scalar c1 = -qc.dot(q1), r1 = Y.half.dot(q1.cwiseAbs()), c2 = -qc.dot(q2), r2 = Y.half.dot(q2.cwiseAbs());
		for (int i = 0; i <= n; ++i)
			for (int j = 0; j <= n; ++j) {
				const int key = firstKey + face * perFace + i * (n + 1) + j;
				if (near && !((near[key / 64] >> (key % 64)) & 1)) continue;
				const auto   a = rdem::trapezoidNode<Scalar>(i, n), b = rdem::trapezoidNode<Scalar>(j, n);
				const Scalar sa = X.half[k1] * a.x, rb = X.half[k2] * b.x;
				const V3     qa    = qc + sa * q1;
				const auto   hit   = rdem::sampleDepthLocal<Scalar>(Y.half, qa + rb * q2, uq);
				const Scalar cover = clip
				        ? rdem::tributaryCover<Scalar>(i, n, X.half[k1], c1, r1) * rdem::tributaryCover<Scalar>(j, n, X.half[k2], c2, r2)
				        : Scalar(1);
				if (hit.hit && cover > 0)
					hits.push_back(
					        Hit { key, fc + sa * t1 + rb * t2 + (hit.depth / 2) * u, hit.depth, area * a.w * b.w * cosine / 2 * cover });
			}
	}
	return hits;
}

std::vector<Hit> fastSamples(const Block& X, const Block& Y, const V3& u, int n, int firstKey, const std::uint64_t* near, bool clip = true)
{
	std::vector<Hit>                   hits;
	const rdem::TrapezoidNodes<Scalar> node(n);
	rdem::faceSamplesInside<Scalar>(X, Y, u, n, firstKey, near, node, clip, [&](const Hit& h) { hits.push_back(h); });
	return hits;
}

// Both ways, hit by hit to the bit; returns the number of hits.
int compareToTheBit(const Block& X, const Block& Y, const V3& u, int n, int firstKey, const std::uint64_t* near, bool clip = true)
{
	const std::vector<Hit> full = everySample(X, Y, u, n, firstKey, near, clip), fast = fastSamples(X, Y, u, n, firstKey, near, clip);
	EXPECT_EQ(fast.size(), full.size());
	for (size_t h = 0; h < std::min(fast.size(), full.size()); ++h) {
		EXPECT_EQ(fast[h].key, full[h].key);
		for (int c = 0; c < 3; ++c)
			EXPECT_EQ(fast[h].point[c], full[h].point[c]);
		EXPECT_EQ(fast[h].depth, full[h].depth);
		EXPECT_EQ(fast[h].area, full[h].area);
	}
	return int(full.size());
}

// A certificate of random bits over keys [0, keys) (each set with probability 1/2), in 64-bit words.
std::vector<std::uint64_t> randomBits(std::mt19937& gen, int keys)
{
	std::vector<std::uint64_t> near(size_t((keys + 63) / 64));
	for (auto& w : near)
		w = (std::uint64_t(gen()) << 32) | gen();
	return near;
}

TEST(FaceSamples, TributaryCoverIsTheCoveredPartOfTheNodesInterval)
{
	// Node i of the (n+1)-point rule on [-h, h] owns [x - h/n, x + h/n], only the inward half at an end: for n = 2,
	// h = 1 the nodes -1, 0, 1 own [-1, -0.5], [-0.5, 0.5], [0.5, 1].
	EXPECT_EQ(rdem::tributaryCover<Scalar>(0, 2, 1, 0, 10), 1);        // Y across everything
	EXPECT_EQ(rdem::tributaryCover<Scalar>(1, 2, 1, 0, 0.25), 0.5);    // [-0.25, 0.25] of [-0.5, 0.5]
	EXPECT_EQ(rdem::tributaryCover<Scalar>(0, 2, 1, -1.5, 0.75), 0.5); // [-2.25, -0.75] covers [-1, -0.75] of [-1, -0.5]
	EXPECT_EQ(rdem::tributaryCover<Scalar>(2, 2, 1, 3, 1), 0);         // Y beyond the end
	EXPECT_EQ(rdem::tributaryCover<Scalar>(2, 2, 1, 1.5, 0.5), 0);     // Y's edge on the face's edge: touches, covers nothing
	EXPECT_NEAR(rdem::tributaryCover<Scalar>(0, 1, 0.2825, -0.2825 - 0.0625 + 1e-3, 0.0625), 1e-3 / 0.2825, 1e-15);
}

TEST(FaceSamples, CornerOfALargeFaceOnTheEdgeOfASmallBlockCarriesTheOverlapOnly)
{
	// The two-storey house of scripts/building.py --big (doc/building.md "Runs"): a roof-slab piece (half-extents
	// 0.2825 × 0.2894 × 0.075 m) whose corner rests on the edge of a top brick (0.0625 × 0.13 × 0.03 m), their faces
	// overlapping by a strip d wide along x and 0.13 m along y, 1 µm deep, vertex samples (n = 1). Each block's corner
	// sample in the other takes the strip's area d × 0.13 m, halved (both blocks are sampled): together the overlap of
	// the two faces. Without the cover, the slab's corner took a quarter of its face, halved (0.0409 m²: more than the
	// brick's whole top face, 0.0325 m²), for any d.
	const Scalar d = 2e-3;
	const Block  slab { V3(0, 0, 0), M3::Identity(), V3(0.2825, 0.2894, 0.075) };
	const Block  brick { V3(-0.2825 - 0.0625 + d, -0.2894, -0.075 - 0.03 + 1e-6), M3::Identity(), V3(0.0625, 0.13, 0.03) };
	const V3     u(0, 0, 1); // the slab (X) separates upwards from the brick (Y)
	const auto   inBrick = fastSamples(slab, brick, u, 1, 0, nullptr), inSlab = fastSamples(brick, slab, V3(-u), 1, 24, nullptr);
	ASSERT_EQ(inBrick.size(), 1u);
	ASSERT_EQ(inSlab.size(), 1u);
	EXPECT_NEAR(inBrick[0].area, d * 0.13 / 2, 1e-12);
	EXPECT_NEAR(inSlab[0].area, d * 0.13 / 2, 1e-12);
	const auto unclipped = fastSamples(slab, brick, u, 1, 0, nullptr, false);
	ASSERT_EQ(unclipped.size(), 1u);
	EXPECT_NEAR(unclipped[0].area, 0.565 * 0.5788 / 8, 1e-12);
	compareToTheBit(slab, brick, u, 1, 0, nullptr);
	compareToTheBit(brick, slab, V3(-u), 1, 24, nullptr);
}

TEST(FaceSamples, SmallFaceFlatOnALargeOneKeepsItsWholeArea)
{
	// A brick lying on a slab, inside its outline, 1 µm deep: the brick's bottom samples are covered whole and their
	// areas sum to half its face (both blocks are sampled; the slab's vertices are not inside the brick), as before.
	for (int n : { 1, 2, 3 }) {
		const Block slab { V3(0, 0, 0), M3::Identity(), V3(0.2825, 0.2894, 0.075) };
		const Block brick { V3(0.05, -0.1, 0.075 + 0.03 - 1e-6), M3::Identity(), V3(0.0625, 0.13, 0.03) };
		Scalar      sum = 0;
		for (const Hit& h : fastSamples(brick, slab, V3(0, 0, 1), n, 0, nullptr))
			sum += h.area;
		EXPECT_NEAR(sum, 0.125 * 0.26 / 2, 1e-14) << "n = " << n;
		EXPECT_TRUE(fastSamples(slab, brick, V3(0, 0, -1), n, 24, nullptr).empty() || n > 1) << "n = " << n;
	}
}

TEST(FaceSamples, TrapezoidNodesAreTrapezoidNode)
{
	// The table holds trapezoidNode's values to the bit, in place (n + 1 ≤ 10) and on the heap (n = 9: 10 nodes, in
	// place; n = 10 and 40: on the heap).
	for (int n : { 1, 2, 3, 9, 10, 40 }) {
		const rdem::TrapezoidNodes<Scalar> node(n);
		for (int i = 0; i <= n; ++i) {
			EXPECT_EQ(node[i].x, rdem::trapezoidNode<Scalar>(i, n).x);
			EXPECT_EQ(node[i].w, rdem::trapezoidNode<Scalar>(i, n).w);
		}
	}
}

TEST(FaceSamples, RandomPairsGiveEverySampleInContactToTheBit)
{
	// 300 random pairs of blocks (general rotations, half-extents 0.2-1 m, B's centre in [-1.5, 1.5]³ m, so that most
	// overlap), each block sampled inside the other along a random unit u, with 1, 2, 3 and 12 samples per edge (12: the
	// heap's nodes), without a certificate, with every bit set and with random bits; key ranges as the functor's
	// (body 1 from 0, body 2 from 6(n+1)²). Both outcomes are frequent: the comparison tests something either way.
	std::mt19937 gen(20261127);
	int          hits = 0, empty = 0;
	for (int k = 0; k < 300; ++k) {
		const Block A { V3(uniform(gen, -0.2, 0.2), uniform(gen, -0.2, 0.2), uniform(gen, -0.2, 0.2)),
			        randomRotation(gen),
			        V3(uniform(gen, 0.2, 1), uniform(gen, 0.2, 1), uniform(gen, 0.2, 1)) };
		const Block B { V3(uniform(gen, -1.5, 1.5), uniform(gen, -1.5, 1.5), uniform(gen, -1.5, 1.5)),
			        randomRotation(gen),
			        V3(uniform(gen, 0.2, 1), uniform(gen, 0.2, 1), uniform(gen, 0.2, 1)) };
		const V3    u    = V3(uniform(gen, -1, 1), uniform(gen, -1, 1), uniform(gen, -1, 1)).normalized();
		const int   n    = std::vector<int> { 1, 2, 3, 12 }[size_t(k % 4)];
		const int   all  = 2 * 6 * (n + 1) * (n + 1);
		const auto  ones = std::vector<std::uint64_t>(size_t((all + 63) / 64), ~std::uint64_t(0));
		const auto  bits = randomBits(gen, all);
		for (const std::uint64_t* near : { static_cast<const std::uint64_t*>(nullptr), ones.data(), bits.data() }) {
			const int found = compareToTheBit(A, B, u, n, 0, near, k % 2) + compareToTheBit(B, A, V3(-u), n, 6 * (n + 1) * (n + 1), near, k % 2);
			(found > 0 ? hits : empty)++;
		}
	}
	EXPECT_GE(hits, 200);
	EXPECT_GE(empty, 100);
}

TEST(FaceSamples, GridNeighboursStrainedAlongAnEdgeToTheBit)
{
	// The sampled contacts of a wall (MI1, doc/performance.md): blocks of 0.25 × 0.12 × 0.055 m half-extents offset
	// across an edge or a corner (half a block along the course, or a whole one), strained into each other by up to
	// 1e-6 m and turned by up to 1e-4 rad, sampled with 3 × 3 points per face along the pair's normal (contactNormal),
	// without a certificate and with random bits. Most of their samples lie on the other block's surface, where the
	// depth test's tolerance decides: the two ways must still agree to the bit.
	std::mt19937 gen(20261128);
	const V3     h(0.25, 0.12, 0.055);
	int          hits = 0;
	for (int k = 0; k < 400; ++k) {
		V3 offset, strain, axis;
		do {
			for (int i = 0; i < 3; ++i) // -1, 0 or 1 block along each axis; along the course also half a block
				offset[i] = 2 * h[i] * Scalar(int(gen() % 3) - 1) / (i == 0 && gen() % 2 ? 2 : 1);
		} while ((offset.array() != 0).count() < 2); // across an edge or a corner, not a face
		for (int i = 0; i < 3; ++i)
			strain[i] = uniform(gen, -1e-6, 0) * (offset[i] > 0 ? 1 : -1);
		for (int i = 0; i < 3; ++i)
			axis[i] = uniform(gen, -1, 1);
		const Block A { V3(0.3, -0.2, 1.1), M3::Identity(), h };
		const Block B { A.pos + offset + strain, Eigen::AngleAxis<Scalar>(uniform(gen, 0, 1e-4), axis.normalized()).toRotationMatrix(), h };
		const rdem::BlockPair<Scalar> pair(A, B);
		const V3                      normal = rdem::contactNormal<Scalar>(pair, rdem::SeparatingAxes<Scalar>(pair));
		const auto                    bits   = randomBits(gen, 2 * 6 * 9);
		for (const std::uint64_t* near : { static_cast<const std::uint64_t*>(nullptr), bits.data() })
			hits += compareToTheBit(A, B, V3(-normal), 2, 0, near, k % 2) + compareToTheBit(B, A, normal, 2, 6 * 9, near, k % 2);
	}
	EXPECT_GE(hits, 400);
}

} // namespace
