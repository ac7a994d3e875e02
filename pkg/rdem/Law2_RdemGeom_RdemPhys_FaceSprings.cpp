/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Scene.hpp>
#include <pkg/rdem/FindEngine.hpp>
#include <pkg/rdem/InertialMass.hpp>
#include <pkg/rdem/InteractionOrder.hpp>
#include <pkg/rdem/Ip2_RdemMat_RdemMat_RdemPhys.hpp>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/RdemRanks.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <pkg/rdem/math/BlockCells.hpp>
#include <pkg/rdem/math/ContactBound.hpp>
#include <pkg/rdem/math/DensityScaling.hpp>
#include <pkg/rdem/math/FaceSprings.hpp>
#include <pkg/rdem/math/LeapfrogEnergy.hpp>
#include <pkg/rdem/math/Softening.hpp>
#include <pkg/rdem/math/SortedKeys.hpp>
#include <algorithm>
#include <limits>
#include <type_traits>
#include <utility>

namespace yade {

YADE_PLUGIN((Law2_RdemGeom_RdemPhys_FaceSprings));
CREATE_LOGGER(Law2_RdemGeom_RdemPhys_FaceSprings);

/* How to read this file: Law2_RdemGeom_RdemPhys_FaceSprings::go (at the end) sends a bond to bondForces and a contact of
   blocks that are not bonded to sampledContactForces. A bond's segments run one of three laws each step: restoringSpring
   (an intact segment, eqs. 14-16), softeningSpring (an intact segment of a softening bond, doc/sphinx/rdemTheory.rst §2.1) or
   brokenSegment (its contact spring, eqs. 13, 17). A face-to-face contact goes to patchContactForces. The physics of
   a point is in pkg/rdem/math/FaceSprings.hpp (rdem::restoringStress, rdem::contactSpringForce) and
   pkg/rdem/math/Softening.hpp (rdem::softeningStep), unit-tested there; this file turns the blocks' motion into their
   arguments and their results into forces, moments, counters and energies. */
namespace {
	using Energies = rdem::SpringEnergies<Real>;

	/// Restoring springs broken in one call of the law.
	struct Breaks {
		int tension = 0, shear = 0;
	};

	/// e with its energies times share (rdem::energyShare: 1/2 for an interaction with a ghost of YADE's MPI).
	Energies shareOf(Energies e, Real share)
	{
		for (Real* x : { &e.elastic, &e.dashpot, &e.friction, &e.bondBreak, &e.contactRelease, &e.fractureTension, &e.fractureShear, &e.crushing })
			*x *= share;
		return e;
	}

	/// Force on body 2 and its moment about x₂, summed over the points of an interaction [N, N·m].
	struct ForceOnBody2 {
		Vector3r f = Vector3r::Zero(), t = Vector3r::Zero();
		/// Adds the force F at the point x₂ + r₂.
		void add(const Vector3r& F, const Vector3r& r2)
		{
			f += F;
			t += r2.cross(F);
		}
	};

	/// The two blocks of an interaction in this step: states, centroids (body 2 shifted by the periodic cell), time step.
	struct Pair {
		const State& s1;
		const State& s2;
		Vector3r     x1, x2;
		Real         dt;
		bool         trackEnergy;

		/// Velocity of body 2 relative to body 1 at the point x₂ + r₂ [m/s].
		Vector3r relativeVelocity(const Vector3r& r2) const { return s2.vel + s2.angVel.cross(r2) - s1.vel - s1.angVel.cross(r2 + x2 - x1); }

		/// Contact spring of a point of area A [m²] at C with normal n (eqs. 13, 17): p's constants per area times the
		/// weighted area, dashpots capped (dashpotCap) for the point's share of the contact area; friction tanPhi.
		rdem::ContactConstants<Real> contactConstants(const RdemPhys& p, Real area, const Vector3r& C, const Vector3r& n, Real share, Real tanPhi) const
		{
			const Real     an = p.weightNormal * area, as = p.weightShear * area;
			const Vector2r cMax = Law2_RdemGeom_RdemPhys_FaceSprings::dashpotCap(s1, x1, s2, x2, C, n, share, dt);
			return { p.kn * an, p.ks * as, math::min(p.cn * an, cMax[0]), math::min(p.cs * as, cMax[1]), tanPhi };
		}
	};

	/* Offset correction of a bond's intact shear springs (rdem::offsetSlip, doc/sphinx/rdemTheory.rst §5.4): the slip E₁a₁ - E₂a₂
	   that the blocks' cell strains (RdemState::strain, scaled by RdemState::cellScale, from RdemCellStrainUpdater) give
	   at the bonded face's centre, a_b its offset from block b's centroid along the face (a1 in body 1's frame, a2 in body
	   2's), in global coordinates and in the tangent plane of n [m]. */
	Vector3r cellOffsetSlip(
	        const State&    s1,
	        const State&    s2,
	        const Matrix3r& R1,
	        const Matrix3r& R12,
	        const RdemGeom& g,
	        const Vector3r& a1,
	        const Vector3r& a2,
	        const Vector3r& n)
	{
		const auto&    a     = static_cast<const RdemState&>(s1);
		const auto&    b     = static_cast<const RdemState&>(s2);
		const Vector3r local = rdem::offsetSlip<Real>(a.cellScale * a.strain, a1, R12, b.cellScale * b.strain, a2, g.segNormal1);
		const Vector3r slip  = R1 * local;
		return slip - slip.dot(n) * n;
	}

