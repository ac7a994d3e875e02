/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Softening restoring springs: a traction-separation law per segment after the composite interface model of
   Lourenço & Rots (1997, J. Eng. Mech. 123(7):660-668, [LR]; doc/references.bib LourencoRots1997), derived in
   doc/sphinx/rdemTheory.rst §2.1.

   Three surfaces on the stresses of the segment's spring, each with its own plastic displacement:
   * tension cut-off       σ ≤ f_t(ξ) = f_t (1 - ξ),                       plastic crack opening w ≥ 0;
   * Coulomb friction      |τ| ≤ c(ξ) - σ tanφ(ξ), c(ξ) = c (1 - ξ),        plastic slip vector s (no dilatancy);
                           tanφ(ξ) = tanφ₀ + (tanφ_r - tanφ₀) ξ;
   * compression cap       -σ ≤ f_c(κ), linear from f_c to r f_c over κ_u,  plastic crushing closure κ ≥ 0.
   Tension and shear soften together ([LR]'s isotropic coupling): one variable ξ ∈ [0, 1] with dξ = dw/w_I + dκ_s/w_II,
   w_I = 2G_f^I/f_t and w_II = 2G_f^II/c the final opening and slip of the linear softening, so that a crack opened in
   pure mode I dissipates ∫f_t(ξ)dw = G_f^I per unit area and one slid in pure mode II ∫c(ξ)dκ_s = G_f^II, whatever the
   spring's stiffness (the segment's size), provided the spring does not snap back (k_n > f_t/w_I, k_s > c/w_II:
   checkSoftening). At ξ = 1 the spring is broken: the contact spring of the segment (eqs. 13, 17 of the paper) takes
   over, with the residual friction tanφ_r.

   Simplifications against [LR], stated in doc/sphinx/rdemTheory.rst §2.1: linear instead of exponential softening (the same G_f,
   a finite final opening, closed-form returns); the cap on σ alone (no τ term); the returns made one surface after the
   other (tension or cap, then shear with the updated σ and ξ) instead of [LR]'s corner return; an open crack closes
   without stress (σ = 0 for 0 ≤ u < w: crack faces apart) and carries compression once closed (u < 0).

   Sign convention: σ and the opening u_n positive in TENSION (paper eq. 14). Units: stiffness per area [N/m³],
   stresses [Pa], displacements [m], fracture energies and dissipation per unit area [J/m²]. */
#pragma once

#include <pkg/rdem/math/Failure.hpp>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace yade {
namespace rdem {

	/// Constants of a softening spring per unit area.
	template <class S> struct SofteningConstants {
		S kn, ks;            ///< elastic springs k̄_n, k̄_s [N/m³] (eq. 12)
		S ft, GfI;           ///< tensile strength [Pa] (inf: no cut-off) and mode-I fracture energy [J/m²]
		S c, GfII;           ///< cohesion [Pa] (inf: no Coulomb surface) and mode-II fracture energy [J/m²]
		S tanPhi, tanPhiR;   ///< initial and residual friction coefficients tanφ₀, tanφ_r
		S fc, Gfc, residual; ///< compressive strength [Pa] (inf: no cap), its fracture energy [J/m²], residual fraction r
	};

	/// k with its strengths f_t, c, f_c and fracture energies G_f^I, G_f^II, G_fc multiplied by the heterogeneity factor
	/// f > 0 (doc/sphinx/rdemTheory.rst §2.2): the final openings 2G/f stay the material's; stiffnesses, friction and r unchanged.
	template <class S> SofteningConstants<S> scaledStrengths(SofteningConstants<S> k, S f)
	{
		k.ft *= f;
		k.GfI *= f;
		k.c *= f;
		k.GfII *= f;
		k.fc *= f;
		k.Gfc *= f;
		return k;
	}

	/// History of a softening spring: plastic crack opening w [m], crushing closure κ [m], softening ξ, plastic slip s [m].
	template <class S> struct SofteningState {
		S                      crack = 0, crush = 0, xi = 0;
		Eigen::Matrix<S, 3, 1> slip = Eigen::Matrix<S, 3, 1>::Zero();
	};

