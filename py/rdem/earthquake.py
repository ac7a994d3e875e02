"""Earthquakes: a ground motion (:mod:`rdem.ground_motion`: records read from PEER ``.AT2`` or two-column files, synthetic
pulses) applied to a scene by :yref:`RdemGroundShaker` (doc/earthquake.md).

Typical use::

    from rdem import ground_motion as gm
    motion = gm.GroundMotion(x=gm.readAT2('RSN6_IMPVALL.I_I-ELC180.AT2').baselineCorrected(2))
    rdem.earthquake.shaker(motion, ids=w.beams['base'])          # the base beam moves with the ground
    O.run(int(motion.duration / O.dt))

:class:`DryWall` is a dry-stacked brick wall standing free on a base, for tilting-table tests (:meth:`DryWall.tilt`,
against :func:`rdem.limit_analysis.stackTilt`) and for overturning under a pulse.
"""
import math
from yade import O, Vector3
from yade.wrapper import RdemGroundShaker, RdemMat
from . import ground_motion
from .limit_analysis import stackTilt
from .wall_layout import wallLayout
from . import build

MODES = ('prescribed', 'inertial')


def shaker(motion, ids=None, mode='prescribed', scale=1.0):
	"""Put an :yref:`RdemGroundShaker` playing ``motion`` into ``O.engines``, right before the :yref:`NewtonIntegrator`, and
	return it.

	:param motion: a :class:`rdem.ground_motion.GroundMotion`, or one :class:`rdem.ground_motion.Record` (taken as the x
	    component). Its velocity and displacement are integrated from its acceleration (baseline-correct the record first).
	:param ids: the base blocks that move with the ground (``mode='prescribed'``); their DOFs are blocked here.
	:param mode: ``'prescribed'`` (the base blocks follow the ground displacement exactly, as on a shaking table) or
	    ``'inertial'`` (no base motion; every body feels $-m\\,\\mathbf{a}_g(t)$ through :yref:`NewtonIntegrator::gravity`).
	:param scale: factor on the motion."""
	if isinstance(motion, ground_motion.Record):
		motion = ground_motion.GroundMotion(x=motion)
	if not isinstance(motion, ground_motion.GroundMotion):
		raise ValueError('motion = %r: must be an rdem.ground_motion.GroundMotion or Record' % (motion, ))
	if mode not in MODES:
		raise ValueError('mode = %r: must be one of %s' % (mode, MODES))
	newton = build.newtonIntegrator()
	ids = list(ids or [])
	if mode == 'prescribed':
		if not ids:
			raise ValueError("ids = %r: mode='prescribed' needs the base blocks that move with the ground" % (ids, ))
		for i in ids:
			if O.bodies[i] is None:
				raise ValueError('ids: body %s does not exist' % i)
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	toVectors = lambda a: [Vector3(float(r[0]), float(r[1]), float(r[2])) for r in a]
	eng = RdemGroundShaker(mode=mode, times=[float(t) for t in motion.times()], accelerations=toVectors(motion.accelerations()),
	                       velocities=toVectors(motion.velocities()), displacements=toVectors(motion.displacements()), ids=ids,
	                       gravity=Vector3(newton.gravity), scale=float(scale), label='groundShaker')
	engines = list(O.engines)
	engines.insert(engines.index(newton), eng)
	O.engines = engines
	return eng


