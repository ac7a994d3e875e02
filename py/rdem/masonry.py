"""Masonry walls as refined-DEM scenes: :func:`wall` lays out a wall of bricks and mortar (:mod:`rdem.wall_layout`), appends
its blocks to ``O.bodies`` and bonds them, every joint with its :yref:`RdemJoint`.

Typical use (after ``O.engines = rdem.engines(formulation='consistent')``)::

    brick = RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick')
    mortar = RdemJoint(young=2e9, poisson=0.25, tensileStrength=0.2e6, cohesion=0.3e6, frictionAngle=math.atan(0.8))
    w = rdem.masonry.wall(1.51, 0.975, 0.12, bond='running', brickMaterial=brick, jointMaterial=mortar, topBeam=0.1, baseBeam=0.1)
    rdem.poissonEngine().build(w.ids)

Joints (:ref:`theory §1.1 <rdem-theory-1-1>`, :ref:`wall layouts <rdem-wall-layout>`): with ``mortar='interface'`` every brick reaches the mid-planes of its joints
and each bed, head and collar bond puts brick, mortar and brick in series (:yref:`RdemJoint` of thickness $t$); with
``mortar='layer'`` the mortar is made of blocks of its own (so that its Poisson expansion acts on the bricks) and the
brick–mortar bonds are interfaces of zero thickness with the joint's strengths. Blocks of one brick are bonded directly
(the brick's material), and so are the blocks of one mortar layer; the beams are bonded to the bricks by interfaces with
the joint's strengths.
"""
import math
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint
from . import build
from .wall_layout import wallLayout

#: Colours of the blocks by unit kind (ParaView and the Qt viewer).
COLORS = {'brick': Vector3(0.72, 0.33, 0.22), 'bat': Vector3(0.82, 0.45, 0.3), 'mortar': Vector3(0.8, 0.8, 0.75), 'beam': Vector3(0.5, 0.55, 0.65)}


class Wall:
	"""A wall made by :func:`wall`: its body ids grouped as a masonry engineer reads them.

	:ivar ids: every block of the wall, beams included.
	:ivar units: per unit of the layout (brick, bat, mortar piece, beam), its block ids (same order as ``layout.units``).
	:ivar bricks: the block ids of each brick and bat (one list per brick).
	:ivar courses: per course, the block ids of its bricks and bats.
	:ivar mortar: the block ids of the mortar pieces (``mortar='layer'``).
	:ivar beams: ``{'base': ids, 'top': ids}`` (empty lists without beams).
	:ivar joints: ``{kind: [(id1, id2), ...]}`` the bonded pairs by kind: ``'internal'`` (inside a brick or beam), ``'bed'``,
	    ``'head'``, ``'collar'``, ``'mortar'`` (between mortar pieces), ``'beam'``.
	:ivar jointOf: ``{kind: RdemJoint}`` the joint each kind of bond was made with (``None``: bonded directly).
	:ivar layout: the :class:`rdem.wall_layout.WallLayout`.
	:ivar nBonds: number of bonds made.
	:ivar made: the ids of the blocks made in this scene (all of ``ids``, or those :func:`wall`'s ``only`` chose)."""

	def __init__(self, layout, ids, jointOf, nBonds, made=None):
		self.layout, self.ids, self.jointOf, self.nBonds = layout, ids, jointOf, nBonds
		self.made = list(ids) if made is None else made
		self.units = [[ids[b] for b in u.blocks] for u in layout.units]
		self.bricks = [self.units[k] for k, u in enumerate(layout.units) if u.kind in ('brick', 'bat')]
		self.courses = [[] for _ in range(layout.courseCount)]
		for k, u in enumerate(layout.units):
			if u.kind in ('brick', 'bat'):
				self.courses[u.course] += self.units[k]
		self.mortar = [i for k, u in enumerate(layout.units) if u.kind == 'mortar' for i in self.units[k]]
		self.beams = {'base': [], 'top': []}
		for k, u in enumerate(layout.units):
			if u.kind == 'beam':
				self.beams[u.piece] += self.units[k]
		self.joints = {}
		for i, j, kind, area in layout.pairs:
			self.joints.setdefault(kind, []).append((ids[i], ids[j]))

	def masonry(self):
		"""The block ids of the bricks, bats and mortar (the wall without its beams)."""
		beams = set(self.beams['base'] + self.beams['top'])
		return [i for i in self.ids if i not in beams]

	def __repr__(self):
		return 'Wall(%d blocks, %d bricks, %d courses, %d bonds: %s)' % (len(self.ids), len(self.bricks), len(self.courses), self.nBonds, ', '.join(
		        '%d %s' % (len(v), k) for k, v in sorted(self.joints.items())))


def numbers(text, n=None):
	"""Numbers separated by commas, as a command-line option gives them: a list of floats, ``n`` of them if given;
	:class:`argparse.ArgumentTypeError` (a ValueError) naming the text otherwise."""
	import argparse
	try:
		v = [float(x) for x in text.split(',')]
	except ValueError:
		raise argparse.ArgumentTypeError('%r: expected numbers separated by commas' % text)
	if n is not None and len(v) != n:
		raise argparse.ArgumentTypeError('%r: expected %d numbers separated by commas' % (text, n))
	return v