	/// Energy dissipated in a step per unit area [J/m²]: tension softening (mode I), cohesion softening (mode II), friction
	/// on the Coulomb surface (-σ tanφ times the slip; negative in tension), crushing.
	template <class S> struct SofteningDissipation {
		S tension = 0, shear = 0, friction = 0, crushing = 0;
	};

	/// Stresses of a softening spring after a step: σ (tension > 0) [Pa], τ [Pa], and Intact or what broke it (ξ = 1).
	template <class S> struct SofteningStress {
		S                      sigma;
		Eigen::Matrix<S, 3, 1> tau;
		SegmentState           state;
	};

	/// Final crack opening (or slip) of a linear softening from strength f to 0 that dissipates G: w = 2G/f [m].
	template <class S> S finalOpening(S f, S G) { return 2 * G / f; }

	/// Compressive strength of the cap after the crushing closure κ [m]: linear from f_c to r f_c over κ_u =
	/// 2G_fc/((1-r) f_c), then r f_c [Pa].
	template <class S> S capStrength(const SofteningConstants<S>& k, S kappa)
	{
		const S ku = finalOpening((1 - k.residual) * k.fc, k.Gfc);
		return kappa < ku ? k.fc * (1 - (1 - k.residual) * kappa / ku) : k.residual * k.fc;
	}

	/// Work of the cap's stress from closure 0 to κ, ∫₀^κ f_c(κ')dκ' [J/m²] (capStrength integrated in closed form).
	template <class S> S capWork(const SofteningConstants<S>& k, S kappa)
	{
		const S ku = finalOpening((1 - k.residual) * k.fc, k.Gfc);
		if (kappa < ku) return k.fc * (kappa - (1 - k.residual) * kappa * kappa / (2 * ku));
		return k.fc * (ku - (1 - k.residual) * ku / 2) + k.residual * k.fc * (kappa - ku);
	}

	/* Compression cap: returns σ (< 0) for the trial σ_tr = k_n u (u < 0) and advances the crushing closure κ. Yield on
	   the total stress σ + σ_extra; the softening branch (slope H = (1-r)f_c/κ_u) and the residual plateau are each
	   returned exactly (piecewise linear in κ). Books the work of the spring's own stress on the closure, ∫-σ dκ =
	   ∫(f_c(κ) + σ_extra)dκ (on the cap σ = -f_c(κ) - σ_extra): what the spring's force dissipates, which differs from
	   the cap's ∫f_c dκ by σ_extra κ where the Poisson cells load the face (σ_extra constant within the step). */
	template <class S> S capReturn(const SofteningConstants<S>& k, S sigmaTrial, S sigmaExtra, SofteningState<S>& st, SofteningDissipation<S>& d)
	{
		S F = -(sigmaTrial + sigmaExtra) - capStrength(k, st.crush);
		if (!(F > 0)) return sigmaTrial;
		const S ku = finalOpening((1 - k.residual) * k.fc, k.Gfc), H = (1 - k.residual) * k.fc / ku;
		S       dk = 0;
		if (st.crush < ku) {
			dk = k.kn > H ? F / (k.kn - H) : std::numeric_limits<S>::infinity();
			if (st.crush + dk > ku) { // past the softening branch: the rest on the residual plateau
				F -= (k.kn - H) * (ku - st.crush);
				dk = ku - st.crush + F / k.kn;
			}
		} else
			dk = F / k.kn;
		d.crushing += capWork(k, st.crush + dk) - capWork(k, st.crush) + sigmaExtra * dk;
		st.crush += dk;
		return sigmaTrial + k.kn * dk;
	}

