/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
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
	constexpr int cellTag = 2701; // mpy's own tags are 11 … 22 (py/mpy.py)

	void pack(const Scene& scene, const vector<Body::id_t>& ids, vector<Real>& out)
	{
		out.assign(ids.size() * RdemGhostExchange::valuesPerBlock, Real(0));
		for (size_t k = 0; k < ids.size(); ++k) {
			const auto& b = Body::byId(ids[k], const_cast<Scene*>(&scene));
			const auto* s = b ? dynamic_cast<const RdemState*>(b->state.get()) : nullptr;
			if (!s) continue; // not a block: nothing to send (zeros keep the message length)
			Real* v = &out[k * RdemGhostExchange::valuesPerBlock];
			for (int d = 0; d < 3; ++d) {
				v[d]     = s->strain[d];
				v[4 + d] = s->cellStress[d];
			}
			v[3] = s->cellScale;
		}
	}

	long unpack(Scene& scene, const vector<Body::id_t>& ids, const vector<Real>& in)
	{
		long n = 0;
		for (size_t k = 0; k < ids.size(); ++k) {
			const auto& b = Body::byId(ids[k], &scene);
			auto*       s = b ? dynamic_cast<RdemState*>(b->state.get()) : nullptr;
			if (!s) continue;
			const Real* v = &in[k * RdemGhostExchange::valuesPerBlock];
			for (int d = 0; d < 3; ++d) {
				s->strain[d]     = v[d];
				s->cellStress[d] = v[4 + d];
			}
			s->cellScale = v[3];
			++n;
		}
		return n;
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
	bytesSent      = 0;
	ghostsReceived = 0;
	const int rank = scene->subdomain;
	if (!exchange || rank == 0) return; // the master holds no block
	const auto subD = YADE_PTR_DYN_CAST<Subdomain>(scene->subD);
	if (!subD || subD->intersections.size() <= size_t(rank)) return; // not split (yet): nothing is a ghost
	const MPI_Comm            comm = subD->selfComm();
	const vector<Body::id_t>& nbrs = subD->intersections[size_t(rank)]; // the ranks whose bodies intersect this subdomain
	vector<vector<Real>>      sendBuf(nbrs.size()), recvBuf(nbrs.size());
	vector<MPI_Request>       reqs;
	reqs.reserve(2 * nbrs.size());
	for (size_t j = 0; j < nbrs.size(); ++j) {
		const int other = nbrs[j];
		if (other == 0 || other == rank) continue;
		recvBuf[j].resize(subD->mirrorIntersections[size_t(other)].size() * valuesPerBlock);
		reqs.emplace_back();
		MPI_Irecv(recvBuf[j].data(), int(recvBuf[j].size()), MPI_DOUBLE, other, cellTag, comm, &reqs.back());
	}
	for (size_t j = 0; j < nbrs.size(); ++j) {
		const int other = nbrs[j];
		if (other == 0 || other == rank) continue;
		pack(*scene, subD->intersections[size_t(other)], sendBuf[j]);
		reqs.emplace_back();
		MPI_Isend(sendBuf[j].data(), int(sendBuf[j].size()), MPI_DOUBLE, other, cellTag, comm, &reqs.back());
		bytesSent += long(sendBuf[j].size() * sizeof(double));
	}
	MPI_Waitall(int(reqs.size()), reqs.data(), MPI_STATUSES_IGNORE);
	for (size_t j = 0; j < nbrs.size(); ++j) {
		const int other = nbrs[j];
		if (other == 0 || other == rank) continue;
		ghostsReceived += unpack(*scene, subD->mirrorIntersections[size_t(other)], recvBuf[j]);
	}
#endif
}

} // namespace yade