def openings(text):
	"""Openings of a wall as a command-line option gives them, rectangles ``x0,z0,width,height`` separated by ";": a list of
	[x0, z0, width, height] for :func:`wall`'s ``openings``; ArgumentTypeError naming the bad rectangle otherwise."""
	return [numbers(r, 4) for r in filter(None, text.split(';'))]


def addWallArguments(parser, length, height, thickness, bond, blocks, beam, brick=(0.25, 0.12, 0.055), joint=0.01):
	"""The options of a wall's geometry (lengths in m) in an argument group of ``parser``, with these defaults:
	--length, --height, --thickness, --brick, --joint, --bond, --mortar, --blocks, --openings (parsed by :func:`openings`)
	and --beam, the arguments of :func:`wall` as scripts/wall.py and scripts/shear_wall.py take them."""
	g = parser.add_argument_group('wall (lengths in m)')
	g.add_argument('--length', type=float, default=length, help='masonry length (default %(default)g)')
	g.add_argument('--height', type=float, default=height, help='masonry height between the beams (default %(default)g)')
	g.add_argument('--thickness', type=float, default=thickness, help='masonry thickness (default %(default)g)')
	g.add_argument('--brick', type=lambda s: numbers(s, 3), default=list(brick), help='brick length,width,height (default %s)' % ','.join('%g' % v for v in brick))
	g.add_argument('--joint', type=float, default=joint, help='mortar joint thickness (default %(default)g)')
	g.add_argument('--bond', choices=['stack', 'running', 'english', 'flemish'], default=bond, help='bond pattern (default %(default)s)')
	g.add_argument('--mortar', choices=['interface', 'layer'], default='interface', help='joint model: interface (zero-thickness joints in series) or '
	               'layer (mortar blocks, needed for the Poisson mismatch of mortar and brick); default interface')
	g.add_argument('--blocks', type=lambda s: [int(x) for x in numbers(s, 3)], default=list(blocks),
	               help='blocks per brick along its length,width,height (default %s)' % ','.join(str(b) for b in blocks))
	g.add_argument('--openings', type=openings, default=[], help='rectangles x0,z0,width,height separated by ";" (default none)')
	g.add_argument('--beam', type=float, default=beam, help='height of the base and top beams (default %(default)g)')
	return g


def _material(value, name):
	mat = O.materials[value] if isinstance(value, int) else value
	if not isinstance(mat, RdemMat):
		raise ValueError('%s = %r: must be an RdemMat (or its index in O.materials)' % (name, value))
	return mat


def _jointLike(template, thickness, label):
	"""A copy of the RdemJoint ``template`` (every attribute: elastic constants, strengths, fracture energies, ...) with the
	given thickness and label."""
	attrs = template.dict()
	attrs.update(thickness=thickness, label=label)
	return RdemJoint(**attrs)


def _joints(jointMaterial, mortar, t):
	"""The RdemJoint of each kind of pair: interface joints carry the mortar (thickness t), layer-mode brick-mortar faces are
	interfaces without thickness; blocks of one unit and of one mortar layer are bonded directly."""
	thick = t if mortar == 'interface' else 0.0
	out = {kind: _jointLike(jointMaterial, thick, kind) for kind in ('bed', 'head', 'collar')}
	out['beam'] = _jointLike(jointMaterial, 0.0, 'beam')
	out['internal'] = out['mortar'] = None
	return out


