/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The scalar the unit tests instantiate pkg/rdem/math with. The tests are compiled twice (CMakeLists.txt): as
   rdem_unit_tests in double, and as rdem_unit_tests_long_double with -DRDEM_TEST_SCALAR="long double", because YADE
   builds its Real as double, long double, float128 or MPFR, and the math layer is templated on it. Tolerances are
   written for double's round-off (2.2e-16); long double's (1.1e-19) passes them a fortiori. */
#pragma once

#include <Eigen/Core>

#ifndef RDEM_TEST_SCALAR
#define RDEM_TEST_SCALAR double
#endif

namespace rdem_test {
using Scalar  = RDEM_TEST_SCALAR;
using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
using Vector2 = Eigen::Matrix<Scalar, 2, 1>;
using MatrixX = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
}
