/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Dispatching.hpp>
#include <pkg/rdem/RdemMat.hpp>
#include <pkg/rdem/RdemPhys.hpp>

namespace yade {

/// Spring stiffness (eqs. 11-12), dashpots (eq. 13) and joint strengths of a pair of blocks.
class Ip2_RdemMat_RdemMat_RdemPhys : public IPhysFunctor {
public:
	void go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I) override;
	/// Throws std::invalid_argument (Python: ValueError) for a springModulus other than 0 or 1.
	void postLoad(Ip2_RdemMat_RdemMat_RdemPhys&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(Ip2_RdemMat_RdemMat_RdemPhys,IPhysFunctor,R"""(Physics functor of two :yref:`RdemMat`, producing :yref:`RdemPhys` once per interaction.

Per-area spring stiffness of each block from eq. 11, $k_n=M/\ell$, $k_s=E/(2(1+\nu)\ell)$, with $\ell$ the centroid-to-face distance (:yref:`RdemGeom::ell1`, ``ell2``); the two blocks in series (eq. 12). $M=E/(1-\nu^2)$ as in the paper (``springModulus=0``) or $M=\lambda+2\mu$ (``springModulus=1``, the *consistent* formulation, which together with :yref:`RdemPoissonEngine` reproduces the full isotropic tensor; see doc/theory.md). Dashpots per area $c=2h\sqrt{m_{ave}\bar{k}}$, $m_{ave}=\rho_A\ell_A+\rho_B\ell_B$ (eq. 13), $h$ the mean of the two materials' constants. The joint takes the smaller tensile strength, bond strength and friction angle of the two materials.)""",
		((int,springModulus,0,Attr::triggerPostLoad,"Normal modulus of the springs: 0 = paper, $E/(1-\\nu^2)$ (eq. 11); 1 = consistent, $\\lambda+2\\mu$."))
	);
	// clang-format on
	FUNCTOR2D(RdemMat, RdemMat);
};
REGISTER_SERIALIZABLE(Ip2_RdemMat_RdemMat_RdemPhys);

} // namespace yade