class DryWall:
	"""A free-standing brick wall laid dry (no mortar), one block per brick, on a fixed base block: every bed and head
	joint and the wall's footing are contacts, sampled at the vertices (``contactSamples=1``, doc/theory.md §4.2), with
	critical dashpots (``dampingConstant``) and Coulomb friction; nothing is bonded. The masonry spans
	$x\\in[0, L]$, $y\\in[0, t]$, $z\\in[0, H]$ (:func:`rdem.wall_layout.wallLayout` with ``joint=0``); the base
	reaches ``baseMargin`` beyond the wall's foot on every side and beyond its head once it has fallen towards $+y$
	(widen it for a collapse: blocks that tumble off its edge fall for ever). Lengths in m, SI units.

	:meth:`tilt` turns gravity by $\\theta$ about $x$ towards $+y$: a base tilted by $\\theta$ seen in its own frame, as on a
	tilting table (de Felice 2011). :attr:`limit` is the rigid-block limit analysis of that test
	(:func:`rdem.limit_analysis.stackTilt`: $\\tan\\theta_c = \\min(t/H, \\mu)$ for one wythe).

	:ivar ids: the blocks of the wall (bricks and bats, course by course).
	:ivar courses: per course, its block ids.
	:ivar base: the id of the base block (its DOFs are blocked; ``rdem.earthquake.shaker(..., ids=[w.base])`` moves it).
	:ivar layout: the :class:`rdem.wall_layout.WallLayout`.
	:ivar limit: the :class:`rdem.limit_analysis.TiltCollapse` of the wall on a tilting base.
	:ivar theta: the current tilt [rad]."""

	def __init__(self, length=0.75, height=0.55, thickness=0.12, brick=(0.25, 0.12, 0.055), bond='running', young=16.7e9, poisson=0.15, density=1800,
	             friction=0.75, dampingConstant=1.0, contactSamples=1, gravity=9.81, baseMargin=0.05):
		for name, value in (('young', young), ('density', density), ('friction', friction), ('gravity', gravity), ('baseMargin', baseMargin)):
			if not (math.isfinite(value) and value > 0):
				raise ValueError('%s = %r: must be finite and > 0' % (name, value))
		if bond not in ('stack', 'running'):
			raise ValueError("bond = %r: must be 'stack' or 'running' (one wythe: every course spans the thickness)" % (bond, ))
		if len(O.bodies) or len(O.interactions):
			raise RuntimeError('DryWall builds into an empty scene: call O.reset() first')
		self.layout = wallLayout(length, height, thickness, brick=brick, joint=0.0, bond=bond)
		if self.layout.thickness > brick[1] * (1 + 1e-9):
			raise ValueError('thickness = %r: must be one brick width w = %r (one wythe)' % (thickness, brick[1]))
		self.g, self.theta = gravity, 0.0
		self.material = O.materials.append(
		        RdemMat(young=young, poisson=poisson, density=density, tensileStrength=float('inf'), cohesion=float('inf'), frictionAngle=math.atan(friction),
		                dampingNormal=dampingConstant, dampingShear=dampingConstant, label='brick'))
		O.engines = build.engines(poisson=None, recontact='always', contactSamples=contactSamples, gravity=(0, 0, -gravity))
		L, H, t = self.layout.length, self.layout.height, self.layout.thickness
		margin, depth = baseMargin, 0.05  # [m] the base reaches this far beyond the wall's foot and its head once fallen; its thickness
		lo, hi = Vector3(-margin, -margin, -depth), Vector3(L + margin, t + H + margin, 0)
		self.base = O.bodies.append(build.block((lo + hi) / 2, (hi - lo) / 2, self.material, fixed=True))
		bodies = [build.block(Vector3(*((a + b) / 2 for a, b in zip(*box))), tuple((b - a) / 2 for a, b in zip(*box)), self.material) for box in self.layout.blocks]
		self.ids = O.bodies.append(bodies)
		self.courses = [[] for _ in range(self.layout.courseCount)]
		for k, unit in enumerate(self.layout.units):
			self.courses[unit.course] += [self.ids[b] for b in unit.blocks]
		self.limit = stackTilt(t, H, [k * self.layout.brick[2] for k in range(self.layout.courseCount)], friction)  # joint = 0: course k starts at k h
		O.dt = -1

	def tilt(self, theta):
		"""Turn gravity by ``theta`` [rad] about $x$, towards $+y$: $\\mathbf{g} = g(0, \\sin\\theta, -\\cos\\theta)$
		(:attr:`theta`)."""
		self.theta = theta
		build.newtonIntegrator().gravity = Vector3(0, self.g * math.sin(theta), -self.g * math.cos(theta))

	def lean(self, ids=None):
		"""Mean rotation of the blocks ``ids`` (default: the whole wall) about $x$, positive when leaning towards $+y$
		[rad]: the angle of each block's own $z$ axis from the vertical in the $y$-$z$ plane."""
		ids = self.ids if ids is None else ids
		total = 0.0
		for i in ids:
			up = O.bodies[i].state.ori * Vector3(0, 0, 1)
			total += math.atan2(up[1], up[2])
		return total / len(ids)


