/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/Softening.hpp, the softening spring after Lourenço & Rots (1997) (doc/theory.md §2.1).
   Each test drives one spring through a displacement path in small steps and checks (a) the booked dissipation against
   the fracture energy, (b) the work of the stresses along the path, ∫σ du_n + τ·du_s by the trapezoid rule, against the
   booked dissipation plus the stored energy (an independent check that the stresses follow the law the booking
   assumes), and (c) the characteristic stresses (peak, residual) exactly. σ positive in tension. */
#include <pkg/rdem/math/Softening.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

namespace rdem = yade::rdem;
using V        = Eigen::Vector3d;
using rdem::SegmentState;
constexpr double inf = std::numeric_limits<double>::infinity();

/* A mortar joint of Lourenço & Rots (1997)'s size: f_t = 0.25 MPa, G_f^I = 18 J/m², c = 0.35 MPa, G_f^II = 125 J/m²,
   tanφ₀ = 0.75, tanφ_r = 0.6, no cap; springs per area of a 0.1 m block pair in brick and mortar (k_n = 1e11, k_s = 4e10). */
rdem::SofteningConstants<double> joint() { return { 1e11, 4e10, 0.25e6, 18.0, 0.35e6, 125.0, 0.75, 0.6, inf, 0.0, 0.0 }; }

/// Drives the spring linearly from (un0, us0) to (un1, us1) in n steps, accumulating the work of its stresses
/// (trapezoid) and its dissipation; returns the stress of the last step.
struct Path {
	explicit Path(const rdem::SofteningConstants<double>& constants)
	        : k(constants)
	{
	}
	rdem::SofteningConstants<double>   k;
	rdem::SofteningState<double>       st;
	rdem::SofteningDissipation<double> d;
	double                             extra = 0; ///< σ_extra, the Poisson cells' normal stress on the face [Pa]
	double                             work = 0, un = 0, sigma = 0, peakSigma = -inf, peakTau = 0;
	V                                  us = V::Zero(), tau = V::Zero();
	SegmentState                       state = SegmentState::Intact;

	void to(double un1, const V& us1, int n)
	{
		const double un0 = un;
		const V      us0 = us;
		for (int i = 1; i <= n; ++i) {
			const double t = double(i) / n;
			const double u = un0 + (un1 - un0) * t;
			const V      s = us0 + (us1 - us0) * t;
			const auto   r = rdem::softeningStep(k, u, s, extra, st, d);
			work += (sigma + r.sigma) / 2 * (u - un) + (tau + r.tau).dot(s - us) / 2;
			un        = u;
			us        = s;
			sigma     = r.sigma;
			tau       = r.tau;
			state     = r.state;
			peakSigma = std::max(peakSigma, sigma);
			peakTau   = std::max(peakTau, tau.norm());
			if (state != SegmentState::Intact) return;
		}
	}
	double dissipated() const { return d.tension + d.shear + d.friction + d.crushing; }
	double stored() const { return rdem::softeningEnergy(k, sigma, tau); }
};

TEST(Softening, ModeIDissipatesGfWhateverTheStiffness)
{
	// Two springs 10x apart in stiffness (blocks 10x apart in size): each opened in pure tension until it breaks.
	for (double kn : { 1e11, 1e10 }) {
		Path p(joint());
		p.k.kn          = kn;
		const double wI = 2 * 18.0 / 0.25e6; // final crack opening 1.44e-4 m
		p.to(2 * wI, V::Zero(), 20000);
		EXPECT_EQ(p.state, SegmentState::BrokenTension);
		// Booked: the exact integral of the linear softening, G_f^I to round-off.
		EXPECT_NEAR(p.d.tension, 18.0, 1e-9 * 18.0);
		EXPECT_NEAR(p.st.crack, wI, 1e-12 * wI);
		// Work of the stresses along the path: G_f^I within the trapezoid error of 20000 steps (< 1e-3), nothing left stored.
		EXPECT_NEAR(p.work, 18.0, 1e-3 * 18.0);
		// Peak: f_t, reached at u = f_t/k_n; the step grid passes it within one step of softening (H·Δw ≤ f_t·Δu/w_I).
		EXPECT_NEAR(p.peakSigma, 0.25e6, 0.25e6 * 2 * wI / 20000 / wI);
		EXPECT_EQ(p.d.shear, 0.0);
		EXPECT_EQ(p.d.friction, 0.0);
	}
}

