/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <pkg/rdem/NumberText.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemJoint.hpp>
#include <pkg/rdem/math/CrackBand.hpp>
#include <pkg/rdem/math/Failure.hpp>
#include <pkg/rdem/math/Heterogeneity.hpp>
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace yade {

YADE_PLUGIN((Ip2_RdemMat_RdemMat_RdemPhys));

void Ip2_RdemMat_RdemMat_RdemPhys::postLoad(Ip2_RdemMat_RdemMat_RdemPhys&)
{
	if (!rdem::springModulusFromName(formulation, modulus))
		throw std::invalid_argument("Ip2_RdemMat_RdemMat_RdemPhys.formulation = '" + formulation + "': must be 'paper' or 'consistent'");
	for (const auto& cv : { std::make_pair("strengthCoV", strengthCoV), std::make_pair("stiffnessCoV", stiffnessCoV) })
		if (!(math::isfinite(cv.second) && cv.second >= 0))
			throw std::invalid_argument(
			        std::string("Ip2_RdemMat_RdemMat_RdemPhys.") + cv.first + " = " + rdem::numberText(cv.second) + ": must be finite and >= 0");
}

rdem::SpringModulus Ip2_RdemMat_RdemMat_RdemPhys::formulationOf(const Scene* scene)
{
	const auto* ip2 = rdem::findLoopFunctor<Ip2_RdemMat_RdemMat_RdemPhys>(scene);
	return ip2 ? ip2->springModulus() : rdem::SpringModulus::Paper;
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

Real Ip2_RdemMat_RdemMat_RdemPhys::bondFactor(const Interaction& I, Real cov, int stream) const
{
	const auto lo = std::uint64_t(math::min(I.getId1(), I.getId2())), hi = std::uint64_t(math::max(I.getId1(), I.getId2()));
	return rdem::lognormalFactor<Real>(cov, rdem::keyedNormal(std::uint64_t(seed), lo, hi, std::uint64_t(stream)));
}

void Ip2_RdemMat_RdemMat_RdemPhys::scaleStrengths(RdemPhys& p, Real f)
{
	p.tensileStrength *= f;
	p.cohesion *= f;
	p.compressiveStrength *= f;
	p.fractureEnergy *= f; // the critical openings 2G/f stay the material's
	p.shearFractureEnergy *= f;
	p.compressiveFractureEnergy *= f;
}

void Ip2_RdemMat_RdemMat_RdemPhys::setSoftening(RdemPhys& p, const RdemMat& a, const RdemMat& b, const RdemJoint* joint)
{
	// The joint's parameters, else the weaker material's (as the strengths).
	auto pick                   = [&](Real RdemJoint::*j, Real RdemMat::*m) { return joint ? joint->*j : math::min(a.*m, b.*m); };
	p.softening                 = true;
	p.fractureEnergy            = pick(&RdemJoint::fractureEnergy, &RdemMat::fractureEnergy);
	p.shearFractureEnergy       = pick(&RdemJoint::shearFractureEnergy, &RdemMat::shearFractureEnergy);
	p.compressiveStrength       = pick(&RdemJoint::compressiveStrength, &RdemMat::compressiveStrength);
	p.compressiveFractureEnergy = pick(&RdemJoint::compressiveFractureEnergy, &RdemMat::compressiveFractureEnergy);
	p.compressiveResidual       = pick(&RdemJoint::compressiveResidual, &RdemMat::compressiveResidual);
	// Residual friction angle: nan stands for the friction angle of the same joint or material.
	auto residual         = [](Real phiR, Real phi) { return math::isnan(phiR) ? phi : phiR; };
	p.tanResidualFriction = math::tan(
	        joint ? residual(joint->residualFrictionAngle, joint->frictionAngle)
	              : math::min(residual(a.residualFrictionAngle, a.frictionAngle), residual(b.residualFrictionAngle, b.frictionAngle)));
	const size_t nSeg = p.segState.size();
	p.segCrack.assign(nSeg, 0);
	p.segCrush.assign(nSeg, 0);
	p.segSoftening.assign(nSeg, 0);
	p.segSlip.assign(nSeg, Vector3r::Zero());
}

rdem::SofteningConstants<Real> Ip2_RdemMat_RdemMat_RdemPhys::softeningConstants(const RdemPhys& p)
{
	return { p.kn,
		 p.ks,
		 p.tensileStrength,
		 p.fractureEnergy,
		 p.cohesion,
		 p.shearFractureEnergy,
		 p.tanFriction,
		 p.tanResidualFriction,
		 p.compressiveStrength,
		 p.compressiveFractureEnergy,
		 p.compressiveResidual };
}

void Ip2_RdemMat_RdemMat_RdemPhys::checkSoftening(const RdemPhys& p, const RdemMat& a, const RdemMat& b, const RdemJoint* joint)
{
	const std::string owner = joint
	        ? "RdemJoint" + (joint->label.empty() ? std::string() : " '" + joint->label + "'")
	        : "RdemMat" + (a.label.empty() ? std::string() : " '" + a.label + "'") + (&a == &b || b.label.empty() ? std::string() : "/'" + b.label + "'");
	// Per-segment strengths: the strongest segment is the one that could snap back (f_t²/(2G_f) grows with the factor).
	const Real        f   = p.segStrengthFactor.empty() ? Real(1) : *std::max_element(p.segStrengthFactor.begin(), p.segStrengthFactor.end());
	const std::string err = rdem::checkSoftening(rdem::scaledStrengths(softeningConstants(p), f), owner);
	if (!err.empty()) throw std::invalid_argument(err);
}

void Ip2_RdemMat_RdemMat_RdemPhys::lowerToCrackBand(RdemPhys& p)
{
	// The strongest segment is the one checkSoftening checks (f_t²/(2G_f) grows with the factor).
	const Real f          = p.segStrengthFactor.empty() ? Real(1) : *std::max_element(p.segStrengthFactor.begin(), p.segStrengthFactor.end());
	const auto k          = rdem::crackBandStrengths(softeningConstants(p), f);
	p.tensileStrength     = k.ft;
	p.cohesion            = k.c;
	p.compressiveStrength = k.fc;
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
		        "RdemJoint.thickness = " + rdem::numberText(t) + ": must be less than twice the centroid-to-face distance of both blocks it joins ("
		        + rdem::numberText(g.ell1) + " and " + rdem::numberText(g.ell2) + " m for bodies " + std::to_string(I->getId1()) + " and "
		        + std::to_string(I->getId2()) + "): each block reaches the joint's mid-plane");
	const Real Gm = joint ? rdem::shearModulus(joint->young, joint->poisson) : Real(1);

	auto p = shared_ptr<RdemPhys>(new RdemPhys);
	// Eqs. (11)-(12), with the mortar of the joint in series [N/m³].
	p->kn = 1 / normalCompliances(a, b, g, modulus).sum();
	p->ks = 1
	        / (rdem::bondSideCompliance(rdem::shearModulus(a.young, a.poisson), g.ell1, Gm, t)
	           + rdem::bondSideCompliance(rdem::shearModulus(b.young, b.poisson), g.ell2, Gm, t));
	const size_t nSeg = g.nSegments();
	if (nSeg > 0 && stiffnessCoV > 0) { // heterogeneity: one factor per bond (before the dashpots, which follow k)
		const Real f = bondFactor(*I, stiffnessCoV, 1);
		p->kn *= f;
		p->ks *= f;
	}
	// Eq. (13) [N·s/m³].
	const Real mAve = rdem::equivalentMassPerArea(a.density, g.ell1, b.density, g.ell2);
	p->cn           = rdem::dampingPerArea((a.dampingNormal + b.dampingNormal) / 2, mAve, p->kn);
	p->cs           = rdem::dampingPerArea((a.dampingShear + b.dampingShear) / 2, mAve, p->ks);
	// Strengths: the joint's, else the weaker material's.
	p->tensileStrength = joint ? joint->tensileStrength : math::min(a.tensileStrength, b.tensileStrength);
	p->cohesion        = joint ? joint->cohesion : math::min(a.cohesion, b.cohesion);
	p->tanFriction     = math::tan(joint ? joint->frictionAngle : math::min(a.frictionAngle, b.frictionAngle));
	// The arrays every step of an intact bond touches first, so that they are allocated next to each other.
	p->segState.assign(nSeg, int(rdem::SegmentState::Intact));
	p->segSigma.assign(nSeg, 0);
	p->segTau.assign(nSeg, 0);
	p->segShear.assign(nSeg, Vector3r::Zero());
	p->segDashpot.assign(nSeg, Vector3r::Zero());
	if (nSeg > 0 && softening) setSoftening(*p, a, b, joint);
	if (nSeg > 0 && strengthCoV > 0) {
		if (strengthPerSegment) { // streams 2, 3, ...: one per segment (0 and 1 are the bond's strength and stiffness)
			p->segStrengthFactor.resize(nSeg);
			for (size_t i = 0; i < nSeg; ++i)
				p->segStrengthFactor[i] = bondFactor(*I, strengthCoV, 2 + int(i));
		} else
			scaleStrengths(*p, bondFactor(*I, strengthCoV, 0));
	}
	if (p->softening && crackBand) lowerToCrackBand(*p);
	if (p->softening) checkSoftening(*p, a, b, joint);
	I->phys = p;
}

} // namespace yade
