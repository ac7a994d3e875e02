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

/// On YADE's MPI (yade.mpy): sends the Poisson cell state of each block on a subdomain boundary to the ranks that hold it
/// as a ghost, on mpy's own ghost lists (Subdomain::intersections, ::mirrorIntersections), after the cells' strains are
/// updated and before the interaction loop reads them; and their cells' full ∂W/∂ε in RdemPoissonEngine, before the
/// bonds' forces (through RdemSharedState::cellStressSync).
class RdemGhostExchange : public GlobalEngine {
public:
	void action() override;
	/// Values sent per block: RdemState::strain (3), ::cellScale (1), ::cellStress (3).
	static constexpr int valuesPerBlock = 7;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemGhostExchange,GlobalEngine,R"""(The Poisson cells of the refined DEM on YADE's MPI (:ref:`mpy`, YADE built with ``ENABLE_MPI``): a block on a subdomain boundary is a *ghost* on the neighbouring ranks, which receive from mpy only its position, velocity, angular velocity and orientation, and do not have its bonds to blocks of its own subdomain (mpy erases interactions between two ghosts). The cell strain $\varepsilon$ of a ghost computed there from the bonds it has would be wrong, and so would the Poisson forces of the bonds between it and the rank's own blocks (they use both blocks' $\partial W/\partial\varepsilon$) and the total stress of their faces (:yref:`Law2_RdemGeom_RdemPhys_FaceSprings::totalStress`).

Every step, after :yref:`RdemCellStrainUpdater` and before the :yref:`InteractionLoop`, each worker sends, for each of its blocks that another rank holds as a ghost (mpy's :yref:`Subdomain.intersections`), the owner's :yref:`RdemState::strain`, :yref:`RdemState::cellScale` and :yref:`RdemState::cellStress` (7 reals, 56 bytes per block and neighbour), and writes what it receives into its ghosts (:yref:`Subdomain.mirrorIntersections`, the same order). Then, inside the step's :yref:`RdemPoissonEngine`, between the cells' $\partial W/\partial\varepsilon$ and the bonds' forces, the full $\partial W/\partial\varepsilon$ of the same blocks (3 reals, 24 bytes), which includes the reaction of the centroid-offset correction of all their bonds (running bond, :yref:`RdemPhys::offsetGrad1`), most of which the ghost's rank does not have. One ghost layer, point-to-point.

The cells of blocks on the master (fixed beams and slabs, which mpy keeps on rank 0) have their bonds on the workers of the blocks they join, each worker a part. With :yref:`RdemGhostExchange::masterCells`, every rank, the master too, sends the terms of such a cell's bonds to its own blocks to all ranks (two ``MPI_Allgatherv`` per step: the bonds' openings, cell coefficients and intact fractions after the strains' update, 56 bytes per bond; the gradients of their offset correction inside :yref:`RdemPoissonEngine`, 40 bytes per bond with an offset), and each rank completes the cell from all of them, summed in the order of the other block's id as a serial run sums them: the cell's strain, crack scale and stresses are then the serial run's, bit for bit.

Not exchanged (``rdem.distributed.check`` refuses such scenes): the scales of the paper's hexahedra across a subdomain boundary (their bonds between two ghosts are reset by the :yref:`InteractionLoop` under MPI, which would release them). Needs YADE built with MPI; in another YADE its first step stops with an error.)""",
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`; None: the law's, taken at the first step)."))
		((bool,exchange,true,,"Send and receive (``False``: the ghosts keep the strains computed from the bonds the rank has, which is wrong at the boundary: for tests)."))
		((bool,masterCells,false,,"Complete the cells of blocks on the master from every rank's part of their bonds (collective: the same on every rank; ``rdem.distributed.prepare`` sets it when the scene has such cells; ``False`` with them: each rank takes the cell from its own part of the bonds, which is wrong: for tests)."))
		((long,bytesSent,0,(Attr::readonly|Attr::noSave),"Bytes this rank sent in the last step (both exchanges; of the gathers for the master's cells, its own part once)."))
		((long,ghostsReceived,0,(Attr::readonly|Attr::noSave),"Ghost blocks updated in the last step."))
	);
	// clang-format on
	DECLARE_LOGGER;
};
REGISTER_SERIALIZABLE(RdemGhostExchange);

} // namespace yade
