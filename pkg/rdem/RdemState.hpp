/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/State.hpp>

namespace yade {

/// State of a block: YADE's State plus the block's Poisson cell (consistent formulation on any layout).
class RdemState : public State {
public:
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR(RdemState,State,R"""(State of an :yref:`RdemBlock` (made by :yref:`RdemMat`'s ``newAssocState``, as ``rdem.block`` does): YADE's :yref:`State` plus the block's *Poisson cell*, set by :yref:`RdemPoissonEngine` ``.build`` when the layout is not a grid of $2\times2\times2$ groups (:ref:`theory §5.4 <rdem-theory-5-4>`).

The cell's normal strains along the block's axes, $\varepsilon_d=\sum_q c_q u_{n,q}$ over the openings $u_{n,q}$ of the block's bonds along $d$ (:yref:`RdemPhys::cellCoef1`), are updated every step by :yref:`RdemCellStrainUpdater`; :yref:`RdemPoissonEngine` turns them into forces on the bonds.)""",
		((Real,cellVolume,0,Attr::readonly,"Volume $V$ of the block's cell [m³] (half the block along a platen axis); 0: no cell."))
		((Matrix3r,cellStiffness,Matrix3r::Zero(),Attr::readonly,"$V(D_{cond}-M\\,I)$ on the normal strains along the block's axes [N·m]: the normal block of the isotropic tensor (eq. 18), condensed over the axes without bonds ($\\sigma=0$ there), minus the springs' modulus $M=\\lambda+2\\mu$."))
		((Matrix3r,cellCondensation,Matrix3r::Zero(),Attr::readonly,"Maps the strains of the axes with bonds to all three ($\\varepsilon_{all}=C\\varepsilon$): identity on axes with bonds, $-D_{UU}^{-1}D_{UR}$ on the others."))
		((Vector3r,strain,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"Normal strains of the cell along the block's axes in this step, positive in extension (axes without bonds: from ``cellCondensation``) [-]."))
		((Vector3r,cellStress,Vector3r::Zero(),(Attr::noSave|Attr::readonly),"$\\partial W/\\partial\\varepsilon$ of the cell's elastic energy in this step, $sV(D-M\\,I)\\varepsilon$ along the block's axes [N·m] (without the offset correction's reaction): the Poisson part of the normal stress on the block's faces, read by the law for :yref:`Law2_RdemGeom_RdemPhys_FaceSprings::totalStress`."))
		((Real,cellScale,1,Attr::readonly,"Crack scale of the cell: the smallest fraction of intact restoring springs among the block's bonds so far (1 intact, 0 once a bond is released); it never increases."))
		,
		/* ctor */ createIndex();
	);
	// clang-format on
	REGISTER_CLASS_INDEX(RdemState, State);
};
REGISTER_SERIALIZABLE(RdemState);

} // namespace yade