	/* Tension cut-off: returns σ for the trial σ_tr = k_n(u - w) ≥ 0 and advances w and ξ (slope H = f_t/w_I of
	   f_t(ξ) in w), booking the work of the spring's own stress on the opening, ∫σ dw = ∫(f_t(ξ) - σ_extra)dw (on the
	   cut-off σ = f_t(ξ) - σ_extra; trapezoid, exact for the linear law): ∫f_t(ξ)dw, the fracture energy, less
	   σ_extra w where the Poisson cells load the face. Sets broken when ξ reaches 1 (then the exact rest is booked, with
	   the energy σ_extra²/2k_n the spring still held on the cut-off, and σ = 0). */
	template <class S>
	S tensionReturn(const SofteningConstants<S>& k, S sigmaTrial, S sigmaExtra, SofteningState<S>& st, SofteningDissipation<S>& d, bool& broken)
	{
		const S F = sigmaTrial + sigmaExtra - k.ft * (1 - st.xi);
		if (!(F > 0)) return sigmaTrial;
		const S wI = finalOpening(k.ft, k.GfI), H = k.ft / wI;
		const S dw = k.kn > H ? F / (k.kn - H) : std::numeric_limits<S>::infinity();
		if (!(st.xi + dw / wI < 1)) { // fully softened in this step (or a spring that would snap back: at once)
			const S rest = (1 - st.xi) * wI;
			d.tension += k.ft * (1 - st.xi) * rest / 2 - sigmaExtra * rest + sigmaExtra * sigmaExtra / (2 * k.kn);
			st.crack += rest;
			st.xi  = 1;
			broken = true;
			return 0;
		}
		const S xiNew = st.xi + dw / wI;
		d.tension += (k.ft * ((1 - st.xi) + (1 - xiNew)) / 2 - sigmaExtra) * dw;
		st.crack += dw;
		st.xi = xiNew;
		return sigmaTrial - k.kn * dw;
	}

	/* Coulomb surface with cohesion softening: returns τ for the trial τ_tr = k_s(u_s - s) at normal stress σ (total
	   σ + σ_extra in the criterion), advancing s along τ_tr (no dilatancy) and ξ by dκ/w_II. Slope of the yield stress
	   Y(ξ) = c(ξ) - σ tanφ(ξ) in the slip: -H, H = (c + σ(tanφ_r - tanφ₀))/w_II. Books ∫c(ξ)dκ as shear and
	   ∫-σ tanφ(ξ)dκ as friction (trapezoids, exact: both linear in κ). Sets broken when ξ reaches 1, and returns the
	   residual friction stress -σ tanφ_r along the slip (the slip beyond w_II on it booked as friction). */
	template <class S>
	Eigen::Matrix<S, 3, 1> shearReturn(
	        const SofteningConstants<S>&  k,
	        const Eigen::Matrix<S, 3, 1>& tauTrial,
	        S                             sigma,
	        SofteningState<S>&            st,
	        SofteningDissipation<S>&      d,
	        bool&                         broken)
	{
		using std::isfinite;
		if (!isfinite(k.c)) return tauTrial;
		const S tn     = tauTrial.norm();
		auto    tanPhi = [&](S xi) { return k.tanPhi + (k.tanPhiR - k.tanPhi) * xi; };
		const S F      = tn - (k.c * (1 - st.xi) - sigma * tanPhi(st.xi));
		// No trial shear: nothing to return and no direction to slip in. F > 0 then means σ beyond the surface's apex
		// (the cells pulling a barely pressed face), a normal stress that the tension cut-off deals with, not slip.
		if (!(F > 0) || !(tn > 0)) return tauTrial;
		const S wII = finalOpening(k.c, k.GfII), H = (k.c + sigma * (k.tanPhiR - k.tanPhi)) / wII;
		S       dk = k.ks > H ? F / (k.ks - H) : std::numeric_limits<S>::infinity();
		if (!(st.xi + dk / wII < 1)) { // fully softened in this step: the exact rest of the two integrals, then residual
			const S dkSoft = (1 - st.xi) * wII, tauR = -sigma * k.tanPhiR > 0 ? -sigma * k.tanPhiR : S(0);
			const S dkAll = (tn - tauR) / k.ks > dkSoft ? (tn - tauR) / k.ks : dkSoft; // slip to the residual surface
			d.shear += k.c * (1 - st.xi) * dkSoft / 2;
			d.friction += -sigma * (tanPhi(st.xi) + k.tanPhiR) / 2 * dkSoft + tauR * (dkAll - dkSoft);
			st.slip += dkAll * tauTrial / tn;
			st.xi  = 1;
			broken = true;
			return tauTrial * (tauR / tn); // the residual friction, which the contact spring takes over
		}
		const S xiNew = st.xi + dk / wII;
		d.shear += k.c * ((1 - st.xi) + (1 - xiNew)) / 2 * dk;
		d.friction += -sigma * (tanPhi(st.xi) + tanPhi(xiNew)) / 2 * dk;
		st.slip += dk * tauTrial / tn;
		st.xi          = xiNew;
		const S remain = tn - k.ks * dk; // = Y(ξ_new) ≥ 0 where checkSoftening holds (f_t tanφ ≤ c)
		return remain > 0 ? Eigen::Matrix<S, 3, 1>(tauTrial * (remain / tn)) : Eigen::Matrix<S, 3, 1>::Zero();
	}

