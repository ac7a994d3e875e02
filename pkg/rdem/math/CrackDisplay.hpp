/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* What YADE's 3D view shows of the refined DEM (Gl1_RdemPhys, GlExtra_RdemPoissonElements): which mark a bonded
   segment gets, where its quad lies, and the edges of a Poisson element.

   A segment k = i n + j of a bond's shared face (paper §3.1, Fig. 2a) is the rectangle c + s a + r b ± a ± b in body 1's
   frame, (s, r) its grid coordinates (rdem::segmentCoordinate), c the face centre and a, b the segment's half-size
   vectors; its centre is the material point P₁ of body 1 that the law uses (rdem::bondKinematics). Units: m.
   Sign convention: normal stress σ positive in tension (paper eq. 14), as in RdemPhys::segSigma. */
#pragma once

#include <pkg/rdem/math/Failure.hpp>

#include <Eigen/Core>
#include <array>

namespace yade {
namespace rdem {

	/// The mark of a bonded segment in the view: what broke it (eqs. 15-16 [P]) or crushed it (compression cap of the
	/// softening model, Lourenço & Rots 1997); None for an intact, uncrushed segment (not drawn).
	enum class SegmentMark { None = 0, Tension = 1, Shear = 2, Crushing = 3 };

	/// Mark of a segment of state `state` (RdemPhys::segState, SegmentState's values) and plastic crushing closure `crush`
	/// [m] (RdemPhys::segCrush, 0 without softening). A broken segment shows what broke it, even if it was crushed before.
	template <class S> SegmentMark segmentMark(int state, S crush)
	{
		if (state == int(SegmentState::BrokenTension)) return SegmentMark::Tension;
		if (state == int(SegmentState::BrokenShear)) return SegmentMark::Shear;
		return crush > 0 ? SegmentMark::Crushing : SegmentMark::None;
	}

	/// Whether a broken segment is a closed crack: its contact spring (eq. 13 [P]) touches and carries compression, σ < 0
	/// (RdemPhys::segSigma; the law sets it to 0 while the segment's sides are apart).
	template <class S> bool segmentInContact(int state, S sigma) { return state != int(SegmentState::Intact) && sigma < 0; }

	/// Corners (counter-clockwise about a × b) of the quad drawn for the segment at grid coordinates (s, r) of a face of
	/// centre c and segment half-size vectors a, b, all in body 1's frame [m], shrunk about the segment's centre by
	/// `fill` (1: the segments tile the face; less leaves a gap between neighbours) [m].
	template <class S>
	std::array<Eigen::Matrix<S, 3, 1>, 4>
	segmentQuad(const Eigen::Matrix<S, 3, 1>& c, const Eigen::Matrix<S, 3, 1>& a, const Eigen::Matrix<S, 3, 1>& b, S s, S r, S fill)
	{
		const Eigen::Matrix<S, 3, 1> centre = c + s * a + r * b, u = fill * a, v = fill * b;
		return { centre - u - v, centre + u - v, centre + u + v, centre - u + v };
	}

	/// Colour of a Poisson element of force scale `scale` (1 intact … 0 released by cracks, RdemPoissonEngine's
	/// elementScales): linear from `released` to `intact`, scale clamped to [0, 1]. RGB in [0, 1].
	template <class S> Eigen::Matrix<S, 3, 1> elementColour(S scale, const Eigen::Matrix<S, 3, 1>& intact, const Eigen::Matrix<S, 3, 1>& released)
	{
		const S t = scale < 0 ? S(0) : scale > 1 ? S(1) : scale;
		return released + t * (intact - released);
	}

} // namespace rdem
} // namespace yade
