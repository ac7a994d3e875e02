"""Earthquakes: a ground motion (:mod:`rdem.ground_motion`: records read from PEER ``.AT2`` or two-column files, synthetic
pulses) applied to a scene by :yref:`RdemGroundShaker` (:ref:`earthquakes <rdem-earthquake>`).

Typical use::

    from yade.rdem import ground_motion as gm
    motion = gm.GroundMotion(x=gm.readAT2('RSN6_IMPVALL.I_I-ELC180.AT2').baselineCorrected(2))
    rdem.earthquake.shaker(motion, ids=w.beams['base'])          # the base beam moves with the ground
    O.run(int(motion.duration / O.dt))

:class:`DryWall` is a dry-stacked brick wall standing free on a base, for tilting-table tests (:meth:`DryWall.tilt`,
against :func:`rdem.limit_analysis.stackTilt`) and for overturning under a pulse. Whole buildings: :func:`rdem.masonry.building`.
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
	joint and the wall's footing are contacts, sampled at the vertices (``contactSamples=1``, :ref:`theory §4.2 <rdem-theory-4-2>`), with
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
		O.engines = build.engines(formulation=None, recontact='always', contactSamples=contactSamples, gravity=(0, 0, -gravity))
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