	/* Normal stress the Poisson cells of the two blocks exert on their bonded face, positive in tension [Pa]: the cell
	   force on the bond, -(c₁S₁ + c₂S₂) on body 2 along n (RdemPoissonEngine), as a traction over the face's weighted
	   area w_n A, from the cells' elastic stresses of this step (RdemState::cellStress, along each block's axis of the
	   bond). Added to the springs' σ = k_n u_n it is the total σ_nn of the face (doc/sphinx/rdemTheory.rst §5.6). Zero without cells. */
	Real cellNormalStress(const State& s1, const State& s2, const RdemGeom& g, const RdemPhys& p)
	{
		if (p.cellCoef1 == 0 && p.cellCoef2 == 0) return 0;
		const auto& a = static_cast<const RdemState&>(s1);
		const auto& b = static_cast<const RdemState&>(s2);
		const Real  S = p.cellCoef1 * a.cellStress[rdem::dominantAxis<Real>(g.segNormal1)]
		        + p.cellCoef2 * b.cellStress[rdem::dominantAxis<Real>(g.segNormal2)];
		return S / (p.weightNormal * g.segmentArea() * Real(g.nSegments()));
	}

	/// Calls f(k, s, r) for every segment k = i n + j of a face of n×n segments, (s, r) its grid coordinates.
	template <class F> void forSegments(int nEdge, F f)
	{
		size_t k = 0;
		for (int i = 0; i < nEdge; ++i) {
			const Real s = rdem::segmentCoordinate<Real>(i, nEdge);
			for (int j = 0; j < nEdge; ++j, ++k)
				f(k, s, rdem::segmentCoordinate<Real>(j, nEdge));
		}
	}

	/* One step of a bond: the segments' kinematics of this step (RdemGeom::kin, set by the geometry functor; paper eq. 14),
	   the loop invariants, and the sums the segments' forces go into. Segment k = i n + j sits at grid coordinates
	   (s, r) = (s_i, s_j) (rdem::segmentCoordinate), where its d = P₂ - P₁ and r₂ = C - x₂ are affine in (s, r)
	   (rdem::BondKinematics). So is the moment of the segment forces about x₂: Σ r₂ × F = r0 × ΣF + ra × Σ sF + rb × Σ rF,
	   summed from three force sums without a cross product per segment. The constants are copied into the object, not
	   read from RdemPhys: the stores to the per-segment arrays could alias them (all doubles). */
	struct BondStep {
		const Pair&                    pair;
		const RdemGeom&                g;
		Matrix3r                       R1;  ///< rotation of body 1, for softening springs and offset bonds only (else identity)
		Vector3r                       n;   ///< face normal from body 1 to body 2
		rdem::BondKinematics<Real>     kin; ///< d and r₂ of the segments
		Real                           A;   ///< area of a segment [m²]
		rdem::RestoringConstants<Real> k;   ///< restoring springs per area
		Real                           wn, ws;
		Real                           springN, springS; ///< restoring spring of one segment with its weight, w k A [N/m]
		Real                           contactArea = 0;  ///< of the broken segments in contact: shares of the dashpot caps [m²]
		Vector3r                       slip;             ///< cells' offset slip of the intact shear springs [m]
		Real                           sigmaCells = 0;   ///< cells' normal stress on the face, for the criteria [Pa]
		Vector3r                       fSum = Vector3r::Zero(), fs = Vector3r::Zero(), fr = Vector3r::Zero(); ///< ΣF, Σ sF, Σ rF on body 2 [N]
		Vector3r                       tSum                = Vector3r::Zero(); ///< Σ w_s k_s A (d_t - slip) over the intact segments [N]
		bool                           anyIntactOrTouching = false;

		BondStep(const Pair& pr, RdemGeom& geom, const RdemPhys& p)
		        : pair(pr)
		        , g(geom)
		        , R1(p.softening || p.offsetCorrection ? pr.s1.ori.toRotationMatrix() : Matrix3r::Identity())
		        , n(geom.normal)
		        , kin(geom.kin)
		        , A(geom.segmentArea())
		        , k { p.kn, p.ks, p.tensileStrength, p.cohesion, p.tanFriction }
		        , wn(p.weightNormal)
		        , ws(p.weightShear)
		        , springN(wn * p.kn * A)
		        , springS(ws * p.ks * A)
		{
		}
		/// Adds the force F at the segment of grid coordinates (s, r).
		void applyAt(const Vector3r& F, Real s, Real r)
		{
			fSum += F;
			fs += s * F;
			fr += r * F;
		}
		/// A broken segment is in contact while its material points overlap and face each other (slid less than the
		/// smaller half-size of a segment).
		bool touching(Real un, const Vector3r& us) const { return un < 0 && us.norm() < g.segHalfSizes().minCoeff(); }
		/* Opening of broken segment i's contact spring [m] for the segment's opening un (eq. 14, positive in tension): un,
		   plus, for a softening bond, the closure κ that its compression cap crushed off while it was intact
		   (RdemPhys::segCrush; rdem::softeningStep's u = u_n + κ). The crushed material is gone: the contact spring takes
		   over the softening spring's σ = k̄_n u (u < 0, crack closed) without a jump, and is apart while the crack is open
		   (u ≥ 0). Counted from u_n alone, a segment crushed by κ that broke in tension at u_n < 0 pushed back at once
		   with k_n(-u_n), and the elastic energy of that spring came out of nothing. */
		Real contactOpening(const RdemPhys& p, size_t i, Real un) const { return p.softening ? un + p.segCrush[i] : un; }
		/// Sum of the areas of the broken segments in contact [m²].
		Real brokenContactArea(const RdemPhys& p) const
		{
			Real area = 0;
			forSegments(g.samplesPerEdge, [&](size_t i, Real s, Real r) {
				if (p.segState[i] == int(rdem::SegmentState::Intact)) return;
				const Vector3r d  = kin.displacement(s, r);
				const Real     un = d.dot(n);
				if (touching(contactOpening(p, i, un), d - un * n)) area += A;
			});
			return area;
		}
	};

