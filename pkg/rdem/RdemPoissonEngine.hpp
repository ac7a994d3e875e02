/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/GlobalEngine.hpp>
#include <core/Interaction.hpp>
#include <pkg/rdem/math/Hex8.hpp>

namespace yade {

/// The Poisson effect: virtual 8-node hexahedra on the centroids of 2×2×2 bonded blocks (paper §4.2, eqs. 18-21).
class RdemPoissonEngine : public GlobalEngine {
public:
	void action() override;
	/// Find every 2×2×2 group of bonded blocks among ids (all RdemBlock bodies if empty) and make one element each;
	/// the current positions become the reference. Throws std::invalid_argument for block sets that are not grids.
	void build(const vector<Body::id_t>& ids);
	/// Python front of build: a list of ids, empty (default) for all blocks.
	void buildPy(const py::list& ids);
	/// Upper bound of the Poisson stiffness per body: max over its 3 rows of Σ|K_p| of every element it is a node of [N/m].
	vector<Real> stiffnessBound() const;
	/// Number of elements.
	int nElements() const { return int(nodes.size() / 8); }
	/// Current scale factor of each element (1 intact, 0 released by a crack or an erased block).
	vector<Real> elementScales();
	void         postLoad(RdemPoissonEngine&);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(RdemPoissonEngine,GlobalEngine,R"""(Adds the Poisson effect to the refined DEM (paper §4.2, eqs. 18-21).

One virtual 8-node hexahedral finite element is made for every $2\times2\times2$ group of face-bonded blocks; its nodes are the 8 block centroids (call ``build()`` once the bonds exist; a $10\times10\times12$ grid gives $9\times9\times11=891$ elements). Every step each element adds to its 8 blocks the nodal forces $\mathbf{F}=-K_p\,\Delta\mathbf{u}$, $K_p=\int B^T D_p B\,dV$ (trilinear shape functions, $2\times2\times2$ Gauss), $D_p$ the off-diagonal part of the isotropic elasticity tensor (eq. 19) and $\Delta\mathbf{u}$ the centroid displacements from the reference positions. Shortening along $z$ pushes the blocks outward in $x$ and $y$.

*Materials:* an element of one material uses its Lamé constant $\lambda$; an element of blocks of different :yref:`RdemMat` uses $\lambda_e=\langle\lambda/M\rangle/\langle 1/M\rangle$, $M=\lambda+2\mu$, $\langle\cdot\rangle$ block-volume averages (Backus 1962, the coupling across the layers of a layered medium; the harmonic mean of $\lambda$ for equal $\nu$), so that a soft mortar layer softens the coupling as it softens the springs.

*Corotational* (``corotational=True``): the element's rigid rotation (polar decomposition of the deformation gradient at its centre) is removed before $K_p$ and the forces are rotated back, so rigidly rotating groups of blocks stay force-free (needed when blocks rotate by more than a few degrees, e.g. masonry collapse). Off by default, as in the paper.

*Cracks:* an element's forces are scaled by the smallest fraction of intact restoring springs over the 12 bonds between its blocks, so an element bridging an open crack stops pushing its sides apart (a fully broken bond releases it for good). An element one of whose blocks is erased (``O.bodies.erase``) is released too.

With :yref:`O.trackEnergy<Omega.trackEnergy>`: ``rdemPoisson``, the elements' elastic energy $\tfrac12 s\,\Delta\mathbf{u}^T K_p\Delta\mathbf{u}$ (current value; rotation removed in the corotational case), and ``rdemPoissonRelease``, the element energy $\tfrac12(s_{prev}-s)\Delta\mathbf{u}^T K_p\Delta\mathbf{u}$ taken away when cracks lower an element's scale (cumulated; negative when the released element energy was negative, since $D_p$ alone is indefinite: releasing then *adds* energy, up to a few % of the work in the compression test, doc/stability.md).

*Topology:* ``build`` refuses blocks with two bonded neighbours on one side (e.g. running-bond masonry), groups that close inconsistently and block sets with no group at all; blocks at edges and surfaces belong to fewer elements or none.)""",
		((vector<int>,nodes,,Attr::readonly,"Body ids of the element nodes, 8 per element, node $a=i+2j+4k$ at the block $(i,j,k)\\in\\{0,1\\}^3$ of the group."))
		((vector<Vector3r>,refPos,,Attr::readonly,"Reference positions of the nodes (8 per element) [m]."))
		((vector<Real>,lambda,,Attr::readonly,"Lamé constant $\\lambda$ of each element (see *Materials*) [Pa]."))
		((bool,consistent,false,,"Consistent formulation (doc/theory.md §5.2): elements also integrate over the half-block skin beyond free faces and ``build`` sets boundary weights of the springs, so that with $\\lambda+2\\mu$ springs (:yref:`Ip2_RdemMat_RdemMat_RdemPhys::springModulus` = 1) a uniform strain is an exact equilibrium and the apparent $E$ and $\\nu$ equal the input. Faces whose blocks have their normal translation prescribed (blocked DOF) are platens: no skin there. Off: the paper's elements on the centroid hull only."))
		((vector<Real>,skin,,Attr::readonly,"Skin weights of each element (6 per element: $-x,+x,-y,+y,-z,+z$ of its axes), 0 without skin; see :yref:`RdemPoissonEngine::consistent`."))
		((bool,corotational,false,,"Remove each element's rigid rotation before $K_p$ (see above)."))
		((bool,releaseOnCrack,true,,"Scale element forces by the intact fraction of their bonds (see above)."))
		((vector<Real>,scalePrev,,(Attr::hidden|Attr::readonly),"Force scale of each element in the last step (saved: the energy released by cracks in the next step depends on it)."))
		((int,energyIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
		((int,releaseIx,-1,(Attr::hidden|Attr::noSave),"Energy index."))
		,
		/* ctor */,
		.def("build",&RdemPoissonEngine::buildPy,(py::arg("ids")=py::list()),"Make the elements from the bonded blocks ``ids`` (default: all blocks); current positions become the reference. With ``consistent``, block the platens' DOFs first: the skin and spring weights depend on them.")
		.def("stiffnessBound",&RdemPoissonEngine::stiffnessBound,"Per body, an upper bound of the Poisson stiffness it feels [N/m] (used by :yref:`RdemTimeStepper`).")
		.def("elementScales",&RdemPoissonEngine::elementScales,"Per element, the current force scale (1 intact, 0 released by a crack or an erased block).")
		.add_property("nElements",&RdemPoissonEngine::nElements,"Number of elements.")
	);
	// clang-format on
	DECLARE_LOGGER;

private:
	vector<rdem::Mat24<Real>>       stiffness;   // the distinct K_p of the elements, rebuilt from refPos, lambda, skin (not saved)
	vector<size_t>                  stiffnessOf; // per element, its K_p in stiffness (not saved)
	vector<shared_ptr<Interaction>> bonds;     // the 12 bonds of each element, looked up once (not saved)
	vector<Real>                    scales;    // force scale of each element, see elementScales (not saved)
	vector<Vector3r>                nodalForce; // this step's force of each element on each of its nodes, 8 per element (not saved)
	vector<size_t>                  nodeFirst;  // the nodal forces on body b are nodalForce[nodeSlot[k]], k in [nodeFirst[b], nodeFirst[b+1]) (not saved)
	vector<size_t>                  nodeSlot;
	vector<Vector3r>                nodeRef;           // per body: its reference position, from refPos (the same in all its elements) (not saved)
	vector<Vector3r>                nodePos;           // per body: its position in this step, copied once per step for the elements (not saved)
	long                            scalesBroken = -1; // broken springs in the scene when scales were computed
	long                            scalesIntrs  = -1; // number of interactions then
	void                            prepare();
	rdem::Mat24<Real>               elementStiffness(size_t e) const;
	bool                            prepared() const { return stiffnessOf.size() == size_t(nElements()); }
};
REGISTER_SERIALIZABLE(RdemPoissonEngine);

} // namespace yade
