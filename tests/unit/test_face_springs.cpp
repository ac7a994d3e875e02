/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/FaceSprings.hpp, the point laws Law2_RdemGeom_RdemPhys_FaceSprings runs: the restoring
   spring (eqs. 14-16) and the contact spring with dashpots and friction (eqs. 13, 17). Values are chosen exact in
   binary where the result is a single product or sum (EXPECT_EQ); elsewhere the tolerance is a few ulps of the
   largest term. σ positive in tension. */
#include <pkg/rdem/math/FaceSprings.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

namespace rdem = yade::rdem;
using V        = Eigen::Vector3d;
using rdem::SegmentState;

const rdem::RestoringConstants<double> spring { 4e12, 2e12, 2e6, 4e6, 0.75 }; // k̄_n, k̄_s [N/m³], f_t, c [Pa], tan φ

TEST(FaceSprings, RestoringStressIsEq14)
{
	// u_n = 2^-22 m, u_s = (0, 2^-23, 0) m: σ = 4e12·2^-22 = 953674.3 Pa, τ = 2e12·2^-23 = 238418.6 Pa, both exact.
	const double un = std::ldexp(1.0, -22);
	const V      us(0, std::ldexp(1.0, -23), 0);
	const auto   r = rdem::restoringStress(spring, un, us, 0.0);
	EXPECT_EQ(r.sigma, 4e12 * un);
	EXPECT_EQ(r.tau, V(0, 2e12 * us[1], 0));
	EXPECT_EQ(r.tauNorm, 2e12 * us[1]);
	EXPECT_EQ(r.state, SegmentState::Intact);
	// Elastic energy of a segment of 1e-4 m² with weights (1, 0.5): A(σ²/k_n + 0.5 τ²/k_s)/2 = A(k_n u_n² + 0.5 k_s u_s²)/2.
	const double expected = 1e-4 * (4e12 * un * un + 0.5 * 2e12 * us[1] * us[1]) / 2;
	EXPECT_NEAR(rdem::restoringEnergy(spring, r, 1e-4, 1.0, 0.5), expected, 4e-16 * expected);
}

TEST(FaceSprings, RestoringStateJudgedOnTotalStress)
{
	// σ = k_n u_n = 1e6 < f_t: intact alone; with the cells' σ_extra = 1.5e6 the face's total 2.5e6 > f_t breaks it.
	const double un = 1e6 / 4e12;
	EXPECT_EQ(rdem::restoringStress(spring, un, V::Zero().eval(), 0.0).state, SegmentState::Intact);
	EXPECT_EQ(rdem::restoringStress(spring, un, V::Zero().eval(), 1.5e6).state, SegmentState::BrokenTension);
	// Shear: τ = 3.5e6 with σ = 0: |τ| < c = 4e6, intact; with σ_extra = 1e6 (tension): 3.5e6 + 0.75e6 > 4e6, shear break.
	const V us(3.5e6 / 2e12, 0, 0);
	EXPECT_EQ(rdem::restoringStress(spring, 0.0, us, 0.0).state, SegmentState::Intact);
	EXPECT_EQ(rdem::restoringStress(spring, 0.0, us, 1e6).state, SegmentState::BrokenShear);
	// The stress returned is the springs' own, not the total.
	EXPECT_EQ(rdem::restoringStress(spring, un, V::Zero().eval(), 1.5e6).sigma, 1e6);
}

TEST(FaceSprings, ScaledStrengthsMoveTheBreakingStress)
{
	// Heterogeneity (doc/theory.md §2.2): a segment of factor 0.5 breaks in tension at 0.5 f_t = 1e6 Pa and in shear at
	// 0.5 c = 2e6 Pa; stiffnesses and friction are the bond's.
	const auto weak = rdem::scaledStrengths(spring, 0.5);
	EXPECT_EQ(weak.kn, spring.kn);
	EXPECT_EQ(weak.tanPhi, spring.tanPhi);
	EXPECT_EQ(rdem::restoringStress(weak, 0.99e6 / 4e12, V::Zero().eval(), 0.0).state, SegmentState::Intact);
	EXPECT_EQ(rdem::restoringStress(weak, 1.01e6 / 4e12, V::Zero().eval(), 0.0).state, SegmentState::BrokenTension);
	EXPECT_EQ(rdem::restoringStress(weak, 0.0, V(1.99e6 / 2e12, 0, 0), 0.0).state, SegmentState::Intact);
	EXPECT_EQ(rdem::restoringStress(weak, 0.0, V(2.01e6 / 2e12, 0, 0), 0.0).state, SegmentState::BrokenShear);
}

// A contact point: k_n = 1e8 N/m, k_s = 5e7 N/m, c_n = 200, c_s = 100 N·s/m, tan φ = 0.5; normal along z.
const rdem::ContactConstants<double> contact { 1e8, 5e7, 200, 100, 0.5 };
const V                              nz(0, 0, 1);

TEST(FaceSprings, ContactAtRestIsTheNormalSpring)
{
	V                            shear = V::Zero(), dashpot = V::Zero();
	rdem::SpringEnergies<double> e;
	const double                 delta = std::ldexp(1.0, -20); // 9.5e-7 m
	const V                      F     = rdem::contactSpringForce(contact, delta, nz, V::Zero().eval(), 1e-6, shear, dashpot, true, e);
	EXPECT_EQ(F, V(0, 0, 1e8 * delta));
	EXPECT_EQ(shear, V::Zero());
	EXPECT_EQ(e.elastic, 1e8 * delta * delta / 2);
	EXPECT_EQ(e.friction, 0.0);
	EXPECT_EQ(e.dashpot, 0.0);
}