	/* The restoring spring of intact segment i at (s, r) with opening un and shear elongation ust [m] (eqs. 14-16,
	   rdem::restoringStress): adds its force -(w_n σ n + w_s τ)A and returns true, or, if it breaks in this step, counts
	   the break, releases its elastic energy (rdemBondBreak) and returns false. withCells: judge it on σ plus the cells'
	   normal stress, and sum its shear force for the offset correction's reaction. */
	template <bool withCells>
	bool restoringSpring(BondStep& b, RdemPhys& p, size_t i, Real s, Real r, Real un, const Vector3r& ust, Energies& e, Breaks& breaks)
	{
		const auto stress = rdem::restoringStress<Real>(b.k, un, ust, withCells ? b.sigmaCells : Real(0));
		if (stress.state == rdem::SegmentState::Intact) {
			b.applyAt(-(b.springN * un * b.n + b.springS * ust), s, r); // -(w_n σ n + w_s τ) A
			if (withCells) b.tSum += b.springS * ust;
			p.segSigma[i]         = stress.sigma;
			p.segTau[i]           = stress.tauNorm;
			b.anyIntactOrTouching = true;
			if (b.pair.trackEnergy) e.elastic += rdem::restoringEnergy<Real>(b.k, stress, b.A, b.wn, b.ws);
			return true;
		}
		p.segState[i] = int(stress.state);
		if (stress.state == rdem::SegmentState::BrokenTension) breaks.tension += 1;
		else
			breaks.shear += 1;
		/* Released: the shear spring's energy, and the normal spring's unless the segment stays in contact, where its
		   contact spring (brokenSegment, in this step) takes over the compression w_n k̄_n A u_n²/2 with the same constant
		   (paper §3.2): booked there as elastic, it is not lost. Each as the leapfrog balance needs it,
		   rdem::releasedSpringEnergy with the springs' w k̄ A and the point's velocity v_{n-1/2} (body 2's relative to
		   body 1's; the elongations grew by it in the last step). */
		const Vector3r us    = ust + (withCells ? b.slip : Vector3r::Zero());
		const Vector3r v     = b.pair.relativeVelocity(b.kin.arm(s, r));
		const Real     vn    = v.dot(b.n);
		const Real     shear = rdem::releasedSpringEnergy<Real>(b.springS, ust, Vector3r(v - vn * b.n), b.pair.dt);
		e.bondBreak += b.touching(b.contactOpening(p, i, un), us) ? shear : shear + rdem::releasedSpringEnergy<Real>(b.springN, un, vn, b.pair.dt);
		p.segShear[i] = Vector3r::Zero();
		return false;
	}

	/* The softening spring of intact segment i at (s, r) (rdem::softeningStep, doc/sphinx/rdemTheory.rst §2.1), with opening un and
	   shear elongation ust [m]; its plastic slip is kept in body 1's frame, so that it turns with the pair. Adds its force
	   -(w_n σ n + w_s τ)A and the dissipation of the step (weighted by w_n for tension and crushing, w_s for shear and
	   friction, as the forces); returns false if it broke in this step (ξ reached 1): the contact spring takes over its
	   shear stress, and the elastic energy it cannot take (the segment apart) is released. */
	template <bool withCells>
	bool softeningSpring(
	        BondStep&                             b,
	        RdemPhys&                             p,
	        const rdem::SofteningConstants<Real>& k,
	        size_t                                i,
	        Real                                  s,
	        Real                                  r,
	        Real                                  un,
	        const Vector3r&                       ust,
	        Energies&                             e,
	        Breaks&                               breaks)
	{
		rdem::SofteningState<Real>       st { p.segCrack[i], p.segCrush[i], p.segSoftening[i], p.segSlip[i] };
		rdem::SofteningDissipation<Real> d;
		const auto                       stress = rdem::softeningStep<Real>(k, un, b.R1.transpose() * ust, withCells ? b.sigmaCells : Real(0), st, d);
		const Vector3r                   tauG   = b.R1 * stress.tau;
		const Vector3r                   tau    = tauG - tauG.dot(b.n) * b.n; // in the current tangent plane
		p.segCrack[i]                           = st.crack;
		p.segCrush[i]                           = st.crush;
		p.segSoftening[i]                       = st.xi;
		p.segSlip[i]                            = st.slip;
		e.softening                             = true;
		e.fractureTension += b.wn * b.A * d.tension;
		e.crushing += b.wn * b.A * d.crushing;
		e.fractureShear += b.ws * b.A * d.shear;
		e.friction += b.ws * b.A * d.friction;
		const Real elastic = b.A * (b.wn * stress.sigma * stress.sigma / k.kn + b.ws * tau.squaredNorm() / k.ks) / 2;
		if (stress.state == rdem::SegmentState::Intact) {
			b.applyAt(-(b.wn * stress.sigma * b.n + b.ws * tau) * b.A, s, r);
			if (withCells) b.tSum += b.ws * b.A * tau;
			p.segSigma[i]         = stress.sigma;
			p.segTau[i]           = tau.norm();
			b.anyIntactOrTouching = true;
			if (b.pair.trackEnergy) e.elastic += elastic;
			return true;
		}
		p.segState[i] = int(stress.state);
		if (stress.state == rdem::SegmentState::BrokenTension) breaks.tension += 1;
		else
			breaks.shear += 1;
		const Vector3r us = ust + (withCells ? b.slip : Vector3r::Zero());
		if (b.touching(b.contactOpening(p, i, un), us)) p.segShear[i] = tau / k.ks; // the contact spring carries on with the residual friction
		else {
			p.segShear[i] = Vector3r::Zero();
			e.bondBreak += elastic;
		}
		return false;
	}