	/* One step of a softening spring: stresses for the segment's total opening u_n and shear displacement u_s [m]
	   (eq. 14's measures; u_s in any fixed frame, the slip s is kept in the same), updating the history st and adding
	   the step's dissipation to d. σ_extra: the normal stress the Poisson cells add to the face (doc/sphinx/rdemTheory.rst
	   §5.6), in the criteria (the spring's own σ is returned, and the dissipation is the work of its own stresses).
	   Normal: u = u_n + κ (the crushed length taken off); u ≥ w: spring k_n(u - w), tension cut-off; 0 ≤ u < w: crack
	   open, σ = 0; u < 0: crack closed, k_n u, compression cap. Then shear. */
	template <class S>
	SofteningStress<S>
	softeningStep(const SofteningConstants<S>& k, S un, const Eigen::Matrix<S, 3, 1>& us, S sigmaExtra, SofteningState<S>& st, SofteningDissipation<S>& d)
	{
		using std::isfinite;
		bool    brokenTension = false, brokenShear = false;
		const S u     = un + st.crush;
		S       sigma = 0;
		if (u >= st.crack) {
			sigma = k.kn * (u - st.crack);
			if (isfinite(k.ft)) sigma = tensionReturn(k, sigma, sigmaExtra, st, d, brokenTension);
		} else if (u < 0) {
			sigma = k.kn * u;
			if (isfinite(k.fc)) sigma = capReturn(k, sigma, sigmaExtra, st, d);
		}
		SofteningStress<S> r;
		r.sigma = sigma;
		r.tau   = brokenTension ? Eigen::Matrix<S, 3, 1>::Zero() : shearReturn<S>(k, k.ks * (us - st.slip), sigma + sigmaExtra, st, d, brokenShear);
		r.state = brokenTension ? SegmentState::BrokenTension : brokenShear ? SegmentState::BrokenShear : SegmentState::Intact;
		return r;
	}

	/// Elastic energy per unit area stored in a softening spring with stresses (σ, τ): σ²/(2k_n) + |τ|²/(2k_s) [J/m²].
	template <class S> S softeningEnergy(const SofteningConstants<S>& k, S sigma, const Eigen::Matrix<S, 3, 1>& tau)
	{
		return sigma * sigma / (2 * k.kn) + tau.squaredNorm() / (2 * k.ks);
	}

	/// Softening parameters of a material or joint as the user sets them (validated by checkFractureParameters).
	template <class S> struct FractureParameters {
		S fractureEnergy, shearFractureEnergy, residualFrictionAngle, compressiveStrength, compressiveFractureEnergy, compressiveResidual;
	};

	/// Empty string if the softening parameters are admissible, else one line per violated bound ("<owner>.<name> = <value>:
	/// must be ..."). residualFrictionAngle NaN means "equal to frictionAngle".
	template <class S> std::string checkFractureParameters(const FractureParameters<S>& f, const std::string& owner)
	{
		using std::isfinite;
		using std::isnan;
		std::ostringstream err;
		const S            pi = S(3.14159265358979323846);
		auto               bad
		        = [&](const char* name, S value, const char* range) { err << owner << "." << name << " = " << value << ": must be " << range << "\n"; };
		if (!(isfinite(f.fractureEnergy) && f.fractureEnergy > 0)) bad("fractureEnergy", f.fractureEnergy, "finite and > 0 [J/m2]");
		if (!(isfinite(f.shearFractureEnergy) && f.shearFractureEnergy > 0)) bad("shearFractureEnergy", f.shearFractureEnergy, "finite and > 0 [J/m2]");
		if (!(isnan(f.residualFrictionAngle) || (f.residualFrictionAngle >= 0 && f.residualFrictionAngle < pi / 2)))
			bad("residualFrictionAngle", f.residualFrictionAngle, "in [0, pi/2) [rad] (nan: equal to frictionAngle)");
		if (!(f.compressiveStrength > 0)) bad("compressiveStrength", f.compressiveStrength, "> 0 [Pa] (inf: no compression cap)");
		if (!(isfinite(f.compressiveFractureEnergy) && f.compressiveFractureEnergy > 0))
			bad("compressiveFractureEnergy", f.compressiveFractureEnergy, "finite and > 0 [J/m2]");
		if (!(f.compressiveResidual >= 0 && f.compressiveResidual < 1)) bad("compressiveResidual", f.compressiveResidual, "in [0, 1)");
		return err.str();
	}

