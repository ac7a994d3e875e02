/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemCellNetwork.hpp>
#include <pkg/rdem/RdemCellStrainUpdater.hpp>

namespace yade {

YADE_PLUGIN((RdemCellStrainUpdater));
CREATE_LOGGER(RdemCellStrainUpdater);

void RdemCellStrainUpdater::action()
{
	// The cells belong to the scene's RdemPoissonEngine, which applies their forces after the loop (RdemSharedState::cells).
	RdemSharedState& sh = RdemSharedState::of(scene, shared); // checks the engines when they changed
	if (sh.cells) sh.cells->updateStrains(scene, sh.brokenSprings(), ompThreads);
}

} // namespace yade
