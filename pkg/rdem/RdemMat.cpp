/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemMat.hpp>
#include <pkg/rdem/math/MaterialCheck.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RdemMat));

void RdemMat::validate() const
{
	const rdem::MaterialParameters<Real> p { young, poisson, density, tensileStrength, cohesion, frictionAngle, dampingNormal, dampingShear };
	const std::string                    err = rdem::checkMaterial(p, "RdemMat" + (label.empty() ? std::string() : " '" + label + "'"));
	if (!err.empty()) throw std::invalid_argument(err);
}

} // namespace yade
