/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Random draws of the unit tests, the same on every platform for a seed: std::mt19937 is fully specified, and the
   mapping of its 32-bit draws to [lo, hi) is done here (std::uniform_real_distribution's is not specified), in double
   and then converted, so that the double and the long double builds draw the same numbers. */
#pragma once

#include <Eigen/Geometry>
#include <random>

namespace rdem_test {

/// A draw in [lo, hi) from gen.
template <class S> S uniform(std::mt19937& gen, S lo, S hi) { return lo + (hi - lo) * S(gen() / 4294967296.0); }

/// A rotation from four uniform draws in [-1, 1) normalised (not uniform over rotations; any rotation can come).
template <class S> Eigen::Quaternion<S> randomQuaternion(std::mt19937& gen)
{
	Eigen::Quaternion<S> q(uniform<S>(gen, -1, 1), uniform<S>(gen, -1, 1), uniform<S>(gen, -1, 1), uniform<S>(gen, -1, 1));
	q.normalize();
	return q;
}

}
