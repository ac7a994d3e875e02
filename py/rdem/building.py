"""Masonry buildings as refined-DEM scenes: :func:`building` (``rdem.masonry.building``) lays a building out
(:func:`rdem.building_layout.buildingLayout`), appends its blocks to ``O.bodies`` and bonds the touching pairs, each kind of
joint with its :yref:`RdemJoint`.

Typical use (after ``O.engines = rdem.engines(formulation='consistent', contactSamples=1, gravity=(0, 0, -9.81))``)::

    brick = RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick')
    mortar = RdemJoint(young=2e9, poisson=0.25, tensileStrength=0.2e6, cohesion=0.3e6, frictionAngle=math.atan(0.75))
    b = rdem.masonry.building(plan=(2.59, 2.07), storeys=[1.355], brickMaterial=brick, jointMaterial=mortar,
                              openings=[('front', 0, 0.905, 0.0, 0.78, 0.97)], floors='slab', roofLoad=150)
    rdem.poissonEngine().elements = 'cells'
    b.fixBase(); rdem.poissonEngine().build(b.bonded())
    rdem.earthquake.shaker(motion, ids=b.base)

Joints (:ref:`buildings <rdem-building>`): bed, head and collar joints, the corners and T-junctions included, are interface joints of
the mortar (thickness $t$, :yref:`RdemJoint`); the base beam, lintels and slab pieces are bonded to the masonry by
interfaces without thickness with the mortar's strengths; the blocks of a brick, and the slab pieces among themselves,
are bonded directly; joists rest on their seats by contact and friction, or are tied (bonded with ``tieJoint``).
"""
import math
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint
from . import build
from .building_layout import buildingLayout
from .masonry import COLORS, _jointLike, _material

#: Colours of the blocks by unit kind, beyond those of :data:`rdem.masonry.COLORS`.
BUILDING_COLORS = dict(COLORS, lintel=Vector3(0.45, 0.45, 0.5), slab=Vector3(0.6, 0.6, 0.62), joist=Vector3(0.55, 0.4, 0.2))


class Building:
	"""A building made by :func:`building`: its body ids grouped as an engineer reads them.

	:ivar layout: the :class:`rdem.building_layout.BuildingLayout`.
	:ivar ids: every block, in the layout's order (``ids[k]`` is block ``k`` of the layout).
	:ivar base: the base beam's blocks (move them with the ground: ``rdem.earthquake.shaker(motion, ids=b.base)``).
	:ivar walls: ``{name: ids}`` the bricks and bats of each wall, all storeys.
	:ivar lintels, slabs, joists: ``{storey: ids}``.
	:ivar joints: ``{kind: [(id1, id2), ...]}`` every touching pair by kind (:data:`rdem.building_layout.PAIR_KINDS`),
	    bonded or not (see :attr:`jointOf`).
	:ivar jointOf: ``{kind: RdemJoint or None}`` the joint each kind was bonded with (``None``: bonded directly); kinds
	    missing here were not bonded (``'base'``; ``'joist'`` without ties).
	:ivar nBonds: number of bonds made."""

	def __init__(self, layout, ids, jointOf, nBonds):
		self.layout, self.ids, self.jointOf, self.nBonds = layout, ids, jointOf, nBonds
		byKind = lambda kind, storey=None: [ids[b] for b in layout.blocksOf(kind, storey=storey)]
		self.base = byKind('beam')
		self.walls = {w.name: [ids[b] for b in layout.blocksOf('masonry', wall=w.index)] for w in layout.walls}
		self.lintels = {s.index: byKind('lintel', s.index) for s in layout.storeys}
		self.slabs = {s.index: byKind('slab', s.index) for s in layout.storeys}
		self.joists = {s.index: byKind('joist', s.index) for s in layout.storeys}
		self.joints = {}
		for i, j, kind, area in layout.pairs:
			self.joints.setdefault(kind, []).append((ids[i], ids[j]))

	def of(self, wall=None, storey=None, kind='masonry'):
		"""Block ids of a ``wall`` (name or index), ``storey`` and ``kind`` (as
		:meth:`rdem.building_layout.BuildingLayout.unitsOf`; ``None`` selects all)."""
		return [self.ids[b] for b in self.layout.blocksOf(kind, wall, storey)]

	def masonry(self):
		"""The bricks and bats of every wall."""
		return self.of()

	def bonded(self):
		"""Every block bonded to another (all but the joists without ties): the blocks to build the Poisson cells on."""
		loose = set() if 'joist' in self.jointOf else set(i for s in self.joists.values() for i in s)
		return [i for i in self.ids if i not in loose]

	def fixBase(self):
		"""Block every DOF of the base beam's blocks (before ``rdem.poissonEngine().build``; the ground shaker moves them)."""
		for i in self.base:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'

	def weight(self, g=9.81):
		"""The weight of everything above the base beam [N] (loads included)."""
		base = set(self.base)
		return g * sum(O.bodies[i].state.mass for i in self.ids if i not in base)

	def __repr__(self):
		c = self.layout.counts()
		return 'Building(%d blocks: %d walls %s, %d storeys, %d lintels, %d slab pieces, %d joists, base %d; %d bonds)' % (len(
		        self.ids), len(self.walls), '/'.join(self.walls), len(self.layout.storeys), c['units:lintel'], c['units:slab'], c['units:joist'],
		                                                                                                        len(self.base), self.nBonds)


