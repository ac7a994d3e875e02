/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Failure of restoring springs and the friction limit of contact springs.

   Reference [P]: eqs. (14)-(17) of the paper (shared/reference/paper-poisson-effect-refined-dem.txt).
   Sign convention: normal stress σ positive in TENSION (as in eq. 14); τ is the magnitude of the shear
   stress in the face plane. Units: Pa. */
#pragma once

#include <cmath>

namespace yade {
namespace rdem {

	/// What broke a restoring spring. The integer values are stored per segment in RdemPhys::segState.
	enum class SegmentState { Intact = 0, BrokenTension = 1, BrokenShear = 2 };

	/// Eq. (15) [P]: tensile yield function f_1 = σ - f_t; the spring breaks when f_1 > 0.
	template <class S> S tensileYield(S sigma, S ft) { return sigma - ft; }

	/// Eq. (16) [P]: Mohr-Coulomb yield function f_2 = |τ| + σ tanφ - c; the spring breaks when f_2 > 0.
	template <class S> S shearYield(S sigma, S tau, S tanPhi, S c)
	{
		using std::abs;
		return abs(tau) + sigma * tanPhi - c;
	}

	/// Eqs. (15)-(16) [P]: state of a restoring spring after a step with stresses (σ, τ). Tension is checked first,
	/// so a spring that violates both criteria counts as a tensile break. An infinite c or f_t never breaks.
	template <class S> SegmentState restoringSpringState(S sigma, S tau, S ft, S c, S tanPhi)
	{
		if (tensileYield(sigma, ft) > 0) return SegmentState::BrokenTension;
		if (shearYield(sigma, tau, tanPhi, c) > 0) return SegmentState::BrokenShear;
		return SegmentState::Intact;
	}

	/// Eq. (17) [P]: largest shear stress a contact spring transmits, |τ| ≤ -σ tanφ for σ ≤ 0 (compression); zero in tension.
	template <class S> S frictionLimit(S sigma, S tanPhi) { return sigma < 0 ? -sigma * tanPhi : S(0); }

} // namespace rdem
} // namespace yade