	/* The contact spring of broken segment i at (s, r) with the segment's opening segmentOpening (its spring's:
	   BondStep::contactOpening) and shear displacement us [m] (eqs. 13, 17, rdem::contactSpringForce) while it touches;
	   zero otherwise. Its dashpot force is kept for the energy balance (the
	   array is sized here, not for every bond and step: an intact bond never reads its header). */
	void brokenSegment(BondStep& b, RdemPhys& p, size_t i, Real s, Real r, Real segmentOpening, const Vector3r& us, Energies& e)
	{
		const Real   un   = b.contactOpening(p, i, segmentOpening);
		const size_t nSeg = b.g.nSegments();
		if (p.segDashpot.size() != nSeg) p.segDashpot.resize(nSeg, Vector3r::Zero());
		if (!b.touching(un, us)) {
			p.segShear[i] = p.segDashpot[i] = Vector3r::Zero();
			p.segSigma[i] = p.segTau[i] = 0;
			return;
		}
		const Vector3r r2     = b.kin.arm(s, r);
		const Real     share  = b.contactArea > 0 ? b.A / b.contactArea : Real(1);   // a segment broken in this step joins now
		const Real     tanPhi = p.softening ? p.tanResidualFriction : p.tanFriction; // a softened bond slides on its residual friction
		const auto     k      = b.pair.contactConstants(p, b.A, b.pair.x2 + r2, b.n, share, tanPhi);
		const Vector3r F      = rdem::contactSpringForce<Real>(
                        k, -un, b.n, b.pair.relativeVelocity(r2), b.pair.dt, p.segShear[i], p.segDashpot[i], b.pair.trackEnergy, e);
		b.applyAt(F, s, r);
		p.segSigma[i]         = -F.dot(b.n) / (p.weightNormal * b.A);
		p.segTau[i]           = (F - F.dot(b.n) * b.n).norm() / (p.weightShear * b.A);
		b.anyIntactOrTouching = true;
	}

	/* Every segment of the bond, each by its law. Instantiated twice: with the Poisson cells' offset correction and
	   total stress (withCells), and without them, so that a bond of the paper's scene runs the same code as before the
	   cells (it inlines alike). */
	template <bool withCells> void segmentForces(BondStep& b, RdemPhys& p, Energies& e, Breaks& breaks)
	{
		const bool perSegment = !p.segStrengthFactor.empty(); // heterogeneous strengths per segment (doc/sphinx/rdemTheory.rst §2.2)
		const auto k          = b.k;
		forSegments(b.g.samplesPerEdge, [&](size_t i, Real s, Real r) {
			if (perSegment) b.k = rdem::scaledStrengths(k, p.segStrengthFactor[i]);
			const Vector3r d  = b.kin.displacement(s, r);
			const Real     un = d.dot(b.n); // eq. (14): opening positive
			const Vector3r us = d - un * b.n;
			if (p.segState[i] == int(rdem::SegmentState::Intact)
			    && restoringSpring<withCells>(b, p, i, s, r, un, withCells ? Vector3r(us - b.slip) : us, e, breaks))
				return;
			brokenSegment(b, p, i, s, r, un, us, e);
		});
		b.k = k;
	}

	/// segmentForces of a softening bond: softeningSpring in place of restoringSpring.
	template <bool withCells> void softeningSegmentForces(BondStep& b, RdemPhys& p, Energies& e, Breaks& breaks)
	{
		const auto k          = Ip2_RdemMat_RdemMat_RdemPhys::softeningConstants(p);
		const bool perSegment = !p.segStrengthFactor.empty(); // heterogeneous strengths per segment (doc/sphinx/rdemTheory.rst §2.2)
		forSegments(b.g.samplesPerEdge, [&](size_t i, Real s, Real r) {
			const Vector3r d  = b.kin.displacement(s, r);
			const Real     un = d.dot(b.n);
			const Vector3r us = d - un * b.n;
			if (p.segState[i] == int(rdem::SegmentState::Intact)
			    && softeningSpring<withCells>(
			            b,
			            p,
			            perSegment ? rdem::scaledStrengths(k, p.segStrengthFactor[i]) : k,
			            i,
			            s,
			            r,
			            un,
			            withCells ? Vector3r(us - b.slip) : us,
			            e,
			            breaks))
				return;
			brokenSegment(b, p, i, s, r, un, us, e);
		});
	}

	/* A bond (paper §3): its segments' forces into out, and, with the cells' offset correction, the correction's
	   reaction on the cells that made the strains (RdemPhys::offsetGrad1/2, summed by RdemPoissonEngine). Returns false
	   when every segment is broken and none is in contact: the bond is released (the interaction is reset) and the
	   collider and contact sampling take over. */
	bool bondForces(RdemGeom& g, RdemPhys& p, const Pair& pair, bool totalStress, Energies& e, Breaks& breaks, ForceOnBody2& out)
	{
		BondStep b(pair, g, p);
		b.contactArea = b.brokenContactArea(p);
		// Bonds whose centroids are offset along the face (cells only): the intact shear springs measure d_t - slip.
		const bool     offset = p.offsetCorrection;
		const Matrix3r R12    = offset ? Matrix3r(b.R1.transpose() * pair.s2.ori.toRotationMatrix()) : Matrix3r::Identity();
		// the face centre's offsets from the centroids along the face (rdem::offsetSlip's a₁, a₂), for the slip and its gradient
		const Vector3r a1    = offset ? rdem::alongFace<Real>(g.faceCentre1, g.segNormal1) : Vector3r::Zero();
		const Vector3r a2    = offset ? rdem::alongFace<Real>(g.faceCentre2, g.segNormal2) : Vector3r::Zero();
		b.slip               = offset ? cellOffsetSlip(pair.s1, pair.s2, b.R1, R12, g, a1, a2, b.n) : Vector3r::Zero();
		b.sigmaCells         = totalStress ? cellNormalStress(pair.s1, pair.s2, g, p) : Real(0);
		const bool withCells = offset || totalStress;
		if (p.softening) {
			if (withCells) softeningSegmentForces<true>(b, p, e, breaks);
			else
				softeningSegmentForces<false>(b, p, e, breaks);
		} else if (withCells)
			segmentForces<true>(b, p, e, breaks);
		else
			segmentForces<false>(b, p, e, breaks);
		out.f += b.fSum;
		out.t += b.kin.r0.cross(b.fSum) + b.kin.ra.cross(b.fs) + b.kin.rb.cross(b.fr);
		if (offset) {
			rdem::offsetSlipGradient<Real>(b.R1.transpose() * b.tSum, R12, a1, a2, p.offsetGrad1, p.offsetGrad2);
			p.offsetGrad1 *= static_cast<const RdemState&>(pair.s1).cellScale;
			p.offsetGrad2 *= static_cast<const RdemState&>(pair.s2).cellScale;
		}
		return b.anyIntactOrTouching;
	}

