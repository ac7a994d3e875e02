/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <lib/serialization/Serializable.hpp>
#include <core/Body.hpp>

namespace yade {

class RdemGeom;
class RdemPhys;

/// The record of a bond that Law2_RdemGeom_RdemPhys_FaceSprings released: where its face was and what broke each segment.
class RdemReleasedBond : public Serializable {
public:
	/// The record of the bond of geometry g and physics p between bodies id1 and id2, released in step iter.
	static shared_ptr<RdemReleasedBond> of(Body::id_t id1, Body::id_t id2, const RdemGeom& g, const RdemPhys& p, long iter);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemReleasedBond,Serializable,R"""(A bond released by :yref:`Law2_RdemGeom_RdemPhys_FaceSprings`: every segment of its face had broken and none was in contact, so the interaction was reset and the pair's later contacts are sampled (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom`). The crack stays in the material: this record keeps its face in body 1's frame, as :yref:`RdemGeom` had it, and what broke each segment, for the viewer (:yref:`GlExtra_RdemReleasedBonds`) and post-processing (``rdem.measure.brokenSegments``). Listed in :yref:`Law2_RdemGeom_RdemPhys_FaceSprings.releasedBonds`.)""",
		((Body::id_t,id1,Body::ID_NONE,,"Body 1 of the bond."))
		((Body::id_t,id2,Body::ID_NONE,,"Body 2 of the bond."))
		((long,iter,-1,,"Step in which the bond was released."))
		((int,samplesPerEdge,0,,"$n$: segments per face edge (:yref:`RdemGeom.samplesPerEdge`)."))
		((Vector3r,faceCentre1,Vector3r::Zero(),,"Centre of the face in body-1 frame [m] (:yref:`RdemGeom.faceCentre1`)."))
		((Vector3r,segNormal1,Vector3r::Zero(),,"Outward unit normal of body 1's face, in body-1 frame (:yref:`RdemGeom.segNormal1`)."))
		((Vector3r,segHalf1u,Vector3r::Zero(),,"Half-size vector of a segment along the face's first axis, body-1 frame [m] (:yref:`RdemGeom.segHalf1u`)."))
		((Vector3r,segHalf1v,Vector3r::Zero(),,"Half-size vector along the second axis, body-1 frame [m] (:yref:`RdemGeom.segHalf1v`)."))
		((vector<int>,segState,,,"Per segment $k=in+j$: what broke it, 1 tension (eq. 15) or 2 shear (eq. 16): :yref:`RdemPhys.segState` at the release."))
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(RdemReleasedBond);

} // namespace yade
