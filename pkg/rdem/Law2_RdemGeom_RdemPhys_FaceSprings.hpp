/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <lib/base/openmp-accu.hpp>
#include <core/Dispatching.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemReleasedBond.hpp>
#include <pkg/rdem/RdemSharedState.hpp>
#include <pkg/rdem/RdemStiffnessSource.hpp>
#include <pkg/rdem/math/FaceSprings.hpp>
#include <mutex>

namespace yade {

/// Restoring springs, their failure, and contact springs with dashpots and friction (paper §3.5-3.6, eqs. 13-17).
class Law2_RdemGeom_RdemPhys_FaceSprings : public LawFunctor, public RdemStiffnessSource {
public:
	bool go(shared_ptr<IGeom>& geom, shared_ptr<IPhys>& phys, Interaction* I) override;
	/// The springs of every bond segment (its restoring spring, or the contact spring of a broken one: the same k̄A) and
	/// contact sample, as point springs; the dashpots of broken segments that touch and of contact samples (eq. 13),
	/// capped by dashpotCap for capDt; interactions in the order of their bodies' ids.
	void
	addStiffness(Scene* sc, const vector<const Interaction*>& inIdOrder, rdem::BlockStiffness<Real>& K, rdem::BlockStiffness<Real>& C, Real capDt) override;
	/// addStiffness's C alone, from the interactions that can have a dashpot (a contact sample, a patch, a broken segment).
	void addDashpots(Scene* sc, const vector<const Interaction*>& inIdOrder, rdem::BlockStiffness<Real>& C, Real capDt) override;
	/// Per point spring, 2(k_t/m + k_r/I_min) on each free body (rdem::pointSpringOmega2).
	void addOmega2Bound(Scene* sc, vector<Real>& omega2) override;
	/* Stability caps (c_n, c_s) of a contact dashpot at point C with normal n (explicit central differences) [N·s/m], for
	   the blocks with states s1, s2 and centroids x1, x2: a dashpot may at most stop, never reverse, the relative motion
	   of its point within one step, c ≤ share·m_eff/Δt, with m_eff the pair's effective mass at the point
	   (1/m_eff = Σ 1/m + |r×e|²/I_min over the free blocks, e the direction of the dashpot) and share its part of the
	   interaction's contact area. For the shear dashpot, whose direction changes, |r×e|² is bounded by |r|². The caps bind
	   where a contact drives a small effective mass, at an edge or a corner of a tumbling block, and on small blocks at
	   the paper's h = 1; eq. (13) holds elsewhere (:ref:`theory §3 <rdem-theory-3>`). addStiffness caps them the same way. */
	static Vector2r
	dashpotCap(const State& s1, const Vector3r& x1, const State& s2, const Vector3r& x2, const Vector3r& C, const Vector3r& n, Real share, Real dt);
	/// Whether a Law2_RdemGeom_RdemPhys_FaceSprings of the scene has totalStress (RdemPoissonEngine::build then needs cells).
	static bool totalStressOf(const Scene* scene);
	/// releasedBonds as a Python list.
	boost::python::list releasedBondsPy();
	/// A copy of releasedBonds, safe while the simulation runs (for the viewer's thread).
	vector<shared_ptr<RdemReleasedBond>> releasedBondsNow()
	{
		const std::lock_guard<std::mutex> lock(releasedMutex);
		return releasedBonds;
	}
	/// The springs broken so far in tension and in shear (counted in shared).
	long tensionBreaksPy() const { return shared->tensionBreaks.get(); }
	long shearBreaksPy() const { return shared->shearBreaks.get(); }
	/// A law always has a shared state (go() cannot make one: it runs in YADE's parallel loop).
	void postLoad(Law2_RdemGeom_RdemPhys_FaceSprings&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Law2_RdemGeom_RdemPhys_FaceSprings,LawFunctor,R"""(Constitutive law of the refined distinct element method (paper §3, eqs. 13-17).

*Restoring springs* (intact segments of a bond): stresses $\sigma=\bar{k}_n u_n$ (positive in tension) and $\boldsymbol{\tau}=\bar{k}_s\mathbf{u}_s$ from the total relative displacement of the segment's material points (eq. 14); force on body 2 $-(\sigma\mathbf{n}+\boldsymbol{\tau})A$, applied at the segment point, so that bending and twisting moments emerge from the segment grid. A spring breaks when $\sigma>f_t$ (eq. 15) or $|\tau|+\sigma\tan\phi>c$ (eq. 16), tension checked first; its elastic energy is released (``rdemBondBreak`` in :yref:`O.energy<Scene.energy>`).

*Contact springs* (broken segments, and sampled contacts of blocks that are not bonded): compression only, normal force $\max(\bar{k}_n A\delta - c_nA\dot{u}_n,0)$ with $\delta$ the overlap; incremental shear spring $\bar{k}_s A$ limited by Coulomb friction $|F_s|\le\tan\phi\,\bar{k}_nA\delta$ (eq. 17); shear dashpot $c_sA$ while sticking (eq. 13). A broken segment is in contact while its material points overlap and have slid less than the smaller of :yref:`RdemGeom::segHalfSizes`. When every segment of a bond is broken and none is in contact, the interaction is released and later contacts are found by sampling (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom`).

*Softening springs* (bonds made with :yref:`Ip2_RdemMat_RdemMat_RdemPhys::softening`): in place of the breakage of eqs. 15-16, a tension cut-off with linear softening of $f_t$ (fracture energy $G_f^I$), a Coulomb surface whose cohesion softens with $G_f^{II}$ towards residual friction, and a compression cap; the segment breaks when its strengths are gone ($\xi=1$), so that the energy dissipated per unit crack area is $G_f$ whatever the block size (:ref:`theory §2.1 <rdem-theory-2-1>`, after Lourenço & Rots [LourencoRots1997]_).

With :yref:`O.trackEnergy<Omega.trackEnergy>`: ``rdemElastic`` (springs, current value), ``rdemDashpot``, ``rdemFriction`` and ``rdemBondBreak`` (cumulated); with softening bonds also ``rdemFractureTension``, ``rdemFractureShear`` and ``rdemCrushing`` (cumulated); from the first contact spring that :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` drops while it is loaded (a sample that leaves the sampled set, a compression a hand-over cannot pass on: :ref:`theory §4.1 <rdem-theory-4-1>`), ``rdemContactRelease``, its elastic energy of the last step (cumulated).)""",
		((bool,deferForces,false,,"Leave the forces and torques in :yref:`RdemPhys` (``force``, ``torque1``, ``torque2``) for :yref:`RdemForceAssembler`, which sums them per body in a fixed order, instead of adding them to the bodies in the order of the interaction container (which ``O.load`` and the collider change; ``rdem.engines()`` sets it). Needs an :yref:`RdemForceAssembler` after the :yref:`InteractionLoop`: without it the plugin's engines refuse to run (RuntimeError, :yref:`RdemSharedState` checks the engine list once, at the first step and when it changes), and until that check has passed the law, which cannot throw from inside YADE's parallel loop, adds its forces directly."))
		((bool,totalStress,false,,"Failure criteria (eqs. 15-16) on the total normal stress of the face: the springs' $\\sigma$ plus the normal stress the Poisson cells exert on it, $(c_1S_1+c_2S_2)/(w_nA)$ (:yref:`RdemState::cellStress`, :yref:`RdemPhys::cellCoef1`; :ref:`theory §5.6 <rdem-theory-5-6>`); it is the continuum's $\\sigma_{nn}$ of the face, zero on the head joints of a wall in uniform vertical compression. Needs Poisson cells (consistent formulation, :yref:`RdemPoissonEngine::elements` ``'cells'`` or ``'auto'`` on a layout that is not a grid). False (default): the springs' $\\sigma$ alone, the paper's criterion, whose lateral springs carry $M\\nu\\sigma/E$ in tension under uniaxial compression (the paper's splitting mechanism)."))
		((shared_ptr<RdemSharedState>,shared,shared_ptr<RdemSharedState>(new RdemSharedState),Attr::triggerPostLoad,"What the plugin's engines share (:yref:`RdemSharedState`): this law counts the broken springs there (``rdem.engines()`` hands the same object to every engine; a new law makes its own, which the other engines take at the first step)."))
		((vector<shared_ptr<RdemReleasedBond>>,releasedBonds,,Attr::hidden,"The bonds released so far (Python: the read-only list ``releasedBonds``, without a converter of its own)."))
		,
		/* ctor */
		,
		.add_property("tensionBreaks",&Law2_RdemGeom_RdemPhys_FaceSprings::tensionBreaksPy,"Number of restoring springs broken in tension (eq. 15) so far (:yref:`RdemSharedState`, saved with the scene).")
		.add_property("shearBreaks",&Law2_RdemGeom_RdemPhys_FaceSprings::shearBreaksPy,"Number of restoring springs broken in shear (eq. 16) so far (:yref:`RdemSharedState`, saved with the scene).")
		.add_property("releasedBonds",&Law2_RdemGeom_RdemPhys_FaceSprings::releasedBondsPy,"The bonds released so far (every segment broken, none in contact; the interaction is then reset), step by step: the cracks that no interaction shows any more (:yref:`RdemReleasedBond`), drawn by :yref:`GlExtra_RdemReleasedBonds` and exported by ``rdem.export.CrackExport``.")
	);
	// clang-format on
	FUNCTOR2D(RdemGeom, RdemPhys);
	DECLARE_LOGGER;

private:
	/// The interaction's force f₂ on body 2 and moment t₂ about its centroid, and their reaction on body 1 (dx = x₂ - x₁):
	/// left in p for RdemForceAssembler (deferForces) or added to the scene's force container.
	void applyForces(const Interaction& I, RdemPhys& p, const Vector3r& f2, const Vector3r& t2, const Vector3r& dx);
	/// Appends the bond of I, released in this step, to releasedBonds (thread-safe).
	void       recordRelease(const Interaction& I, const RdemGeom& g, const RdemPhys& p);
	std::mutex releasedMutex; // releasedBonds grows from the threads of the interaction loop
};
REGISTER_SERIALIZABLE(Law2_RdemGeom_RdemPhys_FaceSprings);

} // namespace yade