	/// The contact-sample history of one pair being made for this step, in the order of RdemGeom::sampleKey; one per
	/// thread, swapped with the pair's (RdemPhys::contactShear …), so that no step allocates once the sizes settle.
	struct SampleHistory {
		std::vector<int>      previous; ///< index of each sample in the last step's history, -1 if it was not in contact
		std::vector<Vector3r> shear, dashpot;
		std::vector<Real>     offset;
	};

	/* Blocks that are not bonded, in contact at the sample points of RdemGeom (doc/sphinx/rdemTheory.rst §4): each point's contact
	   spring (rdem::contactSpringForce), its history kept by sample key for the samples in contact in the last step
	   (RdemPhys::contactKey, matched by rdem::matchSortedKeys). A point that starts its contact already δ₀ deep
	   entered through a gap of the sampling (a region of overlap that held no sample point, or a change of the pair's
	   normal), not by the motion of one step: its spring counts from δ₀, lowered whenever the depth is (δ₀ = min over the
	   contact of δ), so that it never releases energy it did not store. Returns false when no point is in contact (the
	   collider drops the pair once the bounding boxes separate). */
	bool sampledContactForces(const RdemGeom& g, RdemPhys& p, const Pair& pair, Energies& e, ForceOnBody2& out)
	{
		const size_t n = g.sampleKey.size();
		if (n == 0) return false;
		static thread_local SampleHistory next;
		next.previous.resize(n);
		next.shear.resize(n);
		next.dashpot.resize(n);
		next.offset.resize(n);
		rdem::matchSortedKeys(p.contactKey, g.sampleKey.data(), n, next.previous.data());
		Real contactArea = 0;
		for (Real a : g.sampleArea)
			contactArea += a;
		for (size_t k = 0; k < n; ++k) {
			const int h     = next.previous[k];
			next.offset[k]  = h >= 0 ? math::min(p.contactOffset[size_t(h)], g.sampleDepth[k]) : g.sampleDepth[k];
			next.shear[k]   = h >= 0 ? p.contactShear[size_t(h)] : Vector3r::Zero();
			next.dashpot[k] = h >= 0 ? p.contactDashpot[size_t(h)] : Vector3r::Zero();
			const auto c
			        = pair.contactConstants(p, g.sampleArea[k], g.samplePoint[k], g.sampleNormal[k], g.sampleArea[k] / contactArea, p.tanFriction);
			const Vector3r F = rdem::contactSpringForce<Real>(
			        c,
			        g.sampleDepth[k] - next.offset[k],
			        g.sampleNormal[k],
			        g.sampleVel[k],
			        pair.dt,
			        next.shear[k],
			        next.dashpot[k],
			        pair.trackEnergy,
			        e);
			out.add(F, g.samplePoint[k] - pair.x2);
		}
		p.contactKey.assign(g.sampleKey.begin(), g.sampleKey.end());
		std::swap(p.contactShear, next.shear);
		std::swap(p.contactDashpot, next.dashpot);
		std::swap(p.contactOffset, next.offset);
		return true;
	}

	/* The terms of Law2_RdemGeom_RdemPhys_FaceSprings::dashpotCap that do not depend on the point, for the many points of
	   one interaction: 1/m and 1/I_min of each free block (zero for a fixed one), inertial (rdem::inertialFactor: m/s, I/s
	   with density scaling s). caps() gives the same caps. */
	struct DashpotCaps {
		Real     invMass1, invInertia1, invMass2, invInertia2;
		Vector3r x1, x2;
		Real     dt;
		DashpotCaps(const State& s1, const Vector3r& c1, const State& s2, const Vector3r& c2, Real step)
		        : invMass1(s1.blockedDOFs == State::DOF_ALL ? Real(0) : 1 / rdem::inertialMass(s1))
		        , invInertia1(s1.blockedDOFs == State::DOF_ALL ? Real(0) : 1 / rdem::inertialMinInertia(s1))
		        , invMass2(s2.blockedDOFs == State::DOF_ALL ? Real(0) : 1 / rdem::inertialMass(s2))
		        , invInertia2(s2.blockedDOFs == State::DOF_ALL ? Real(0) : 1 / rdem::inertialMinInertia(s2))
		        , x1(c1)
		        , x2(c2)
		        , dt(step)
		{
		}
		/// (c_n, c_s) caps at point C with normal n for the share of the contact area [N·s/m] (dashpotCap).
		Vector2r caps(const Vector3r& C, const Vector3r& n, Real share) const
		{
			const Vector3r r1 = C - x1, r2 = C - x2;
			const Real     invN = invMass1 + invMass2 + r1.cross(n).squaredNorm() * invInertia1 + r2.cross(n).squaredNorm() * invInertia2;
			const Real     invS = invMass1 + invMass2 + r1.squaredNorm() * invInertia1 + r2.squaredNorm() * invInertia2;
			const Real     inf  = std::numeric_limits<Real>::infinity();
			return Vector2r(invN > 0 ? share / (invN * dt) : inf, invS > 0 ? share / (invS * dt) : inf);
		}
	};

