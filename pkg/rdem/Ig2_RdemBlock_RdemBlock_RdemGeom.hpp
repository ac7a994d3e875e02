/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <lib/base/openmp-accu.hpp>
#include <core/Dispatching.hpp>
#include <pkg/rdem/RdemBlock.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemSharedState.hpp>
#include <pkg/rdem/math/BlockGeometry.hpp>

namespace yade {

/// A pair of blocks the collider found near each other but that are apart, and how long they stay so.
class RdemGap : public IGeom {
public:
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemGap,IGeom,R"""(Certificate of a pair of :yref:`RdemBlock` that the collider found near each other (their bounding boxes overlap) but that are apart: the geometry of a potential, not real, interaction (it has no physics), made by :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` with :yref:`skipApart<Ig2_RdemBlock_RdemBlock_RdemGeom::skipApart>`.

The blocks cannot overlap before the projections of both on one separating axis have grown by the slack $s$ (``rdem::separationSlack``), and every point of a block moves at most its travel, recorded by :yref:`RdemContactGate` (``rdem::rigidTravel`` summed over steps). The functor tests the pair again only once the travels $T_1+T_2$ of its two blocks reach ``reach`` $=T_1+T_2+s$ at the time of the certificate. Pairs that only touch (grid neighbours along an edge or at a corner: slack below the margin, no certificate) keep the face axis that separated them (``witness``), tested alone first at the next step (``rdem::faceAxisOverlap``, [Rabbitz1994]_). Not saved: a loaded scene tests every pair again.)""",
		((Real,reach,0,(Attr::noSave|Attr::readonly),"Summed travel of the two blocks up to which they stay apart [m]."))
		((long,epoch,-1,(Attr::noSave|Attr::readonly),"The travel record the certificate refers to (-1: none, the pair is tested)."))
		((int,witness,-1,(Attr::noSave|Attr::readonly),"The face axis along which the blocks' projections overlapped least when last tested in full (0–2: body 1's axes, 3–5: body 2's), tested first at the next step; -1: none."))
		,
		/* ctor */ createIndex();
		,
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RdemGap, IGeom);
};
REGISTER_SERIALIZABLE(RdemGap);

