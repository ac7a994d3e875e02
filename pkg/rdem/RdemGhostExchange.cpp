/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/RdemCellNetwork.hpp>
#include <pkg/rdem/RdemGhostExchange.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <stdexcept>
#include <type_traits>
#ifdef YADE_MPI
#include <core/Subdomain.hpp>
#endif

namespace yade {

YADE_PLUGIN((RdemGhostExchange));
CREATE_LOGGER(RdemGhostExchange);

#ifdef YADE_MPI
namespace {
	constexpr int strainTag = 2701, stressTag = 2702; // mpy's own tags are 11 … 22 (py/mpy.py)

	/* One point-to-point exchange with every worker whose subdomain intersects this one: `width` reals per block, packed
	   by pack(id, out) for the rank's own blocks that the other holds as ghosts (Subdomain::intersections[other]) and
	   unpacked by unpack(id, in) for the ghosts it owns (Subdomain::mirrorIntersections[other], the same order there).
	   Returns the bytes sent. */
	template <class Pack, class Unpack> long swapWithNeighbours(Subdomain& subD, int rank, int width, int tag, const Pack& pack, const Unpack& unpack)
	{
		const MPI_Comm            comm = subD.selfComm();
		const vector<Body::id_t>& nbrs = subD.intersections[size_t(rank)]; // ranks, not ids, at the rank's own index
		vector<vector<Real>>      sendBuf(nbrs.size()), recvBuf(nbrs.size());
		vector<MPI_Request>       reqs;
		reqs.reserve(2 * nbrs.size());
		long bytes = 0;
		for (size_t j = 0; j < nbrs.size(); ++j) {
			const int other = nbrs[j];
			if (other == 0 || other == rank) continue; // the master holds no block
			recvBuf[j].resize(subD.mirrorIntersections[size_t(other)].size() * size_t(width));
			reqs.emplace_back();
			MPI_Irecv(recvBuf[j].data(), int(recvBuf[j].size()), MPI_DOUBLE, other, tag, comm, &reqs.back());
		}
		for (size_t j = 0; j < nbrs.size(); ++j) {
			const int other = nbrs[j];
			if (other == 0 || other == rank) continue;
			const vector<Body::id_t>& ids = subD.intersections[size_t(other)];
			sendBuf[j].assign(ids.size() * size_t(width), Real(0));
			for (size_t k = 0; k < ids.size(); ++k)
				pack(ids[k], &sendBuf[j][k * size_t(width)]);
			reqs.emplace_back();
			MPI_Isend(sendBuf[j].data(), int(sendBuf[j].size()), MPI_DOUBLE, other, tag, comm, &reqs.back());
			bytes += long(sendBuf[j].size() * sizeof(double));
		}
		MPI_Waitall(int(reqs.size()), reqs.data(), MPI_STATUSES_IGNORE);
		for (size_t j = 0; j < nbrs.size(); ++j) {
			const int other = nbrs[j];
			if (other == 0 || other == rank) continue;
			const vector<Body::id_t>& ids = subD.mirrorIntersections[size_t(other)];
			for (size_t k = 0; k < ids.size(); ++k)
				unpack(ids[k], &recvBuf[j][k * size_t(width)]);
		}
		return bytes;
	}

	RdemState* blockState(Scene* scene, Body::id_t id)
	{
		const auto& b = Body::byId(id, scene);
		return b ? dynamic_cast<RdemState*>(b->state.get()) : nullptr;
	}
}
#endif

void RdemGhostExchange::action()
{
#ifndef YADE_MPI
	throw std::runtime_error("RdemGhostExchange: this YADE is built without MPI (ENABLE_MPI); build the plugin against YADE with MPI "
	                         "(tools/setup.sh --mpi) and run it under mpiexec with yade.mpy");
#else
	static_assert(std::is_same<Real, double>::value, "RdemGhostExchange sends Real as MPI_DOUBLE");
	bytesSent       = 0;
	ghostsReceived  = 0;
	const int  rank = scene->subdomain;
	const auto subD = YADE_PTR_DYN_CAST<Subdomain>(scene->subD);
	if (!subD || subD->intersections.size() <= size_t(rank)) return; // not split (yet): nothing is a ghost
	Scene*           sc    = scene;
	RdemCellNetwork* cells = RdemSharedState::of(scene, shared).cells;
	/* 0. The cells of the master's blocks (fixed beams, slabs), on every rank, the master too: their strains, crack
	      scales and elastic stresses from the parts of their bonds on all ranks (collective); their offset reactions below. */
	const bool reduce = masterCells && cells;
	if (reduce) bytesSent += cells->reduceMasterStrains(scene);
	if (rank == 0 || !exchange) { // the master holds no ghost: only the reductions
		if (reduce)
			RdemSharedState::of(scene, shared).cellStressSync
			        = [cells, sc, this](const vector<Body::id_t>&, vector<Vector3r>&) { bytesSent += cells->reduceMasterStresses(sc); };
		return;
	}
	// 1. Now: each boundary block's strain (3), crack scale (1) and elastic ∂W/∂ε (3), for the law and the cells.
	long received = 0;
	bytesSent += swapWithNeighbours(
	        *subD,
	        rank,
	        valuesPerBlock,
	        strainTag,
	        [sc](Body::id_t id, Real* v) {
		        if (const RdemState* s = blockState(sc, id)) {
			        for (int d = 0; d < 3; ++d) {
				        v[d]     = s->strain[d];
				        v[4 + d] = s->cellStress[d];
			        }
			        v[3] = s->cellScale;
		        }
	        },
	        [sc, &received](Body::id_t id, const Real* v) {
		        if (RdemState* s = blockState(sc, id)) {
			        for (int d = 0; d < 3; ++d) {
				        s->strain[d]     = v[d];
				        s->cellStress[d] = v[4 + d];
			        }
			        s->cellScale = v[3];
			        ++received;
		        }
	        });
	ghostsReceived = received;
	/* 2. In this step's RdemPoissonEngine, between the cells' ∂W/∂ε and the bonds' forces: each boundary block's full
	      ∂W/∂ε (3), which includes the reaction of the offset correction of all its bonds (running bond), most of which the
	      ghost's rank does not have. */
	const shared_ptr<Subdomain> sd                    = subD;
	RdemSharedState::of(scene, shared).cellStressSync = [sd, rank, sc, cells, reduce, this](const vector<Body::id_t>& body, vector<Vector3r>& stress) {
		if (reduce) bytesSent += cells->reduceMasterStresses(sc);
		vector<long> index(sc->bodies->size(), -1); // body id → compact index of the cells
		for (size_t i = 0; i < body.size(); ++i)
			if (size_t(body[i]) < index.size()) index[size_t(body[i])] = long(i);
		const auto at = [&index](Body::id_t id) { return size_t(id) < index.size() ? index[size_t(id)] : -1L; };
		bytesSent += swapWithNeighbours(
		        *sd,
		        rank,
		        3,
		        stressTag,
		        [&](Body::id_t id, Real* v) {
			        const long i = at(id);
			        if (i >= 0)
				        for (int d = 0; d < 3; ++d)
					        v[d] = stress[size_t(i)][d];
		        },
		        [&](Body::id_t id, const Real* v) {
			        const long i = at(id);
			        if (i >= 0)
				        for (int d = 0; d < 3; ++d)
					        stress[size_t(i)][d] = v[d];
		        });
	};
#endif
}

} // namespace yade
