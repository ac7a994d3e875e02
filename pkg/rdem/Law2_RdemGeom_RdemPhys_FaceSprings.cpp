/*************************************************************************
 *  Copyright (C) 2026 yade-rdem authors                                  *
 *                                                                        *
 *  This program is free software; it is licensed under the terms of the  *
 *  GNU General Public License v2 or later. See file LICENSE for details. *
 *************************************************************************/
#include <core/InteractionLoop.hpp>
#include <core/Scene.hpp>
#include <limits>
#include <pkg/rdem/Law2_RdemGeom_RdemPhys_FaceSprings.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <pkg/rdem/math/BlockCells.hpp>
#include <pkg/rdem/math/Failure.hpp>
#include <type_traits>
#include <utility>

namespace yade {

YADE_PLUGIN((Law2_RdemGeom_RdemPhys_FaceSprings));

namespace {
/// Energies of one interaction in one step [J].
struct Energies {
  Real elastic = 0, dashpot = 0, friction = 0, bondBreak = 0;
};

/* Contact spring and dashpot of one point (paper eqs. 13, 17). delta > 0 is the
   overlap [m], n the unit normal from body 1 to body 2, v the velocity of body
   2 relative to body 1 at the point, shear the elastic shear elongation
   (updated here), cMax the stability caps of the normal and shear dashpot
   coefficients [N·s/m], dashpot the dashpot force of the previous step (zero if
   the point was not in contact; replaced by this step's) [N]. Returns the force
   on body 2 [N].

   Energy: v is the mid-step velocity v_{n-1/2} (leapfrog), so the work of this
   step's dashpot force F_n over the step, -F_n·(v_{n-1/2} + v_{n+1/2})/2·Δt, is
   booked half now and half at the next step with that step's velocity
   (trapezoid rule). The dissipation then matches the kinetic energy lost even
   where a dashpot stops a point within a step or two (stability cap); booking
   -F_n·v_{n-1/2}·Δt overstates it by F_n·(v_{n-1/2} - v_{n+1/2})Δt/2, up to
   half of it. The second half of a point's last step is dropped when it leaves
   contact, where its dashpot force is clipped to -k_nAδ → 0. */
Vector3r contactForce(const RdemPhys &p, Real area, Real delta,
                      const Vector3r &n, const Vector3r &v, Real dt,
                      const Vector2r &cMax, Vector3r &shear, Vector3r &dashpot,
                      bool trackEnergy, Energies &e) {
  const Real an = p.weightNormal * area, as = p.weightShear * area;
  const Real kn = p.kn * an, ks = p.ks * as, cn = math::min(p.cn * an, cMax[0]),
             cs = math::min(p.cs * as, cMax[1]);
  const Real vn = v.dot(n);
  const Vector3r vt = v - vn * n;
  const Real fElast = kn * delta; // elastic normal force, compressive > 0
  const Real fN =
      math::max(fElast - cn * vn, Real(0)); // with the dashpot, never tensile
  shear -= shear.dot(n) * n; // keep the spring in the current tangent plane
  shear += vt * dt;
  Vector3r fS = -ks * shear;
  const Real limit =
      p.tanFriction * fElast; // eq. (17): |τ| ≤ -σ tanφ, σ = -k_n δ
  bool slip = false;
  if (fS.squaredNorm() > limit * limit) {
    const Vector3r trial = fS;
    fS *= (fS.norm() > 0 ? limit / fS.norm() : Real(0));
    shear = -fS / ks;
    slip = true;
    if (trackEnergy)
      e.friction += ((trial - fS) / ks)
                        .dot(fS); // plastic slip times the sliding force, >= 0
  }
  const Vector3r fDs =
      slip ? Vector3r::Zero()
           : Vector3r(-cs * vt);               // shear dashpot, while sticking
  const Vector3r fD = (fN - fElast) * n + fDs; // dashpot part of the force
  if (trackEnergy) {
    e.elastic += fElast * delta / 2 + ks * shear.squaredNorm() / 2;
    e.dashpot -= (fD + dashpot).dot(v) * dt / 2;
  }
  dashpot = fD;
  return fN * n + fS + fDs;
}

/* Offset correction of a bond's intact shear springs (rdem::offsetSlip,
   doc/theory.md §5.4): the slip ½(E₁ + E₂)δ that the blocks' cell strains
   (RdemState::strain, scaled by RdemState::cellScale, from
   RdemCellStrainUpdater) give two blocks whose centroids are offset by δ along
   the face, in global coordinates and in the tangent plane of n [m]. */
Vector3r cellOffsetSlip(const State &s1, const State &s2, const Matrix3r &R1,
                        const Matrix3r &R12, const RdemGeom &g,
                        const RdemPhys &p, const Vector3r &n) {
  const auto &a = static_cast<const RdemState &>(s1);
  const auto &b = static_cast<const RdemState &>(s2);
  const Vector3r local = rdem::offsetSlip<Real>(a.cellScale * a.strain, R12,
                                                b.cellScale * b.strain,
                                                p.centroidOffset, g.segNormal1);
  const Vector3r slip = R1 * local;
  return slip - slip.dot(n) * n;
}

/* Normal stress the Poisson cells of the two blocks exert on their bonded face,
   positive in tension [Pa]: the cell force on the bond, -(c₁S₁ + c₂S₂) on body
   2 along n (RdemPoissonEngine), as a traction over the face's weighted area
   w_n A, from the cells' elastic stresses of this step (RdemState::cellStress,
   along each block's axis of the bond). Added to the springs' σ = k_n u_n it is
   the total σ_nn of the face (doc/theory.md §5.6). Zero without cells. */
Real cellNormalStress(const State &s1, const State &s2, const RdemGeom &g,
                      const RdemPhys &p) {
  if (p.cellCoef1 == 0 && p.cellCoef2 == 0)
    return 0;
  const auto &a = static_cast<const RdemState &>(s1);
  const auto &b = static_cast<const RdemState &>(s2);
  const Real S =
      p.cellCoef1 * a.cellStress[rdem::dominantAxis<Real>(g.segNormal1)] +
      p.cellCoef2 * b.cellStress[rdem::dominantAxis<Real>(g.segNormal2)];
  return S / (p.weightNormal * g.segmentArea() * Real(g.nSegments()));
}

/// Calls f(law) for every Law2_RdemGeom_RdemPhys_FaceSprings in the
/// InteractionLoops of the scene.
template <class F> void forEachLaw(const Scene *scene, F f) {
  for (const auto &e : scene->engines) {
    const auto *loop = dynamic_cast<const InteractionLoop *>(e.get());
    if (!loop)
      continue;
    for (const auto &functor : loop->lawDispatcher->functors)
      if (auto *law =
              dynamic_cast<Law2_RdemGeom_RdemPhys_FaceSprings *>(functor.get()))
        f(*law);
  }
}
} // namespace

long Law2_RdemGeom_RdemPhys_FaceSprings::brokenSprings(const Scene *scene) {
  long n = 0;
  forEachLaw(scene, [&](const Law2_RdemGeom_RdemPhys_FaceSprings &law) {
    n += law.tensionBreaks.get() + law.shearBreaks.get();
  });
  return n;
}

bool Law2_RdemGeom_RdemPhys_FaceSprings::totalStressOf(const Scene *scene) {
  bool total = false;
  forEachLaw(scene, [&](const Law2_RdemGeom_RdemPhys_FaceSprings &law) {
    total = total || law.totalStress;
  });
  return total;
}

bool Law2_RdemGeom_RdemPhys_FaceSprings::takeActiveSetChanged(
    const Scene *scene) {
  bool changed = false;
  forEachLaw(scene, [&](Law2_RdemGeom_RdemPhys_FaceSprings &law) {
    if (law.activeSetChanges.get() == 0)
      return;
    changed = true;
    law.activeSetChanges.reset();
  });
  return changed;
}

bool Law2_RdemGeom_RdemPhys_FaceSprings::go(shared_ptr<IGeom> &ig,
                                            shared_ptr<IPhys> &ip,
                                            Interaction *I) {
  RdemGeom &g = *static_cast<RdemGeom *>(ig.get());
  RdemPhys &p = *static_cast<RdemPhys *>(ip.get());
  const size_t nSeg = g.nSegments();
  const State &s1 = *Body::byId(I->getId1(), scene)->state;
  const State &s2 = *Body::byId(I->getId2(), scene)->state;
  const Vector3r x1 = s1.pos;
  const Vector3r x2 =
      scene->isPeriodic
          ? Vector3r(s2.pos + scene->cell->hSize * I->cellDist.cast<Real>())
          : s2.pos;
  const bool trackEnergy = scene->trackEnergy;
  const Real dt = scene->dt;
  Energies e;
  // Force on body 2 and its moment about x2; the reactions on body 1 follow at
  // the end (one cross product per point).
  Vector3r f2 = Vector3r::Zero(), t2 = Vector3r::Zero();
  auto apply = [&](const Vector3r &F,
                   const Vector3r &r2) { // r2: point of application minus x2
    f2 += F;
    t2 += r2.cross(F);
  };
  /// Velocity of body 2 relative to body 1 at the point x2 + r2 [m/s].
  auto relativeVelocity = [&](const Vector3r &r2) {
    return Vector3r(s2.vel + s2.angVel.cross(r2) - s1.vel -
                    s1.angVel.cross(r2 + x2 - x1));
  };
  /* Stability caps of a contact dashpot (explicit central differences): a
     dashpot may at most stop, never reverse, the relative motion of its point
     within one step, c ≤ share·m_eff/Δt, with m_eff the pair's effective mass
     at the point (1/m_eff = Σ 1/m + |r×e|²/I_min over the free blocks, e the
     direction of the dashpot) and share its part of the interaction's contact
     area. For the shear dashpot, whose direction changes, |r×e|² is bounded by
     |r|². The caps bind where a contact drives a small effective mass, at an
     edge or a corner of a tumbling block; eq. (13) holds elsewhere
     (doc/theory.md §3). */
  auto dashpotCap = [&](const Vector3r &C, const Vector3r &n, Real share) {
    Real invN = 0, invS = 0;
    for (const auto &sx : {std::make_pair(&s1, x1), std::make_pair(&s2, x2)}) {
      if (sx.first->blockedDOFs == State::DOF_ALL)
        continue;
      const Vector3r r = C - sx.second;
      invN += 1 / sx.first->mass +
              r.cross(n).squaredNorm() / sx.first->inertia.minCoeff();
      invS +=
          1 / sx.first->mass + r.squaredNorm() / sx.first->inertia.minCoeff();
    }
    const Real inf = std::numeric_limits<Real>::infinity();
    return Vector2r(invN > 0 ? share / (invN * dt) : inf,
                    invS > 0 ? share / (invS * dt) : inf);
  };
  if (nSeg > 0) {
    bool anyIntactOrTouching = false;
    // A broken segment is in contact while its material points overlap and face
    // each other (slid less than the smaller half-size of a segment).
    auto touching = [&](Real un, const Vector3r &us) {
      return un < 0 && us.norm() < g.segHalfSizes().minCoeff();
    };
    // The segments' kinematics from the blocks' current states
    // (RdemGeom::kinematics, paper eq. 14).
    const Matrix3r R1 = s1.ori.toRotationMatrix(),
                   R2 = s2.ori.toRotationMatrix();
    const Vector3r n = (R1 * g.segNormal1 - R2 * g.segNormal2).normalized();
    const auto kin = g.kinematics(R1, R2, x2 - x1);
    g.normal = n;
    const Real A = g.segmentArea();
    /* Segment k = i n + j sits at grid coordinates (s, r) = (s_i, s_j)
       (rdem::segmentCoordinate), where its d = P₂ - P₁ and r₂ = C - x₂ are
       affine in (s, r) (rdem::BondKinematics). So is the moment of the segment
       forces about x₂: Σ r₂ × F = r0 × ΣF + ra × Σ sF + rb × Σ rF, summed from
       three force sums without a cross product per segment. */
    const int nEdge = g.samplesPerEdge;

    auto forSegments = [&](auto f) { // f(k, s, r)
      size_t k = 0;
      for (int i = 0; i < nEdge; ++i) {
        const Real s = rdem::segmentCoordinate<Real>(i, nEdge);
        for (int j = 0; j < nEdge; ++j, ++k)
          f(k, s, rdem::segmentCoordinate<Real>(j, nEdge));
      }
    };
    Vector3r fSum = Vector3r::Zero(), fs = Vector3r::Zero(),
             fr = Vector3r::Zero(); // ΣF, Σ sF, Σ rF on body 2 [N]

    auto applyAt = [&](const Vector3r &F, Real s, Real r) {
      fSum += F;
      fs += s * F;
      fr += r * F;
    };
    Real contactArea =
        0; // of the broken segments in contact: shares of the dashpot caps
    forSegments([&](size_t i, Real s, Real r) {
      if (p.segState[i] == int(rdem::SegmentState::Intact))
        return;
      const Vector3r d = kin.displacement(s, r);
      const Real un = d.dot(n);
      if (touching(un, d - un * n))
        contactArea += A;
    });
    // Bonds whose centroids are offset along the face (cells only): the intact
    // shear springs measure d_t - slip.
    const bool offset = p.centroidOffset != Vector3r::Zero();
    const Matrix3r R12 =
        offset ? Matrix3r(R1.transpose() * R2) : Matrix3r::Identity();
    const Vector3r slip =
        offset ? cellOffsetSlip(s1, s2, R1, R12, g, p, n) : Vector3r::Zero();
    Vector3r tSum = Vector3r::Zero(); // Σ w_s k_s A (d_t - slip) over the
                                      // intact segments [N]
    // With totalStress, the failure criteria add the normal stress the cells
    // exert on the face (tension > 0) [Pa].
    const Real sigmaCells =
        totalStress ? cellNormalStress(s1, s2, g, p) : Real(0);
    // Loop invariants in locals: the stores to the per-segment arrays below
    // could alias them (all doubles).
    const Real kn = p.kn, ks = p.ks, wn = p.weightNormal, ws = p.weightShear;
    const Real ft = p.tensileStrength, cohesion = p.cohesion,
               tanPhi = p.tanFriction;
    const Real
        cn = wn * kn * A,
        cs = ws * ks *
             A; // restoring spring of one segment, with its volume weight [N/m]
    /* The segments' laws, instantiated twice: with the Poisson cells' offset
       correction and total stress (withCells), and without them, so that a bond
       of the paper's scene runs the same code as before the cells (it inlines
       alike). */
    auto segments = [&](auto withCells) {
      forSegments([&](size_t i, Real s, Real r) {
        const Vector3r d = kin.displacement(s, r);
        const Real un = d.dot(n); // eq. (14): opening positive
        const Vector3r us = d - un * n;
        if (p.segState[i] == int(rdem::SegmentState::Intact)) {
          const Vector3r ust = withCells ? Vector3r(us - slip)
                                         : us; // the spring's shear elongation
          const Real sigma = kn * un;
          const Vector3r tau = ks * ust;
          const Real tauNorm = tau.norm();
          const auto state =
              rdem::restoringSpringState(withCells ? sigma + sigmaCells : sigma,
                                         tauNorm, ft, cohesion, tanPhi);
          auto energy = [&]() {
            return A * (wn * sigma * sigma / kn + ws * tau.squaredNorm() / ks) /
                   2;
          };
          if (state == rdem::SegmentState::Intact) {
            applyAt(-(cn * un * n + cs * ust), s, r); // -(w_n σ n + w_s τ) A
            if (withCells)
              tSum += cs * ust;
            p.segSigma[i] = sigma;
            p.segTau[i] = tauNorm;
            anyIntactOrTouching = true;
            if (trackEnergy)
              e.elastic += energy();
            return;
          }
          p.segState[i] = int(state);
          if (state == rdem::SegmentState::BrokenTension)
            tensionBreaks += 1;
          else
            shearBreaks += 1;
          e.bondBreak += energy();
          p.segShear[i] = Vector3r::Zero();
        }
        // Broken: the contact spring of this segment (eqs. 13, 17). Its dashpot
        // force is kept for the energy balance (sized here, not for every bond
        // and step: an intact bond never reads that array's header).
        if (p.segDashpot.size() != nSeg)
          p.segDashpot.resize(nSeg, Vector3r::Zero());
        if (touching(un, us)) {
          const Vector3r r2 = kin.arm(s, r);
          const Real share =
              contactArea > 0
                  ? A / contactArea
                  : Real(1); // a segment broken in this step joins now
          const Vector3r v = relativeVelocity(r2);
          const Vector3r F =
              contactForce(p, A, -un, n, v, dt, dashpotCap(x2 + r2, n, share),
                           p.segShear[i], p.segDashpot[i], trackEnergy, e);
          applyAt(F, s, r);
          p.segSigma[i] = -F.dot(n) / (p.weightNormal * A);
          p.segTau[i] = (F - F.dot(n) * n).norm() / (p.weightShear * A);
          anyIntactOrTouching = true;
        } else {
          p.segShear[i] = p.segDashpot[i] = Vector3r::Zero();
          p.segSigma[i] = p.segTau[i] = 0;
        }
      });
    };
    if (offset || totalStress)
      segments(std::true_type());
    else
      segments(std::false_type());
    f2 += fSum;
    t2 += kin.r0.cross(fSum) + kin.ra.cross(fs) + kin.rb.cross(fr);
    if (offset) { // the reaction of the correction on the cells that made the
                  // strains (RdemPoissonEngine sums it)
      rdem::offsetSlipGradient<Real>(R1.transpose() * tSum, R12,
                                     p.centroidOffset, p.offsetGrad1,
                                     p.offsetGrad2);
      p.offsetGrad1 *= static_cast<const RdemState &>(s1).cellScale;
      p.offsetGrad2 *= static_cast<const RdemState &>(s2).cellScale;
    }
    if (!anyIntactOrTouching) {
      // Fully broken and apart: release the bond (the interaction is reset);
      // the collider and contact sampling take over.
      if (deferForces)
        activeSetChanges += 1;
      return false;
    }
  } else {
    if (g.sampleKey.empty()) { // apart: the collider drops the pair once the
                               // bounding boxes separate
      if (deferForces)
        activeSetChanges += 1;
      return false;
    }
    const size_t nKeys =
        size_t(2 * 6 * (g.samplesPerEdge + 1) * (g.samplesPerEdge + 1) +
               1); // face samples, then the edge contact
    p.sampleShear.resize(nKeys, Vector3r::Zero());
    p.sampleDashpot.resize(nKeys, Vector3r::Zero());
    p.sampleOffset.resize(nKeys, 0);
    p.sampleActive.resize(nKeys, 0);
    std::vector<char> active(nKeys, 0);
    Real contactArea = 0;
    for (Real a : g.sampleArea)
      contactArea += a;
    /* A point that starts its contact already δ₀ deep entered through a gap of
       the sampling (a region of overlap that held no sample point, or a change
       of the pair's normal), not by the motion of one step: its spring counts
       from δ₀, lowered whenever the depth is (δ₀ = min over the contact of δ),
       so that it never releases energy it did not store. */
    for (size_t k = 0; k < g.sampleKey.size(); ++k) {
      const size_t key = size_t(g.sampleKey[k]);
      p.sampleOffset[key] =
          p.sampleActive[key] ? math::min(p.sampleOffset[key], g.sampleDepth[k])
                              : g.sampleDepth[k];
      active[key] = 1;
      const Vector2r cMax = dashpotCap(g.samplePoint[k], g.sampleNormal[k],
                                       g.sampleArea[k] / contactArea);
      apply(contactForce(
                p, g.sampleArea[k], g.sampleDepth[k] - p.sampleOffset[key],
                g.sampleNormal[k], g.sampleVel[k], dt, cMax, p.sampleShear[key],
                p.sampleDashpot[key], trackEnergy, e),
            g.samplePoint[k] - x2);
    }
    for (size_t key = 0; key < nKeys; ++key)
      if (!active[key])
        p.sampleShear[key] = p.sampleDashpot[key] = Vector3r::Zero();
    p.sampleActive.assign(active.begin(), active.end());
  }

  p.force = f2;
  // Body 1 receives -F at every point C: Σ (C - x1) × (-F) = -(t2 + (x2 - x1) ×
  // f2).
  const Vector3r t1 = -(t2 + (x2 - x1).cross(f2));
  if (deferForces) {
    if (p.forceIter != scene->iter - 1)
      activeSetChanges +=
          1; // new, or back after a pause: not in the assembler's lists
    p.torque1 = t1;
    p.torque2 = t2;
    p.forceIter = scene->iter;
  } else {
    scene->forces.addForce(I->getId2(), f2);
    scene->forces.addForce(I->getId1(), -f2);
    scene->forces.addTorque(I->getId2(), t2);
    scene->forces.addTorque(I->getId1(), t1);
  }
  if (trackEnergy) {
    scene->energy->add(e.elastic, "rdemElastic", elasticIx,
                       /*reset every step*/ true);
    scene->energy->add(e.dashpot, "rdemDashpot", dashpotIx, false);
    scene->energy->add(e.friction, "rdemFriction", frictionIx, false);
    scene->energy->add(e.bondBreak, "rdemBondBreak", bondBreakIx, false);
  }
  return true;
}

} // namespace yade
