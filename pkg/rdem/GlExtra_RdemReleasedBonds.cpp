/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#ifdef YADE_OPENGL

#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/Gl1_RdemPhys.hpp>
#include <pkg/rdem/GlExtra_RdemReleasedBonds.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>

namespace yade {

YADE_PLUGIN((GlExtra_RdemReleasedBonds));

void GlExtra_RdemReleasedBonds::render()
{
	if (!scene) return;
	const std::lock_guard<std::mutex> lock(scene->bodies->drawloopmutex);
	rdem::forEachLoopFunctor<Law2_RdemGeom_RdemPhys_FaceSprings>(scene, [&](Law2_RdemGeom_RdemPhys_FaceSprings& law) {
		for (const auto& r : law.releasedBondsNow()) { // the law appends to its list while the simulation runs
			const shared_ptr<Body> b = r ? Body::byId(r->id1, scene) : shared_ptr<Body>();
			if (!b) continue; // body 1 erased since
			Gl1_RdemPhys::Marks marks(r->segState.size());
			for (size_t k = 0; k < marks.size(); ++k)
				marks[k] = rdem::segmentMark<Real>(r->segState[k], Real(0));
			Gl1_RdemPhys::drawFace(scene, *b, r->faceCentre1, r->segHalf1u, r->segHalf1v, r->samplesPerEdge, marks, {}, false);
		}
	});
}

} // namespace yade

#endif // YADE_OPENGL
