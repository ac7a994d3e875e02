/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once
#ifdef YADE_OPENGL

#include <pkg/common/GLDrawFunctors.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/math/CrackDisplay.hpp>

namespace yade {

/// Draws the broken (and crushed) segments of a bond in YADE's 3D view, coloured by failure mode (rdem::segmentMark).
class Gl1_RdemPhys : public GlIPhysFunctor {
public:
	void go(const shared_ptr<IPhys>&, const shared_ptr<Interaction>&, const shared_ptr<Body>&, const shared_ptr<Body>&, bool wire) override;
	using Marks = vector<rdem::SegmentMark>;
	/* Draws, where the renderer shows body b1, the quads of the marked segments k = i n + j of a bond face of n×n
	   segments, centre c and segment half-size vectors a, b in body 1's frame [m] (rdem::segmentQuad), in the colour of
	   their mark, outlined in contactColor where closed[k] (a closed crack); also for released bonds
	   (GlExtra_RdemReleasedBonds). */
	static void drawFace(
	        const Scene*        scene,
	        const Body&         b1,
	        const Vector3r&     c,
	        const Vector3r&     a,
	        const Vector3r&     b,
	        int                 n,
	        const Marks&        marks,
	        const vector<bool>& closed,
	        bool                wire);
	// clang-format off
	YADE_CLASS_BASE_DOC_STATICATTRS(Gl1_RdemPhys,GlIPhysFunctor,R"""(Renders the bonded segments of :yref:`RdemPhys` that have failed: each broken or crushed segment of a bond's shared face (:yref:`RdemGeom`, $n\times n$ segments, the paper's §3.1) is a quad on body 1's face, filled with the colour of what broke it, tension (eq. 15) or shear (eq. 16), or crushed it (compression cap of the softening springs, [LourencoRots1997]_); a broken segment whose contact spring touches and carries compression ($\sigma<0$, :yref:`RdemPhys.segSigma`) is outlined in ``contactColor`` (a closed crack). Intact segments are not drawn.

Drawn only with :yref:`OpenGLRenderer.intrPhys`; the blocks themselves are :yref:`Box` es drawn by :yref:`Gl1_Box` (wire blocks, :yref:`OpenGLRenderer.wire`, let the cracks inside the specimen show). Quads follow body 1 as the renderer displays it (its :yref:`OpenGLRenderer.dispScale`). Contacts of pairs that are not bonded (:yref:`RdemGeom.samplePoint`) are not drawn: their arrays are rebuilt every step while the view draws. Colours are RGB in $[0,1]$, drawn without lighting, so that a picture shows them exactly.)""",
		((Vector3r,tensionColor,Vector3r(0.95,0.1,0.1),,"Fill of segments broken in tension (eq. 15)."))
		((Vector3r,shearColor,Vector3r(0.1,0.35,1),,"Fill of segments broken in shear (Mohr–Coulomb, eq. 16)."))
		((Vector3r,crushingColor,Vector3r(1,0.75,0),,"Fill of intact segments crushed by the compression cap ($\\kappa>0$, :yref:`RdemPhys.segCrush`, softening only)."))
		((Vector3r,contactColor,Vector3r(0.1,0.9,0.2),,"Outline of broken segments whose contact spring carries compression (eq. 13)."))
		((Real,fill,0.9,,"Fraction of a segment's edge lengths its quad covers, about the segment's centre (less than 1 leaves gaps that show the segments); clamped to $[0.05, 1]$."))
		((Real,lineWidth,2,,"Width of outlines (and of quads with :yref:`OpenGLRenderer.intrWire`) [px]."))
	);
	// clang-format on
	RENDERS(RdemPhys);
};
REGISTER_SERIALIZABLE(Gl1_RdemPhys);

} // namespace yade

#endif // YADE_OPENGL
