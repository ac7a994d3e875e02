/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemForceAssembler.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/RdemPhys.hpp>

namespace yade {

YADE_PLUGIN((RdemForceAssembler));

void RdemForceAssembler::action()
{
	const long nBodies = long(scene->bodies->size());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static)
#endif
	for (long id = 0; id < nBodies; ++id) {
		const shared_ptr<Body>& b = (*scene->bodies)[Body::id_t(id)];
		if (!b) continue;
		Vector3r f = Vector3r::Zero(), t = Vector3r::Zero();
		for (const auto& other : b->intrs) { // a std::map: in the order of the other body's id
			const Interaction& I = *other.second;
			const auto*        p = I.isReal() ? dynamic_cast<const RdemPhys*>(I.phys.get()) : nullptr;
			if (!p || p->forceIter != scene->iter) continue; // not deferred, or not computed in this step
			if (I.getId2() == b->id) {
				f += p->force;
				t += p->torque2;
			} else {
				f -= p->force;
				t += p->torque1;
			}
		}
		scene->forces.addForce(b->id, f);
		scene->forces.addTorque(b->id, t);
	}
}

} // namespace yade
