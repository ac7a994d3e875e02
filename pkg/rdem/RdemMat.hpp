/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Material.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <limits>

namespace yade {

/// Material of the refined DEM blocks (paper Table 1); every parameter is validated when set from Python.
class RdemMat : public Material {
public:
	/// Throws std::invalid_argument (Python: ValueError) naming every parameter out of its range.
	void validate() const;
	void postLoad(RdemMat&) { validate(); }
	/// Blocks of this material carry an RdemState (their Poisson cell).
	shared_ptr<State> newAssocState() const override { return shared_ptr<State>(new RdemState); }
	bool              stateTypeOk(State* s) const override { return dynamic_cast<RdemState*>(s) != nullptr; }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR(RdemMat,Material,R"""(Material of a rigid block in the refined distinct element method with the Poisson effect (paper: shared/reference/paper-poisson-effect-refined-dem.txt).

Elastic constants set the restoring-spring stiffness per area of a face, $k_n=E/((1-\nu^2)\ell)$ and $k_s=E/(2(1+\nu)\ell)$ (paper eq. 11), combined in series between two blocks of different materials (eq. 12), and the Poisson elements' $D_p$ (eq. 19) of :yref:`RdemPoissonEngine`. Strengths decide when a restoring spring breaks: tension $\sigma>f_t$ (eq. 15) or Mohr-Coulomb $|\tau|+\sigma\tan\phi>c$ (eq. 16), stresses positive in tension. Broken springs become compression-only contact springs with dashpots $c=2h\sqrt{m_{ave}k}$ (eq. 13) and Coulomb friction (eq. 17).

Defaults are the concrete of the paper's Table 1. Between two materials, the joint takes the smaller strengths and friction angle and the mean damping constants (:yref:`Ip2_RdemMat_RdemMat_RdemPhys`). Parameters are checked whenever they are set from Python; out-of-range values raise ``ValueError``.)""",
		((Real,young,30e9,Attr::triggerPostLoad,"Young's modulus $E$ [Pa], $E>0$."))
		((Real,poisson,0.2,Attr::triggerPostLoad,"Poisson's ratio $\\nu$, $-1<\\nu<0.5$."))
		((Real,tensileStrength,4.5e6,Attr::triggerPostLoad,"Tensile strength $f_t\\ge 0$ [Pa] of the restoring springs (eq. 15); ``inf``: never break in tension."))
		((Real,cohesion,std::numeric_limits<Real>::infinity(),Attr::triggerPostLoad,"Bond strength $c\\ge 0$ [Pa] of the Mohr-Coulomb criterion (eq. 16); ``inf`` (default, as in the paper's §5): never break in shear."))
		((Real,frictionAngle,0.557710,Attr::triggerPostLoad,"Friction angle $\\phi$ [rad], $0\\le\\phi<\\pi/2$, of eqs. 16 and 17; default $\\arctan 0.624$ (paper Table 1)."))
		((Real,dampingNormal,1.0,Attr::triggerPostLoad,"Damping constant $h_n\\ge 0$ of the normal contact dashpot (eq. 13); 1 is critical."))
		((Real,dampingShear,1.0,Attr::triggerPostLoad,"Damping constant $h_s\\ge 0$ of the shear contact dashpot (eq. 13); 1 is critical."))
		((Real,fractureEnergy,80,Attr::triggerPostLoad,"Mode-I fracture energy $G_f^I>0$ [J/m²]: the energy a softening spring dissipates per unit area of a tensile crack (:ref:`theory §2.1 <rdem-theory-2-1>`; used with :yref:`Ip2_RdemMat_RdemMat_RdemPhys::softening`). Default: the CEB-FIP Model Code 1990's $G_F$ of a concrete of $f_{cm}\\approx 40$ MPa [CEBFIP1990]_."))
		((Real,shearFractureEnergy,800,Attr::triggerPostLoad,"Mode-II fracture energy $G_f^{II}>0$ [J/m²]: energy per unit area of the softening of the cohesion $c$ to zero (with softening). Default: $10G_f^I$."))
		((Real,residualFrictionAngle,std::numeric_limits<Real>::quiet_NaN(),Attr::triggerPostLoad,"Residual friction angle $\\phi_r$ [rad], $0\\le\\phi_r<\\pi/2$, reached with the cohesion's softening and kept by the contact springs of the broken segments (with softening); ``nan`` (default): ``frictionAngle``."))
		((Real,compressiveStrength,std::numeric_limits<Real>::infinity(),Attr::triggerPostLoad,"Compressive strength $f_c>0$ [Pa] of the compression cap of a softening spring (crushing); ``inf`` (default): no cap."))
		((Real,compressiveFractureEnergy,5000,Attr::triggerPostLoad,"Compressive fracture energy $G_{fc}>0$ [J/m²] of the cap's softening from $f_c$ to ``compressiveResidual`` $f_c$ (default: Lourenço & Rots' masonry, [LourencoRots1997]_)."))
		((Real,compressiveResidual,0.2,Attr::triggerPostLoad,"Residual strength of the crushed spring as a fraction $r$ of $f_c$, $0\\le r<1$."))
		,
		/* ctor */ createIndex(); density = 2300;
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RdemMat, Material);
};
REGISTER_SERIALIZABLE(RdemMat);

} // namespace yade
