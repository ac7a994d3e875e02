/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/IGeom.hpp>
#include <core/State.hpp>
#include <pkg/rdem/RdemJoint.hpp>
#include <pkg/rdem/math/FacePatch.hpp>
#include <pkg/rdem/math/SegmentGrid.hpp>
#include <cstdint>

namespace yade {

/* Geometry of a pair of blocks: the bonded segments of their shared face (fixed material points in both body frames)
   and, each step, the contact sample points of one block that lie inside the other. */
class RdemGeom : public IGeom {
public:
	/// Number of bonded segments (0 for a pure contact).
	size_t nSegments() const { return bonded ? size_t(samplesPerEdge * samplesPerEdge) : 0; }
	/// Grid coordinates (s, r) of bonded segment k = i n + j (rdem::segmentCoordinate).
	Vector2r segmentCoordinates(size_t k) const;
	/// Area of each bonded segment [m²].
	Real segmentArea() const { return 4 * math::sqrt(segHalf1u.squaredNorm() * segHalf1v.squaredNorm()); }
	/// Half-sizes (h₁, h₂) of a bonded segment along its two in-plane axes [m].
	Vector2r segHalfSizes() const { return Vector2r(segHalf1u.norm(), segHalf1v.norm()); }
	/// First in-plane axis of the bonded face in body-1 frame (unit).
	Vector3r segTangent1() const { return segHalf1u.normalized(); }
	/// Segment kinematics of the bond for the current rotations R1, R2 of its blocks and dx = x₂ - x₁ (rdem::bondKinematics).
	rdem::BondKinematics<Real> kinematics(const Matrix3r& R1, const Matrix3r& R2, const Vector3r& dx) const
	{
		return rdem::bondKinematics<Real>(R1, R2, dx, faceCentre1, segHalf1u, segHalf1v, faceCentre2, segHalf2u, segHalf2v);
	}
	/// Sets normal and kin for this step from the current rotations R1, R2 of the blocks and dx = x₂ - x₁ (a bond only).
	void updateBond(const Matrix3r& R1, const Matrix3r& R2, const Vector3r& dx)
	{
		normal = (R1 * segNormal1 - R2 * segNormal2).normalized();
		kin    = kinematics(R1, R2, dx);
	}
	/* A bond's segment kinematics in this step (d = P₂ - P₁ and the arms, affine in the grid coordinates; paper eq. 14),
	   set with normal by Ig2_RdemBlock_RdemBlock_RdemGeom, read by the law in the same step; not saved. Declared
	   before the attributes, so that it lies with what the law reads first (RdemPrefetch: the object's head). */
	rdem::BondKinematics<Real> kin;
	/// Clear the per-step list of contact samples.
	void clearSamples();
	/// Number of springs of a face-to-face contact patch (0: none; the contact is sampled, or the pair is a bond).
	size_t nPatch() const { return patch.size() / rdem::PatchSprings<Real>::stride; }
	/// The springs of the patch as the law reads them (rdem::PatchSprings: the layout of ``patch``).
	rdem::PatchSprings<Real> patchSprings() const { return rdem::PatchSprings<Real>(patch); }
	/// Forget the patch and the configuration it was derived in: the contact is sampled from now on.
	void clearPatch()
	{
		patch.clear();
		patchArea   = 0;
		patchTravel = 0;
	}
	/// Python: the patch springs' material points in body-1 (body-2) frame [m] and their areas [m²].
	vector<Vector3r> patchPoints1() const;
	vector<Vector3r> patchPoints2() const;
	vector<Real>     patchAreas() const;
	/// Segment centres of a bond in body-1 (body-2) frame [m], and their areas [m²] (empty for a pure contact).
	vector<Vector3r> segmentPoints1() const;
	vector<Vector3r> segmentPoints2() const;
	vector<Real>     segmentAreas() const { return vector<Real>(nSegments(), segmentArea()); }
	/// Python: d = P₂ - P₁ of every bonded segment for the given states of the two blocks [m].
	vector<Vector3r> segDispPy(const shared_ptr<State>& s1, const shared_ptr<State>& s2) const;
	/* The attributes are laid out in memory in this order: what a bond's law reads every step (the face in both block
	   frames, ``normal``) comes first, in as few cache lines as possible. */
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemGeom,IGeom,R"""(Geometry of a pair of :yref:`RdemBlock` (built by :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom`).

*Bonded segments.* When the pair is bonded (created with ``utils.createInteraction`` on face-adjacent blocks), the shared face is cut into $n\times n$ equal segments (paper §3.1, Fig. 2a). The face is stored in both body frames: its centre $\mathbf{c}$ (``faceCentre1``, ``faceCentre2``), its outward normal (``segNormal1``, ``segNormal2``) and the half-size vectors $\mathbf{u}=h_1\mathbf{t}_1$, $\mathbf{v}=h_2\mathbf{t}_2$ of a segment along the face's in-plane axes (``segHalf1u``, ``segHalf1v``, ``segHalf2u``, ``segHalf2v``). Segment $k=in+j$ has its centre, a material point of both blocks, at $\mathbf{c}+s_i\mathbf{u}+s_j\mathbf{v}$, $s_i=2i+1-n$ (``segPoint1``, ``segPoint2``, computed). :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` computes each step, from the blocks' current states, the current face normal $\mathbf{n}$ (from body 1 to body 2, ``normal``) and the relative displacement $\mathbf{d}=\mathbf{P}_2-\mathbf{P}_1$ of the two material points, affine in $(s_i,s_j)$ (its three coefficients, not a per-segment array); :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` splits $\mathbf{d}$ along $\mathbf{n}$: $u_n=\mathbf{d}\cdot\mathbf{n}$ (positive = opening, the paper's tension-positive convention of eq. 14) and $\mathbf{u}_s=\mathbf{d}-u_n\mathbf{n}$. Rigid motions of the pair give $\mathbf{d}=0$ exactly, at any rotation.

*Face-to-face contacts.* Blocks that are not bonded and whose faces meet face to face (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom::persistentContacts`) touch over a patch, the intersection of the two faces (``rdem::facePatch``): its contact springs are fixed material points of both blocks, found once and kept, as a bond's segments (``patch``; the faces' outward normals in ``segNormal1``, ``segNormal2``, and this step's ``normal``); the patch is derived again only once the blocks have moved relative to each other by more than ``patchTravel`` since ``patchRelPos``, ``patchRelOri``.

*Sampled contacts.* Other blocks that are not bonded interact where sample points of one block's faces (an $(n+1)\times(n+1)$ trapezoid grid per face, corners and edges included) have entered the other block: one normal for the pair (the face axis of least overlap), depth = distance to travel along it to leave the other block, weight = trapezoid area × cosine between the sampled face and the normal, halved because both blocks are sampled; plus one edge-to-edge contact when two edges cross (separating-axis test); see :ref:`theory §4 <rdem-theory-4>`.)""",
		((int,samplesPerEdge,2,,"$n$: segments per face edge of the bond, and sample-grid density of contacts; copied from :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom.segmentsPerEdge` when the bond is made (the same $n$: a segment is the patch of one spring, a sample its point; the name stays for saved scenes)."))
		((bool,bonded,false,,"Whether the pair is bonded: its shared face carries $n\\times n$ segments."))
		((Vector3r,segNormal1,Vector3r::Zero(),,"Outward unit normal of body 1's bonded face, in body-1 frame."))
		((Vector3r,segNormal2,Vector3r::Zero(),,"Outward unit normal of body 2's bonded face, in body-2 frame."))
		((Vector3r,faceCentre1,Vector3r::Zero(),,"Centre of the bonded face in body-1 frame [m]."))
		((Vector3r,faceCentre2,Vector3r::Zero(),,"Centre of the bonded face in body-2 frame [m]."))
		((Vector3r,segHalf1u,Vector3r::Zero(),,"Half-size vector $h_1\\mathbf{t}_1$ of a bonded segment along the face's first in-plane axis, in body-1 frame [m]."))
		((Vector3r,segHalf1v,Vector3r::Zero(),,"Half-size vector $h_2\\mathbf{t}_2$ along the second axis $\\mathbf{t}_2=\\mathbf{n}_1\\times\\mathbf{t}_1$ ($\\mathbf{n}_1$ = ``segNormal1``), in body-1 frame [m]."))
		((Vector3r,segHalf2u,Vector3r::Zero(),,"``segHalf1u`` in body-2 frame [m]."))
		((Vector3r,segHalf2v,Vector3r::Zero(),,"``segHalf1v`` in body-2 frame [m]."))
		((Vector3r,normal,Vector3r::Zero(),Attr::readonly,"Unit normal of the bonded face in this step, from body 1 to body 2 (global): $(\\mathbf{R}_1\\mathbf{n}_1-\\mathbf{R}_2\\mathbf{n}_2)/|\\ldots|$ with ``segNormal1``, ``segNormal2`` turned by the blocks' rotations; zero until the geometry functor has run (saved, as the contact samples: what :yref:`RdemTimeStepper` reads of the last step)."))
		((vector<Real>,patch,,,"The springs of a face-to-face contact patch, 7 numbers each (``rdem::PatchSprings``): material point in body-1 frame, relative to the centroid (3) [m], the matching point on body 2's face in body-2 frame (3) [m], tributary area [m²]; empty for a bond or a sampled contact. Python: ``patchPoint1``, ``patchPoint2``, ``patchAreas``."))
		((Real,patchArea,0,,"Area of the face-to-face contact patch, the intersection of the two faces in body 1's face plane (shoelace formula) [m²]; 0: no patch."))
		((Vector3r,patchRelPos,Vector3r::Zero(),,"Centroid of body 2 in body 1's frame when the patch was derived, $\\mathbf{R}_1^T(\\mathbf{x}_2-\\mathbf{x}_1)$ [m]."))
		((Quaternionr,patchRelOri,Quaternionr::Identity(),,"Orientation of body 2 relative to body 1 when the patch was derived, $q_1^{-1}q_2$."))
		((Real,patchRadius,0,,"Circumradius of body 2 about its centroid [m]: with ``patchRelPos`` and ``patchRelOri``, a bound on how far any point of body 2 has moved relative to body 1 (``rdem::rigidTravel``)."))
		((Real,patchTravel,0,,"Relative travel of the blocks up to which the patch holds [m] (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom::patchTravelTolerance` times the smaller half-extent)."))
		((Real,ell1,0,,"Distance from the centroid of body 1 to the bonded (or first contacted) face, $\\ell_A$ of eq. 12 [m]."))
		((Real,ell2,0,,"Distance from the centroid of body 2 to its face, $\\ell_B$ of eq. 12 [m]."))
		((shared_ptr<RdemJoint>,joint,,,"The joint of a bond made with a mortar joint (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom::joint`), or None: blocks bonded directly (eq. 12)."))
		((vector<int>,sampleKey,,Attr::readonly,"Per active contact sample: which sample it is (a stable index, for the shear history). The samples of the last step are saved with the scene, so that :yref:`RdemTimeStepper.estimate` right after ``O.load`` sees the contacts it saw before ``O.save``."))
		((vector<Vector3r>,samplePoint,,Attr::readonly,"Per active contact sample: contact point (global) [m]."))
		((vector<Vector3r>,sampleNormal,,Attr::readonly,"Per active contact sample: unit normal from body 1 to body 2 (global)."))
		((vector<Vector3r>,sampleVel,,Attr::readonly,"Per active contact sample: velocity of body 2 relative to body 1 at the point [m/s]."))
		((vector<Real>,sampleDepth,,Attr::readonly,"Per active contact sample: penetration depth (>0) [m]."))
		((vector<Real>,sampleArea,,Attr::readonly,"Per active contact sample: tributary area, trapezoid weight times the cosine between the sampled face and the contact normal, halved because both blocks are sampled [m²]."))
		,
		/* ctor */ createIndex();
		,
		.add_property("patchPoint1",&RdemGeom::patchPoints1,"Material points of the face-to-face patch springs in body-1 frame, relative to its centroid [m] (empty: no patch).")
		.add_property("patchPoint2",&RdemGeom::patchPoints2,"The matching points on body 2's face, in body-2 frame [m].")
		.add_property("patchAreas",&RdemGeom::patchAreas,"Tributary areas of the patch springs [m²]; they sum to ``patchArea``.")
		.add_property("segPoint1",&RdemGeom::segmentPoints1,"Centres (material points) of the bonded segments in body-1 frame [m], segment $k=in+j$ at ``faceCentre1`` $+\\,s_i$ ``segHalf1u`` $+\\,s_j$ ``segHalf1v``, $s_i=2i+1-n$.")
		.add_property("segPoint2",&RdemGeom::segmentPoints2,"The same points in body-2 frame [m].")
		.add_property("segArea",&RdemGeom::segmentAreas,"Areas of the bonded segments [m²] (all equal, $4h_1h_2$).")
		.add_property("segHalfSizes",&RdemGeom::segHalfSizes,"Half-sizes $(h_1, h_2)$ of a bonded segment [m]; a broken segment is in contact only while its material points have slid less than the smaller one.")
		.add_property("segTangent1",&RdemGeom::segTangent1,"First in-plane axis $\\mathbf{t}_1$ of the bonded face, in body-1 frame (unit).")
		.def("segDisp",&RdemGeom::segDispPy,(py::arg("state1"),py::arg("state2")),"Relative displacement $\\mathbf{P}_2-\\mathbf{P}_1$ of each bonded segment's material points (global) [m] for the given states of body 1 and body 2, e.g. ``I.geom.segDisp(O.bodies[I.id1].state, O.bodies[I.id2].state)`` (without the periodic cell shift).")
	);
	// clang-format on
	/* A sampled contact's sample certificate (Ig2_RdemBlock_RdemBlock_RdemGeom, rdem::sampleOutside): a bit per sample
	   key (bit key % 64 of word key / 64), set for the samples that may enter the other block while
	   the two blocks' travels (RdemContactGate) add up to less than sampleReach in the travel record sampleEpoch; only
	   they are tested. Not saved (a loaded scene makes it
	   again); at the end of the object, away from what a bond's law reads. */
	vector<uint64_t> nearSamples;
	Real             sampleReach = 0;
	long             sampleEpoch = -1;
	REGISTER_CLASS_INDEX(RdemGeom, IGeom);
};
REGISTER_SERIALIZABLE(RdemGeom);

} // namespace yade
