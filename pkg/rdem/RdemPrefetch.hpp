/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Interaction.hpp>
#include <core/Scene.hpp>

namespace yade {
namespace rdem {

	/* Software prefetch for YADE's InteractionLoop over a block assembly.

	   The loop visits the interactions in container order and, for each, follows two chains of pointers: interaction →
	   geometry, physics → the physics' per-segment arrays, and interaction → both bodies → their states. Once a scene
	   outgrows the cache, every link is a wait for memory, and the hardware cannot guess the next address. Called by
	   the geometry functor (the first functor of every interaction) with the interaction at container index i, this
	   asks the processor for the data of the interactions that follow, one link per stage, so that each stage reads
	   only what an earlier one brought in:

	   * i + 2·distance: the interaction;
	   * i + distance: its geometry and physics (the part the law reads; of a potential pair, its RdemGap), both bodies;
	   * i + distance/2: the physics' per-segment arrays (RdemPhys only), both bodies' states.

	   A prefetch is a hint: it never faults and changes no result. Nothing is done for an interaction that is not (yet)
	   in the container (utils.createInteraction). distance > 0. */
	void prefetchInteractionsAhead(Scene& scene, const Interaction& current, int distance);

	/// Bytes of a bond with its share of bodies, states and Poisson elements: the measured memory of the scaling
	/// cubes, 7.3 kB per block with about 2.8 bonds per block, rounded down (scripts/benchmark.py --cases scaling).
	constexpr size_t bytesPerInteraction = 2048;

	/// Distance of the automatic mode: in the 28³ cube (2.4e4 blocks) 2, 4 and 8 were within the noise, 8 fastest in both
	/// rounds, 16 slower.
	constexpr int autoPrefetchDistance = 8;

	/// Size of the last-level cache one core uses [bytes] (Linux sysfs; 32 MiB if the system does not say).
	size_t lastLevelCacheBytes();

	/* The distance to prefetch at in a scene of nInteractions interactions for a requested distance: > 0 and 0 as
	   given; < 0 (automatic) autoPrefetchDistance once the interactions' data, with their share of the bodies and
	   Poisson elements, exceed the last-level cache, else 0. Below, prefetches only add instructions: the paper's
	   1200-block scene (3260 bonds) was 10-20 % slower with them, and the gain starts between 1.3e4 and 2.2e4 bonds.
	*/
	inline int prefetchDistanceFor(int requested, size_t nInteractions)
	{
		if (requested >= 0) return requested;
		static const size_t cache = lastLevelCacheBytes();
		return nInteractions * bytesPerInteraction > cache ? autoPrefetchDistance : 0;
	}

} // namespace rdem
} // namespace yade