	/* Blocks that are not bonded, face to face: the contact springs of their patch (RdemGeom::patch, made by
	   Ig2_RdemBlock_RdemBlock_RdemGeom from rdem::facePatch), fixed material points P₁ of body 1 and P₂ of body 2 as the
	   segments of a bond: depth δ = -(P₂ - P₁)·n (n from body 1 to body 2, RdemGeom::normal of this step), contact
	   point at the mid-point, the contact spring of rdem::contactSpringForce (eqs. 13, 17) as for a sampled point, its
	   history by spring (RdemPhys::contactShear …; contactOffset < 0: out of contact in the last step). As a sampled
	   point, a spring that starts its contact δ₀ deep counts from δ₀, lowered whenever the depth is. The dashpot caps
	   share the area of the springs in contact, as for sampled points. Returns false when no spring is in contact. */
	bool patchContactForces(const RdemGeom& g, RdemPhys& p, const Pair& pair, Energies& e, ForceOnBody2& out)
	{
		const auto   springs = g.patchSprings();
		const size_t n       = springs.size;
		if (!p.contactKey.empty() || p.contactOffset.size() != n) { // a new patch without history (a sampled contact's was handed over)
			p.contactKey.clear();
			p.contactShear.assign(n, Vector3r::Zero());
			p.contactDashpot.assign(n, Vector3r::Zero());
			p.contactOffset.assign(n, Real(-1));
		}
		const Matrix3r  R1 = pair.s1.ori.toRotationMatrix(), R2 = pair.s2.ori.toRotationMatrix();
		const Vector3r& nrm = g.normal;
		const Vector3r  dx  = pair.x2 - pair.x1;
		// Two passes over the springs, both from the stored points (no buffer): the area in contact, for the dashpot caps'
		// shares, then the forces.
		Real contactArea = 0;
		for (size_t i = 0; i < n; ++i)
			if ((dx + R2 * springs.point2(i) - R1 * springs.point1(i)).dot(nrm) < 0) contactArea += springs.area(i);
		if (!(contactArea > 0)) {
			std::fill(p.contactOffset.begin(), p.contactOffset.end(), Real(-1));
			return false;
		}
		const DashpotCaps caps(pair.s1, pair.x1, pair.s2, pair.x2, pair.dt);
		const Real        wn = p.weightNormal, ws = p.weightShear;
		for (size_t i = 0; i < n; ++i) {
			const Vector3r a2    = R2 * springs.point2(i);
			const Vector3r d     = dx + a2 - R1 * springs.point1(i); // P₂ - P₁
			const Real     delta = -d.dot(nrm);
			if (!(delta > 0)) {
				p.contactShear[i] = p.contactDashpot[i] = Vector3r::Zero();
				p.contactOffset[i]                      = -1;
				continue;
			}
			p.contactOffset[i]                      = p.contactOffset[i] >= 0 ? math::min(p.contactOffset[i], delta) : delta;
			const Vector3r                     arm2 = a2 - d / 2; // the mid-point, from x₂
			const Real                         a    = springs.area(i);
			const Real                         an = wn * a, as = ws * a;
			const Vector2r                     cMax = caps.caps(pair.x2 + arm2, nrm, a / contactArea);
			const rdem::ContactConstants<Real> c {
				p.kn * an, p.ks * as, math::min(p.cn * an, cMax[0]), math::min(p.cs * as, cMax[1]), p.tanFriction
			};
			const Vector3r F = rdem::contactSpringForce<Real>(
			        c,
			        delta - p.contactOffset[i],
			        nrm,
			        pair.relativeVelocity(arm2),
			        pair.dt,
			        p.contactShear[i],
			        p.contactDashpot[i],
			        pair.trackEnergy,
			        e);
			out.add(F, arm2);
		}
		return true;
	}

