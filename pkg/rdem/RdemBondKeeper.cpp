/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <lib/pyutil/gil.hpp>
#include <core/Omega.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/RdemBondKeeper.hpp>
#include <pkg/rdem/RdemCellNetwork.hpp>
#include <pkg/rdem/RdemRanks.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RdemBondKeeper));
CREATE_LOGGER(RdemBondKeeper);

long RdemBondKeeper::keep()
{
#ifndef YADE_MPI
	throw std::runtime_error("RdemBondKeeper.keep: this YADE is built without MPI (ENABLE_MPI): there are no subdomains; use the plugin "
	                         "built against YADE with MPI (tools/setup.sh --mpi)");
#else
	Scene* sc = Omega::instance().getScene().get();
	kept.clear();
	for (const auto& I : *sc->interactions) {
		if (!I->isReal()) continue;
		const auto& b1 = Body::byId(I->getId1(), sc);
		const auto& b2 = Body::byId(I->getId2(), sc);
		if (b1 && b2 && !b1->getIsSubdomain() && !b2->getIsSubdomain() && b1->subdomain != b2->subdomain) kept.push_back(I);
	}
	return long(kept.size());
#endif
}

void RdemBondKeeper::action()
{
#ifdef YADE_MPI
	if (kept.empty() || !rdem::splitSubdomain(*scene)) return;
	for (auto& I : kept) {
		const auto& b1 = Body::byId(I->getId1(), scene);
		const auto& b2 = Body::byId(I->getId2(), scene);
		if (!b1 || !b2 || (b1->subdomain != scene->subdomain && b2->subdomain != scene->subdomain)) continue;
		scene->interactions->insertInteractionMPI(I); // in place of the collider's potential interaction of the pair, if any
		++restored;
	}
	if (restored > 0) RdemCellNetwork::generation += 1; // the Poisson cells take the bonds put back, as after a build
	LOG_INFO("rank " << scene->subdomain << ": " << restored << " of " << kept.size() << " bonds across subdomains put back");
	// the master and the other ranks drop the bonds of bodies they no longer hold: the last references, in the simulation's
	// thread, to what may come from Python (an RdemJoint made in a script), which needs the GIL (RdemCellNetwork::rebuild)
	gilLock lock;
	kept.clear();
#endif
}

} // namespace yade