TEST(FaceSprings, ContactSpringEnergyIsWhatTheSpringBooks)
{
	// k_n c²/2 + k_s |u_s|²/2, and the elastic energy contactSpringForce books for a point that sticks (a shear
	// elongation of 1e-7 m gives k_s u_s = 5 N, below tan φ k_n δ = 47.7 N).
	const double c = std::ldexp(1.0, -20), us = 1e-7;
	EXPECT_EQ(rdem::contactSpringEnergy(1e8, 5e7, c, V(us, 0, 0)), 1e8 * c * c / 2 + 5e7 * us * us / 2);
	V                            shear = V(us, 0, 0), dashpot = V::Zero();
	rdem::SpringEnergies<double> e;
	rdem::contactSpringForce(contact, c, nz, V::Zero().eval(), 1e-6, shear, dashpot, true, e);
	EXPECT_EQ(e.elastic, rdem::contactSpringEnergy(1e8, 5e7, c, shear));
	EXPECT_EQ(shear, V(us, 0, 0));
}

TEST(FaceSprings, NormalDashpotNeverPulls)
{
	V                            shear = V::Zero(), dashpot = V::Zero();
	rdem::SpringEnergies<double> e;
	const double                 delta = 1e-6;
	// Approaching at v_n = -0.5 m/s: k_n δ + c_n·0.5 = 100 + 100 N.
	V F = rdem::contactSpringForce(contact, delta, nz, V(0, 0, -0.5), 1e-6, shear, dashpot, false, e);
	EXPECT_NEAR(F[2], 200.0, 1e-13);
	EXPECT_EQ(dashpot, V(0, 0, 100.0));
	// Separating at 1 m/s: k_n δ - c_n·1 = 100 - 200 < 0, clipped to zero (compression only); the dashpot part is -k_n δ.
	dashpot = V::Zero();
	F       = rdem::contactSpringForce(contact, delta, nz, V(0, 0, 1.0), 1e-6, shear, dashpot, false, e);
	EXPECT_EQ(F, V::Zero());
	EXPECT_NEAR(dashpot[2], -100.0, 1e-13);
}

TEST(FaceSprings, ShearSticksBelowFrictionLimit)
{
	// Tangential velocity 0.1 m/s for dt = 1e-6 s: elongation 1e-7 m, spring force -5 N, dashpot -10 N; limit
	// tan φ k_n δ = 0.5·1e8·1e-6 = 50 N is not reached.
	V                            shear = V::Zero(), dashpot = V::Zero();
	rdem::SpringEnergies<double> e;
	const V                      F = rdem::contactSpringForce(contact, 1e-6, nz, V(0.1, 0, 0), 1e-6, shear, dashpot, true, e);
	EXPECT_NEAR(shear[0], 1e-7, 1e-22);
	EXPECT_NEAR(F[0], -5.0 - 10.0, 1e-14);
	EXPECT_NEAR(F[2], 100.0, 1e-13);
	EXPECT_EQ(e.friction, 0.0);
	// Trapezoid dashpot booking: half of -F_d·v dt now, -(-10)(0.1)(1e-6)/2 = 5e-7 J.
	EXPECT_NEAR(e.dashpot, 5e-7, 1e-21);
}

TEST(FaceSprings, Eq17SlidingAtTheFrictionLimit)
{
	// An elongation of 2e-6 m stored in a spring of 5e7 N/m is 100 N, twice the limit 0.5·100 N = 50 N: it slides.
	V                            shear(2e-6, 0, 0), dashpot = V::Zero();
	rdem::SpringEnergies<double> e;
	const double                 delta = 1e-6;
	const V                      F     = rdem::contactSpringForce(contact, delta, nz, V::Zero().eval(), 1e-6, shear, dashpot, true, e);
	const double                 limit = rdem::frictionLimit(-1e8 * delta, 0.5);
	EXPECT_NEAR(limit, 50.0, 1e-13);
	EXPECT_NEAR(F[0], -limit, 1e-13);          // |F_s| = tan φ k_n δ, against the elongation
	EXPECT_NEAR(shear[0], 1e-6, 1e-21);        // the elastic elongation that carries it, 50/5e7
	EXPECT_NEAR(e.friction, 1e-6 * 50, 1e-18); // plastic slip 1e-6 m times the sliding force 50 N
	// Elastic energy after the slip: ½k_nδ² + ½k_s u_s² = 50e-6 + 25e-6 J.
	EXPECT_NEAR(e.elastic, 75e-6, 1e-18);
	// No shear dashpot while sliding.
	EXPECT_EQ(dashpot, V::Zero());
}

TEST(FaceSprings, ShearSpringFollowsTheTangentPlane)
{
	// A stored elongation with a component along the new normal loses it before the step's increment is added.
	V                            shear(1e-7, 0, 3e-7), dashpot = V::Zero();
	rdem::SpringEnergies<double> e;
	const V                      F = rdem::contactSpringForce(contact, 1e-6, nz, V::Zero().eval(), 1e-6, shear, dashpot, false, e);
	EXPECT_EQ(shear, V(1e-7, 0, 0));
	EXPECT_NEAR(F[0], -5.0, 1e-14);
	EXPECT_NEAR(F[2], 100.0, 1e-13);
}

} // namespace