	/// Calls f(law) for every Law2_RdemGeom_RdemPhys_FaceSprings in the InteractionLoops of the scene.
	template <class F> void forEachLaw(const Scene* scene, F f) { rdem::forEachLoopFunctor<Law2_RdemGeom_RdemPhys_FaceSprings>(scene, f); }
} // namespace

Vector2r Law2_RdemGeom_RdemPhys_FaceSprings::dashpotCap(
        const State& s1, const Vector3r& x1, const State& s2, const Vector3r& x2, const Vector3r& C, const Vector3r& n, Real share, Real dt)
{
	Real invN = 0, invS = 0;
	for (const auto& sx : { std::make_pair(&s1, x1), std::make_pair(&s2, x2) }) {
		if (sx.first->blockedDOFs == State::DOF_ALL) continue;
		const Vector3r r = C - sx.second;
		const Real     f = rdem::inertialFactor(sx.first->densityScaling); // inertial mass and inertia (density scaling)
		invN += 1 / (sx.first->mass * f) + r.cross(n).squaredNorm() / (sx.first->inertia.minCoeff() * f);
		invS += 1 / (sx.first->mass * f) + r.squaredNorm() / (sx.first->inertia.minCoeff() * f);
	}
	const Real inf = std::numeric_limits<Real>::infinity();
	return Vector2r(invN > 0 ? share / (invN * dt) : inf, invS > 0 ? share / (invS * dt) : inf);
}

void Law2_RdemGeom_RdemPhys_FaceSprings::postLoad(Law2_RdemGeom_RdemPhys_FaceSprings&)
{
	if (!shared) shared = shared_ptr<RdemSharedState>(new RdemSharedState);
}

bool Law2_RdemGeom_RdemPhys_FaceSprings::totalStressOf(const Scene* scene)
{
	bool total = false;
	forEachLaw(scene, [&](const Law2_RdemGeom_RdemPhys_FaceSprings& law) { total = total || law.totalStress; });
	return total;
}


bool Law2_RdemGeom_RdemPhys_FaceSprings::go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I)
{
	RdemGeom&    g  = *static_cast<RdemGeom*>(ig.get());
	RdemPhys&    p  = *static_cast<RdemPhys*>(ip.get());
	const State& s1 = *Body::byId(I->getId1(), scene)->state;
	const State& s2 = *Body::byId(I->getId2(), scene)->state;
	const Pair   pair { s1,        s2,
                          s1.pos,    scene->isPeriodic ? Vector3r(s2.pos + scene->cell->hSize * I->cellDist.cast<Real>()) : s2.pos,
                          scene->dt, scene->trackEnergy };
	Energies     e;
	Breaks       breaks;
	ForceOnBody2 on2;
	const bool   keep = g.nSegments() > 0 ? bondForces(g, p, pair, totalStress, e, breaks, on2)
	          : g.nPatch() > 0            ? patchContactForces(g, p, pair, e, on2)
	                                      : sampledContactForces(g, p, pair, e, on2);
	// The contact springs the geometry functor dropped in this step while loaded (RdemPhys::releasedEnergy).
	if (pair.trackEnergy && p.releasedIter == scene->iter) e.contactRelease += p.releasedEnergy;
	if (breaks.tension) shared->tensionBreaks += breaks.tension;
	if (breaks.shear) shared->shearBreaks += breaks.shear;
	// Booked also for a bond released in this step: the elastic energy its last segments released as they broke
	// (rdemBondBreak) and a softening spring's last fracture work were lost from the balance with the interaction.
	if (pair.trackEnergy) {
		const Energies mine = shareOf(e, rdem::energyShare(*scene, *Body::byId(I->getId1(), scene), *Body::byId(I->getId2(), scene)));
		if (!(deferForces && shared->deferredForces)) shared->bookSpringEnergies(scene, mine);
		else if (!keep)
			shared->releaseEnergies(I->getId1(), I->getId2(), mine);
		else {
			p.stepEnergies = mine; // for RdemForceAssembler, which books them in a fixed order
			p.energyIter   = scene->iter;
		}
	}
	if (!keep) {
		if (deferForces) shared->activeSetChanges += 1;
		if (g.bonded) recordRelease(*I, g, p);
		return false;
	}
	applyForces(*I, p, on2.f, on2.t, pair.x2 - pair.x1);
	return true;
}

void Law2_RdemGeom_RdemPhys_FaceSprings::applyForces(const Interaction& I, RdemPhys& p, const Vector3r& f2, const Vector3r& t2, const Vector3r& dx)
{
	p.force = f2;
	// Body 1 receives -F at every point C: Σ (C - x₁) × (-F) = -(t₂ + (x₂ - x₁) × f₂).
	const Vector3r t1 = -(t2 + dx.cross(f2));
	// deferForces, and the engine list was checked to have an RdemForceAssembler after the loop (RdemSharedState)
	if (deferForces && shared->deferredForces) {
		if (p.forceIter != scene->iter - 1) shared->join(I); // new, or back after a pause: not in the assembler's lists
		p.torque1   = t1;
		p.torque2   = t2;
		p.forceIter = scene->iter;
	} else {
		scene->forces.addForce(I.getId2(), f2);
		scene->forces.addForce(I.getId1(), -f2);
		scene->forces.addTorque(I.getId2(), t2);
		scene->forces.addTorque(I.getId1(), t1);
	}
}

void Law2_RdemGeom_RdemPhys_FaceSprings::recordRelease(const Interaction& I, const RdemGeom& g, const RdemPhys& p)
{
	auto                              record = RdemReleasedBond::of(I.getId1(), I.getId2(), g, p, scene->iter);
	const std::lock_guard<std::mutex> lock(releasedMutex); // rare: once per bond in a run
	releasedBonds.push_back(std::move(record));
}

boost::python::list Law2_RdemGeom_RdemPhys_FaceSprings::releasedBondsPy()
{
	boost::python::list out;
	for (const auto& r : releasedBondsNow())
		out.append(r);
	return out;
}

