/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/Heterogeneity.hpp: the keyed generator is a pure function of its key, and the lognormal
   factors have the requested mean and coefficient of variation. */
#include <pkg/rdem/math/Heterogeneity.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

namespace rdem = yade::rdem;

TEST(Heterogeneity, SplitMix64ReferenceValue)
{
	// The first output of SplitMix64 seeded with 0 (state advanced once by the golden gamma): 0xE220A8397B1DCDAF, the
	// value of the reference implementation (Vigna, xoshiro's splitmix64.c).
	EXPECT_EQ(rdem::splitMix64(0), 0xE220A8397B1DCDAFull);
}

TEST(Heterogeneity, KeyedDrawsArePureFunctionsOfTheKey)
{
	EXPECT_EQ(rdem::keyedNormal(7, 3, 12, 0), rdem::keyedNormal(7, 3, 12, 0));
	EXPECT_NE(rdem::keyedNormal(7, 3, 12, 0), rdem::keyedNormal(8, 3, 12, 0)); // another seed
	EXPECT_NE(rdem::keyedNormal(7, 3, 12, 0), rdem::keyedNormal(7, 3, 12, 1)); // another stream
	EXPECT_NE(rdem::keyedNormal(7, 3, 12, 0), rdem::keyedNormal(7, 12, 3, 0)); // the key is ordered (callers sort ids)
	for (std::uint64_t k = 0; k < 1000; ++k) {
		const double u = rdem::keyedUniform(1, k, k + 1, 0);
		EXPECT_GT(u, 0.0);
		EXPECT_LT(u, 1.0);
	}
}

TEST(Heterogeneity, LognormalHasTheRequestedMeanAndCoV)
{
	// N = 200000 keyed draws for v = 0.2 and 0.5. Standard error of the sample mean v/√N (4.5e-4 and 1.1e-3), of the
	// sample CoV about v√((κ-1)/4N) with κ the lognormal's kurtosis (κ = 3.3 and 5.8: 2.1e-4 and 1.2e-3); bounds 4
	// standard errors, so that a correct generator fails once in ~1e4 seeds, while a wrong μ (e.g. the normal's mean 0,
	// bias +2 % and +12 %) or a wrong s (CoV off by ≥ 2 %) fails.
	const int N = 200000;
	for (double v : { 0.2, 0.5 }) {
		double sum = 0, sum2 = 0;
		for (int i = 0; i < N; ++i) {
			const double x = rdem::lognormalFactor(v, rdem::keyedNormal(2026, std::uint64_t(i), std::uint64_t(i) + 1, 0));
			sum += x;
			sum2 += x * x;
		}
		const double mean = sum / N, cov = std::sqrt(sum2 / N - mean * mean) / mean;
		EXPECT_NEAR(mean, 1.0, 4 * v / std::sqrt(double(N))) << "v = " << v;
		const double kurt = std::pow(1 + v * v, 4) + 2 * std::pow(1 + v * v, 3) + 3 * std::pow(1 + v * v, 2) - 3;
		EXPECT_NEAR(cov, v, 4 * v * std::sqrt((kurt - 1) / (4.0 * N))) << "v = " << v;
	}
	// v = 0: exactly 1 whatever z.
	EXPECT_EQ(rdem::lognormalFactor(0.0, 1.7), 1.0);
}

} // namespace