TEST(Softening, UnloadingAndReloadingDissipateNothing)
{
	Path         p(joint());
	const double wI = 2 * 18.0 / 0.25e6;
	// Open to half the final opening: ξ between 0 and 1, the crack open by w > 0.
	p.to(wI / 2, V::Zero(), 5000);
	ASSERT_EQ(p.state, SegmentState::Intact);
	const double xi = p.st.xi, w = p.st.crack, G = p.d.tension;
	ASSERT_GT(xi, 0.3);
	ASSERT_LT(xi, 0.7);
	// The softened strength holds on the envelope: σ = f_t(1 - ξ).
	EXPECT_NEAR(p.sigma, 0.25e6 * (1 - xi), 1e-6 * 0.25e6);
	// Unload to zero and into compression: elastic down to σ = 0 at u = w, stress-free crack closing to u = 0,
	// then compression k_n u. No dissipation, ξ and w kept.
	p.to(w, V::Zero(), 1000);
	EXPECT_NEAR(p.sigma, 0.0, 1e-12 * 0.25e6);
	p.to(w / 2, V::Zero(), 1000);
	EXPECT_EQ(p.sigma, 0.0);
	p.to(-1e-6, V::Zero(), 1000);
	EXPECT_NEAR(p.sigma, -1e11 * 1e-6, 1e-9 * 1e5);
	EXPECT_EQ(p.st.xi, xi);
	EXPECT_EQ(p.st.crack, w);
	EXPECT_EQ(p.d.tension, G);
	// Reload: stress-free up to u = w, then elastic to the softened strength f_t(1 - ξ) at u = w + f_t(1-ξ)/k_n.
	p.to(w + 0.5 * 0.25e6 * (1 - xi) / 1e11, V::Zero(), 1000);
	EXPECT_NEAR(p.sigma, 0.5 * 0.25e6 * (1 - xi), 1e-6 * 0.25e6);
	EXPECT_EQ(p.d.tension, G);
	// And on to failure: G_f^I in all, the cycle's work balanced (the loop's work is zero: elastic, no dissipation).
	p.to(2 * wI, V::Zero(), 20000);
	EXPECT_EQ(p.state, SegmentState::BrokenTension);
	EXPECT_NEAR(p.d.tension, 18.0, 1e-9 * 18.0);
	EXPECT_NEAR(p.work, 18.0, 1e-3 * 18.0);
}

