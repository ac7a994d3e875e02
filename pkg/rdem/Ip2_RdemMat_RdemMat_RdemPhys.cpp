/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <core/InteractionLoop.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemJoint.hpp>
#include <pkg/rdem/math/Failure.hpp>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((Ip2_RdemMat_RdemMat_RdemPhys));

void Ip2_RdemMat_RdemMat_RdemPhys::postLoad(Ip2_RdemMat_RdemMat_RdemPhys&)
{
	if (!rdem::springModulusFromName(formulation, modulus))
		throw std::invalid_argument("Ip2_RdemMat_RdemMat_RdemPhys.formulation = '" + formulation + "': must be 'paper' or 'consistent'");
}

rdem::SpringModulus Ip2_RdemMat_RdemMat_RdemPhys::formulationOf(const Scene* scene)
{
	for (const auto& e : scene->engines)
		if (const auto* loop = dynamic_cast<const InteractionLoop*>(e.get()))
			for (const auto& f : loop->physDispatcher->functors)
				if (const auto* ip2 = dynamic_cast<const Ip2_RdemMat_RdemMat_RdemPhys*>(f.get())) return ip2->springModulus();
	return rdem::SpringModulus::Paper;
}

Vector2r Ip2_RdemMat_RdemMat_RdemPhys::normalCompliances(const RdemMat& a, const RdemMat& b, const RdemGeom& g, rdem::SpringModulus modulus)
{
	const RdemJoint* joint = g.nSegments() > 0 ? g.joint.get() : nullptr;
	const Real       t     = joint ? joint->thickness : Real(0);
	const Real       Mm    = joint ? rdem::springNormalModulus(joint->young, joint->poisson, modulus) : Real(1);
	return Vector2r(
	        rdem::bondSideCompliance(rdem::springNormalModulus(a.young, a.poisson, modulus), g.ell1, Mm, t),
	        rdem::bondSideCompliance(rdem::springNormalModulus(b.young, b.poisson, modulus), g.ell2, Mm, t));
}

void Ip2_RdemMat_RdemMat_RdemPhys::go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I)
{
	if (I->phys) return; // constants are fixed when the interaction is made
	const RdemMat&   a     = *static_cast<RdemMat*>(m1.get());
	const RdemMat&   b     = *static_cast<RdemMat*>(m2.get());
	const RdemGeom&  g     = *static_cast<RdemGeom*>(I->geom.get());
	const RdemJoint* joint = g.nSegments() > 0 ? g.joint.get() : nullptr;
	const Real       t     = joint ? joint->thickness : Real(0);
	if (joint && !(t / 2 < math::min(g.ell1, g.ell2)))
		throw std::invalid_argument(
		        "RdemJoint.thickness = " + std::to_string(t) + ": must be less than twice the centroid-to-face distance of both blocks it joins ("
		        + std::to_string(g.ell1) + " and " + std::to_string(g.ell2) + " m for bodies " + std::to_string(I->getId1()) + " and "
		        + std::to_string(I->getId2()) + "): each block reaches the joint's mid-plane");
	const Real Gm = joint ? rdem::shearModulus(joint->young, joint->poisson) : Real(1);

	auto p = shared_ptr<RdemPhys>(new RdemPhys);
	// Eqs. (11)-(12), with the mortar of the joint in series [N/m³].
	p->kn = 1 / normalCompliances(a, b, g, modulus).sum();
	p->ks = 1 / (rdem::bondSideCompliance(rdem::shearModulus(a.young, a.poisson), g.ell1, Gm, t) + rdem::bondSideCompliance(rdem::shearModulus(b.young, b.poisson), g.ell2, Gm, t));
	// Eq. (13) [N·s/m³].
	const Real mAve = rdem::equivalentMassPerArea(a.density, g.ell1, b.density, g.ell2);
	p->cn           = rdem::dampingPerArea((a.dampingNormal + b.dampingNormal) / 2, mAve, p->kn);
	p->cs           = rdem::dampingPerArea((a.dampingShear + b.dampingShear) / 2, mAve, p->ks);
	// Strengths: the joint's, else the weaker material's.
	p->tensileStrength = joint ? joint->tensileStrength : math::min(a.tensileStrength, b.tensileStrength);
	p->cohesion        = joint ? joint->cohesion : math::min(a.cohesion, b.cohesion);
	p->tanFriction     = math::tan(joint ? joint->frictionAngle : math::min(a.frictionAngle, b.frictionAngle));
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
