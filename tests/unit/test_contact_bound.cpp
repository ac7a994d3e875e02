/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/ContactBound.hpp: the Gershgorin terms of a point spring and of a flush contact over a
   whole face, against closed forms. Values are O(1)-O(100) after a few dozen operations: 1e-12 relative covers
   round-off. */
#include <pkg/rdem/math/ContactBound.hpp>

#include <gtest/gtest.h>

namespace {

namespace rdem = yade::rdem;
using V3       = Eigen::Vector3d;

TEST(ContactBound, PointSpringTerms)
{
	// Arm r = (1, 2, 3), normal z: |r×n|² = 1 + 4 = 5, |r|² + (r·n)² = 14 + 9 = 23. With A = 0.5, m = 2, I = 10:
	// 2(max(4, 1)·0.5/2 + 0.5(4·5 + 1·23)/10) = 2(1 + 2.15) = 6.3.
	EXPECT_NEAR(rdem::pointSpringOmega2<double>(V3(1, 2, 3), V3::UnitZ(), 0.5, 4, 1, 2, 10), 6.3, 1e-12);
	// k_n and k_s swapped: 2(4·0.5/2 + 0.5(1·5 + 4·23)/10) = 2(1 + 4.85) = 11.7.
	EXPECT_NEAR(rdem::pointSpringOmega2<double>(V3(1, 2, 3), V3::UnitZ(), 0.5, 1, 4, 2, 10), 11.7, 1e-12);
}

TEST(ContactBound, FaceOfACubeInClosedForm)
{
	// Cube of half-size h, n = 2: 3×3 grid of spacing h with weights h²·{¼, ½, 1}, so Σw = 4h² and Σw·x² = Σw·y² = 2h⁴
	// (the trapezoid rule gives h³ for ∫x² over [-h, h], times 2h); with r = (x, y, h):
	// Σ 2(k_t/m + k_r/I) = 2(4h² max(k_n, k_s)/m + (k_n·4h⁴ + k_s(4h⁴ + 8h⁴))/I), the same for the three axes.
	const double h = 0.5, kn = 3, ks = 1.25, m = 2, I = 0.7;
	const double expected = 2 * (4 * h * h * kn / m + (kn * 4 + ks * 12) * h * h * h * h / I);
	for (int k = 0; k < 3; ++k)
		EXPECT_NEAR(rdem::faceContactOmega2<double>(V3(h, h, h), k, 2, kn, ks, m, I), expected, 1e-12 * expected) << "axis " << k;
}

TEST(ContactBound, FaceOfABoxUsesItsOwnExtents)
{
	// Box (a, b, c) = (1, 2, 3), face x = a, n = 1: the four corners with weight bc each, r = (a, ±b, ±c), normal x:
	// |r×n|² = b² + c² = 13, |r|² + (r·n)² = 2a² + b² + c² = 15, so Σ = 4bc·2(k_n/m + (13k_n + 15k_s)/I) for k_n > k_s.
	const double kn = 2, ks = 1, m = 3, I = 5, b = 2, c = 3;
	const double expected = 4 * b * c * 2 * (kn / m + (kn * 13 + ks * 15) / I);
	EXPECT_NEAR(rdem::faceContactOmega2<double>(V3(1, b, c), 0, 1, kn, ks, m, I), expected, 1e-12 * expected);
}

} // namespace