TEST(Softening, ModeIIUnderCompressionDissipatesGfIIPlusFriction)
{
	// Constant compression σ₀ = -0.5 MPa (u_n = σ₀/k_n), then slip along x until the cohesion is gone.
	Path         p(joint());
	const double s0 = -0.5e6, un = s0 / 1e11;
	p.to(un, V::Zero(), 100);
	const double wII = 2 * 125.0 / 0.35e6; // final slip of the cohesion's softening 7.1e-4 m
	p.to(un, V(2 * wII, 0, 0), 40000);
	EXPECT_EQ(p.state, SegmentState::BrokenShear);
	EXPECT_NEAR(p.sigma, s0, 1e-9 * 0.5e6);
	// Peak: c - σ₀ tanφ₀ = 0.35 + 0.375 MPa, to within one step of softening.
	EXPECT_NEAR(p.peakTau, 0.725e6, 0.725e6 * 2 * 2 * wII / 40000 / wII);
	// Booked cohesion softening: G_f^II to round-off; friction: -σ₀ ∫tanφ(ξ)dκ = -σ₀ (tanφ₀ + tanφ_r)/2 w_II over the
	// softening, plus -σ₀ tanφ_r on the slip past w_II within the last step (at most one step, 2w_II/40000).
	EXPECT_NEAR(p.d.shear, 125.0, 1e-9 * 125.0);
	EXPECT_NEAR(p.d.friction, 0.5e6 * (0.75 + 0.6) / 2 * wII, 0.5e6 * 0.75 * 2 * wII / 40000);
	EXPECT_EQ(p.d.tension, 0.0);
	// At the break the stress is on the residual surface, |τ| = -σ₀ tanφ_r, handed to the contact spring.
	EXPECT_NEAR(p.tau.norm(), 0.5e6 * 0.6, 1e-9 * 0.5e6);
	// Work along the path = dissipation + what the spring still stores (its compression σ₀²/2k_n and the residual
	// τ²/2k_s), within the trapezoid error.
	EXPECT_NEAR(p.work, p.dissipated() + p.stored(), 1e-3 * p.dissipated());
}

TEST(Softening, MixedModeBalancesWorkAndDissipation)
{
	// Opening and slip together (u_s = 3 u_n): tension and shear soften one common ξ; every increment is booked to the
	// mode that made it. The work of the stresses equals the booked dissipation; it lies between the two modes'
	// energies in tension (the Coulomb surface's friction is negative under σ > 0).
	Path         p(joint());
	const double wI = 2 * 18.0 / 0.25e6;
	p.to(wI, V(3 * wI, 0, 0), 40000);
	ASSERT_NE(p.state, SegmentState::Intact);
	EXPECT_NEAR(p.work, p.dissipated() + p.stored(), 2e-3 * p.dissipated());
	EXPECT_GT(p.d.tension, 0.0);
	EXPECT_GT(p.d.shear, 0.0);
	EXPECT_EQ(p.st.xi, 1.0);
	// ξ = w/w_I + κ/w_II = 1 at the break: each mode's share of G_f.
	EXPECT_NEAR(p.st.crack / wI + p.st.slip.norm() / (2 * 125.0 / 0.35e6), 1.0, 1e-12);
	EXPECT_LT(p.d.tension + p.d.shear, 18.0 + 125.0);
}

TEST(Softening, CompressionCapCrushesToItsResidual)
{
	// Cap f_c = 10 MPa, G_fc = 5000 J/m², residual 0.2: κ_u = 2·5000/(0.8·1e7) = 1.25e-3 m.
	Path p(joint());
	p.k.fc          = 10e6;
	p.k.Gfc         = 5000;
	p.k.residual    = 0.2;
	const double ku = 1.25e-3;
	p.to(-2 * ku, V::Zero(), 40000);
	EXPECT_EQ(p.state, SegmentState::Intact);
	// On the residual plateau at the end: σ = -r f_c exactly, κ = -u - r f_c/k_n.
	EXPECT_NEAR(p.sigma, -0.2 * 10e6, 1e-9 * 10e6);
	EXPECT_NEAR(p.st.crush, 2 * ku - 0.2 * 10e6 / 1e11, 1e-12);
	// Booked: G_fc above the plateau plus r f_c times the whole closure; the work of σ along the path: that plus the stored
	// (r f_c)²/2k_n.
	EXPECT_NEAR(p.d.crushing, 5000 + 0.2 * 10e6 * p.st.crush, 1e-9 * 5000);
	EXPECT_NEAR(p.work, p.d.crushing + p.stored(), 1e-3 * 5000);
	EXPECT_NEAR(rdem::capWork(p.k, ku), 5000 + 0.2 * 10e6 * ku, 1e-9 * 5000);
}

