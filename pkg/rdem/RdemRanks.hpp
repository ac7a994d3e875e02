/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

/* A scene split by YADE's MPI (yade.mpy) and the few collective operations the plugin's engines need on it. Without
   YADE_MPI, or before mpy split the scene (its Scene::subD is then no Subdomain), there is one rank: nothing is a ghost
   and the reductions return their argument, so the serial code paths are unchanged. */

#include <lib/base/Math.hpp>
#include <core/Body.hpp>
#include <core/Scene.hpp>
#ifdef YADE_MPI
#include <core/Subdomain.hpp>
#endif

namespace yade {
namespace rdem {

#ifdef YADE_MPI
	/// The Subdomain of a scene that mpy split (every rank has one, the master's empty), or nullptr.
	inline Subdomain* splitSubdomain(const Scene& scene) { return dynamic_cast<Subdomain*>(scene.subD.get()); }
#endif

	/// This process's rank in a scene that mpy split (0, the master, otherwise and without MPI).
	inline int rank(const Scene& scene)
	{
#ifdef YADE_MPI
		return splitSubdomain(scene) ? int(scene.subdomain) : 0;
#else
		(void)scene;
		return 0;
#endif
	}

	/// Whether body b is a ghost on this rank: a body of another subdomain, whose state its owner integrates and mpy sends.
	inline bool isGhost(const Scene& scene, const Body& b)
	{
#ifdef YADE_MPI
		return splitSubdomain(scene) && !b.getIsSubdomain() && b.subdomain != scene.subdomain;
#else
		(void)scene;
		(void)b;
		return false;
#endif
	}

	/// Whether body b is not this rank's to integrate: a ghost, or one of mpy's Subdomain bodies.
	inline bool notOwned(const Scene& scene, const Body& b)
	{
#ifdef YADE_MPI
		return splitSubdomain(scene) && (b.getIsSubdomain() || b.subdomain != scene.subdomain);
#else
		(void)scene;
		(void)b;
		return false;
#endif
	}

	/// Whether body b belongs to the master (rank 0) of a scene that mpy split: a fixed block (a beam, a slab) that the
	/// workers hold too, with its bonds to their own blocks, one part on each.
	inline bool onMaster(const Scene& scene, const Body& b)
	{
#ifdef YADE_MPI
		return splitSubdomain(scene) && !b.getIsSubdomain() && b.subdomain == 0;
#else
		(void)scene;
		(void)b;
		return false;
#endif
	}

	/// The share of an interaction's energies booked on this rank: 1/2 if one of its bodies is a worker's ghost (the
	/// interaction is computed alike on its other body's rank, which books the other half), else 1 (a body on the master
	/// is no such ghost: the master erases its interactions with the workers' blocks, only the worker computes them). Sums
	/// over ranks are then the scene's.
	inline Real energyShare(const Scene& scene, const Body& b1, const Body& b2)
	{
		const auto workersGhost = [&scene](const Body& b) { return isGhost(scene, b) && !onMaster(scene, b); };
		return workersGhost(b1) || workersGhost(b2) ? Real(0.5) : Real(1);
	}

	/// v[0 … n-1] := their minima over all ranks (one MPI_Allreduce; collective: every rank calls it at the same point).
	inline void minOverRanks(const Scene& scene, Real* v, int n)
	{
#ifdef YADE_MPI
		static_assert(std::is_same<Real, double>::value, "rdem::minOverRanks sends Real as MPI_DOUBLE");
		if (Subdomain* sd = splitSubdomain(scene)) MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_MIN, sd->selfComm());
#else
		(void)scene;
		(void)v;
		(void)n;
#endif
	}

	/// Every rank's `mine`, concatenated in rank order (an MPI_Allgather of the counts, then an MPI_Allgatherv; collective:
	/// every rank calls it at the same point). On a scene that is not split: `mine`.
	inline vector<Real> gatherOverRanks(const Scene& scene, const vector<Real>& mine)
	{
#ifdef YADE_MPI
		static_assert(std::is_same<Real, double>::value, "rdem::gatherOverRanks sends Real as MPI_DOUBLE");
		if (Subdomain* sd = splitSubdomain(scene)) {
			const MPI_Comm comm = sd->selfComm();
			int            size = 0;
			MPI_Comm_size(comm, &size);
			const int   n = int(mine.size());
			vector<int> count(size_t(size), 0), offset(size_t(size), 0);
			MPI_Allgather(&n, 1, MPI_INT, count.data(), 1, MPI_INT, comm);
			for (size_t r = 1; r < count.size(); ++r)
				offset[r] = offset[r - 1] + count[r - 1];
			vector<Real> all(size_t(offset.back() + count.back()));
			MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), count.data(), offset.data(), MPI_DOUBLE, comm);
			return all;
		}
#else
		(void)scene;
#endif
		return mine;
	}

	/// Whether x is true on any rank (one MPI_Allreduce; collective).
	inline bool anyOverRanks(const Scene& scene, bool x)
	{
#ifdef YADE_MPI
		if (Subdomain* sd = splitSubdomain(scene)) {
			int v = x ? 1 : 0;
			MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_MAX, sd->selfComm());
			return v != 0;
		}
#else
		(void)scene;
#endif
		return x;
	}

} // namespace rdem
} // namespace yade
