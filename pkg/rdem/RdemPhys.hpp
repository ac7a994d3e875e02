/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/IPhys.hpp>
#include <pkg/rdem/math/FaceSprings.hpp>
#include <limits>

namespace yade {

/// Springs, dashpots, strengths and per-segment state of a pair of blocks (paper §3.2-3.6).
class RdemPhys : public IPhys {
public:
	/// Number of segments whose restoring spring is intact.
	int nIntact() const;
	/* The attributes are laid out in memory in this order: what the law reads and writes for an intact bond every step
	   (stiffnesses, strengths, weights, forces, the per-segment arrays' headers) comes first, in as few cache lines as
	   possible; the contact parameters and arrays a bond uses only once broken follow. */
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemPhys,IPhys,R"""(Physics of a pair of :yref:`RdemBlock` (made by :yref:`Ip2_RdemMat_RdemMat_RdemPhys`, used by :yref:`Law2_RdemGeom_RdemPhys_FaceSprings`).

Stiffnesses and dashpot coefficients are *per unit area*; a segment or contact sample of area $A$ has spring $kA$ and dashpot $cA$. Per-segment state lives in ``segState`` (0 intact, 1 broken in tension, 2 broken in shear) and ``segShear`` (elastic shear elongation of the contact spring of a broken segment). Stresses are positive in tension (paper eq. 14).)""",
		((Real,kn,0,,"$\\bar{k}_n$, normal spring stiffness per area, eq. 12 [N/m³]."))
		((Real,ks,0,,"$\\bar{k}_s$, shear spring stiffness per area, eq. 12 [N/m³]."))
		((Real,tensileStrength,0,,"$f_t$ of the joint [Pa]."))
		((Real,cohesion,0,,"$c$ of the joint [Pa]."))
		((Real,tanFriction,0,,"$\\tan\\phi$ of the joint."))
		((Real,weightNormal,1,,"Volume weight $w_n$ of the normal restoring and contact springs of the segments (1, or set by the consistent formulation of :yref:`RdemPoissonEngine` at boundaries); forces are $w_n\\sigma A$, failure stresses stay $\\sigma$."))
		((Real,weightShear,1,,"Volume weight $w_s$ of the shear springs, as ``weightNormal``."))
		((Vector3r,force,Vector3r::Zero(),,"Total force exerted by body 1 on body 2 in the last step (global) [N]."))
		((Vector3r,torque1,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"Torque on body 1 about its centroid in the last step (global) [N·m]; kept for :yref:`RdemForceAssembler`."))
		((Vector3r,torque2,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"Torque on body 2 about its centroid in the last step (global) [N·m]."))
		((long,forceIter,-1,(Attr::noSave|Attr::readonly),"Iteration whose ``force``, ``torque1``, ``torque2`` wait for :yref:`RdemForceAssembler` (-1: applied by the law itself)."))
		((vector<int>,segState,,,"Per bonded segment: 0 intact, 1 broken in tension (eq. 15), 2 broken in shear (eq. 16)."))
		((vector<Real>,segSigma,,,"Per bonded segment: normal stress of the last step, positive in tension [Pa]."))
		((vector<Real>,segTau,,,"Per bonded segment: magnitude of the shear stress of the last step [Pa]."))
		((bool,softening,false,,"Whether the restoring springs soften (:yref:`Ip2_RdemMat_RdemMat_RdemPhys::softening`, :ref:`theory §2.1 <rdem-theory-2-1>`) instead of breaking at once (eqs. 15-16)."))
		((Real,cellCoef1,0,Attr::readonly,"Poisson cells (:ref:`theory §5.4 <rdem-theory-5-4>`): $\\partial\\varepsilon/\\partial u_n$, how much this bond's opening adds to body 1's cell strain along its normal [1/m]; 0 without cells (set by :yref:`RdemPoissonEngine` ``.build``)."))
		((Real,cellCoef2,0,Attr::readonly,"As ``cellCoef1``, for body 2's cell [1/m]."))
		((bool,offsetCorrection,false,,"Whether the cells correct the intact shear springs for the blocks' strains (``rdem::offsetSlip``, :ref:`theory §5.4 <rdem-theory-5-4>`): the slip $E_1\\mathbf{a}_1-E_2\\mathbf{a}_2$, $\\mathbf{a}_b$ the offset of the bonded face's centre from block $b$'s centroid along the face (:yref:`RdemGeom.faceCentre1`, ``faceCentre2``). Set by :yref:`RdemPoissonEngine` ``.build`` where the two centroids are offset along the face (running bond, a course bonded to a beam); in a grid the slip is zero and the correction is skipped."))
		((Real,opening,0,(Attr::noSave|Attr::readonly),"Normal opening $u_n$ of the bond at its face centre in this step, positive = opening [m] (written by :yref:`RdemCellStrainUpdater` for bonds of cells)."))
		((Vector3r,offsetGrad1,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"$\\partial W/\\partial\\varepsilon_1$ of the offset correction of the intact shear springs in this step, along body 1's axes [N·m] (written by the law, summed into body 1's cell stress by :yref:`RdemPoissonEngine`)."))
		((Vector3r,offsetGrad2,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"As ``offsetGrad1``, for body 2 [N·m]."))
		((Real,cn,0,,"$c_n=2h_n\\sqrt{m_{ave}\\bar{k}_n}$, normal contact dashpot per area, eq. 13 [N·s/m³]."))
		((Real,cs,0,,"$c_s=2h_s\\sqrt{m_{ave}\\bar{k}_s}$, shear contact dashpot per area, eq. 13 [N·s/m³]."))
		((vector<Vector3r>,segShear,,,"Per bonded segment: elastic shear elongation of the contact spring after breakage (global) [m]."))
		((vector<Vector3r>,segDashpot,,,"Per bonded segment: dashpot force of its contact spring in the last step, on body 2 (global) [N]; for the energy balance."))
		((vector<int>,contactKey,,,"Keys of the contact samples that were in contact in the last step (:yref:`RdemGeom.sampleKey`), ascending; the three arrays that follow hold their history, in the same order."))
		((vector<Vector3r>,contactShear,,,"Per sample in ``contactKey``: elastic shear elongation of its contact spring (global) [m]."))
		((vector<Vector3r>,contactDashpot,,,"Per sample in ``contactKey``: dashpot force of the last step, on body 2 (global) [N]; for the energy balance."))
		((vector<Real>,contactOffset,,,"Per sample in ``contactKey``: depth from which its normal spring counts, the least depth since its contact began (the depth at which it entered, if it entered deep) [m]."))
		((Real,fractureEnergy,0,,"$G_f^I$ of the bond, with softening [J/m²]."))
		((Real,shearFractureEnergy,0,,"$G_f^{II}$ of the bond, with softening [J/m²]."))
		((Real,tanResidualFriction,0,,"$\\tan\\phi_r$, residual friction of the Coulomb surface and of the broken segments' contact springs, with softening."))
		((Real,compressiveStrength,std::numeric_limits<Real>::infinity(),,"$f_c$ of the compression cap, with softening [Pa] (``inf``: none)."))
		((Real,compressiveFractureEnergy,0,,"$G_{fc}$ of the cap, with softening [J/m²]."))
		((Real,compressiveResidual,0,,"Residual fraction $r$ of $f_c$ after crushing, with softening."))
		((vector<Real>,segCrack,,,"Per bonded segment, with softening: plastic crack opening $w$ [m]."))
		((vector<Real>,segCrush,,,"Per bonded segment, with softening: plastic crushing closure $\\kappa$ [m]."))
		((vector<Real>,segSoftening,,,"Per bonded segment, with softening: softening $\\xi$ of $f_t$ and $c$, 0 (intact) to 1 (broken)."))
		((vector<Vector3r>,segSlip,,,"Per bonded segment, with softening: plastic slip of the Coulomb surface, in body 1's frame [m]."))
		((vector<Real>,segStrengthFactor,,,"Per bonded segment, with :yref:`Ip2_RdemMat_RdemMat_RdemPhys::strengthPerSegment`: the factor of its strengths and fracture energies (:ref:`theory §2.2 <rdem-theory-2-2>`); empty: the bond's strengths hold for every segment."))
		,
		/* ctor */ createIndex();
		,
		.def("nIntact",&RdemPhys::nIntact,"Number of segments whose restoring spring is intact.")
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RdemPhys, IPhys);
	/// The law's energies of this interaction in step energyIter, left for RdemForceAssembler, which books them in a fixed
	/// order (with Law2…::deferForces and O.trackEnergy; not saved: a step's own).
	rdem::SpringEnergies<Real> stepEnergies;
	long                       energyIter = -1;
	/* The elastic energy of the contact springs that Ig2_RdemBlock_RdemBlock_RdemGeom dropped from this pair in step
	   releasedIter while they were loaded (samples that left the sampled set, the shortfall of a history handed to new
	   points), for the law to book as rdemContactRelease [J] (with O.trackEnergy; not saved: a step's own). */
	Real releasedEnergy = 0;
	long releasedIter   = -1;
};
REGISTER_SERIALIZABLE(RdemPhys);

} // namespace yade