TEST(Softening, CapUnderTheCellsStressBooksTheSpringsWork)
{
	/* The cap yields on the total stress σ + σ_extra (the Poisson cells' normal stress on the face, constant here), so
	   the spring itself carries σ = -f_c(κ) - σ_extra: in a compressed column of cells σ_extra > 0 (the cells' E - M < 0
	   pulls the face), and the spring carries more than f_c. What its force dissipates is ∫-σ dκ = ∫(f_c + σ_extra)dκ,
	   not the cap's ∫f_c dκ: the work of the spring's stress along the path balances the booked crushing plus what the
	   spring stores only with the σ_extra κ term (without it, 3750 J/m² of 8750 go missing here). */
	for (double extra : { 1.5e6, -1.5e6 }) {
		Path p(joint());
		p.k.fc          = 10e6;
		p.k.Gfc         = 5000;
		p.k.residual    = 0.2;
		p.extra         = extra;
		const double ku = 1.25e-3;
		p.to(-2 * ku, V::Zero(), 40000);
		ASSERT_EQ(p.state, SegmentState::Intact);
		// On the residual plateau: σ + σ_extra = -r f_c.
		EXPECT_NEAR(p.sigma, -0.2 * 10e6 - extra, 1e-9 * 10e6) << extra;
		// Booked: G_fc above the plateau, r f_c times the whole closure and σ_extra times it, exactly.
		EXPECT_NEAR(p.d.crushing, 5000 + (0.2 * 10e6 + extra) * p.st.crush, 1e-9 * 5000) << extra;
		EXPECT_NEAR(p.work, p.d.crushing + p.stored(), 1e-3 * 5000) << extra;
	}
}

TEST(Softening, NoTrialShearBeyondTheApexIsNoSlip)
{
	/* A face barely pressed while the cells pull it: σ + σ_extra beyond the Coulomb surface's apex c(1 - ξ)/tanφ with
	   no shear displacement. The shear return has no direction to slip in: τ stays zero (finite), and neither slip nor
	   softening nor dissipation follows from it. */
	rdem::SofteningState<double>       st;
	rdem::SofteningDissipation<double> d;
	const auto                         r = rdem::softeningStep(joint(), -1e-9, V(V::Zero()), 1.5e6, st, d);
	EXPECT_EQ(r.state, SegmentState::Intact);
	EXPECT_TRUE(r.tau.allFinite());
	EXPECT_EQ(r.tau.norm(), 0);
	EXPECT_EQ(st.xi, 0);
	EXPECT_EQ(st.slip.norm(), 0);
	EXPECT_EQ(d.shear + d.friction, 0);
}

TEST(Softening, TensionUnderTheCellsStressBooksTheSpringsWork)
{
	/* The tension cut-off on the total stress: the spring carries σ = f_t(1 - ξ) - σ_extra, and its force dissipates
	   ∫σ dw, G_f^I less σ_extra w. Cells that press the face (σ_extra < 0) make the spring carry -σ_extra even when ξ
	   reaches 1: released at the break (σ_extra²/2k_n). Cells that pull it (σ_extra > 0) up to a partial softening. */
	const double wI = 2 * 18.0 / 0.25e6;
	{
		Path p(joint());
		p.extra = -0.1e6;
		p.to(2 * wI, V::Zero(), 40000);
		ASSERT_EQ(p.state, SegmentState::BrokenTension);
		EXPECT_NEAR(p.d.tension, 18.0 + 0.1e6 * wI + 0.1e6 * 0.1e6 / (2 * 1e11), 1e-9 * 18.0);
		EXPECT_NEAR(p.work, p.d.tension, 1e-3 * 18.0);
	}
	{
		Path p(joint());
		p.extra = 0.05e6;
		p.to(wI / 2, V::Zero(), 20000);
		ASSERT_EQ(p.state, SegmentState::Intact);
		ASSERT_GT(p.st.xi, 0.3);
		EXPECT_NEAR(p.sigma, 0.25e6 * (1 - p.st.xi) - 0.05e6, 1e-6 * 0.25e6);
		EXPECT_NEAR(p.d.tension, 18.0 * (1 - (1 - p.st.xi) * (1 - p.st.xi)) - 0.05e6 * p.st.crack, 1e-9 * 18.0);
		EXPECT_NEAR(p.work, p.d.tension + p.stored(), 1e-3 * 18.0);
	}
}

