/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* A body's inertial mass and smallest moment of inertia: its State's true ones times rdem::inertialFactor of its
   densityScaling (RdemDensityScaling), what every bound on the time step and every dashpot cap uses; the true mass
   stays the gravitational one. Bit for bit the true ones in an unscaled scene. */
#pragma once

#include <core/State.hpp>
#include <pkg/rdem/math/DensityScaling.hpp>

namespace yade {
namespace rdem {

	/// m / s [kg].
	inline Real inertialMass(const State& s) { return s.mass * inertialFactor(s.densityScaling); }

	/// min(I) / s [kg·m²].
	inline Real inertialMinInertia(const State& s) { return s.inertia.minCoeff() * inertialFactor(s.densityScaling); }

} // namespace rdem
} // namespace yade
