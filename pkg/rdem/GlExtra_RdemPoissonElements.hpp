/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once
#ifdef YADE_OPENGL

#include <pkg/common/OpenGLRenderer.hpp>

namespace yade {

/// Draws the Poisson elements of the scene's RdemPoissonEngine as wire hexahedra between their nodes' blocks.
class GlExtra_RdemPoissonElements : public GlExtraDrawer {
public:
	void render() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(GlExtra_RdemPoissonElements,GlExtraDrawer,R"""(Draws the virtual 8-node hexahedra of :yref:`RdemPoissonEngine` (the paper's §4.2, eqs. 18-21) as wire hexahedra whose corners are their nodes, the centroids of their $2\times2\times2$ blocks, where the renderer shows those blocks (its :yref:`OpenGLRenderer.dispScale`). The colour goes linearly from ``releasedColor`` to ``color`` with the element's force scale in the last step (1 intact, 0 released by cracks; :yref:`RdemPoissonEngine.elementScales`). Poisson *cells* (any other layout) have no element to draw: each is its block.

Add it to :yref:`OpenGLRenderer.extraDrawers`; ``rdem.gui.view`` adds one, off (:yref:`GlExtraDrawer.dead`) unless asked for: with 891 elements on 1200 blocks the edges hide the cracks.)""",
		((Vector3r,color,Vector3r(0.3,0.85,1),,"RGB of an intact element (force scale 1)."))
		((Vector3r,releasedColor,Vector3r(0.45,0.45,0.45),,"RGB of an element released by cracks (force scale 0)."))
		((Real,lineWidth,1,,"Width of the edges [px]."))
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(GlExtra_RdemPoissonElements);

} // namespace yade

#endif // YADE_OPENGL