TEST(Softening, ChecksNameTheParameterAndTheBound)
{
	auto k = joint();
	EXPECT_EQ(rdem::checkSoftening(k, "RdemJoint"), "");
	// Snap-back: f_t²/(2k_n) = 0.0625e12/(2e9) = 31.25 J/m² > G_f^I = 18 with k_n = 1e9.
	k.kn                = 1e9;
	const std::string e = rdem::checkSoftening(k, "RdemJoint 'bed'");
	EXPECT_NE(e.find("RdemJoint 'bed'.fractureEnergy = 18: must be > tensileStrength^2/(2 k_n) = 31.25"), std::string::npos) << e;
	k      = joint();
	k.GfII = 0;
	EXPECT_NE(rdem::checkSoftening(k, "RdemMat").find("RdemMat.shearFractureEnergy = 0: must be > 0"), std::string::npos);
	k    = joint();
	k.ft = 0.5e6; // 0.5e6·0.75 > 0.35e6: the cut-off outside the Coulomb cone
	EXPECT_NE(rdem::checkSoftening(k, "RdemMat").find("RdemMat.tensileStrength = 500000: must be <= cohesion/tan"), std::string::npos);
	k     = joint();
	k.fc  = 10e6;
	k.Gfc = 0;
	EXPECT_NE(rdem::checkSoftening(k, "RdemMat").find("RdemMat.compressiveFractureEnergy = 0: must be > 0"), std::string::npos);
}

TEST(Softening, InfiniteStrengthsNeverSoften)
{
	// f_t = c = ∞ (the RdemMat default for c): a linear elastic spring, whatever the displacement.
	Path p(joint());
	p.k.ft = inf;
	p.k.c  = inf;
	p.to(1e-2, V(1e-2, 0, 0), 10);
	EXPECT_EQ(p.state, SegmentState::Intact);
	EXPECT_EQ(p.sigma, 1e11 * 1e-2);
	EXPECT_EQ(p.tau, V(4e10 * 1e-2, 0, 0));
	EXPECT_EQ(p.dissipated(), 0.0);
}

} // namespace

TEST(Softening, ScaledStrengthsScaleThePeakAndTheFractureEnergyNotTheOpening)
{
	// Heterogeneity (doc/theory.md §2.2): a segment of factor f = 1.3 peaks at f f_t and dissipates f G_f^I over the
	// material's final opening w_I = 2G_f^I/f_t; stiffness, friction and residual unchanged.
	const double f = 1.3;
	const auto   k = rdem::scaledStrengths(joint(), f);
	EXPECT_DOUBLE_EQ(k.kn, 1e11);
	EXPECT_DOUBLE_EQ(k.tanPhiR, 0.6);
	EXPECT_DOUBLE_EQ(rdem::finalOpening(k.ft, k.GfI), rdem::finalOpening(0.25e6, 18.0));
	EXPECT_DOUBLE_EQ(k.c, f * 0.35e6);
	EXPECT_DOUBLE_EQ(k.GfII, f * 125.0);
	Path p(k);
	p.to(2 * rdem::finalOpening(0.25e6, 18.0), V::Zero(), 20000);
	EXPECT_EQ(p.state, SegmentState::BrokenTension);
	EXPECT_NEAR(p.d.tension, f * 18.0, 1e-9 * 18.0);
	// Peak: f f_t within one step's stress increment (k_n times the step 1.44e-8 m, 1.4e3 Pa against 3.25e5 Pa).
	EXPECT_NEAR(p.peakSigma, f * 0.25e6, 1e11 * 2 * rdem::finalOpening(0.25e6, 18.0) / 20000);
}
