/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <pkg/common/Box.hpp>

namespace yade {

/// A rigid rectangular block. Deriving from Box lets Bo1_Box_Aabb, Gl1_Box and VTKRecorder's "boxes" handle it as is.
class RdemBlock : public Box {
public:
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR(RdemBlock,Box,R"""(Rigid rectangular block (hexahedron) of the refined distinct element method; :yref:`Box::extents` are its half-sizes along the body axes [m]. The body axes must be its principal axes (``rdem.block`` sets mass $8\rho abc$ and inertia $m(b^2+c^2)/3,\dots$) and :yref:`Body::aspherical` must be true.

Pairs of blocks interact through :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom`; bounding boxes, drawing and :yref:`VTKRecorder` output are those of :yref:`Box`.)""",
		/*attrs*/,
		/*ctor*/ createIndex();
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RdemBlock, Box);
};
REGISTER_SERIALIZABLE(RdemBlock);

} // namespace yade
