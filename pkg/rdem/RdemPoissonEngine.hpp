/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>
#include <core/Interaction.hpp>
#include <pkg/rdem/RdemCellNetwork.hpp>
#include <pkg/rdem/RdemSharedState.hpp>
#include <pkg/rdem/RdemStiffnessSource.hpp>
#include <pkg/rdem/math/Hex8.hpp>
#include <pkg/rdem/math/StiffnessSpectrum.hpp>
#include <map>
#include <set>

namespace yade {

/// The Poisson effect: the paper's virtual hexahedra on 2×2×2 groups of blocks (eqs. 18-21), or Poisson cells on any layout.
class RdemPoissonEngine : public GlobalEngine, public RdemStiffnessSource {
public:
	void action() override;
	/// Make the elements (a grid of 2×2×2 groups) or the cells (any layout) of the blocks ids (all blocks if empty), as
	/// ``elements`` says; current positions become the reference. Throws std::invalid_argument for what cannot be built.
	void build(const vector<Body::id_t>& ids);
	/// Python front of build: a list of ids, empty (default) for all blocks.
	void buildPy(const py::list& ids);
	/// Per body, an upper bound of the squared eigenfrequency the Poisson forces add (Gershgorin) [1/s²] (RdemTimeStepper).
	vector<Real> omega2Bound();
	/// Adds the linear stiffness of the elements (s K_p on their nodes' translations, without the corotational frame's
	/// rotation) and of the cells to K, for RdemTimeStepper; K points to this engine's matrices until the next build.
	/// No dashpots. Nothing while the engine is dead.
	void
	addStiffness(Scene* sc, const vector<const Interaction*>& inIdOrder, rdem::BlockStiffness<Real>& K, rdem::BlockStiffness<Real>& C, Real capDt) override;
	/// The elements and cells have no dashpots: nothing.
	void addDashpots(Scene*, const vector<const Interaction*>&, rdem::BlockStiffness<Real>&, Real) override { }
	/// omega2Bound on the bodies that are not fixed; nothing while the engine is dead.
	void addOmega2Bound(Scene* sc, vector<Real>& omega2) override;
	/// Number of elements (paper's hexahedra).
	int nElements() const { return int(nodes.size() / 8); }
	/// Number of blocks with a Poisson cell.
	int nCells() const;
	/// How many times the cells' network was built (RdemCellNetwork::rebuilds).
	long cellRebuilds() const { return cells.rebuilds(); }
	/// The cells at run time (RdemCellStrainUpdater updates their strains before the interaction loop).
	RdemCellNetwork& cellNetwork() { return cells; }
	/// The RdemPoissonEngine of the scene, or nullptr.
	static RdemPoissonEngine* of(const Scene* scene);
	/// Current scale factor of each element (1 intact, 0 released by a crack or an erased block).
	vector<Real> elementScales();
	void         postLoad(RdemPoissonEngine&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemPoissonEngine,GlobalEngine,R"""(Adds the Poisson effect to the refined DEM (paper §4.2, eqs. 18-21), in the formulation of :yref:`Ip2_RdemMat_RdemMat_RdemPhys::formulation` (the scene's one setting: ``'paper'`` or ``'consistent'``). Call ``build()`` once the bonds exist (and, for the consistent formulation, once the platens' DOFs are blocked).

*Elements* (a grid of $2\times2\times2$ groups of face-bonded blocks, the paper's case): one virtual 8-node hexahedral finite element per group, nodes at the 8 block centroids (a $10\times10\times12$ grid gives $9\times9\times11=891$ elements). Every step each element adds to its blocks the nodal forces $\mathbf{F}=-K_p\,\Delta\mathbf{u}$, $K_p=\int B^T D_p B\,dV$ (trilinear shape functions, $2\times2\times2$ Gauss), $D_p$ the off-diagonal part of the isotropic tensor (eq. 19), $\Delta\mathbf{u}$ the centroid displacements from the reference. Shortening along $z$ pushes the blocks outward in $x$ and $y$. An element of blocks of different :yref:`RdemMat` uses $\lambda_e=\langle\lambda/M\rangle/\langle 1/M\rangle$, $M=\lambda+2\mu$ (Backus 1962). With ``corotational``, the element's rigid rotation (polar decomposition of the deformation gradient at its centre) is removed before $K_p$. The consistent formulation adds the half-block skin beyond free faces (:ref:`theory §5.2 <rdem-theory-5-2>`).

*Cells* (any other layout of face-bonded rectangular blocks: running and English bond, bricks cut into blocks that do not line up, T-junctions, mixed sizes; consistent formulation only; :ref:`theory §5.4 <rdem-theory-5-4>`): every block is a cell whose normal strains $\varepsilon_d=\sum_q c_q u_{n,q}$ are weighted sums of the openings of its bonds (:yref:`RdemCellStrainUpdater`, which must come before the :yref:`InteractionLoop`); the cell's energy $\tfrac12 V\varepsilon^T(D-M I)\varepsilon$ gives each bond a normal force $-\partial W/\partial u_n$ at its face centre. Axes of a block without bonds, or bonded over less than a quarter of a face (a sliver), are condensed ($\sigma=0$: plane stress through a one-wythe wall). Openings are total measures, so rigid rotations of any size give no force (``corotational`` is not needed). Bonds whose centroids are offset along the face (running bond) correct their shear springs with the cells' strains at the face centre (:yref:`RdemPhys::offsetCorrection`). A uniform strain is an exact equilibrium, so apparent $E$ and $\nu$ equal the input.

Both: spring weights at free faces and platens are set by ``build`` in the consistent formulation (:yref:`RdemPhys::weightNormal`). An element's or cell's forces are scaled by the smallest fraction of intact restoring springs of its bonds (it never increases; a fully broken bond or an erased block releases it), so nothing bridging an open crack keeps pushing its sides apart.

With :yref:`O.trackEnergy<Omega.trackEnergy>`: ``rdemPoisson``, the elements' or cells' elastic energy (current value), and ``rdemPoissonRelease``, the energy taken away when cracks lower the scales (cumulated; negative when the released energy was negative, since $D_p$ alone is indefinite: releasing then *adds* energy.)""",
		((string,elements,"auto",Attr::triggerPostLoad,"What ``build`` makes: ``'auto'`` (default): cells where the formulation is consistent and the blocks are of more than one material (E, $\\nu$: a hexahedron straddling two blends their $\\lambda$, and a stack-bonded brick-mortar prism expands 44 % more than the layered medium; with cells within 1.7 %) or springs break on the total stress (:yref:`Law2_RdemGeom_RdemPhys_FaceSprings::totalStress`), cells on any layout that is not a grid of $2\\times2\\times2$ groups (one bonded neighbour per face), else the paper's hexahedra; ``'hex8'``: hexahedra (refused for other layouts); ``'cells'``: cells (consistent formulation). ``build`` says in the log which and why (a warning when ``'auto'`` puts cells on a grid, or the paper's hexahedra blend two materials), and in :yref:`chosen<RdemPoissonEngine::chosen>`."))
		((string,chosen,"",Attr::readonly,"What the last ``build`` made (``'hex8'`` or ``'cells'``) and why, e.g. ``'cells: blocks of 2 materials ...'``."))
		((vector<int>,nodes,,Attr::readonly,"Body ids of the element nodes, 8 per element, node $a=i+2j+4k$ at the block $(i,j,k)\\in\\{0,1\\}^3$ of the group."))
		((vector<Vector3r>,refPos,,Attr::readonly,"Reference positions of the nodes (8 per element) [m]."))
		((vector<Real>,lambda,,Attr::readonly,"Lamé constant $\\lambda$ of each element (see *Elements*) [Pa]."))
		((vector<Real>,skin,,Attr::readonly,"Skin weights of each element (6 per element: $-x,+x,-y,+y,-z,+z$ of its axes), 0 without skin (paper formulation)."))
		((bool,corotational,false,,"Remove each element's rigid rotation before $K_p$ (see *Elements*; cells need no such option)."))
		((shared_ptr<RdemSharedState>,shared,,,"What the plugin's engines share (:yref:`RdemSharedState`: the broken springs release elements and cells; handed by ``rdem.engines()``; None: the law's, taken at the first step)."))
		((bool,releaseOnCrack,true,,"Scale the forces of elements and cells by the intact fraction of their bonds (see above)."))
		((vector<Real>,scalePrev,,(Attr::hidden|Attr::readonly),"Force scale of each element in the last step (saved: the energy released by cracks in the next step depends on it)."))
		((int,energyIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
		((int,releaseIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
		,
		/* ctor */,
		.def("build",&RdemPoissonEngine::buildPy,(py::arg("ids")=py::list()),"Make the elements or cells of the bonded blocks ``ids`` (default: all blocks); current positions become the reference. In the consistent formulation, block the platens' DOFs first: skin, half cells and spring weights depend on them.")
		.def("omega2Bound",&RdemPoissonEngine::omega2Bound,"Per body, an upper bound of the squared eigenfrequency the Poisson forces add [1/s²] (used by :yref:`RdemTimeStepper`).")
		.def("elementScales",&RdemPoissonEngine::elementScales,"Per element, the current force scale (1 intact, 0 released by a crack or an erased block).")
		.add_property("nElements",&RdemPoissonEngine::nElements,"Number of elements (the paper's hexahedra).")
		.add_property("nCells",&RdemPoissonEngine::nCells,"Number of blocks with a Poisson cell.")
		.add_property("cellRebuilds",&RdemPoissonEngine::cellRebuilds,"How many times the cells' run-time network was made from the scene's bonds: at the first step after a ``build``, when bodies are added or erased or a bond is erased, and once the bonds released by the law are a quarter of its bonds (a released bond stays until then as a term of zero, having released the cells of both its blocks); not when contacts come and go (read-only, for tests).")
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	using Neighbours = std::map<Body::id_t, vector<std::pair<Body::id_t, Vector3r>>>; // per block: bonded block, unit direction
	// build, in RdemPoissonEngineBuild.cpp
	std::set<Body::id_t> collectBlocks(const vector<Body::id_t>& ids) const;
	Neighbours           bondedNeighbours(const std::set<Body::id_t>& ids) const;
	string               gridDefect(const Neighbours& nbr) const;
	string               materialMix(const std::set<Body::id_t>& ids) const; // "" for one material, else which
	void                 buildHex8(const std::set<Body::id_t>& ids, const Neighbours& nbr, bool consistent);
	void                 addHex8Element(const std::array<Body::id_t, 8>& n, const Neighbours& nbr, bool consistent);
	void                 setHex8SpringWeights(const std::set<Body::id_t>& ids, const Neighbours& nbr, bool consistent);
	void                 buildCells(const std::set<Body::id_t>& ids);
	void                 clearCells(const std::set<Body::id_t>& ids);
	// run, in RdemPoissonEngine.cpp
	void                            hex8Action();
	void                            cellAction();
	vector<Real>                    hex8Omega2Bound() const;
	vector<rdem::Mat24<Real>>       stiffness;   // the distinct K_p of the elements, rebuilt from refPos, lambda, skin (not saved)
	vector<size_t>                  stiffnessOf; // per element, its K_p in stiffness (not saved)
	vector<shared_ptr<Interaction>> bonds;       // the 12 bonds of each element, looked up once (not saved)
	vector<Real>                    scales;      // force scale of each element, see elementScales (not saved)
	vector<Vector3r>                nodalForce;  // this step's force of each element on each of its nodes, 8 per element (not saved)
	vector<size_t>                  nodeFirst;   // the nodal forces on body b are nodalForce[nodeSlot[k]], k in [nodeFirst[b], nodeFirst[b+1]) (not saved)
	vector<size_t>                  nodeSlot;
	vector<Vector3r>                nodeRef;           // per body: its reference position, from refPos (the same in all its elements) (not saved)
	vector<Vector3r>                nodePos;           // per body: its position in this step, copied once per step for the elements (not saved)
	long                            scalesBroken = -1; // broken springs in the scene when scales were computed
	long                            scalesIntrs  = -1; // number of interactions then
	RdemCellNetwork                 cells;             // the cells at run time (not saved: rebuilt from the states and interactions)
	void                            prepare();
	rdem::Mat24<Real>               elementStiffness(size_t e) const;
	bool                            prepared() const { return stiffnessOf.size() == size_t(nElements()); }
};
REGISTER_SERIALIZABLE(RdemPoissonEngine);

} // namespace yade
