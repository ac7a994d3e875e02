/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemReleasedBond.hpp>

namespace yade {

YADE_PLUGIN((RdemReleasedBond));

shared_ptr<RdemReleasedBond> RdemReleasedBond::of(Body::id_t id1, Body::id_t id2, const RdemGeom& g, const RdemPhys& p, long iter)
{
	auto r            = shared_ptr<RdemReleasedBond>(new RdemReleasedBond);
	r->id1            = id1;
	r->id2            = id2;
	r->iter           = iter;
	r->samplesPerEdge = g.samplesPerEdge;
	r->faceCentre1    = g.faceCentre1;
	r->segNormal1     = g.segNormal1;
	r->segHalf1u      = g.segHalf1u;
	r->segHalf1v      = g.segHalf1v;
	r->segState       = p.segState;
	return r;
}

} // namespace yade
