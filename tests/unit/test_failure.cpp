/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/Failure.hpp: the yield functions of eqs. (15)-(16), the state of a restoring spring
   and the friction limit of eq. (17). σ is positive in tension. The values are chosen exactly representable in
   binary so that "on the line" is exactly zero and "just above" is one ulp above, with no tolerance needed. */
#include <pkg/rdem/math/Failure.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

namespace rdem = yade::rdem;
using rdem::SegmentState;

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double ft  = 2e6;  // tensile strength [Pa]
constexpr double c   = 2e6;  // cohesion [Pa]
constexpr double tp  = 0.75; // tan φ (φ ≈ 36.87°), exact in binary

TEST(Failure, Eq15TensileYieldSign)
{
	// f_1 = σ - f_t: all operands are integers below 2^53, so the results are exact.
	EXPECT_EQ(rdem::tensileYield(1e6, ft), -1e6);
	EXPECT_EQ(rdem::tensileYield(ft, ft), 0.0);
	EXPECT_EQ(rdem::tensileYield(3e6, ft), 1e6);
	EXPECT_EQ(rdem::tensileYield(-5e6, ft), -7e6); // compression is always far from tensile yield
}

TEST(Failure, Eq16ShearYieldSign)
{
	// f_2 = |τ| + σ tanφ - c, exact for these binary-representable values.
	EXPECT_EQ(rdem::shearYield(0.0, 1e6, tp, c), -1e6);
	EXPECT_EQ(rdem::shearYield(0.0, -1e6, tp, c), -1e6); // |τ|: the sign of τ does not matter
	EXPECT_EQ(rdem::shearYield(0.0, 3e6, tp, c), 1e6);
	// Compression (σ < 0) raises the shear capacity: c - σ tanφ = 2e6 + 0.75e6.
	EXPECT_EQ(rdem::shearYield(-1e6, 2.75e6, tp, c), 0.0);
	EXPECT_EQ(rdem::shearYield(-1e6, 2.5e6, tp, c), -0.25e6);
	// Tension lowers it: c - σ tanφ = 2e6 - 0.75e6.
	EXPECT_EQ(rdem::shearYield(1e6, 1.5e6, tp, c), 0.25e6);
}

TEST(Failure, TensionThresholdIsStrict)
{
	// No shear, so only eq. (15) matters. At σ = f_t exactly, f_1 = 0: intact (breaks only when f_1 > 0).
	EXPECT_EQ(rdem::restoringSpringState(std::nextafter(ft, 0.0), 0.0, ft, c, 0.0), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(ft, 0.0, ft, c, 0.0), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(std::nextafter(ft, inf), 0.0, ft, c, 0.0), SegmentState::BrokenTension);
	// f_t = 0 (no tensile strength): any positive σ breaks, σ = 0 does not.
	EXPECT_EQ(rdem::restoringSpringState(0.0, 0.0, 0.0, c, 0.0), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(1e-300, 0.0, 0.0, c, 0.0), SegmentState::BrokenTension);
}

TEST(Failure, ShearOnMohrCoulombLine)
{
	// σ = -1e6 (compression), tanφ = 0.75, c = 2e6: the line |τ| = c - σ tanφ = 2.75e6 exactly.
	const double sigma = -1e6, tauLine = 2.75e6;
	EXPECT_EQ(rdem::restoringSpringState(sigma, tauLine, ft, c, tp), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(sigma, -tauLine, ft, c, tp), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(sigma, std::nextafter(tauLine, 0.0), ft, c, tp), SegmentState::Intact);
	// One ulp of 2.75e6 (2^-31) above the line: f_2 = 2^-31 > 0, exactly representable after the sums.
	EXPECT_EQ(rdem::restoringSpringState(sigma, std::nextafter(tauLine, inf), ft, c, tp), SegmentState::BrokenShear);
	EXPECT_EQ(rdem::restoringSpringState(sigma, -std::nextafter(tauLine, inf), ft, c, tp), SegmentState::BrokenShear);
	// In tension below f_t the shear capacity is lower: σ = 1e6 gives |τ| = 2e6 - 0.75e6 = 1.25e6 on the line.
	EXPECT_EQ(rdem::restoringSpringState(1e6, 1.25e6, ft, c, tp), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(1e6, 1.3e6, ft, c, tp), SegmentState::BrokenShear);
}

TEST(Failure, TensionIsCheckedFirst)
{
	// σ = 3e6 > f_t and |τ| = 5e6 far above the Mohr-Coulomb line: both violated, reported as tension.
	EXPECT_EQ(rdem::restoringSpringState(3e6, 5e6, ft, c, tp), SegmentState::BrokenTension);
	// Same τ below f_t: shear.
	EXPECT_EQ(rdem::restoringSpringState(1e6, 5e6, ft, c, tp), SegmentState::BrokenShear);
}

TEST(Failure, InfiniteStrengthsNeverBreak)
{
	// c = ∞: f_2 = -∞ for any finite σ, τ.
	EXPECT_EQ(rdem::restoringSpringState(1e6, 1e300, ft, inf, tp), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(-1e300, -1e300, ft, inf, tp), SegmentState::Intact);
	// f_t = ∞: f_1 = -∞; with c = ∞ too, nothing breaks even at σ = 1e300.
	EXPECT_EQ(rdem::restoringSpringState(1e300, 1e300, inf, inf, tp), SegmentState::Intact);
	// f_t = ∞ alone: tension never breaks, but shear still can (σ tanφ + |τ| > c).
	EXPECT_EQ(rdem::restoringSpringState(1e300, 0.0, inf, c, 0.0), SegmentState::Intact);
	EXPECT_EQ(rdem::restoringSpringState(1e6, 5e6, inf, c, tp), SegmentState::BrokenShear);
	// c = ∞ alone: tension still breaks.
	EXPECT_EQ(rdem::restoringSpringState(3e6, 0.0, ft, inf, tp), SegmentState::BrokenTension);
}

TEST(Failure, Eq17FrictionLimit)
{
	// Zero in tension and at σ = 0 (a contact spring carries no shear without compression).
	EXPECT_EQ(rdem::frictionLimit(1e6, tp), 0.0);
	EXPECT_EQ(rdem::frictionLimit(0.0, tp), 0.0);
	// -σ tanφ in compression: 2e6·0.75 = 1.5e6, exact in binary.
	EXPECT_EQ(rdem::frictionLimit(-2e6, tp), 1.5e6);
	// φ = 30°: tanφ = 1/√3; -σ tanφ = 1e6/√3 = 577350.2691896258 Pa; one product: 1e-15 relative.
	EXPECT_NEAR(rdem::frictionLimit(-1e6, std::tan(M_PI / 6)), 577350.2691896258, 1e-15 * 577350.27);
	// tanφ = 0: frictionless.
	EXPECT_EQ(rdem::frictionLimit(-1e6, 0.0), 0.0);
}

} // namespace
