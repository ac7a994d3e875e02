/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/math/Elasticity.hpp>
#include <pkg/rdem/math/Failure.hpp>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((Ip2_RdemMat_RdemMat_RdemPhys));

void Ip2_RdemMat_RdemMat_RdemPhys::postLoad(Ip2_RdemMat_RdemMat_RdemPhys&)
{
	if (springModulus != 0 && springModulus != 1)
		throw std::invalid_argument(
		        "Ip2_RdemMat_RdemMat_RdemPhys.springModulus = " + std::to_string(springModulus) + ": must be 0 (paper) or 1 (consistent)");
}

void Ip2_RdemMat_RdemMat_RdemPhys::go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return; // constants are fixed when the interaction is made
	const RdemMat&  a = *static_cast<RdemMat*>(m1.get());
	const RdemMat&  b = *static_cast<RdemMat*>(m2.get());
	const RdemGeom& g = *static_cast<RdemGeom*>(I->geom.get());
	const auto      M = static_cast<rdem::SpringModulus>(springModulus);

	auto p = shared_ptr<RdemPhys>(new RdemPhys);
	// Eq. (11) for each block, eq. (12) in series [N/m³].
	p->kn = rdem::seriesStiffness(rdem::normalStiffnessPerArea(a.young, a.poisson, g.ell1, M), rdem::normalStiffnessPerArea(b.young, b.poisson, g.ell2, M));
	p->ks = rdem::seriesStiffness(rdem::shearStiffnessPerArea(a.young, a.poisson, g.ell1), rdem::shearStiffnessPerArea(b.young, b.poisson, g.ell2));
	// Eq. (13) [N·s/m³].
	const Real mAve = rdem::equivalentMassPerArea(a.density, g.ell1, b.density, g.ell2);
	p->cn           = rdem::dampingPerArea((a.dampingNormal + b.dampingNormal) / 2, mAve, p->kn);
	p->cs           = rdem::dampingPerArea((a.dampingShear + b.dampingShear) / 2, mAve, p->ks);
	// Joint strengths: the weaker material governs.
	p->tensileStrength = math::min(a.tensileStrength, b.tensileStrength);
	p->cohesion        = math::min(a.cohesion, b.cohesion);
	p->tanFriction     = math::tan(math::min(a.frictionAngle, b.frictionAngle));
	const size_t nSeg  = g.nSegments();
	// The arrays every step of an intact bond touches first, so that they are allocated next to each other.
	p->segState.assign(nSeg, int(rdem::SegmentState::Intact));
	p->segSigma.assign(nSeg, 0);
	p->segTau.assign(nSeg, 0);
	p->segShear.assign(nSeg, Vector3r::Zero());
	p->segDashpot.assign(nSeg, Vector3r::Zero());
	I->phys = p;
}

} // namespace yade