	/* Set-up check of a softening spring: empty if admissible, else one line per violated condition, naming owner's
	   parameter. Needed: fracture energies > 0 where the strength is finite; no snap-back of the spring against its
	   softening slope (k_n > f_t²/(2G_f^I), k_s > c²/(2G_f^II), k_n > (1-r)²f_c²/(2G_fc): else the elastic energy a
	   spring releases at its peak exceeds G_f and the law is not objective; smaller blocks or a larger G_f cure it);
	   a tension cut-off inside the Coulomb cone (f_t max(tanφ₀, tanφ_r) ≤ c, [LR]'s composite surface). */
	template <class S> std::string checkSoftening(const SofteningConstants<S>& k, const std::string& owner)
	{
		using std::isfinite;
		std::ostringstream err;
		if (isfinite(k.ft) && k.ft > 0) {
			if (!(k.GfI > 0)) err << owner << ".fractureEnergy = " << k.GfI << ": must be > 0 [J/m2] with tensileStrength = " << k.ft << "\n";
			else if (!(k.kn > k.ft * k.ft / (2 * k.GfI)))
				err << owner << ".fractureEnergy = " << k.GfI << ": must be > tensileStrength^2/(2 k_n) = " << k.ft * k.ft / (2 * k.kn)
				    << " [J/m2] for this bond (k_n = " << k.kn
				    << " N/m3): the spring would snap back; use smaller blocks or a larger fracture energy\n";
		}
		if (isfinite(k.c) && k.c > 0) {
			if (!(k.GfII > 0)) err << owner << ".shearFractureEnergy = " << k.GfII << ": must be > 0 [J/m2] with cohesion = " << k.c << "\n";
			else if (!(k.ks > k.c * k.c / (2 * k.GfII)))
				err << owner << ".shearFractureEnergy = " << k.GfII << ": must be > cohesion^2/(2 k_s) = " << k.c * k.c / (2 * k.ks)
				    << " [J/m2] for this bond (k_s = " << k.ks
				    << " N/m3): the spring would snap back; use smaller blocks or a larger fracture energy\n";
			const S tanMax = k.tanPhi > k.tanPhiR ? k.tanPhi : k.tanPhiR;
			if (isfinite(k.ft) && k.ft * tanMax > k.c)
				err << owner << ".tensileStrength = " << k.ft
				    << ": must be <= cohesion/tan(max(frictionAngle, residualFrictionAngle)) = " << k.c / tanMax
				    << " [Pa] with softening (the tension cut-off inside the Coulomb cone)\n";
		}
		if (isfinite(k.fc)) {
			if (!(k.Gfc > 0))
				err << owner << ".compressiveFractureEnergy = " << k.Gfc << ": must be > 0 [J/m2] with compressiveStrength = " << k.fc << "\n";
			else if (!(k.kn > (1 - k.residual) * (1 - k.residual) * k.fc * k.fc / (2 * k.Gfc)))
				err << owner << ".compressiveFractureEnergy = " << k.Gfc
				    << ": must be > ((1 - compressiveResidual) compressiveStrength)^2/(2 k_n) = "
				    << (1 - k.residual) * (1 - k.residual) * k.fc * k.fc / (2 * k.kn) << " [J/m2] for this bond (k_n = " << k.kn
				    << " N/m3): the spring would snap back\n";
		}
		return err.str();
	}

} // namespace rdem
} // namespace yade
