/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/IGeom.hpp>

namespace yade {

/* Geometry of a pair of blocks: the bonded segments of their shared face (fixed material points in both body frames)
   and, each step, the contact sample points of one block that lie inside the other. */
class RdemGeom : public IGeom {
public:
	/// Number of bonded segments (0 for a pure contact).
	size_t nSegments() const { return segArea.size(); }
	/// Clear the per-step list of contact samples.
	void clearSamples();
	/// A bonded segment whose material points are p1, p2 (body frames) in the frame (R1, R2, dx = x₂ - x₁) of its pair:
	/// d = P₂ - P₁, the relative displacement of the two points (paper eq. 14), and r₂ = C - x₂, the offset of the
	/// segment's current point C = (P₁ + P₂)/2 from body 2's centroid [m].
	static void
	segmentKinematics(const Matrix3r& R1, const Matrix3r& R2, const Vector3r& dx, const Vector3r& p1, const Vector3r& p2, Vector3r& d, Vector3r& r2)
	{
		const Vector3r a = R1 * p1, b = R2 * p2; // P₁ - x₁, P₂ - x₂
		d  = dx + b - a;
		r2 = b - d / 2;
	}
	/// Segment i in the pair's current frame (pos1, pos2, rot1, rot2), see the static version.
	void segmentKinematics(size_t i, Vector3r& d, Vector3r& r2) const { segmentKinematics(rot1, rot2, pos2 - pos1, segPoint1[i], segPoint2[i], d, r2); }
	/// Python: d = P₂ - P₁ of every bonded segment in the current frame [m]; empty while the Ig2 has set no frame.
	vector<Vector3r> segDispPy() const;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemGeom,IGeom,R"""(Geometry of a pair of :yref:`RdemBlock` (built by :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom`).

*Bonded segments.* When the pair is bonded (created with ``utils.createInteraction`` on face-adjacent blocks), the shared face is cut into $n\times n$ segments (paper §3.1, Fig. 2a). The centre of each is stored as a material point of both blocks (``segPoint1``, ``segPoint2`` in body frames). Each step :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` updates the pair's frame (``pos1``, ``pos2``, ``rot1``, ``rot2``, ``normal``), from which the relative displacement $\mathbf{d}=\mathbf{P}_2-\mathbf{P}_1$ of the two material points follows where the law needs it (no per-segment array is written and read back every step); it is split along the current face normal $\mathbf{n}$ (from body 1 to body 2): $u_n=\mathbf{d}\cdot\mathbf{n}$ (positive = opening, the paper's tension-positive convention of eq. 14) and $\mathbf{u}_s=\mathbf{d}-u_n\mathbf{n}$. Rigid motions of the pair give $\mathbf{d}=0$ exactly, at any rotation.

*Sampled contacts.* Blocks that are not bonded interact where sample points of one block's faces (an $(n+1)\times(n+1)$ trapezoid grid per face, corners and edges included) have entered the other block: one normal for the pair (the face axis of least overlap), depth = distance to travel along it to leave the other block, weight = trapezoid area × cosine between the sampled face and the normal, halved because both blocks are sampled; plus one edge-to-edge contact when two edges cross (separating-axis test); see doc/theory.md.)""",
		((int,samplesPerEdge,2,,"$n$: segments per face edge of the bond, and sample-grid density of contacts."))
		((Real,ell1,0,,"Distance from the centroid of body 1 to the bonded (or first contacted) face, $\\ell_A$ of eq. 12 [m]."))
		((Real,ell2,0,,"Distance from the centroid of body 2 to its face, $\\ell_B$ of eq. 12 [m]."))
		((Vector3r,segNormal1,Vector3r::Zero(),,"Outward unit normal of body 1's bonded face, in body-1 frame."))
		((Vector3r,segNormal2,Vector3r::Zero(),,"Outward unit normal of body 2's bonded face, in body-2 frame."))
		((Vector3r,segTangent1,Vector3r::Zero(),,"First in-plane axis of the bonded face (body-1 frame); the second is ``segNormal1`` × ``segTangent1``."))
		((Vector2r,segHalfSizes,Vector2r::Zero(),,"Half-sizes of a segment along the two in-plane axes [m]; a broken segment is in contact only while its material points have slid less than the smaller one."))
		((vector<Vector3r>,segPoint1,,,"Segment centres (material points) in body-1 frame [m]."))
		((vector<Vector3r>,segPoint2,,,"The same points in body-2 frame [m]."))
		((vector<Real>,segArea,,,"Segment areas [m²]."))
		((Vector3r,normal,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"Current unit normal of the bonded face, from body 1 to body 2 (global)."))
		((Vector3r,pos1,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"Current frame of a bonded pair: centroid $\\mathbf{x}_1$ of body 1 [m]."))
		((Vector3r,pos2,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"Current frame of a bonded pair: centroid $\\mathbf{x}_2$ of body 2, with the periodic cell shift [m]."))
		((Matrix3r,rot1,Matrix3r::Identity(),(Attr::noSave|Attr::readonly),"Current frame of a bonded pair: rotation of body 1 (body to global)."))
		((Matrix3r,rot2,Matrix3r::Identity(),(Attr::noSave|Attr::readonly),"Current frame of a bonded pair: rotation of body 2 (body to global)."))
		((vector<int>,sampleKey,,(Attr::noSave|Attr::readonly),"Per active contact sample: which sample it is (a stable index, for the shear history)."))
		((vector<Vector3r>,samplePoint,,(Attr::noSave|Attr::readonly),"Per active contact sample: contact point (global) [m]."))
		((vector<Vector3r>,sampleNormal,,(Attr::noSave|Attr::readonly),"Per active contact sample: unit normal from body 1 to body 2 (global)."))
		((vector<Vector3r>,sampleVel,,(Attr::noSave|Attr::readonly),"Per active contact sample: velocity of body 2 relative to body 1 at the point [m/s]."))
		((vector<Real>,sampleDepth,,(Attr::noSave|Attr::readonly),"Per active contact sample: penetration depth (>0) [m]."))
		((vector<Real>,sampleArea,,(Attr::noSave|Attr::readonly),"Per active contact sample: tributary area, trapezoid weight times the cosine between the sampled face and the contact normal, halved because both blocks are sampled [m²]."))
		,
		/* ctor */ createIndex();
		,
		.add_property("segDisp",&RdemGeom::segDispPy,"Relative displacement $\\mathbf{P}_2-\\mathbf{P}_1$ of each bonded segment's material points in the current frame (global) [m]; empty until the geometry functor has set the frame (after ``O.load``, until the next step).")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RdemGeom, IGeom);
};
REGISTER_SERIALIZABLE(RdemGeom);

} // namespace yade
