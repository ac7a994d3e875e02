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

/// Draws the bonds the law released (Law2_RdemGeom_RdemPhys_FaceSprings::releasedBonds): the open cracks.
class GlExtra_RdemReleasedBonds : public GlExtraDrawer {
public:
	void render() override;
	// clang-format off
	YADE_CLASS_BASE_DOC(GlExtra_RdemReleasedBonds,GlExtraDrawer,R"""(Draws the bonds that :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` released (:yref:`Law2_RdemGeom_RdemPhys_FaceSprings.releasedBonds`): a bond whose segments have all broken and opened has no interaction any more, so :yref:`Gl1_RdemPhys` cannot show it, yet it is the widest crack of the scene. Each segment is a quad on body 1's face, where the renderer shows body 1, in the colour of what broke it (:yref:`Gl1_RdemPhys.tensionColor`, :yref:`Gl1_RdemPhys.shearColor`; the colours and :yref:`Gl1_RdemPhys.fill` are shared with it).

Add it to :yref:`OpenGLRenderer.extraDrawers`; ``rdem.gui.view`` adds one.)""");
	// clang-format on
};
REGISTER_SERIALIZABLE(GlExtra_RdemReleasedBonds);

} // namespace yade

#endif // YADE_OPENGL
