/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Interaction.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/RdemState.hpp>
#include <pkg/rdem/math/StiffnessSpectrum.hpp>
#include <functional>

namespace yade {

/* The Poisson cells at run time (doc/sphinx/rdemTheory.rst §5.4): their bonds and blocks in compact arrays, built from the scene's
   interactions and states when they change (a new RdemPoissonEngine.build, bodies or interactions added or removed),
   then two passes per step that follow no pointer to an interaction: updateStrains before the interaction loop (the
   blocks' poses, the bonds' openings and normals, the cells' strains and elastic stresses, written to each block's
   RdemState for the law) and applyForces after it (the cells' normal forces on their bonds, summed per block).
   Not a YADE class: RdemPoissonEngine owns one; RdemCellStrainUpdater calls updateStrains on it. */
class RdemCellNetwork {
public:
	/// Called by applyForces between the cells' ∂W/∂ε and the bonds' forces with the blocks' ids and their ∂W/∂ε [N·m] (by
	/// compact index): on YADE's MPI, RdemGhostExchange replaces the ghosts' by their owners' (it needs bonds the rank lacks).
	using StressSync = std::function<void(const vector<Body::id_t>& body, vector<Vector3r>& stress)>;
	/* Rebuilds the arrays if what defines them changed since the last call: a new RdemPoissonEngine.build (generation;
	   RdemBondKeeper's bonds put back bump it too), the bodies' count, and, once the interaction container's size
	   changes, a bond erased without being released (O.interactions.erase, the erasure of a body) or released bonds
	   making up a quarter of the network, once their cells have seen them. Contacts that come and go leave them, and so
	   does a release: a released bond stays, with intact fraction 0, and releases its cells. False if there is no cell. */
	bool refresh(Scene* scene);
	/// Before the law: poses, openings u_n = n·(P₂ - P₁) at the face centres, crack scales, RdemState::strain,
	/// ::cellScale and ::cellStress of every cell; brokenSprings: the scene's count (RdemSharedState), the crack scales
	/// are recomputed when it changes. On `threads` OpenMP threads (the calling engine's ompThreads, ≤ 0: all).
	void updateStrains(Scene* scene, long brokenSprings, int threads);
	/// After the law: ∂W/∂ε of every cell (its elastic stress plus the reaction of its bonds' offset correction), then the
	/// normal force -Σ c ∂W/∂ε of every bond at its face centre, added to the blocks in a fixed order. Adds the cells'
	/// energy ½ s εᵀKε and the energy released by a drop of s [J]. Threads as for updateStrains.
	void applyForces(Scene* scene, bool releaseOnCrack, Real& energy, Real& released, int threads, const StressSync& sync = StressSync());
	/* YADE's MPI: the cells of blocks on the master (fixed beams and slabs; mpy keeps them on rank 0) have their bonds on
	   the ranks of the blocks they join, each rank a part. Called on every rank (collective), these complete such a cell
	   from every rank's part, summed over its bonds in the order of the other block's id as on one rank: each rank sends
	   the terms of the bonds between it and the rank's own blocks (rdem::gatherOverRanks). reduceMasterStrains: the
	   strains, crack scales and elastic stresses (after updateStrains, before the law reads them); reduceMasterStresses:
	   the reaction of their bonds' offset correction in ∂W/∂ε (inside applyForces, through its sync, before the bonds'
	   forces). Each returns the bytes of this rank's part. */
	long reduceMasterStrains(Scene* scene);
	long reduceMasterStresses(Scene* scene);
	/// Per body id, the Gershgorin bound of the squared eigenfrequency the cells add [1/s²] (see the definition).
	vector<Real> omega2Bound(Scene* scene);
	/// Adds the cells' linear stiffness ½ s εᵀ CᵀKC ε on the bond openings at the current poses to K (RdemTimeStepper),
	/// and the coupling of the offset correction of the bonds' intact shear springs to the cells' strains.
	void addStiffness(Scene* scene, bool releaseOnCrack, long brokenSprings, rdem::BlockStiffness<Real>& K);
	/// Number of blocks with a cell.
	size_t nCells() const { return nCellBlocks; }
	/// How many times the arrays were built (read by RdemPoissonEngine.cellRebuilds, for tests).
	long rebuilds() const { return nRebuilds; }
	/// Incremented by RdemPoissonEngine::build: arrays made before it are rebuilt.
	static long generation;

private:
	struct Bond {                      // constant between rebuilds
		size_t   i1, i2;           // compact indices of the two blocks
		int      ax1, ax2;         // the bond's axis in each block's frame
		Real     c1, c2;           // cell coefficients ∂ε/∂u_n of the two blocks [1/m] (RdemPhys::cellCoef1, 2)
		Vector3r n1, n2, fc1, fc2; // face normal and face centre in each block's frame
	};
	vector<Bond>                    bond;
	vector<shared_ptr<Interaction>> intr;    // per bond, to see it released and read its intact fraction
	vector<shared_ptr<IPhys>>       phys;    // per bond, held directly (one pointer less to follow, alive after a release)
	vector<Real>                    opening; // per bond, this step [m]
	vector<Vector3r>                normal;  // per bond, this step: body 1's rotated face normal
	vector<Vector3r>   arm1, arm2;           // per bond, this step: moment about each block's centroid of a unit force along normal at the face centre [m]
	vector<Real>       intact;               // per bond, fraction of intact restoring springs (0 once released)
	vector<Body::id_t> body;                 // per compact block: its id
	vector<RdemState*> state;                // per compact block
	vector<char>       hasCell;              // per compact block: whether it has a cell (else it only moves bonds)
	vector<size_t>     first;                // compact block i: sides first[i] … first[i+1]-1
	vector<size_t>     sideBond;             // the bond of each side
	vector<char>       sideSecond;           // whether the block is the bond's second block
	vector<char>       sideOffset;           // whether the bond has a centroid offset (its law writes RdemPhys::offsetGrad)
	vector<Matrix3r>   rot;                  // per compact block, this step
	vector<Vector3r>   pos;
	vector<Matrix3r>   stiffness;    // per compact block: RdemState::cellStiffness (constant between builds)
	vector<Matrix3r>   condensation; // per compact block: RdemState::cellCondensation
	vector<Vector3r>   stress;       // per compact block: ∂W/∂ε this step [N·m]
	vector<Vector3r>   elastic;      // per compact block: its elastic part s K ε this step [N·m]
	vector<char>       booksEnergy;  // per compact block on the master (YADE's MPI): whether this rank books its cell's energy
	vector<Real>       scalePrev;    // per compact block: cell scale of the last step
	size_t             nCellBlocks     = 0;
	long               builtGeneration = -1, builtBodies = -1, brokenSeen = -1;
	long               seenInteractions = -1; // the container's size when the bonds were last found in it
	long               nRebuilds        = 0;
	void               rebuild(Scene* scene);
	/// Whether bond k was released by the law (its interaction reset, or a contact since).
	bool released(size_t k) const;
	/// What became of the network's bonds: whether one left the container without being released (an erased one keeps
	/// its old linIx), how many were released with their cells released too (cellsReleased), and whether a release
	/// is still unseen by the cells (updateStrains has not run since).
	struct BondCensus {
		bool   erased   = false;
		size_t released = 0;
		bool   unseen   = false;
	};
	BondCensus bondCensus(Scene* scene) const;
	/// Whether the cells that bond k is part of (its sides with a coefficient) have dropped to crack scale 0.
	bool cellsReleased(size_t k) const;
	/// Cell i's strain from ε (before the condensation), its crack scale and elastic stress (RdemState).
	void setStrain(size_t i, const Vector3r& eps, Real scale);
	/// The cells' ∂W/∂ε: the elastic part s K ε plus the reaction Cᵀ g of its bonds' offset correction (C the condensation).
	static Vector3r fullStress(const Vector3r& sKe, const Matrix3r& condensation, const Vector3r& g) { return sKe + condensation.transpose() * g; }
	/// Total shear stiffness k_s w_s A of bond k's intact springs when they carry the offset correction [N/m]; else 0.
	Real offsetShearStiffness(size_t k) const;
	void updateIntact(long brokenSprings);
};

} // namespace yade
