/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The two spring laws of a point of a face, as Law2_RdemGeom_RdemPhys_FaceSprings runs them.

   Reference [P]: the paper (shared/reference/paper-poisson-effect-refined-dem.txt), eqs. (13)-(17); doc/sphinx/rdemTheory.rst §1–3.
   Sign conventions: normal stress σ and opening u_n positive in TENSION/OPENING (eq. 14); an overlap δ = -u_n > 0.
   Vectors are global; n is the unit normal from body 1 to body 2; forces are those on body 2.
   Units: stiffness per area [N/m³] and stresses [Pa] for the restoring spring; stiffness [N/m], dashpot [N·s/m] and
   force [N] for the contact spring of one point. */
#pragma once

#include <pkg/rdem/math/Failure.hpp>

#include <Eigen/Core>
#include <cmath>

namespace yade {
namespace rdem {

	/// Energies of one interaction in one step [J]: elastic (current value), the others dissipated in this step; the
	/// softening springs' (rdem::softeningStep) only where softening is true.
	template <class S> struct SpringEnergies {
		S    elastic = 0, dashpot = 0, friction = 0, bondBreak = 0, contactRelease = 0;
		S    fractureTension = 0, fractureShear = 0, crushing = 0;
		bool softening = false;
		/// Adds another interaction's energies, each to each.
		SpringEnergies& operator+=(const SpringEnergies& o)
		{
			elastic += o.elastic;
			dashpot += o.dashpot;
			friction += o.friction;
			bondBreak += o.bondBreak;
			contactRelease += o.contactRelease;
			fractureTension += o.fractureTension;
			fractureShear += o.fractureShear;
			crushing += o.crushing;
			softening = softening || o.softening;
			return *this;
		}
	};

	/// Constants of a restoring spring per unit area (eqs. 12, 15, 16): k̄_n, k̄_s [N/m³], f_t, c [Pa], tan φ.
	template <class S> struct RestoringConstants {
		S kn, ks, tensileStrength, cohesion, tanPhi;
	};

	/// k with its strengths f_t and c multiplied by the heterogeneity factor f > 0 (doc/sphinx/rdemTheory.rst §2.2); stiffnesses and
	/// friction unchanged.
	template <class S> RestoringConstants<S> scaledStrengths(RestoringConstants<S> k, S f)
	{
		k.tensileStrength *= f;
		k.cohesion *= f;
		return k;
	}

	/// Stresses of a restoring spring and whether it holds them.
	template <class S> struct RestoringStress {
		S                      sigma;   ///< σ = k̄_n u_n, positive in tension [Pa]
		Eigen::Matrix<S, 3, 1> tau;     ///< τ = k̄_s u_s [Pa]
		S                      tauNorm; ///< |τ| [Pa]
		SegmentState           state;   ///< Intact, or what breaks it (eqs. 15-16)
	};

	/* Eq. (14) [P]: the restoring spring's stresses for the opening u_n [m] and shear elongation u_s [m] of its segment,
	   and eqs. (15)-(16): its state, judged on σ + σ_extra (σ_extra: the normal stress the Poisson cells add to the face,
	   doc/sphinx/rdemTheory.rst §5.6; 0 for the paper's criterion). */
	template <class S> RestoringStress<S> restoringStress(const RestoringConstants<S>& k, S un, const Eigen::Matrix<S, 3, 1>& us, S sigmaExtra)
	{
		RestoringStress<S> r;
		r.sigma   = k.kn * un;
		r.tau     = k.ks * us;
		r.tauNorm = r.tau.norm();
		r.state   = restoringSpringState(r.sigma + sigmaExtra, r.tauNorm, k.tensileStrength, k.cohesion, k.tanPhi);
		return r;
	}

	/// Elastic energy of a restoring spring of area A [m²] with volume weights w_n, w_s: A(w_n σ²/k̄_n + w_s |τ|²/k̄_s)/2 [J].
	template <class S> S restoringEnergy(const RestoringConstants<S>& k, const RestoringStress<S>& r, S area, S wn, S ws)
	{
		return area * (wn * r.sigma * r.sigma / k.kn + ws * r.tau.squaredNorm() / k.ks) / 2;
	}

