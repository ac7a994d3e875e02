/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/CrackBand.hpp: Bažant & Oh's (1983) equivalent strength of a crack band wider than the
   one whose softening snaps back, f_eq = sqrt(2 E G_f / h), applied to a softening spring (E/h -> k per area). */
#include <pkg/rdem/math/CrackBand.hpp>
#include <pkg/rdem/math/Elasticity.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

namespace rdem = yade::rdem;
using S        = rdem_test::Scalar;
const S inf    = std::numeric_limits<S>::infinity();

/* The hand-computed case: the springs inside a hollow clay unit of Petry & Beyer's walls (PUP1-PUP6) under the rule set
   of py/rdem/wall_database.py: E = 3.55 GPa, ν = 0.25, the consistent modulus M = E(1-ν)/((1+ν)(1-2ν))
   = 3.55e9·0.75/0.625 = 4.26 GPa; two blocks of the 300 mm unit cut at its middle, each reaching the head joint's
   mid-plane (155 mm), so ℓ_A + ℓ_B = 0.155 m and k_n = 4.26e9/0.155 = 2.74839e10 N/m³; f_t = 0.065·35 MPa = 2.275 MPa,
   G_f^I = 80 J/m². Bažant & Oh's equivalent strength sqrt(2 k_n G_f^I) = sqrt(2·2.74839e10·80) = 2.097002 MPa: below
   f_t, which would snap back (f_t²/(2k_n) = 94.16 J/m² > 80). */
TEST(CrackBand, EquivalentStrengthOfTheSourceOnAHandComputedCase)
{
	const S M = rdem::springNormalModulus<S>(3.55e9, 0.25, rdem::SpringModulus::Consistent);
	EXPECT_NEAR(M, 4.26e9, 1e-6 * 4.26e9);
	const S kn = M / S(0.155);
	EXPECT_NEAR(kn, 2.748387e10, 1e-6 * 2.748387e10);
	// rho = 1: the vertical drop of the source, f_eq = sqrt(2 E G_f / h).
	EXPECT_NEAR(rdem::crackBandStrength<S>(kn, 80, 1), 2.097002e6, 1e-6 * 2.097002e6);
	// rho = 0.99 (the law's margin): sqrt(0.99) = 0.994987 of it, 2.086491 MPa.
	EXPECT_NEAR(rdem::crackBandStrength<S>(kn, 80, rdem::crackBandFraction<S>()), 2.086491e6, 1e-6 * 2.086491e6);
}

// The lowered spring: f_t at the bound, the elastic energy at the peak rho G_f, the fracture energies kept, and the
// snap-back check passes; the compression cap of the same unit (f_b = 35 MPa, r = 0.2, G_fc = 5000 J/m²) lowered so that
// ((1 - r) f_c)²/(2 k_n) = rho G_fc: f_c = sqrt(2·0.99·2.74839e10·5000)/0.8 = 20.61895 MPa.
TEST(CrackBand, LowersOnlyWhatSnapsBackAndPassesTheCheck)
{
	const S                     kn = S(4.26e9) / S(0.155), ks = S(3.55e9) / (2 * S(1.25)) / S(0.155);
	rdem::SofteningConstants<S> k { kn, ks, S(2.275e6), 80, S(2.275e6) * S(1.4), 800, S(0.75), S(0.75), S(35e6), 5000, S(0.2) };
	ASSERT_FALSE(rdem::checkSoftening(k, "unit").empty()); // as given: refused
	const auto low = rdem::crackBandStrengths(k);
	EXPECT_NEAR(low.ft, 2.086491e6, 1e-6 * 2.086491e6);
	EXPECT_NEAR(low.ft * low.ft / (2 * low.GfI), rdem::crackBandFraction<S>() * kn, 1e-9 * kn);
	EXPECT_NEAR(low.fc, 20.61895e6, 1e-6 * 20.61895e6);
	EXPECT_EQ(low.c, k.c); // c²/(2k_s) = 554 J/m² < G_f^II = 800: no snap-back, kept
	EXPECT_EQ(low.GfI, k.GfI);
	EXPECT_EQ(low.GfII, k.GfII);
	EXPECT_EQ(low.Gfc, k.Gfc);
	EXPECT_EQ(low.kn, k.kn);
	EXPECT_TRUE(rdem::checkSoftening(low, "unit").empty()) << rdem::checkSoftening(low, "unit");
	// An admissible spring is not touched; infinite strengths (no surface) stay infinite.
	rdem::SofteningConstants<S> ok { kn, ks, S(0.2e6), 18, S(0.27e6), 125, S(0.75), S(0.75), inf, 5000, S(0.2) };
	const auto                  same = rdem::crackBandStrengths(ok);
	EXPECT_EQ(same.ft, ok.ft);
	EXPECT_EQ(same.c, ok.c);
	EXPECT_TRUE(std::isinf(same.fc));
}

// A lowered cohesion keeps the tension cut-off inside the Coulomb cone (f_t tanφ ≤ c), and per-segment factors bound
// the strongest segment: scaled by f, the check of rdem::scaledStrengths passes at the largest factor.
TEST(CrackBand, CohesionConeAndSegmentFactors)
{
	const S                     kn = 1e10, ks = 4e9;
	rdem::SofteningConstants<S> k { kn, ks, S(1e6), 100, S(2e6), 100, S(1.0), S(0.6), inf, 0, 0 };
	const auto                  low = rdem::crackBandStrengths(k);
	EXPECT_NEAR(low.c, std::sqrt(S(2) * S(0.99) * ks * 100), 1e-9 * low.c); // 0.889944 MPa < 2 MPa
	EXPECT_EQ(low.ft, low.c);                                               // f_t = c/tanφ₀ (tanφ₀ = 1 > tanφ_r): below 1 MPa
	EXPECT_TRUE(rdem::checkSoftening(low, "bond").empty()) << rdem::checkSoftening(low, "bond");
	const S    f    = 1.3;
	const auto lowF = rdem::crackBandStrengths(k, f);
	EXPECT_TRUE(rdem::checkSoftening(rdem::scaledStrengths(lowF, f), "bond").empty());
	EXPECT_LT(lowF.ft, low.ft);
}

} // namespace
