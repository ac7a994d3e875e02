/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemCellStrainUpdater.hpp>
#include <pkg/rdem/RdemPoissonEngine.hpp>

namespace yade {

YADE_PLUGIN((RdemCellStrainUpdater));
CREATE_LOGGER(RdemCellStrainUpdater);

void RdemCellStrainUpdater::action()
{
	// The cells belong to the scene's RdemPoissonEngine, which applies their forces after the loop.
	const long broken = RdemSharedState::of(scene, shared).brokenSprings(); // checks the engines when they changed
	if (RdemPoissonEngine* poisson = RdemPoissonEngine::of(scene)) poisson->cellNetwork().updateStrains(scene, broken, ompThreads);
}

} // namespace yade
