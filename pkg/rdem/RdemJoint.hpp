/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <lib/serialization/Serializable.hpp>
#include <limits>

namespace yade {

/// A mortar joint between two blocks: thickness, the mortar's elastic constants and the unit–mortar bond's strengths.
class RdemJoint : public Serializable {
public:
	/// Throws std::invalid_argument (Python: ValueError) naming every parameter out of its range.
	void validate() const;
	void postLoad(RdemJoint&) { validate(); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(RdemJoint,Serializable,R"""(A joint between two blocks (masonry: the mortar between two bricks, or the bond between a brick and a mortar block), given to the bonds made while it is :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom::joint` (``rdem.bond(ids, joint=...)`` and ``rdem.masonry.wall`` set it).

*Interface joint* (``thickness`` $t>0$): the two blocks reach the joint's mid-plane (a brick plus half a joint each side) and the joint's springs put brick, mortar and brick in series, eq. 12 extended by the mortar term:

.. math:: \frac{1}{\bar k_n}=\frac{\ell_A-t/2}{M_A}+\frac{t}{M_m}+\frac{\ell_B-t/2}{M_B},\qquad \frac{1}{\bar k_s}=\frac{\ell_A-t/2}{G_A}+\frac{t}{G_m}+\frac{\ell_B-t/2}{G_B},

$M$ the springs' modulus of the formulation ($E/(1-\nu^2)$ or $\lambda+2\mu$, :yref:`Ip2_RdemMat_RdemMat_RdemPhys::formulation`), $G=E/(2(1+\nu))$. The mortar's own Poisson expansion is not represented (use mortar blocks for that).

*Bond interface* (``thickness`` $=0$): blocks bonded face to face as by eq. 12, e.g. a brick and a mortar block of the *layer* model, with the joint's strengths.

Either way the bond breaks on the joint's strengths (eqs. 15-16): ``tensileStrength`` (the unit–mortar tensile bond strength), ``cohesion`` and ``frictionAngle`` (its Mohr–Coulomb line), in place of the blocks' materials'.)""",
		((Real,thickness,0,Attr::triggerPostLoad,"Mortar thickness $t\\ge 0$ [m]; 0: a bond interface without mortar of its own."))
		((Real,young,2e9,Attr::triggerPostLoad,"Young's modulus of the mortar $E_m>0$ [Pa] (used when ``thickness`` > 0)."))
		((Real,poisson,0.2,Attr::triggerPostLoad,"Poisson's ratio of the mortar $\\nu_m$, $-1<\\nu_m<0.5$ (used when ``thickness`` > 0)."))
		((Real,tensileStrength,0.1e6,Attr::triggerPostLoad,"Tensile bond strength $f_t\\ge 0$ of the joint (eq. 15) [Pa]; ``inf``: never breaks in tension."))
		((Real,cohesion,0.2e6,Attr::triggerPostLoad,"Cohesion $c\\ge 0$ of the joint's Mohr–Coulomb criterion (eq. 16) [Pa]; ``inf``: never breaks in shear."))
		((Real,frictionAngle,0.6747,Attr::triggerPostLoad,"Friction angle $\\phi$ of the joint, $0\\le\\phi<\\pi/2$ [rad] (eqs. 16-17); default $\\arctan 0.8$."))
		((Real,fractureEnergy,18,Attr::triggerPostLoad,"Mode-I fracture energy $G_f^I>0$ [J/m²]: the energy a softening spring dissipates per unit area of a tensile crack (:ref:`theory §2.1 <rdem-theory-2-1>`; used with :yref:`Ip2_RdemMat_RdemMat_RdemPhys::softening`). Default: the unit–mortar interface of Lourenço & Rots [LourencoRots1997]_."))
		((Real,shearFractureEnergy,125,Attr::triggerPostLoad,"Mode-II fracture energy $G_f^{II}>0$ [J/m²]: energy per unit area of the softening of the cohesion $c$ to zero (with softening). Default: Lourenço & Rots' [LourencoRots1997]_."))
		((Real,residualFrictionAngle,std::numeric_limits<Real>::quiet_NaN(),Attr::triggerPostLoad,"Residual friction angle $\\phi_r$ [rad], $0\\le\\phi_r<\\pi/2$, reached with the cohesion's softening and kept by the contact springs of the broken segments (with softening); ``nan`` (default): ``frictionAngle``."))
		((Real,compressiveStrength,std::numeric_limits<Real>::infinity(),Attr::triggerPostLoad,"Compressive strength $f_c>0$ [Pa] of the compression cap of a softening spring (crushing); ``inf`` (default): no cap."))
		((Real,compressiveFractureEnergy,5000,Attr::triggerPostLoad,"Compressive fracture energy $G_{fc}>0$ [J/m²] of the cap's softening from $f_c$ to ``compressiveResidual`` $f_c$ (default: Lourenço & Rots' masonry, [LourencoRots1997]_)."))
		((Real,compressiveResidual,0.2,Attr::triggerPostLoad,"Residual strength of the crushed spring as a fraction $r$ of $f_c$, $0\\le r<1$."))
		((string,label,"",,"Name of the joint (e.g. 'bed', 'head', 'collar'), for the user."))
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(RdemJoint);

} // namespace yade
