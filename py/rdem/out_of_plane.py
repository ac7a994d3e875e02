"""Out-of-plane scenes of unreinforced masonry (:ref:`out-of-plane mechanisms <rdem-out-of-plane>`): a wall spanning one way between its base and a
top support pushed out of its plane quasi-statically (:class:`OneWayWallPush`), and a free-standing parapet on a roof
shaken by a ground pulse (:class:`Parapet`). Each is checked against rigid-block theory
(:class:`rdem.limit_analysis.OneWayWall`, :class:`rdem.rocking.RockingBlockEquation`) in tests/yade/test_out_of_plane.py
and tests/yade/test_parapet.py.

Coordinates: $x$ along the wall, $y$ through its thickness (the loaded face at $y = 0$, pushed towards $+y$), $z$ up. SI
units.
"""
import math
from yade import O, Vector3
from yade.wrapper import RdemMat
from . import build
from . import ground_motion
from . import earthquake
from .limit_analysis import OneWayWall
from .rocking import RockingBlockEquation


def _check(name, value, low=0.0):
	if isinstance(value, bool) or not isinstance(value, (int, float)) or not (math.isfinite(value) and value > low):
		raise ValueError('%s = %r: must be a finite number > %g' % (name, value, low))
	return float(value)


class OneWayWallPush:
	"""A dry-stacked wall strip ``courses`` courses high (one block per course, ``length`` long) on a fixed base, with a top
	beam that stays horizontal and is held along $x$ and $y$ but free to rise (its weight is the overburden, bearing on the
	wall through high-friction contacts that hold the wall's top horizontally), pushed out of plane at the two courses
	next to mid-height: their $y$ velocity is prescribed (``rate``, after a half-cosine ramp), everything else follows.
	The push force is the $y$ reaction on those two courses.

	Contacts are sampled at the vertices (``contactSamples=1``), the joints have friction ``friction`` (high: the
	rigid-body relation assumes no sliding); Cundall's damping 0.2 (quasi-static).

	:param height: $h$ [m]. :param thickness: $t$ [m]. :param length: along $x$ [m]. :param courses: even, >= 4.
	:param overburden: $O$ [N] >= 0, the top beam's weight; with 0 the top beam still weighs ``beamWeight`` [N] (it must
	    press on the wall to hold it by friction).
	:param young, density: of the wall and beams (units: Pa, kg/m³)."""

	def __init__(self, height=1.0, thickness=0.1, length=0.2, courses=20, overburden=0.0, beamWeight=None, young=1e9, density=2000, friction=5.0,
	             rate=0.02, ramp=0.2, gravity=9.81):
		h, t, L = _check('height', height), _check('thickness', thickness), _check('length', length)
		if not t < h:
			raise ValueError('thickness = %r: must be < height = %g' % (thickness, h))
		if isinstance(courses, bool) or not isinstance(courses, int) or courses < 4 or courses % 2:
			raise ValueError('courses = %r: must be an even integer >= 4 (the push acts on the two courses next to mid-height)' % (courses, ))
		if not (isinstance(overburden, (int, float)) and math.isfinite(overburden) and overburden >= 0):
			raise ValueError('overburden = %r: must be a finite number >= 0 [N]' % (overburden, ))
		self.rate, self.ramp = _check('rate', rate), _check('ramp', ramp)
		_check('young', young), _check('density', density), _check('friction', friction), _check('gravity', gravity)
		if len(O.bodies) or len(O.interactions):
			raise RuntimeError('OneWayWallPush builds into an empty scene: call O.reset() first')
		self.h, self.t, self.L, self.n, self.g = h, t, L, courses, gravity
		c = h / courses
		self.course = c
		W = density * L * t * h * gravity
		self.weight = W
		self.overburden = float(overburden) if overburden > 0 else (beamWeight if beamWeight is not None else 0.02 * W)
		mat = O.materials.append(
		        RdemMat(young=young, poisson=0.2, density=density, tensileStrength=float('inf'), cohesion=float('inf'), frictionAngle=math.atan(friction),
		                dampingNormal=1.0, dampingShear=1.0, label='wall'))
		O.engines = build.engines(formulation=None, recontact='always', contactSamples=1, gravity=(0, 0, -gravity), damping=0.2)
		self.base = O.bodies.append(build.block((L / 2, t / 2, -c / 2), (L / 2 + 0.05, t / 2 + 0.1, c / 2), mat, fixed=True))
		self.courses = [O.bodies.append(build.block((L / 2, t / 2, (k + 0.5) * c), (L / 2, t / 2, c / 2), mat)) for k in range(courses)]
		beam = build.block((L / 2, t / 2, h + c / 2), (L / 2, t / 2, c / 2), mat)
		beam.state.mass = self.overburden / gravity
		beam.state.blockedDOFs = 'xyXYZ'
		self.beam = O.bodies.append(beam)
		self.driven = self.courses[courses // 2 - 1:courses // 2 + 1]
		for i in self.driven:
			O.bodies[i].state.blockedDOFs = 'y'
		self.rigid = OneWayWall(h, t, W, self.overburden, loadHeight=h / 2 - c / 2)
		O.dt = -1

	def settle(self, duration=0.3):
		"""Let the wall settle under its weight before the push [s]."""
		for i in self.driven:
			O.bodies[i].state.vel = Vector3(0, 0, 0)
		end = O.time + duration
		while O.time < end:
			build.run(50)
		self.t0 = O.time
		self.y0 = self.midHeightFace()

	def midHeightFace(self):
		"""$y$ of the loaded face at mid-height: the material point of the lower driven course at its top loaded edge [m]."""
		b = O.bodies[self.driven[0]]
		return (b.state.pos + b.state.ori * Vector3(0, -self.t / 2, self.course / 2))[1]

	def displacement(self):
		"""Mid-height displacement $\\Delta$ of the loaded face since :meth:`settle` [m]."""
		return self.midHeightFace() - self.y0

	def force(self):
		"""Push force [N]: minus the $y$ forces of the contacts on the two driven courses (their $y$ is prescribed)."""
		return -sum(O.forces.f(i)[1] for i in self.driven)

	def push(self, to=None, every=50, callback=None):
		"""Push until the mid-height displacement reaches ``to`` [m] (default 1.1 t, past the instability). Returns the
		history [(Δ, F)]."""
		to = 1.1 * self.t if to is None else to
		hist = []
		while self.displacement() < to:
			tau = O.time - self.t0
			v = self.rate * (0.5 * (1 - math.cos(math.pi * tau / self.ramp)) if tau < self.ramp else 1.0)
			for i in self.driven:
				s = O.bodies[i].state
				s.vel = Vector3(s.vel[0], v, s.vel[2])
			build.run(every)
			hist.append((self.displacement(), self.force()))
			if callback:
				callback(hist[-1])
		return hist


class Parapet:
	"""Housner's block as a parapet: a free-standing wall $2b$ thick and $2h$ tall standing dry on a roof slab (a fixed block
	that moves with the roof's motion, ``mode='prescribed'``), contacts at the vertices (``contactSamples=1``: impacts
	follow Housner's, :ref:`theory §4.2 <rdem-theory-4-2>`) with critical dashpots and friction ``friction`` (high: it rocks, it does not
	slide). :meth:`shake` plays a one-sine pulse; :attr:`equation` is the rigid block's exact equation of motion.

	In this class's frame the parapet's thickness is along $x$, the direction of the pulse, and its length along $y$; it
	rocks about $y$.

	:param b: half-thickness [m]. :param h: half-height [m]. :param depth: half-length [m]."""

	def __init__(self, b=0.06, h=0.3, depth=0.1, young=1e9, density=1800, friction=1.0, gravity=9.81):
		for name, value in (('b', b), ('h', h), ('depth', depth), ('young', young), ('density', density), ('friction', friction), ('gravity', gravity)):
			_check(name, value)
		if len(O.bodies) or len(O.interactions):
			raise RuntimeError('Parapet builds into an empty scene: call O.reset() first')
		self.b, self.h, self.g = b, h, gravity
		self.equation = RockingBlockEquation(b, h, g=gravity)
		self.alpha = self.equation.alpha
		mat = O.materials.append(
		        RdemMat(young=young, poisson=0.2, density=density, tensileStrength=float('inf'), cohesion=float('inf'), frictionAngle=math.atan(friction),
		                dampingNormal=1.0, dampingShear=1.0, label='parapet'))
		self.material = mat
		O.engines = build.engines(formulation=None, recontact='always', contactSamples=1, gravity=(0, 0, -gravity))
		self.roof = O.bodies.append(build.block((0, 0, -0.05), (2 * h + 2 * b + 0.2, depth + 0.2, 0.05), mat, fixed=True))
		self.block = O.bodies.append(build.block((0, 0, h), (b, depth, h), mat))
		O.dt = -1

	def angle(self):
		"""Rotation about $y$ [rad], positive onto the $+x$ corner (the equation's sign)."""
		axis, angle = O.bodies[self.block].state.ori.toAxisAngle()
		return angle * axis[1]

	def shake(self, amplitude, period, before=0.05, after=None, every=20):
		"""Play the one-sine roof pulse $\\ddot u_g = A\\sin(2\\pi (t - t_0)/T)$ (``amplitude`` $A$ [m/s²], ``period`` $T$ [s],
		starting ``before`` s from now) and run until the block falls ($|\\theta| > \\pi/4$, or $|\\theta| > \\alpha$ after the
		pulse: the criterion of :meth:`rdem.rocking.RockingBlockEquation.overturns`) or up to ``after`` s after the pulse's end
		(default $8/p$, as that method).
		Returns (overturned, largest $|\\theta|$); the rotation's history is in :attr:`history`."""
		dt = period / 400
		record = ground_motion.sinePulse(amplitude, period, dt=dt, before=O.time + before)
		earthquake.shaker(record, ids=[self.roof], mode='prescribed')
		end = O.time + before + period
		stop = end + (after if after is not None else 8 / self.equation.p)
		largest = 0.0
		self.history = []  # (time [s], rotation [rad]) every ``every`` steps
		while O.time < stop:
			build.run(every)
			self.history.append((O.time, self.angle()))
			th = abs(self.angle())
			largest = max(largest, th)
			if th > math.pi / 4 or (O.time > end and th > self.alpha):
				return True, largest
		return False, largest