def wall(length,
         height,
         thickness,
         brick=(0.25, 0.12, 0.055),
         joint=0.01,
         bond='running',
         blocksPerBrick=(1, 1, 1),
         mortar='interface',
         openings=(),
         baseBeam=None,
         topBeam=None,
         beamBlocks=1,
         brickMaterial=None,
         jointMaterial=None,
         mortarMaterial=None,
         beamMaterial=None,
         origin=(0, 0, 0),
         only=None):
	"""Build a masonry wall into the current scene: lay it out (:func:`rdem.wall_layout.wallLayout`, whose arguments the
	first twelve are), append its blocks to ``O.bodies`` and bond every touching pair with the joint of its kind. ``O.engines``
	must come from :func:`rdem.engines` first. Lengths in m; the wall spans $x\\in$ [0, length], $y\\in$ [0, thickness], $z\\in$
	[0, height] from ``origin``, beams below and above.

	:param brickMaterial: :yref:`RdemMat` of the bricks (blocks of one brick are bonded with its strengths).
	:param jointMaterial: :yref:`RdemJoint` of the mortar joints: the mortar's $E_m$, $\\nu_m$ and the unit–mortar bond's
	    strengths (its ``thickness`` is set from ``joint``: $t$ for ``mortar='interface'``, 0 for the brick–mortar faces of
	    ``mortar='layer'``). Copied per kind: :attr:`Wall.jointOf`.
	:param mortarMaterial: :yref:`RdemMat` of the mortar blocks (``mortar='layer'`` only); default: $E_m$ and $\\nu_m$ of
	    ``jointMaterial``, the joint's strengths, density 1800 kg/m³ (a cement–lime mortar).
	:param beamMaterial: :yref:`RdemMat` of the beams; default: the brick's elastic constants and density, unbreakable.
	:param only: ``None``: make every block; or a function of the :class:`rdem.wall_layout.WallLayout` that returns the
	    indices (into its ``blocks``) of the blocks to make, for a set-up on YADE's MPI in which each rank makes only its
	    own blocks and the neighbours it needs (:class:`rdem.distributed.PerRank`, mpy's ``DISTRIBUTED_INSERT``). The
	    blocks of the whole wall then have the ids ``len(O.bodies)`` + their index (at the call), on every rank alike;
	    each block made is inserted at its id (``O.bodies.insertAtId``) and every pair of two blocks made is bonded.
	    :attr:`Wall.ids` and the groups are the whole wall's ids, :attr:`Wall.made` the ids made.
	:return: a :class:`Wall`.

	ValueError for any argument out of range, naming it (the layout's arguments are checked by ``wallLayout``)."""
	if jointMaterial is None or not isinstance(jointMaterial, RdemJoint):
		raise ValueError('jointMaterial = %r: must be an RdemJoint (the mortar joints: E and nu of the mortar, bond strengths)' % (jointMaterial, ))
	if brickMaterial is None:
		raise ValueError('brickMaterial = None: must be an RdemMat (or its index in O.materials)')
	brickMat = _material(brickMaterial, 'brickMaterial')
	if len(origin) != 3 or not all(math.isfinite(c) for c in origin):
		raise ValueError('origin = %r: must be 3 finite numbers [m]' % (origin, ))
	build.geomFunctor()  # fail early and clearly if the engines are not there
	layout = wallLayout(length, height, thickness, brick=brick, joint=joint, bond=bond, blocksPerBrick=blocksPerBrick, mortar=mortar, openings=openings,
	                    baseBeam=baseBeam, topBeam=topBeam, beamBlocks=beamBlocks)
	if mortar == 'layer':
		mortarMat = _material(mortarMaterial, 'mortarMaterial') if mortarMaterial is not None else RdemMat(
		        young=jointMaterial.young, poisson=jointMaterial.poisson, density=1800, tensileStrength=jointMaterial.tensileStrength,
		        cohesion=jointMaterial.cohesion, frictionAngle=jointMaterial.frictionAngle, label='mortar')
	elif mortarMaterial is not None:
		raise ValueError("mortarMaterial is for mortar='layer' (mortar blocks); with mortar='interface' the joint carries the mortar: jointMaterial")
		if mortarMaterial is None:
			O.materials.append(mortarMat)
	beamMat = _material(beamMaterial, 'beamMaterial') if beamMaterial is not None else RdemMat(
	        young=brickMat.young, poisson=brickMat.poisson, density=brickMat.density, tensileStrength=float('inf'), cohesion=float('inf'), label='beam')
	if beamMaterial is None and (baseBeam is not None or topBeam is not None):
		O.materials.append(beamMat)
	materialOf = {'brick': brickMat, 'bat': brickMat, 'beam': beamMat}
	if mortar == 'layer':
		materialOf['mortar'] = mortarMat
	o = Vector3(*origin)
	first = len(O.bodies)
	made = range(len(layout.blocks)) if only is None else sorted(set(int(k) for k in only(layout)))
	if made and not 0 <= made[0] <= made[-1] < len(layout.blocks):
		raise ValueError('only: returned block indices outside 0 ... %d (the layout\'s blocks)' % (len(layout.blocks) - 1))
	bodies = []
	for k in made:
		lo, hi = layout.blocks[k]
		unit = layout.units[layout.blockUnit[k]]
		centre = o + Vector3(*((lo[d] + hi[d]) / 2 for d in range(3)))
		half = tuple((hi[d] - lo[d]) / 2 for d in range(3))
		bodies.append(build.block(centre, half, materialOf[unit.kind], color=COLORS[unit.kind]))
	if only is None:
		ids = O.bodies.append(bodies)
	else:
		ids = list(range(first, first + len(layout.blocks)))
		for k, b in zip(made, bodies):
			O.bodies.insertAtId(b, first + k)
		made = set(made)
	jointOf = _joints(jointMaterial, mortar, layout.joint)
	byKind = {}
	for i, j, kind, area in layout.pairs:
		if only is None or (i in made and j in made):
			byKind.setdefault(kind, []).append((ids[i], ids[j]))
	nBonds = sum(build.bondPairs(pairs, joint=jointOf[kind]) for kind, pairs in sorted(byKind.items()))
	return Wall(layout, ids, jointOf, nBonds, None if only is None else [ids[k] for k in sorted(made)])


from .building import building, Building  # noqa: E402  (rdem.masonry.building: a whole building of such walls)
from .arch import arch, Arch  # noqa: E402  (rdem.masonry.arch: arches and barrel vaults of voussoirs)