def _defaultMaterial(name, **attrs):
	m = RdemMat(label=name, **attrs)
	O.materials.append(m)
	return m


def building(plan,
             storeys,
             brickMaterial,
             jointMaterial,
             slabMaterial=None,
             lintelMaterial=None,
             timberMaterial=None,
             beamMaterial=None,
             ties=False,
             tieJoint=None,
             origin=(0, 0, 0),
             **layout):
	"""Build a masonry building into the current scene: lay it out with :func:`rdem.building_layout.buildingLayout` (``plan``,
	``storeys`` and the keyword arguments ``layout`` are its arguments), append its blocks to ``O.bodies`` and bond the
	touching pairs. ``O.engines`` must come from :func:`rdem.engines` first (with ``recontact`` for joists without ties:
	they rest on their seats by contact). Lengths in m from ``origin``.

	:param brickMaterial: :yref:`RdemMat` of the bricks. :param jointMaterial: :yref:`RdemJoint` of the mortar (copied
	    per kind of joint, :attr:`Building.jointOf`).
	:param slabMaterial, lintelMaterial: :yref:`RdemMat` of the RC slabs and lintels; default reinforced concrete kept
	    elastic: $E$ = 30 GPa, $\\nu$ = 0.2, 2500 kg/m³, unbreakable ([EN1992-1-1]_ Table 3.1: C30/37 has $E_{cm}$ = 33 GPa,
	    taken lower for cracking; [EN1991-1-1]_ Table A.1: 25 kN/m³ for reinforced concrete).
	:param timberMaterial: :yref:`RdemMat` of the joists; default softwood C24 ([EN338]_: $E_{0,mean}$ = 11 GPa, 420 kg/m³
	    mean density; $\\nu$ = 0.3, assumed), unbreakable, friction coefficient 0.5 against the masonry (assumed).
	:param beamMaterial: of the base beam; default the brick's elastic constants and density, unbreakable.
	:param ties: bond the joists to their seats with ``tieJoint`` (an :yref:`RdemJoint`; default the mortar joint's
	    properties with zero thickness): steel ties or anchored joists; ``False``: they rest by friction only.
	:return: a :class:`Building`.

	ValueError for any argument out of range, naming it."""
	if not isinstance(jointMaterial, RdemJoint):
		raise ValueError('jointMaterial = %r: must be an RdemJoint (the mortar joints: E and nu of the mortar, bond strengths)' % (jointMaterial, ))
	if brickMaterial is None:
		raise ValueError('brickMaterial = None: must be an RdemMat (or its index in O.materials)')
	brick = _material(brickMaterial, 'brickMaterial')
	if len(origin) != 3 or not all(math.isfinite(c) for c in origin):
		raise ValueError('origin = %r: must be 3 finite numbers [m]' % (origin, ))
	if not isinstance(ties, bool):
		raise ValueError('ties = %r: must be True or False' % (ties, ))
	if tieJoint is not None and not isinstance(tieJoint, RdemJoint):
		raise ValueError('tieJoint = %r: must be an RdemJoint or None' % (tieJoint, ))
	build.geomFunctor()  # fail early and clearly if the engines are not there
	lay = buildingLayout(plan, storeys, **layout)
	inf = float('inf')
	rc = lambda name: _defaultMaterial(name, young=30e9, poisson=0.2, density=2500, tensileStrength=inf, cohesion=inf, frictionAngle=math.atan(0.75))
	counts = lay.counts()
	slab = _material(slabMaterial, 'slabMaterial') if slabMaterial is not None else (rc('slab') if counts['units:slab'] else None)
	lintel = _material(lintelMaterial, 'lintelMaterial') if lintelMaterial is not None else (rc('lintel') if counts['units:lintel'] else None)
	timber = _material(timberMaterial, 'timberMaterial') if timberMaterial is not None else (_defaultMaterial(
	        'timber', young=11e9, poisson=0.3, density=420, tensileStrength=inf, cohesion=inf, frictionAngle=math.atan(0.5)) if counts['units:joist'] else None)
	beam = _material(beamMaterial, 'beamMaterial') if beamMaterial is not None else _defaultMaterial(
	        'beam', young=brick.young, poisson=brick.poisson, density=brick.density, tensileStrength=inf, cohesion=inf)
	materialOf = {'brick': brick, 'bat': brick, 'beam': beam, 'lintel': lintel, 'slab': slab, 'joist': timber}
	o = Vector3(*origin)
	bodies = []
	unitVolume = {}
	for k, (lo, hi) in enumerate(lay.blocks):
		u = lay.blockUnit[k]
		unit = lay.units[u]
		centre = o + Vector3(*((lo[d] + hi[d]) / 2 for d in range(3)))
		half = tuple((hi[d] - lo[d]) / 2 for d in range(3))
		body = build.block(centre, half, materialOf[unit.kind], color=BUILDING_COLORS[unit.kind])
		if lay.unitMass[u] > 0:  # the floor or roof load on this unit, shared by its blocks by volume
			if u not in unitVolume:
				unitVolume[u] = sum(math.prod(lay.blocks[b][1][d] - lay.blocks[b][0][d] for d in range(3)) for b in unit.blocks)
			factor = 1 + lay.unitMass[u] * (8 * half[0] * half[1] * half[2] / unitVolume[u]) / body.state.mass
			body.state.mass *= factor
			body.state.inertia = body.state.inertia * factor
		bodies.append(body)
	ids = O.bodies.append(bodies)
	t = lay.joint
	jointOf = {kind: _jointLike(jointMaterial, t, kind) for kind in ('bed', 'head', 'collar')}
	jointOf.update((kind, _jointLike(jointMaterial, 0.0, kind)) for kind in ('beam', 'lintel', 'floor'))
	jointOf['internal'] = jointOf['slab'] = None
	if ties:
		jointOf['joist'] = tieJoint if tieJoint is not None else _jointLike(jointMaterial, 0.0, 'tie')
	byKind = {}
	for i, j, kind, area in lay.pairs:
		if kind in jointOf:
			byKind.setdefault(kind, []).append((ids[i], ids[j]))
	nBonds = sum(build.bondPairs(pairs, joint=jointOf[kind]) for kind, pairs in sorted(byKind.items()))
	return Building(lay, ids, jointOf, nBonds)