class Building:
	"""A one-storey box of four brick walls made by :func:`building`: the body ids grouped as an engineer reads them.

	:ivar walls: ``{'front', 'back', 'left', 'right': rdem.masonry.Wall}`` (their bodies moved into place).
	:ivar ids: every block of the building, base and slab included.
	:ivar masonry: the blocks of the four walls.
	:ivar base: the base slab's block ids (move them with the ground: ``shaker(..., ids=b.base)``).
	:ivar slab: the roof slab's block ids (empty without one).
	:ivar top: the blocks of the walls' top courses.
	:ivar corners: the number of bonds made between the walls at the four corners."""

	def __init__(self, walls, base, slab, corners):
		self.walls, self.base, self.slab, self.corners = walls, base, slab, corners
		self.masonry = [i for w in walls.values() for i in w.ids]
		self.ids = base + self.masonry + slab
		self.top = [i for w in walls.values() for i in w.courses[-1]]

	def __repr__(self):
		return 'Building(%d blocks: walls %s, %d corner bonds, base %d, slab %d)' % (len(self.ids), ', '.join(
		        '%s %d' % (k, len(w.ids)) for k, w in self.walls.items()), self.corners, len(self.base), len(self.slab))


def _box(i):
	"""Axis-aligned box (lo, hi) of block ``i``, whose axes are along the global ones in any order [m]."""
	s = O.bodies[i].state
	R = s.ori.toRotationMatrix()
	h = O.bodies[i].shape.extents
	ext = Vector3(*(sum(abs(R[r, c]) * h[c] for c in range(3)) for r in range(3)))
	return s.pos - ext, s.pos + ext


def _touchingPairs(idsA, idsB, tol):
	"""Pairs (a, b), a in idsA and b in idsB, of boxes that share a face: touching along one axis (within ``tol`` [m]) and
	overlapping by more than ``tol`` along the two others."""
	boxesB = [(j, _box(j)) for j in idsB]
	pairs = []
	for i in idsA:
		lo, hi = _box(i)
		for j, (lo2, hi2) in boxesB:
			overlap = [min(hi[d], hi2[d]) - max(lo[d], lo2[d]) for d in range(3)]
			if sum(1 for o in overlap if abs(o) <= tol) == 1 and sum(1 for o in overlap if o > tol) == 2:
				pairs.append((i, j))
	return pairs


def _slab(lo, hi, material, touching, joint, tol):
	"""A block filling the box ``lo``–``hi`` [m], bonded with ``joint`` to the blocks of ``touching`` it shares a face with;
	returns its id."""
	i = O.bodies.append(build.block((lo + hi) / 2, (hi - lo) / 2, material, color=Vector3(0.5, 0.55, 0.65)))
	build.bondPairs(_touchingPairs([i], touching, tol), joint=joint)
	return i


