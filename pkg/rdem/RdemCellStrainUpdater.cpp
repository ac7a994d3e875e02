/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemCellStrainUpdater.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <pkg/rdem/math/BlockCells.hpp>

namespace yade {

YADE_PLUGIN((RdemCellStrainUpdater));
CREATE_LOGGER(RdemCellStrainUpdater);

void RdemCellStrainUpdater::action()
{
	cells.refresh(scene);
	if (cells.bonds.empty()) return;
	// Openings at the face centres: u_n = n·d0, d0 = P₂ - P₁ of the centre (rdem::BondKinematics at s = r = 0).
	const long nBonds = long(cells.bonds.size());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static)
#endif
	for (long k = 0; k < nBonds; ++k) {
		const Interaction& I = *cells.bonds[size_t(k)];
		if (!I.isReal() || !static_cast<const RdemGeom*>(I.geom.get())->bonded) continue; // released (then maybe a contact)
		const auto&    g  = *static_cast<const RdemGeom*>(I.geom.get());
		auto&          p  = *static_cast<RdemPhys*>(I.phys.get());
		const State&   s1 = *Body::byId(I.getId1(), scene)->state;
		const State&   s2 = *Body::byId(I.getId2(), scene)->state;
		const Matrix3r R1 = s1.ori.toRotationMatrix(), R2 = s2.ori.toRotationMatrix();
		const Vector3r n  = (R1 * g.segNormal1 - R2 * g.segNormal2).normalized();
		p.opening         = n.dot(s2.pos + R2 * g.faceCentre2 - s1.pos - R1 * g.faceCentre1);
	}
	// Per block: ε_d = Σ c_q u_n,q over its bonds along d; the crack scale never increases.
	const long nBodies = long(cells.nBodies());
#ifdef YADE_OPENMP
#pragma omp parallel for schedule(static)
#endif
	for (long b = 0; b < nBodies; ++b) {
		if (cells.first[size_t(b)] == cells.first[size_t(b) + 1]) continue;
		auto&    st    = *static_cast<RdemState*>(Body::byId(Body::id_t(b), scene)->state.get());
		Vector3r eps   = Vector3r::Zero();
		Real     scale = st.cellScale;
		for (size_t k = cells.first[size_t(b)]; k < cells.first[size_t(b) + 1]; ++k) {
			const auto& side = cells.sides[k];
			if (!side.I->isReal() || !static_cast<const RdemGeom*>(side.I->geom.get())->bonded) { // released: the cell is off for good
				scale = 0;
				continue;
			}
			const auto& g = *static_cast<const RdemGeom*>(side.I->geom.get());
			const auto& p = *static_cast<const RdemPhys*>(side.I->phys.get());
			eps[rdem::dominantAxis<Real>(side.second ? g.segNormal2 : g.segNormal1)] += (side.second ? p.cellCoef2 : p.cellCoef1) * p.opening;
			scale = math::min(scale, Real(p.nIntact()) / Real(p.segState.size()));
		}
		st.strain     = st.cellCondensation * eps;
		st.cellScale  = scale;
		st.cellStress = scale * (st.cellStiffness * st.strain);
	}
}

} // namespace yade
