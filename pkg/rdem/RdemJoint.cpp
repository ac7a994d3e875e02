/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemJoint.hpp>
#include <pkg/rdem/math/MaterialCheck.hpp>
#include <pkg/rdem/math/Softening.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RdemJoint));

void RdemJoint::validate() const
{
	const rdem::JointParameters<Real>    p { thickness, young, poisson, tensileStrength, cohesion, frictionAngle };
	const std::string                    owner = "RdemJoint" + (label.empty() ? std::string() : " '" + label + "'");
	const rdem::FractureParameters<Real> f { fractureEnergy,      shearFractureEnergy,       residualFrictionAngle,
		                                 compressiveStrength, compressiveFractureEnergy, compressiveResidual };
	const std::string                    err = rdem::checkJoint(p, owner) + rdem::checkFractureParameters(f, owner);
	if (!err.empty()) throw std::invalid_argument(err);
}

} // namespace yade
