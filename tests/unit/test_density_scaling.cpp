/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/DensityScaling.hpp and rdem::largestBlockEigenvalue (StiffnessSpectrum.hpp): the force
   handed to NewtonIntegrator's a = F/m + g gives the scaled acceleration s(F/m + g); one oscillator (mass m, spring k,
   gravity) integrated as NewtonIntegrator does, with that force, rests where the true weight puts it (x = -mg/k) and has
   the critical step of its inertial mass, 2 sqrt(m/(s k)) (stable at 0.99 of it, unstable at 1.01); the block
   eigenvalue of hand-worked blocks. Tolerances: round-off of a few operations on O(1) numbers (1e-12 relative). */
#include <pkg/rdem/math/DensityScaling.hpp>
#include <pkg/rdem/math/StiffnessSpectrum.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

namespace rdem = yade::rdem;
using rdem_test::Scalar;
using V3 = rdem_test::Vector3;

TEST(DensityScaling, InertialFactor)
{
	EXPECT_EQ(rdem::inertialFactor<Scalar>(-1), Scalar(1)); // YADE's default: none
	EXPECT_EQ(rdem::inertialFactor<Scalar>(0), Scalar(1));
	EXPECT_EQ(rdem::inertialFactor<Scalar>(1), Scalar(1)); // exactly: m * 1 is m bit for bit
	EXPECT_EQ(rdem::inertialFactor<Scalar>(0.25), Scalar(4));
}

TEST(DensityScaling, ForceGivesTheScaledAcceleration)
{
	const V3     F(1.5, -2, 30), g(0, 0, -9.81);
	const Scalar m = 2, s = 0.3;
	const V3     a    = (F + rdem::densityScalingForce<Scalar>(s, F, m, g)) / m + g; // what NewtonIntegrator computes
	const V3     want = s * (F / m + g);
	EXPECT_LT((a - want).norm(), 1e-12 * want.norm());
	EXPECT_EQ(rdem::densityScalingForce<Scalar>(1, F, m, g), V3::Zero()); // s = 1: nothing added
}

/// Largest |x| over the last half of n leapfrog steps of one oscillator (NewtonIntegrator's update, the force of
/// densityScalingForce, Cundall's damping d) from x0 at rest [m].
Scalar oscillate(Scalar m, Scalar k, Scalar s, Scalar g, Scalar dt, Scalar d, int n, Scalar& x)
{
	Scalar v = 0, worst = 0;
	for (int i = 0; i < n; ++i) {
		const V3 F(0, 0, -k * x), grav(0, 0, g);
		Scalar   a = ((F + rdem::densityScalingForce<Scalar>(s, F, m, grav)) / m + grav)[2];
		a *= 1 - d * (a * (v + dt * a / 2) > 0 ? 1 : (a * (v + dt * a / 2) < 0 ? -1 : 0));
		v += dt * a;
		x += dt * v;
		if (i > n / 2) worst = std::max(worst, std::abs(x));
	}
	return worst;
}

TEST(DensityScaling, OscillatorRestsUnderItsTrueWeightWithTheInertialStep)
{
	const Scalar m = 0.95, k = 4e8, s = 0.25, g = -9.81;
	Scalar       x = 0;
	oscillate(m, k, s, g, 1e-6, 0.3, 200000, x);        // damped to rest
	EXPECT_NEAR(x / (m * g / k), 1, 1e-9);              // the true weight's settlement, not the inertial mass's
	const Scalar critical = 2 * std::sqrt(m / (s * k)); // 2/omega with the inertial mass m/s
	x                     = 1e-6;
	EXPECT_LT(oscillate(m, k, s, 0, 0.99 * critical, 0, 20000, x), 1e-5);
	x = 1e-6;
	EXPECT_GT(oscillate(m, k, s, 0, 1.01 * critical, 0, 2000, x), 1e-3); // grows by 1.33 a step
}

TEST(DensityScaling, BlockEigenvalue)
{
	rdem::BlockStiffness<Scalar> C(1);
	const V3                     r(0.05, 0, 0), n(1, 0, 0);
	const Scalar                 cn = 300, cs = 100, m = 2, I = 0.01;
	C.addPointSpring(0, -1, r, V3::Zero(), n, cn, cs); // one dashpot to a fixed point, arm r along its normal
	auto scale = rdem::bodyScale<Scalar>(m, V3(I, I, I), rdem_test::Matrix3::Identity(), 0);
	// translation x: cn/m = 150; y, z with rotation: the 2x2 [[cs/m, cs|r|/sqrt(mI)], [., cs|r|^2/I]] has cs(1/m + |r|^2/I) = 100 (0.5 + 0.25) = 75
	EXPECT_NEAR(rdem::largestBlockEigenvalue<Scalar>(C.diagonalBlock(0), scale), 150, 1e-12 * 150);
	scale = rdem::bodyScale<Scalar>(m, V3(I, I, I), rdem_test::Matrix3::Identity(), 1u); // x blocked
	EXPECT_NEAR(rdem::largestBlockEigenvalue<Scalar>(C.diagonalBlock(0), scale), 75, 1e-12 * 75);
	scale = rdem::bodyScale<Scalar>(m, V3(I, I, I), rdem_test::Matrix3::Identity(), 63u); // fixed
	EXPECT_EQ(rdem::largestBlockEigenvalue<Scalar>(C.diagonalBlock(0), scale), Scalar(0));
}

} // namespace