/// Bonds face-adjacent blocks (on utils.createInteraction) and finds contacts between blocks that are not bonded.
class Ig2_RdemBlock_RdemBlock_RdemGeom : public IGeomFunctor {
public:
	bool go(const shared_ptr<Shape>&       shape1,
	        const shared_ptr<Shape>&       shape2,
	        const State&                   state1,
	        const State&                   state2,
	        const Vector3r&                shift2,
	        const bool&                    force,
	        const shared_ptr<Interaction>& I) override;
	/// Throws std::invalid_argument (Python: ValueError) for segmentsPerEdge < 1, contactSamplesPerEdge < 0, a negative
	/// bondGapTolerance, prefetchDistance < -1, or a patch tolerance outside its range.
	void postLoad(Ig2_RdemBlock_RdemBlock_RdemGeom&);
	/* Separating-axis tests saved so far by RdemGap certificates, summed over threads. Not an attribute: YADE's
	   attribute macros instantiate boost::python::extract<OpenMPAccumulator<…>>, which gcc 12 flags with
	   -Wmaybe-uninitialized (YADE's own HertzMindlin.hpp and ViscoelasticCapillarPM.hpp give the same warning). */
	OpenMPAccumulator<Real> skippedTests;
	Real                    skippedTestsPy() const { return skippedTests.get(); }
	/// Pairs found apart by their witness axis alone (RdemGap::witness), summed over threads; not an attribute (above).
	OpenMPAccumulator<Real> witnessTests;
	Real                    witnessTestsPy() const { return witnessTests.get(); }
	/// The sample grid of sampled contacts: contactSamplesPerEdge, or segmentsPerEdge if that is 0.
	int contactSamples() const { return contactSamplesPerEdge > 0 ? contactSamplesPerEdge : segmentsPerEdge; }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ig2_RdemBlock_RdemBlock_RdemGeom,IGeomFunctor,R"""(Geometry functor of two :yref:`RdemBlock`, producing :yref:`RdemGeom`.

*Bonding.* Called through ``utils.createInteraction`` (``force=True``) on two blocks whose faces are parallel, aligned and within ``bondGapTolerance``, it cuts the shared rectangle into ``segmentsPerEdge``² segments and fixes their centres as material points of both blocks (paper §3.1, Fig. 2a): the face is stored in both body frames (:yref:`RdemGeom`). Blocks that share no face make ``createInteraction`` fail. Afterwards, every step, it computes the bond's current face normal and the relative displacements of the segments' material points from the blocks' states (:yref:`RdemGeom.normal`; paper eq. 14), which :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` turns into forces.

*Face-to-face contact.* For pairs found by the collider (not bonded) that overlap with two faces meeting face to face (outward normals antiparallel within ``patchAngleTolerance``), with :yref:`persistentContacts<Ig2_RdemBlock_RdemBlock_RdemGeom::persistentContacts>` on (the default), the two faces are clipped against each other once (``rdem::facePatch``: Sutherland-Hodgman clipping [SutherlandHodgman1974]_ in body 1's face plane; :ref:`theory §4.3 <rdem-theory-4-3>`) and the patch gets $(m+1)\times(m+1)$ contact springs at fixed material points of both blocks (trapezoid nodes; the vertices of cells the patch's edge cuts; tributary areas and their first moments exact), stored in :yref:`RdemGeom.patch` and updated every step as a bond's segments, with their history (shear elongation) by spring. The patch is derived again only when the blocks have moved relative to each other, at any of their points, by more than ``patchTravelTolerance`` times the smaller half-extent (``rdem::rigidTravel`` in body 1's frame), the springs' history (their compression, shear elongation and dashpot force) passing to the nearest new springs; when the faces no longer meet, the contact is sampled. Each step of a persistent contact costs a relative-travel bound and its springs, instead of the separating-axis test and the sample grids.

*Sampled contact.* For other pairs found by the collider (not bonded), a separating-axis test first discards blocks that are apart or only touch; otherwise the pair's normal is the face axis of least overlap (blended within 1 %), and the trapezoid sample grid of each block's faces that face the other is tested against it (depth: distance to travel along the normal to leave the other block; :ref:`theory §4 <rdem-theory-4>`). Bonded pairs are never sampled: their broken segments are the paper's contact springs. A bond whose segments are all broken and whose blocks have slid apart is turned into a sampled contact by :yref:`Law2_RdemGeom_RdemPhys_FaceSprings`.

Not for periodic cells with shear (``shift2`` of the cell is honoured, the cell's shear is not).)""",
		((int,segmentsPerEdge,2,Attr::triggerPostLoad,"$n$: each bonded face is cut into $n\\times n$ segments (paper: 4 springs per face, $n=2$); also the density of the contact sample grid. $n\\ge 1$."))
		((int,contactSamplesPerEdge,1,Attr::triggerPostLoad,"$m$: the sample grid of sampled contacts (blocks that are not bonded) is $(m+1)\\times(m+1)$ points per face, trapezoid weights; 0: $m$ = ``segmentsPerEdge``. $m=1$ (default) samples the vertices, as the contacts of the distinct element codes (UDEC, 3DEC, [Cundall1988]_): for rigid blocks the forces at the corners of a flat contact span every resultant it can carry, and rocking impacts follow Housner's angular momentum balance about the new corner ([Housner1963]_: the energy kept through an impact within 3.4 % of $\\eta^2$ for $h/b$ = 2.5 to 20), while samples inside a face store impact energy in their springs and give it back as the block rolls onto the new corner (+6 to +8 % with 3 to 9 samples per edge). Where two blocks overlap and no vertex of either is inside the other (faces that cross), the contact samples the grid of ``segmentsPerEdge`` instead. $m\\ge 0$."))
		((Real,bondGapTolerance,1e-6,Attr::triggerPostLoad,"Largest gap or overlap between two faces that are bonded, relative to the smaller half-extent of the two blocks."))
		((shared_ptr<RdemJoint>,joint,,,"The :yref:`RdemJoint` given to the bonds made from now on (by ``utils.createInteraction``), or None (default): blocks bonded directly. ``rdem.bond(..., joint=...)`` sets it for its bonds and resets it."))
		((bool,skipApart,true,,"Test a pair of blocks found apart again only once they may have moved enough to touch (:yref:`RdemGap`, with the travel recorded by :yref:`RdemContactGate`): after the first crack, the collider's pairs of grid neighbours that are apart by a strain-sized gap cost a few loads per step instead of a separating-axis test. A pair that only touches (no certificate) is tested first along the face axis that separated it in the last step (:yref:`RdemGap.witness`): one overlap instead of two rotation matrices and the separating-axis test. Likewise a sampled contact tests only its samples that lay within 2 % of the smaller half-extent of the other block when last all were tested, until the blocks may have moved that far (``rdem::sampleOutside``): grid neighbours strained into each other along an edge test the samples of that edge, not every face. Exact: the pairs and samples skipped are those the tests would find apart, so results do not depend on it."))
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`): the blocks' travel, recorded by :yref:`RdemContactGate` (handed by ``rdem.engines()``; None: the law's, taken at the first step; pairs are not skipped without it)."))
		((bool,clipSampleAreas,false,,"A sampled contact's face sample acts over the part of its tributary rectangle across which the other block lies (``rdem::tributaryCover``, along both axes of its face, the other block's extent projected on them): springs and dashpots act per unit contact area (paper §3.1, eq. 13), and the part of a sample's area beyond the other block's outline is not in contact. A sample with none is not in contact. Without it (the default, with which the paper's cube and the walls were validated) a sample takes its whole tributary area wherever it is inside the other block: the corner of a large face resting on the edge of a small block takes a quarter of the large face, halved, with its eq. 13 dashpot (the roof-slab corners on the top bricks of ``scripts/building.py --big``, which sets this: 0.0409 m² on a brick of 0.0325 m², which made its cracked step 0.96 µs instead of 8 µs); the grid neighbours of the paper's cube, strained into each other along an edge, touch through such areas after its first crack (with the clip, 1358 springs broke at once at the first break and its tensile failure, where the apparent Poisson ratio departs, came at 17.36 MPa instead of 18.31 MPa, with 1497 broken springs at 0.25 mm instead of 1642; :ref:`theory §4 <rdem-theory-4>`, *Clipped areas*)."))
		((bool,persistentContacts,true,,"Blocks whose faces meet face to face get a persistent patch of contact springs (``rdem::facePatch``, above) instead of sample points tested every step (the default); False: every contact is sampled (the reference the patch is tested against, tests/yade/test_persistent_contact.py)."))
		((Real,patchAngleTolerance,5e-5,Attr::triggerPostLoad,"Two faces meet face to face when their outward normals satisfy $\\mathbf{n}_1\\cdot\\mathbf{n}_2\\le-(1-\\epsilon_\\theta)$: the default $5\\times10^{-5}$ is an angle of 0.01 rad, across which the depth of a face of size $L$ varies by $0.01L$, far beyond an elastic contact's overlap: a tilted block touches by an edge, which the patch's springs on the edge also carry, and the force direction differs from the sampled contact's by at most half that angle. $0<\\epsilon_\\theta<1$."))
		((Real,patchTravelTolerance,1e-3,Attr::triggerPostLoad,"A patch holds while no point of body 2 has moved relative to body 1 by more than this times the smaller half-extent of the two blocks; beyond, it is derived again. The patch's boundary is then off by at most that distance, and its area by at most the perimeter times it: $4\\epsilon_T h_{max}/h_{min}$ relative for cubes, 0.4 % at the default $10^{-3}$, while a block sliding at 1 m/s at a step of $10^{-6}$ s keeps its patch for ten steps of a 2 cm block. $0<\\epsilon_T\\le0.1$."))
		((int,prefetchDistance,-1,Attr::triggerPostLoad,"How many interactions ahead of the one being processed this functor asks the processor to fetch the data of (interaction, geometry, physics, bodies and their states, in stages; ``pkg/rdem/RdemPrefetch.hpp``), to hide the memory latency of scenes larger than the cache. $-1$ (default): automatic, 8 once the interactions' data exceed the last-level cache, else off; 0: off; $>0$: always, at this distance. A hint only: results do not depend on it. $\\ge -1$."))
		,
		/* ctor */
		,
		.add_property("skippedTests",&Ig2_RdemBlock_RdemBlock_RdemGeom::skippedTestsPy,"Separating-axis tests saved so far by :yref:`RdemGap` certificates (pairs found apart and not tested again in a step), counted as a real number; not saved with the scene.")
		.add_property("witnessTests",&Ig2_RdemBlock_RdemBlock_RdemGeom::witnessTestsPy,"Pairs found apart so far by their :yref:`RdemGap.witness` axis alone (no full separating-axis test in that step), counted as a real number; not saved with the scene.")
	);
	// clang-format on
	FUNCTOR2D(RdemBlock, RdemBlock);
	DEFINE_FUNCTOR_ORDER_2D(RdemBlock, RdemBlock);
	DECLARE_LOGGER;

private:
	/* Whether I is a pair found apart (an RdemGap) that is still apart in this step, without the full test: its
	   certificate holds for the blocks' travel (counted in skippedTests), or its witness axis still separates the blocks
	   (half-extents hA, hB) by more than the round-off (rdem::faceAxisOverlap, faceAxisRoundOff), so that blocksOverlap
	   would return false (counted in witnessTests; then, with the travel recorded, a certificate of the slack that axis
	   leaves if it exceeds the margin). */
	bool knownApart(Interaction& I, const Vector3r& hA, const Vector3r& hB, const State& s1, const State& s2, const Vector3r& shift2);
	/// Bonding (utils.createInteraction): the shared face of A and B cut into segmentsPerEdge² segments; false if none.
	bool bond(const rdem::OrientedBlock<Real>& A, const rdem::OrientedBlock<Real>& B, const shared_ptr<Interaction>& I) const;
	/// A pair that is not a real interaction: a new contact if samples of either block lie inside the other; else
	/// false, with a new certificate (RdemGap) if the blocks are apart and skipApart is on.
	bool
	findContact(const rdem::OrientedBlock<Real>& A, const rdem::OrientedBlock<Real>& B, const State& s1, const State& s2, const shared_ptr<Interaction>& I);
	/* The sample certificate of the sampled contact I (blocks of pair, geometry g; RdemGeom::nearSamples) if it holds for
	   the blocks' travel in this step, else nullptr: every sample is tested, and, with skipApart and the travel recorded,
	   a new certificate made for the next steps, of the samples less than sampleSkin times the smaller half-extent
	   outside the other block (rdem::sampleOutside). */
	const vector<uint64_t>* nearSamples(const rdem::BlockPair<Real>& pair, const Interaction& I, RdemGeom& g) const;
	/// Skin of a sample certificate, relative to the smaller half-extent of the two blocks: a sample of a pair of 3 cm
	/// blocks is tested again once it may have come within 0.6 mm of the other block.
	static constexpr Real sampleSkin = 0.02;
	/// Whether the blocks' states are within g.patchTravel of relative travel of the configuration in which g's patch was
	/// last derived, or found not to exist (a sampled contact with g.patchTravel > 0: see markDerived).
	bool withinPatchTravel(const RdemGeom& g, const State& s1, const State& s2, const Vector3r& shift2) const;
	/// Records the configuration of blocks A, B (orientations q1, q2) in g as the one in which the patch was derived,
	/// or found not to exist: it is not derived again before the blocks have moved by patchTravel relative to each other.
	void
	markDerived(const rdem::OrientedBlock<Real>& A, const rdem::OrientedBlock<Real>& B, const Quaternionr& q1, const Quaternionr& q2, RdemGeom& g) const;
	/// Adds the elastic energy [J] of contact springs dropped from p in this step while loaded to what the law books as
	/// rdemContactRelease (RdemPhys::releasedEnergy; with O.trackEnergy only).
	void releaseSprings(RdemPhys& p, Real energy) const;
	/// (Re)derives g's face-to-face patch (rdem::facePatch) for the blocks A, B with orientations q1, q2; false, with g
	/// unchanged, if their faces do not meet (or, for a new contact, p null, if no spring overlaps yet). With p, the history
	/// of the old patch or of the last step's samples passes to the new springs (handOver).
	bool derivePatch(
	        const rdem::OrientedBlock<Real>& A, const rdem::OrientedBlock<Real>& B, const Quaternionr& q1, const Quaternionr& q2, RdemGeom& g, RdemPhys* p)
	        const;
};
REGISTER_SERIALIZABLE(Ig2_RdemBlock_RdemBlock_RdemGeom);

} // namespace yade