namespace {
	/* Every point spring of interaction I as the law applies it in this configuration, f(b1, b2, point, r1, r2, n, k_n,
	   k_s, c_n, c_s) with the point in global coordinates and its arms from the two centroids [m], the springs [N/m] and
	   dashpots [N·s/m] (zero where none acts):
	   each bond segment at its material point of body 1 (paper eq. 14: the restoring spring, or the contact spring of a
	   broken segment, of the same k̄A), with the dashpot of a broken segment that touched in the last step (it left a
	   stress; one that touches again before the next update is covered by the time step's safety factor, as contacts
	   that start); each contact sample with its dashpot (eq. 13); each spring of a face-to-face patch at its material point
	   of body 1, along the pair's normal, with its dashpot (eq. 13, its share of the patch area). Dashpots are capped as contactConstants caps them,
	   for the step capDt (no cap for capDt = 0); a broken segment's share of the contact area is bounded by 1. */
	template <class F> void forPointSprings(Scene* sc, const Interaction& I, Real capDt, F f)
	{
		const auto&       g  = *static_cast<const RdemGeom*>(I.geom.get());
		const auto&       p  = *static_cast<const RdemPhys*>(I.phys.get());
		const State&      s1 = *Body::byId(I.getId1(), sc)->state;
		const State&      s2 = *Body::byId(I.getId2(), sc)->state;
		const long        b1 = I.getId1(), b2 = I.getId2();
		const DashpotCaps caps(s1, s1.pos, s2, s2.pos, capDt); // the pair's terms of dashpotCap, once
		const auto        dashpots = [&](const Vector3r& point, const Vector3r& n, Real a, Real share) {
                        const Vector2r c(p.weightNormal * p.cn * a, p.weightShear * p.cs * a);
                        return capDt > 0 ? Vector2r(c.cwiseMin(caps.caps(point, n, share))) : c;
		};
		const Vector3r normal = g.normal.squaredNorm() > 0 ? g.normal : Vector3r(s1.ori * g.segNormal1);
		const Real     A      = g.segmentArea();
		const auto     points = g.segmentPoints1();
		for (size_t i = 0; i < points.size(); ++i) {
			const Vector3r arm1 = s1.ori * points[i], point = s1.pos + arm1;
			const bool     damped = i < p.segState.size() && p.segState[i] != int(rdem::SegmentState::Intact) && i < p.segSigma.size()
			        && (p.segSigma[i] < 0 || p.segTau[i] > 0);
			const Vector2r c = damped ? dashpots(point, normal, A, 1) : Vector2r::Zero();
			f(b1, b2, point, arm1, Vector3r(point - s2.pos), normal, p.weightNormal * p.kn * A, p.weightShear * p.ks * A, c[0], c[1]);
		}
		Real contactArea = 0;
		for (Real a : g.sampleArea)
			contactArea += a;
		for (size_t k = 0; k < g.sampleKey.size(); ++k) {
			const Real     a = g.sampleArea[k];
			const Vector2r c = dashpots(g.samplePoint[k], g.sampleNormal[k], a, a / contactArea);
			f(b1,
			  b2,
			  g.samplePoint[k],
			  Vector3r(g.samplePoint[k] - s1.pos),
			  Vector3r(g.samplePoint[k] - s2.pos),
			  g.sampleNormal[k],
			  p.weightNormal * p.kn * a,
			  p.weightShear * p.ks * a,
			  c[0],
			  c[1]);
		}
		const auto springs = g.patchSprings(); // a face-to-face contact's springs, at body 1's material points
		for (size_t k = 0; k < springs.size; ++k) {
			const Vector3r arm1 = s1.ori * Vector3r(springs.point1(k)), point = s1.pos + arm1;
			const Real     a = springs.area(k);
			const Vector2r c = dashpots(point, normal, a, a / g.patchArea);
			f(b1, b2, point, arm1, Vector3r(point - s2.pos), normal, p.weightNormal * p.kn * a, p.weightShear * p.ks * a, c[0], c[1]);
		}
	}
} // namespace

void Law2_RdemGeom_RdemPhys_FaceSprings::addStiffness(
        Scene* sc, const vector<const Interaction*>& inIdOrder, rdem::BlockStiffness<Real>& K, rdem::BlockStiffness<Real>& C, Real capDt)
{
	for (const Interaction* I : inIdOrder) {
		const auto& g = *static_cast<const RdemGeom*>(I->geom.get());
		if (g.nSegments() == 0 && g.sampleKey.empty() && g.nPatch() == 0) continue;
		K.beginPair(I->getId1(), I->getId2());
		C.beginPair(I->getId1(), I->getId2());
		forPointSprings(
		        sc,
		        *I,
		        capDt,
		        [&](long b1, long b2, const Vector3r&, const Vector3r& r1, const Vector3r& r2, const Vector3r& n, Real kn, Real ks, Real cn, Real cs) {
			        K.addPointSpring(b1, b2, r1, r2, n, kn, ks);
			        C.addPointSpring(b1, b2, r1, r2, n, cn, cs); // nothing where no dashpot acts (zero)
		        });
		K.endPair();
		C.endPair();
	}
}

void Law2_RdemGeom_RdemPhys_FaceSprings::addDashpots(Scene* sc, const vector<const Interaction*>& inIdOrder, rdem::BlockStiffness<Real>& C, Real capDt)
{
	for (const Interaction* I : inIdOrder) {
		const auto& g = *static_cast<const RdemGeom*>(I->geom.get());
		const auto& p = *static_cast<const RdemPhys*>(I->phys.get());
		// a bond whose segments are all intact has no dashpot (forPointSprings): addStiffness adds nothing to C for it
		const bool broken = std::any_of(p.segState.begin(), p.segState.end(), [](int s) { return s != int(rdem::SegmentState::Intact); });
		if (g.sampleKey.empty() && g.nPatch() == 0 && !broken) continue;
		C.beginPair(I->getId1(), I->getId2());
		forPointSprings(
		        sc,
		        *I,
		        capDt,
		        [&](long b1, long b2, const Vector3r&, const Vector3r& r1, const Vector3r& r2, const Vector3r& n, Real, Real, Real cn, Real cs) {
			        C.addPointSpring(b1, b2, r1, r2, n, cn, cs);
		        });
		C.endPair();
	}
}

void Law2_RdemGeom_RdemPhys_FaceSprings::addOmega2Bound(Scene* sc, vector<Real>& omega2)
{
	for (const Interaction* I : rdem::interactionsInIdOrder(sc)) {
		const State& s1 = *Body::byId(I->getId1(), sc)->state;
		const State& s2 = *Body::byId(I->getId2(), sc)->state;
		forPointSprings(
		        sc,
		        *I,
		        0,
		        [&](long b1, long b2, const Vector3r& point, const Vector3r&, const Vector3r&, const Vector3r& n, Real kn, Real ks, Real, Real) {
			        for (const auto& side : { std::make_pair(b1, &s1), std::make_pair(b2, &s2) })
				        if (side.second->blockedDOFs != State::DOF_ALL)
					        omega2[size_t(side.first)] += rdem::pointSpringOmega2<Real>(
					                point - side.second->pos,
					                n,
					                1,
					                kn,
					                ks,
					                rdem::inertialMass(*side.second),
					                rdem::inertialMinInertia(*side.second));
		        });
	}
}

} // namespace yade
