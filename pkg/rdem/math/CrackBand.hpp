/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The crack-band remedy for springs too long for their fracture energy (Bažant & Oh 1983, Materials and Structures
   16:155-177, doc/references.bib BazantOh1983; doc/sphinx/rdemTheory.rst §2.1).

   A softening spring of stiffness k per area (k = M/(ℓ_A + ℓ_B): the spring's tributary length plays the part of the
   crack band's width h) with strength f and fracture energy G snaps back when its elastic energy at the peak,
   f²/(2k), exceeds G (rdem::checkSoftening refuses it). Bažant & Oh's remedy for a finite element wider than the
   band whose softening would snap back: keep G, and lower the strength until the softening branch is vertical,
   f_eq = sqrt(2 E G / h) (here sqrt(2 k G)), so that the element dissipates G per unit crack area at a sudden drop.
   The same energy argument is applied to each softening surface of the spring: the tension cut-off (k_n, G_f^I), the
   Coulomb cohesion (k_s, G_f^II) and the compression cap, whose part (1 - r) f_c above the residual softens
   (k_n, G_fc). The strengths are lowered to a fraction rho < 1 of the vertical drop's elastic energy,
   f²/(2G) = rho k, because the return map of the law divides by k - H (H = f²/(2G) the softening slope): rho = 0.99
   leaves a branch 1 % short of vertical. A spring that does not snap back is left as it is; the fracture energies are
   never changed. A bond with per-segment strength factors (rdem::scaledStrengths) is bounded for its largest factor,
   the segment rdem::checkSoftening checks. If the cohesion is lowered, the tension cut-off is kept inside the Coulomb
   cone (f_t max(tanφ₀, tanφ_r) ≤ c, a condition of rdem::checkSoftening).

   Units: stiffness per area [N/m³], strengths [Pa], fracture energies [J/m²]. */
#pragma once

#include <pkg/rdem/math/Softening.hpp>

#include <cmath>

namespace yade {
namespace rdem {

	/// The fraction of the vertical drop's elastic energy the lowered strengths store at their peak (f²/(2G) = rho k).
	template <class S> constexpr S crackBandFraction() { return S(0.99); }

	/* Bažant & Oh's equivalent strength of a spring of stiffness k per area [N/m³] and fracture energy G [J/m²] at which
	   its elastic energy at the peak is rho G (rho = 1: the vertical drop, f = sqrt(2 k G)) [Pa]; for a strength
	   scaled with its fracture energy by the factor `factor` (a segment's), the unscaled strength whose scaled one is at
	   that bound, sqrt(2 rho k G/factor). */
	template <class S> S crackBandStrength(S k, S G, S rho, S factor = S(1))
	{
		using std::sqrt;
		return sqrt(2 * rho * k * G / factor);
	}

	/* k with f_t, c and f_c lowered where its springs would snap back (see above), for the largest strength factor
	   `factor` of its segments (1 without heterogeneity); everything else as in k. Strengths that are infinite (no
	   surface) or already admissible are kept. */
	template <class S> SofteningConstants<S> crackBandStrengths(SofteningConstants<S> k, S factor = S(1), S rho = crackBandFraction<S>())
	{
		using std::isfinite;
		if (isfinite(k.ft) && k.ft > 0 && k.GfI > 0) {
			const S bound = crackBandStrength(k.kn, k.GfI, rho, factor);
			if (k.ft > bound) k.ft = bound;
		}
		if (isfinite(k.c) && k.c > 0 && k.GfII > 0) {
			const S bound = crackBandStrength(k.ks, k.GfII, rho, factor);
			if (k.c > bound) {
				k.c            = bound;
				const S tanMax = k.tanPhi > k.tanPhiR ? k.tanPhi : k.tanPhiR;
				if (isfinite(k.ft) && tanMax > 0 && k.ft * tanMax > k.c) k.ft = k.c / tanMax;
			}
		}
		if (isfinite(k.fc) && k.Gfc > 0 && k.residual < 1) {
			const S bound = crackBandStrength(k.kn, k.Gfc, rho, factor) / (1 - k.residual);
			if (k.fc > bound) k.fc = bound;
		}
		return k;
	}

} // namespace rdem
} // namespace yade