	/// Elastic energy of a contact spring of stiffnesses k_n, k_s [N/m] compressed by c >= 0 [m] with the elastic shear
	/// elongation u_s [m] (eqs. 13, 17): k_n c²/2 + k_s |u_s|²/2 [J].
	template <class S> S contactSpringEnergy(S kn, S ks, S c, const Eigen::Matrix<S, 3, 1>& us) { return kn * c * c / 2 + ks * us.squaredNorm() / 2; }

	/// Constants of the contact spring of one point (eqs. 13, 17): springs k_n, k_s [N/m], dashpots c_n, c_s [N·s/m]
	/// (each already capped for stability), tan φ of its friction.
	template <class S> struct ContactConstants {
		S kn, ks, cn, cs, tanPhi;
	};

	/* Contact spring and dashpot of one point (eqs. 13, 17) [P]. delta > 0 is the overlap [m], n the unit normal from
	   body 1 to body 2, v the velocity of body 2 relative to body 1 at the point [m/s], dt the time step [s]; shear is the
	   spring's elastic shear elongation (updated here) [m], dashpot the dashpot force of the previous step (zero if the
	   point was not in contact; replaced by this step's) [N]. Returns the force on body 2 [N]: normal
	   max(k_n δ - c_n v_n, 0) (never tensile), incremental shear spring -k_s u_s limited by Coulomb friction at
	   tan φ · k_n δ (eq. 17, rdem::frictionLimit of the elastic normal force), shear dashpot -c_s v_t while it sticks.

	   Energy (into e when track is true): v is the mid-step velocity v_{n-1/2} (leapfrog), so the work of this step's
	   dashpot force F_n over the step, -F_n·(v_{n-1/2} + v_{n+1/2})/2·Δt, is booked half now and half at the next step
	   with that step's velocity (trapezoid rule). The dissipation then matches the kinetic energy lost even where a
	   dashpot stops a point within a step or two (stability cap); booking -F_n·v_{n-1/2}·Δt overstates it by
	   F_n·(v_{n-1/2} - v_{n+1/2})Δt/2, up to half of it. The second half of a point's last step is dropped when it
	   leaves contact, where its dashpot force is clipped to -k_nδ → 0. Friction: the plastic slip times the sliding
	   force, ≥ 0. */
	template <class S>
	Eigen::Matrix<S, 3, 1> contactSpringForce(
	        const ContactConstants<S>&    k,
	        S                             delta,
	        const Eigen::Matrix<S, 3, 1>& n,
	        const Eigen::Matrix<S, 3, 1>& v,
	        S                             dt,
	        Eigen::Matrix<S, 3, 1>&       shear,
	        Eigen::Matrix<S, 3, 1>&       dashpot,
	        bool                          track,
	        SpringEnergies<S>&            e)
	{
		using V        = Eigen::Matrix<S, 3, 1>;
		const S vn     = v.dot(n);
		const V vt     = v - vn * n;
		const S fElast = k.kn * delta;                                       // elastic normal force, compressive > 0
		const S fN     = fElast - k.cn * vn > 0 ? fElast - k.cn * vn : S(0); // with the dashpot, never tensile
		shear -= shear.dot(n) * n;                                           // keep the spring in the current tangent plane
		shear += vt * dt;
		V       fS    = -k.ks * shear;
		const S limit = frictionLimit(-fElast, k.tanPhi); // eq. (17) on the forces: homogeneous of degree 1 in σ
		bool    slip  = false;
		if (fS.squaredNorm() > limit * limit) {
			const V trial = fS;
			fS *= (fS.norm() > 0 ? limit / fS.norm() : S(0));
			shear = -fS / k.ks;
			slip  = true;
			if (track) e.friction += ((trial - fS) / k.ks).dot(fS);
		}
		const V fDs = slip ? V(V::Zero()) : V(-k.cs * vt); // shear dashpot, while sticking
		const V fD  = (fN - fElast) * n + fDs;             // dashpot part of the force
		if (track) {
			e.elastic += contactSpringEnergy(k.kn, k.ks, delta, shear);
			e.dashpot -= (fD + dashpot).dot(v) * dt / 2;
		}
		dashpot = fD;
		return fN * n + fS + fDs;
	}

} // namespace rdem
} // namespace yade