def building(length, width, height, brickMaterial, jointMaterial, thickness=0.12, brick=(0.25, 0.12, 0.055), joint=0.01, bond='running', openings=None,
             slab=0.1, baseSlab=0.1, slabMaterial=None):
	"""Build a one-storey box of four brick walls into the current scene (``O.engines`` from :func:`rdem.engines` first):
	the front and back walls along $x$, ``length`` long, at $y\\in[0, t]$ and $[W - t, W]$ ($W$ = ``width``); the left and
	right walls along $y$ between them, $W - 2t$ long, at $x\\in[0, t]$ and $[L - t, L]$ (made by :func:`rdem.masonry.wall`
	along $x$ and turned by 90° about $z$ with their bonds, which live in the blocks' frames). The side walls butt against
	the inner faces of the front and back walls and are bonded to them by ``jointMaterial`` (a butt joint, as a head
	joint); a base slab under the whole plan and a roof slab on the walls (a rigid diaphragm) are bonded to the walls the
	same way. Lengths in m; every wall length must fit the bond's module (:func:`rdem.wall_layout.wallLayout`).

	:param openings: ``{'front'|'back'|'left'|'right': [(x0, z0, width, height), ...]}`` in each wall's own coordinates
	    (along the wall from its end at smaller $x$ or $y$) [m].
	:param slab, baseSlab: heights of the roof and base slabs [m] (``None``: no roof slab; the base slab is needed).
	:param slabMaterial: :yref:`RdemMat` of the slabs; default: the brick's elastic constants and density, unbreakable.
	:return: a :class:`Building`."""
	from . import masonry
	from yade import Quaternion
	for name, value in (('length', length), ('width', width), ('height', height), ('thickness', thickness), ('baseSlab', baseSlab)):
		if not (value is not None and math.isfinite(value) and value > 0):
			raise ValueError('%s = %r: must be finite and > 0 [m]' % (name, value))
	if not width > 2 * thickness:
		raise ValueError('width = %r: must exceed twice the thickness (%g m), the side walls lie between the front and back walls' % (width, 2 * thickness))
	openings = dict(openings or {})
	unknown = set(openings) - {'front', 'back', 'left', 'right'}
	if unknown:
		raise ValueError('openings: unknown wall %s (front, back, left, right)' % sorted(unknown))
	t = thickness
	args = dict(brick=brick, joint=joint, bond=bond, brickMaterial=brickMaterial, jointMaterial=jointMaterial)
	walls = {
	        'front': masonry.wall(length, height, t, openings=openings.get('front', ()), **args),
	        'back': masonry.wall(length, height, t, openings=openings.get('back', ()), origin=(0, width - t, 0), **args)
	}
	quarter = Quaternion(Vector3(0, 0, 1), math.pi / 2)  # x -> y, y -> -x
	for name, x0 in (('left', t), ('right', length)):
		w = masonry.wall(width - 2 * t, height, t, openings=openings.get(name, ()), **args)
		for i in w.ids:  # along x at y in [0, t] -> along y at x in [x0 - t, x0], from y = t
			s = O.bodies[i].state
			s.pos = s.refPos = quarter * s.pos + Vector3(x0, t, 0)
			s.ori = s.refOri = quarter * s.ori
		walls[name] = w
	tol = 1e-6 * min(brick)
	corner = masonry._jointLike(jointMaterial, joint, 'corner')
	corners = sum(
	        build.bondPairs(_touchingPairs(walls[side].ids, walls[face].ids, tol), joint=corner) for side in ('left', 'right') for face in ('front', 'back'))
	if slabMaterial is None:
		b = O.materials[brickMaterial] if isinstance(brickMaterial, int) else brickMaterial
		slabMaterial = O.materials.append(
		        RdemMat(young=b.young, poisson=b.poisson, density=b.density, tensileStrength=float('inf'), cohesion=float('inf'), label='slab'))
	interface = masonry._jointLike(jointMaterial, 0.0, 'slab')
	bottom = [i for w in walls.values() for i in w.courses[0]]
	base = [_slab(Vector3(0, 0, -baseSlab), Vector3(length, width, 0), slabMaterial, bottom, interface, tol)]
	top = [i for w in walls.values() for i in w.courses[-1]]
	roof = [_slab(Vector3(0, 0, height), Vector3(length, width, height + slab), slabMaterial, top, interface, tol)] if slab else []
	return Building(walls, base, roof, corners)
