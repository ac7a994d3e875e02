/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>
#include <pkg/rdem/RdemSharedState.hpp>

namespace yade {

/// Updates the normal strains of the blocks' Poisson cells from the openings of their bonds, before the interaction loop.
class RdemCellStrainUpdater : public GlobalEngine {
public:
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemCellStrainUpdater,GlobalEngine,R"""(Updates, at the start of every step, the normal strains of the blocks' Poisson cells (:yref:`RdemState::strain`, :ref:`theory §5.4 <rdem-theory-5-4>`): each bond's opening at its face centre, $u_n=\mathbf{n}\cdot(\mathbf{P}_2-\mathbf{P}_1)$ (:yref:`RdemPhys::opening`), then per block $\varepsilon_d=\sum_q c_q u_{n,q}$ over its bonds along $d$ (:yref:`RdemPhys::cellCoef1`), completed on the axes without bonds by :yref:`RdemState::cellCondensation`; each cell's crack scale (:yref:`RdemState::cellScale`) and elastic stress (:yref:`RdemState::cellStress`).

It must come before the :yref:`InteractionLoop`, because :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` corrects the shear springs of bonds whose centroids are offset along the face with these strains (running bond); :yref:`RdemPoissonEngine` turns them into forces after the loop. ``rdem.engines(poisson='consistent')`` places it. Without cells (no ``build``, or a grid of $2\times2\times2$ groups, which uses the paper's elements) it does nothing.)""",
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`: broken springs release the cells; handed by ``rdem.engines()``; None: the law's, taken at the first step)."))
	);
	// clang-format on
	DECLARE_LOGGER;
};
REGISTER_SERIALIZABLE(RdemCellStrainUpdater);

} // namespace yade
