/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Dispatching.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemMat.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/math/Elasticity.hpp>
#include <pkg/rdem/math/Softening.hpp>

namespace yade {

/// Spring stiffness (eqs. 11-12, with a mortar joint in series), dashpots (eq. 13) and joint strengths of a pair of blocks.
class Ip2_RdemMat_RdemMat_RdemPhys : public IPhysFunctor {
public:
	void go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I) override;
	/// Throws std::invalid_argument (Python: ValueError) for a formulation other than "paper" or "consistent".
	void postLoad(Ip2_RdemMat_RdemMat_RdemPhys&);
	/// The springs' modulus this functor uses.
	rdem::SpringModulus springModulus() const { return modulus; }
	/// The formulation of the scene: that of its Ip2_RdemMat_RdemMat_RdemPhys (the one place it is set; paper if there is
	/// none). RdemPoissonEngine and RdemTimeStepper read it here.
	static rdem::SpringModulus formulationOf(const Scene* scene);
	/// Normal compliances per area (C₁, C₂) of the two sides of the bond g between blocks of materials a and b, from each
	/// centroid to the joint's mid-plane, the joint's mortar included (rdem::bondSideCompliance) [m³/N]: k̄_n = 1/(C₁ + C₂).
	static Vector2r normalCompliances(const RdemMat& a, const RdemMat& b, const RdemGeom& g, rdem::SpringModulus modulus);
	/// The constants of the softening springs of a bond (doc/sphinx/rdemTheory.rst §2.1).
	static rdem::SofteningConstants<Real> softeningConstants(const RdemPhys& p);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(Ip2_RdemMat_RdemMat_RdemPhys,IPhysFunctor,R"""(Physics functor of two :yref:`RdemMat`, producing :yref:`RdemPhys` once per interaction.

Per-area spring stiffness of each block from eq. 11, $k_n=M/\ell$, $k_s=E/(2(1+\nu)\ell)$, with $\ell$ the centroid-to-face distance (:yref:`RdemGeom::ell1`, ``ell2``); the two blocks in series (eq. 12). A bond made with an :yref:`RdemJoint` of thickness $t$ adds the mortar in series, $1/\bar k_n=(\ell_A-t/2)/M_A+t/M_m+(\ell_B-t/2)/M_B$ (and likewise with $G$), and breaks on the joint's strengths. Dashpots per area $c=2h\sqrt{m_{ave}\bar{k}}$, $m_{ave}=\rho_A\ell_A+\rho_B\ell_B$ (eq. 13), $h$ the mean of the two materials' constants. Without a joint the bond takes the smaller tensile strength, bond strength and friction angle of the two materials.

``formulation`` is the scene's one setting of the Poisson formulation: :yref:`RdemPoissonEngine` builds the elements or cells of that formulation and :yref:`RdemTimeStepper` bounds contacts with its modulus.)""",
		((string,formulation,"paper",Attr::triggerPostLoad,"``'paper'``: springs $M=E/(1-\\nu^2)$ (eq. 11) and the paper's Poisson elements; ``'consistent'``: $M=\\lambda+2\\mu$, so that springs and Poisson elements or cells add up to the full isotropic tensor (:ref:`theory §5.2 <rdem-theory-5-2>`, :ref:`theory §5.4 <rdem-theory-5-4>`)."))
		((bool,softening,false,,"Restoring springs of new bonds soften (the composite interface model after Lourenço & Rots [LourencoRots1997]_, :ref:`theory §2.1 <rdem-theory-2-1>`): tension softening with ``fractureEnergy`` $G_f^I$, cohesion softening with ``shearFractureEnergy`` $G_f^{II}$ towards residual friction ``residualFrictionAngle``, a compression cap ``compressiveStrength`` with ``compressiveFractureEnergy``, each of the :yref:`RdemJoint` or else the weaker :yref:`RdemMat`; dissipated energy booked as ``rdemFractureTension``, ``rdemFractureShear``, ``rdemCrushing`` and ``rdemFriction``. False (default): the paper's brittle springs (eqs. 15-16). A bond whose springs would snap back ($\\bar k_n\\le f_t^2/(2G_f^I)$, blocks too large for $G_f$) is refused with an error, unless ``crackBand``."))
		((bool,crackBand,false,,"With ``softening``: a bond whose springs would snap back gets the strengths of Bažant & Oh's crack-band remedy [BazantOh1983]_ instead of an error: its fracture energies are kept and $f_t$, $c$ and the part $(1-r)f_c$ of the cap that softens are lowered to $\\sqrt{2\\rho\\bar k G}$ ($\\bar k_n$ with $G_f^I$ and $G_{fc}$, $\\bar k_s$ with $G_f^{II}$; $\\rho=0.99$: a softening branch 1 % short of vertical), the equivalent strength of a crack band wider than the one whose softening snaps back (``rdem::crackBandStrengths``, :ref:`theory §2.1 <rdem-theory-2-1>`). Bonds that do not snap back are unchanged. False (default): refused."))
		((Real,strengthCoV,0,Attr::triggerPostLoad,"Coefficient of variation $v\\ge 0$ of the strengths of new bonds: $f_t$, $c$, $f_c$ and the fracture energies of each bond are multiplied by one lognormal factor of mean 1 and CoV $v$ (``rdem::lognormalFactor``), drawn from ``seed`` and the bond's body ids (the same for a bond whatever the order bonds are made in; :ref:`theory §2.2 <rdem-theory-2-2>`). 0: uniform."))
		((bool,strengthPerSegment,false,,"With ``strengthCoV`` > 0: draw the strength factor of every segment of a bond (its own stream of ``seed`` and the bond's body ids; kept in :yref:`RdemPhys::segStrengthFactor`) instead of one per bond, so that a face cracks gradually rather than at once (:ref:`theory §2.2 <rdem-theory-2-2>`)."))
		((Real,stiffnessCoV,0,Attr::triggerPostLoad,"As ``strengthCoV``, for the spring stiffnesses $\\bar k_n$, $\\bar k_s$ of each bond (an independent factor)."))
		((int,seed,0,,"Seed of ``strengthCoV`` and ``stiffnessCoV``: a fixed seed reproduces a scene bit for bit."))
	);
	// clang-format on
	FUNCTOR2D(RdemMat, RdemMat);

private:
	rdem::SpringModulus modulus = rdem::SpringModulus::Paper; // formulation, parsed (not saved: postLoad sets it)
	/// Lognormal factor of mean 1 and CoV cov of the bond I, from seed, its sorted body ids and the stream (0 strengths,
	/// 1 stiffnesses): rdem::keyedNormal, rdem::lognormalFactor.
	Real bondFactor(const Interaction& I, Real cov, int stream) const;
	/// Multiplies every strength and fracture energy of p by f.
	static void scaleStrengths(RdemPhys& p, Real f);
	/// Switches p's springs to softening: the softening parameters of the joint (or the weaker material), per-segment state.
	static void setSoftening(RdemPhys& p, const RdemMat& a, const RdemMat& b, const RdemJoint* joint);
	/// Throws std::invalid_argument naming the joint's or materials' parameter if p's softening springs are inadmissible
	/// (rdem::checkSoftening: snap-back, tension cut-off outside the Coulomb cone).
	static void checkSoftening(const RdemPhys& p, const RdemMat& a, const RdemMat& b, const RdemJoint* joint);
	/// Lowers the strengths of p's softening springs where they would snap back (crackBand; rdem::crackBandStrengths).
	static void lowerToCrackBand(RdemPhys& p);
};
REGISTER_SERIALIZABLE(Ip2_RdemMat_RdemMat_RdemPhys);

} // namespace yade
