"""In-plane shear tests of masonry walls, as in the laboratory: a wall (:func:`rdem.masonry.wall`) between a fixed base
beam and a top beam, a constant vertical stress $\\sigma_0$ applied first, then a horizontal displacement of the top beam
(monotonic, or cycles of growing amplitude), with the boundary condition of the top beam chosen by the test.

Typical use (scripts/shear_wall.py does all of it with every parameter an option)::

    O.engines = rdem.engines(formulation='consistent', failureStress='total', damping=0.2)
    w = rdem.masonry.wall(1.55, 2.005, 0.38, bond='english', baseBeam=0.2, topBeam=0.2, brickMaterial=brick, jointMaterial=mortar,
                          beamMaterial=concrete)
    rdem.poissonEngine().build(w.ids)
    test = rdem.walltest.ShearWallTest(w, sigma0=1.2e6, boundary='fixed')
    test.compress(0.05)                         # sigma0 ramped up over 0.05 s, then held until the wall is at rest
    test.push([0.008], rate=0.01, record=...)   # top beam to +8 mm at 10 mm/s

Conventions (SI units): $x$ along the wall, $y$ through its thickness, $z$ up (the wall of :func:`rdem.masonry.wall`).
The *shear* $V$ is the force the actuator exerts on the top beam along $+x$ [N]; the *top displacement* $u$ is the top
beam's $x$-displacement since the vertical load was applied [m]; the *drift* is $u/H$, $H$ the height of the masonry
between the beams. Vertical stresses are positive in compression here, as engineers quote $\\sigma_0$.

Boundary conditions of the top beam, one rigid block (``beamBlocks=1``): it is guided along $x$ (prescribed velocity),
held along $y$, and free along $z$ under the constant vertical force $N = \\sigma_0 L t$ (less its own weight, so that
the masonry carries exactly $N$ at its top). ``'fixed'``: both ends fixed against rotation (the top beam never rotates,
the shear span is $H_0 = H/2$, as in Magenes & Calvi 1992); ``'cantilever'``: the top beam rotates in the wall's
plane (about $y$) as a rigid lever pinned at the height $H_0$ above the base, so that the moment at the masonry's top is
$V (H_0 - H)$ at every step: the pin, not the centroid, is moved along $x$ at the prescribed velocity, and a
:yref:`PyRunner` sets the beam's couple and $x$-velocity every step from that step's forces (:func:`applyLever`); the
shear span $H_0$ given as ``shearSpan`` $= H_0/H$ (default 1: no moment at the top, a cantilever; 1.5: Petry & Beyer
2014's walls, whose actuators held that ratio). A couple set once per chunk of steps from the $V$ of the chunk before fed
back and broke the walls of $H_0/H = 1.5$ (:ref:`validation <rdem-validation>`). The base beam is fixed.

Quasi-static loading: the top beam's velocity rises from 0 to ``rate`` along a half cosine over ``ramp`` seconds at the
start and at every reversal, and Cundall's non-viscous damping of :yref:`NewtonIntegrator` (``rdem.engines(damping=...)``)
takes out the vibrations; it acts on unbalanced forces only, so it does not change a static state. Whether a run is slow
enough is checked by running it again at half the rate (scripts/shear_wall.py ``--rate``; :ref:`validation <rdem-validation>`).
"""
import math
from yade import O, Vector3, Quaternion
from yade.wrapper import ForceEngine, PyRunner, NewtonIntegrator, RdemDensityScaling
from . import build, quasi_static  # relative: the package is also yade.rdem (merged into YADE's tree)

BOUNDARIES = ('fixed', 'cantilever')
#: The label of the :yref:`RdemDensityScaling` that :func:`scaleDensity` puts before the integrator.
DENSITY_SCALING = 'rdemDensityScaling'
#: The top beam's blocked degrees of freedom per boundary condition (z is free: the vertical load acts along it).
TOP_DOFS = {'fixed': 'xyXYZ', 'cantilever': 'xyXZ'}


def timoshenkoStiffness(E, nu, length, thickness, height, boundary, shearFactor=5.0 / 6.0):
	"""Elastic lateral stiffness $K = V/u$ [N/m] of a wall as a Timoshenko beam of a rectangular section $L\\times t$
	(bending about the wall's thickness), clamped at its base:

	$1/K = H^3/(c E I) + H/(\\kappa G A)$, $I = tL^3/12$, $A = Lt$, $G = E/(2(1+\\nu))$,

	$c = 3$ for a cantilever (no moment at the top) and $c = 12$ for both ends fixed (the top kept horizontal), $\\kappa$
	the shear correction factor, 5/6 for a rectangle ([TimoshenkoGere1972]_).
	Lengths in m, E in Pa.

	ValueError naming the argument if one is out of range."""
	for name, value in (('E', E), ('length', length), ('thickness', thickness), ('height', height), ('shearFactor', shearFactor)):
		if not (math.isfinite(value) and value > 0):
			raise ValueError('%s = %r: must be finite and > 0' % (name, value))
	if not -1 < nu < 0.5:
		raise ValueError('nu = %r: must be in (-1, 0.5)' % (nu, ))
	if boundary not in BOUNDARIES:
		raise ValueError('boundary = %r: must be one of %s' % (boundary, ', '.join(repr(b) for b in BOUNDARIES)))
	I = thickness * length**3 / 12
	G = E / (2 * (1 + nu))
	c = 3.0 if boundary == 'cantilever' else 12.0
	return 1.0 / (height**3 / (c * E * I) + height / (shearFactor * G * length * thickness))


def coupleMoment(shear, arm):
	"""The couple about $+y$ [N·m] that the test applies to a rotating top beam so that the moment at the masonry's top is
	$V (H_0 - H)$: $C = V a$ with the arm $a = H_0 - H - b/2$ [m] (the actuator's force $V$ [N] acts at the beam's centroid,
	$b/2$ above the masonry, and adds $V b/2$). Positive about $+y$ tilts the top towards $+x$."""
	return shear * arm


def applyLever(top, arm, velocity):
	"""One step of the top beam as a rigid lever pinned at the height $H_0$ (the arm ``arm`` [m] above its centroid),
	the pin moved along $x$ at ``velocity`` [m/s]: the couple :func:`coupleMoment` of this step's $V = -F_x$ (the force
	the masonry exerts on the beam now) and the beam's $x$-velocity $v - \\omega_y a$, so that the pin moves at $v$. The
	:yref:`PyRunner` of :class:`ShearWallTest` calls it every step after the forces are summed and before the integrator
	(:data:`LEVER_COMMAND`)."""
	# sync=True: mid-step, the container is unsynced (the vertical load's ForceEngine has added to it) and f(id) without
	# sync would read the per-thread part only, not the face springs' sums of RdemForceAssembler
	O.forces.addT(top, Vector3(0, coupleMoment(-O.forces.f(top, sync=True)[0], arm), 0))
	s = O.bodies[top].state
	s.vel = Vector3(velocity - s.angVel[1] * arm, 0, s.vel[2])


#: The command of the lever (top beam id, arm [m], the pin's velocity [m/s]): a PyRunner run every step (a string, so
#: that the scene saves); :class:`ShearWallTest` sets the velocity as the push goes.
LEVER_COMMAND = "__import__('yade.rdem.walltest', fromlist=['applyLever']).applyLever(%d, %r, %r)"


def halfCosineRamp(t, duration):
	"""0 at $t \\le 0$, $(1 - \\cos(\\pi t/T))/2$ for $0 < t < T$, 1 from $T$ on: a velocity ramp whose acceleration has
	no jump at its end (T = ``duration`` [s]; T = 0: a step)."""
	if t <= 0:
		return 0.0 if duration > 0 else 1.0
	if t >= duration:
		return 1.0
	return 0.5 * (1 - math.cos(math.pi * t / duration))


def cycleTargets(amplitudes, cycles=1):
	"""The top-displacement targets of a cyclic test: each amplitude ``cycles`` times to $+a$ and to $-a$, then back to 0
	(the same units as the amplitudes). ValueError if an amplitude is not > 0 or ``cycles`` not an integer >= 1."""
	if not (isinstance(cycles, int) and cycles >= 1):
		raise ValueError('cycles = %r: must be an integer >= 1' % (cycles, ))
	out = []
	for a in amplitudes:
		if not (math.isfinite(a) and a > 0):
			raise ValueError('amplitude %r: every amplitude must be finite and > 0' % (a, ))
		out += [a, -a] * cycles
	return out + [0.0]


class ShearWallTest:
	"""A shear test of the wall ``wall`` (:class:`rdem.masonry.Wall` with a base beam and a top beam of one block each,
	``beamBlocks=1``) in the current scene, whose engines come from :func:`rdem.engines`.

	:param sigma0: vertical stress on the masonry's top [Pa], >= 0 (compression positive).
	:param boundary: ``'fixed'`` or ``'cantilever'`` (module docstring).
	:param shearSpan: $H_0/H$ with ``boundary='cantilever'`` (default 1); with ``'fixed'`` it is 0.5 (None or 0.5).

	:ivar top: id of the top beam; :ivar base: ids of the base beam's blocks; :ivar height: $H$ [m];
	:ivar area: $L t$, the masonry's horizontal cross-section [m²]; :ivar axialForce: $N = \\sigma_0 L t$ [N].
	:ivar work: work of the actuator on the top beam, $\\int V\\,du$, of the applied vertical force (the top beam's
	    weight is in YADE's ``gravWork``) and of the couple on the top beam, since the test began [J] (``{'horizontal': ...,
	    'vertical': ..., 'moment': ...}``), step by step as the leapfrog does it (:meth:`advance`).
	"""

	def __init__(self, wall, sigma0, boundary='fixed', shearSpan=None):
		if boundary not in BOUNDARIES:
			raise ValueError('boundary = %r: must be one of %s' % (boundary, ', '.join(repr(b) for b in BOUNDARIES)))
		if shearSpan is None:
			shearSpan = 0.5 if boundary == 'fixed' else 1.0
		if boundary == 'fixed' and shearSpan != 0.5:
			raise ValueError("shearSpan = %r: with boundary='fixed' the shear span ratio is 0.5 (the top beam kept horizontal); "
			                 "use boundary='cantilever' for another" % (shearSpan, ))
		if not (math.isfinite(shearSpan) and shearSpan > 0):
			raise ValueError('shearSpan = %r: must be finite and > 0 (H0/H)' % (shearSpan, ))
		if not (math.isfinite(sigma0) and sigma0 >= 0):
			raise ValueError('sigma0 = %r: must be finite and >= 0 [Pa] (compression positive)' % (sigma0, ))
		if not wall.beams['base'] or len(wall.beams['top']) != 1:
			raise ValueError('wall: a shear test needs a base beam and a top beam of one block (rdem.masonry.wall(baseBeam=..., topBeam=..., '
			                 'beamBlocks=1)); this wall has %d base and %d top beam blocks' % (len(wall.beams['base']), len(wall.beams['top'])))
		self.wall, self.sigma0, self.boundary, self.shearSpan = wall, float(sigma0), boundary, float(shearSpan)
		self.top, self.base = wall.beams['top'][0], list(wall.beams['base'])
		lay = wall.layout
		self.height, self.area = lay.height, lay.length * lay.thickness
		self.axialForce = self.sigma0 * self.area
		for i in self.base:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
			O.bodies[i].state.vel = O.bodies[i].state.angVel = Vector3.Zero
		s = O.bodies[self.top].state
		s.blockedDOFs = TOP_DOFS[boundary]
		s.vel = s.angVel = Vector3.Zero
		self._velocity = 0.0  # of the top beam along x, or of the lever's pin [m/s]
		# Not damped: NewtonIntegrator books |F_i||v_i| D dt as damping energy on blocked DOFs too, which on the driven
		# beam is the actuator's work, not a loss (the wall's blocks are damped as usual).
		s.isDamped = False
		self._weight = -s.mass * build.newtonIntegrator().gravity[2]  # the top beam's own weight [N] (gravity along -z)
		self._load = ForceEngine(ids=[self.top], force=Vector3.Zero)
		engines = O.engines
		# before the integrator, and before RdemDensityScaling if there is one (it scales every force, the loads' too)
		k = next(k for k, e in enumerate(engines) if e.label in (build.LABELS['newton'], DENSITY_SCALING))
		# A rotating top beam is a rigid lever pinned at H0 above the base (applyLever, every step): the couple that makes
		# the moment at the masonry's top V (H0 - H) (the actuator's force acts at the beam's centroid, b/2 above the
		# masonry, which adds V b/2), the beam's x following its rotation so that the pin moves at the prescribed velocity,
		# and the beam's inertia about the pin. A couple set once per chunk from the V of the chunk before fed back with a
		# delay (H0/H = 1.5: V alternated from chunk to chunk until the wall broke); set every step with the beam's x held,
		# it is a follower load, and the beam fluttered (the user guide, validation, "The top beam of a long shear span").
		lever = wall.layout.topBeam or 0.0
		self._coupleArm = self.shearSpan * self.height - self.height - lever / 2
		self._couple = PyRunner(iterPeriod=1, updateGlobals=False, label='rdemShearSpanLever') if boundary == 'cantilever' else None
		if self._couple:
			self._setVelocity(0.0)
			s.inertia = s.inertia + Vector3(0, s.mass * self._coupleArm**2, 0)  # the beam's inertia about the pin
		O.engines = engines[:k] + [self._load] + ([self._couple] if self._couple else []) + engines[k:]  # after the force assembler, before the integrator
		self.origin = Vector3(s.pos)
		self.work = {'horizontal': 0.0, 'vertical': 0.0, 'moment': 0.0}
		self._last = None  # the last step (displacements at its start and end, its loads), whose work waits for the next

	def _setVelocity(self, v):
		"""The top beam moved along $x$ at ``v`` [m/s]: its centroid (both ends fixed) or the lever's pin (cantilever)."""
		self._velocity = v
		if self._couple:
			self._couple.command = LEVER_COMMAND % (self.top, self._coupleArm, v)
		s = O.bodies[self.top].state
		s.vel = Vector3(v, 0, s.vel[2])

	# Measurements -----------------------------------------------------------------------------------------------------
	def topDisplacement(self):
		"""$u$: the top beam's $x$-displacement since the vertical load was applied [m]."""
		return O.bodies[self.top].state.pos[0] - self.origin[0]

	def drift(self):
		"""$u/H$ [-]."""
		return self.topDisplacement() / self.height

	def verticalDisplacement(self):
		"""The top beam's $z$-displacement since it was made (down < 0) [m]."""
		s = O.bodies[self.top].state
		return s.pos[2] - s.refPos[2]

	def topRotation(self):
		"""The top beam's rotation about $y$ since it was made [rad] (right-handed about $+y$)."""
		s = O.bodies[self.top].state
		q = s.ori * s.refOri.conjugate()
		axis, angle = q.toAxisAngle()
		return angle * axis[1]

	def shear(self):
		"""$V$: the force the actuator exerts on the top beam along $+x$ [N], the opposite of the masonry's force on it
		(the beam's $x$ is held, so the actuator balances whatever the masonry does)."""
		return -O.forces.f(self.top)[0]

	def baseShear(self):
		"""The masonry's force on the base beam along $+x$ [N]; equals :meth:`shear` at rest (no inertia)."""
		return sum(O.forces.f(i)[0] for i in self.base)

	def axialLoad(self):
		"""The vertical force the test applies to the masonry's top now, compression positive [N]."""
		return -self._load.force[2] + self._weight

	# Loading ------------------------------------------------------------------------------------------------------------
	def _setLoad(self, fraction):
		self._load.force = Vector3(0, 0, -(fraction * self.axialForce - self._weight))

	def couple(self):
		"""The couple the test applies to the top beam in the last step about $+y$ [N·m]: :func:`coupleMoment` of that
		step's $V$ (0 with both ends fixed, where the top beam's rotation is held instead)."""
		return coupleMoment(self.shear(), self._coupleArm) if self._couple else 0.0

	def topMoment(self):
		"""The moment the test applies to the masonry's top about $+y$ [N·m]: the couple and the actuator's force $V$ at
		the beam's centroid, $b/2$ above the masonry: $V (H_0 - H)$ (0 with both ends fixed)."""
		return self.couple() + self.shear() * (self.wall.layout.topBeam or 0.0) / 2 if self._couple else 0.0

	def topMomentOfMasonry(self):
		"""The moment the top beam exerts on the masonry about $+y$ at the masonry's top below the beam's centroid [N·m],
		measured from the contact forces of the last step (the beam's force and torque less the test's couple; the
		vertical load and the actuator act at the centroid): the reaction to the masonry's moment on the beam, equal to
		:meth:`topMoment` when the beam is at rest and different from it by the beam's rotational inertia when it is not."""
		s = O.bodies[self.top].state
		F, T = O.forces.f(self.top), O.forces.t(self.top)
		P = s.pos - Vector3(0, 0, (self.wall.layout.topBeam or 0.0) / 2)
		return -(T[1] - self.couple() + (s.pos - P).cross(F)[1])

	def _loads(self):
		"""(the actuator's force, the vertical load, the couple) of the step just made [N, N, N·m]."""
		return (self.shear(), self._load.force[2], self.couple())

	def _displacements(self):
		"""(top displacement, vertical displacement, top rotation) now [m, m, rad]."""
		return (self.topDisplacement(), self.verticalDisplacement(), self.topRotation())

	def advance(self, steps):
		"""Run ``steps`` steps and add, step by step, the work of the actuator, of the vertical load and of the couple
		(a cantilever's couple follows V at every step, :func:`applyLever`). The step that moved the top from $x_k$ to
		$x_{k+1}$ under the loads $P_k$, made at $x_k$, does the work $\tfrac12(P_k + P_{k+1})(x_{k+1} - x_k)$ [J]: summed,
		$\sum_k P_k (x_{k+1} - x_{k-1})/2$, the leapfrog's own work, which its energies balance (the kinetic energy paired
		across the step, RdemLeapfrogEnergy; the springs' at $x_k$). It is added once $P_{k+1}$ is known, after the next
		step, so that the work read after a step is the work up to the configuration whose energies that step booked. On
		the elastic wall of tests/yade/test_shear_wall.py the booked energies equal this work to 1e-11; a trapezoid over
		chunks of 100 steps, which misses the load's oscillations within a chunk, was off by 2 % (both ends fixed) and 7 %
		(a cantilever)."""
		for _ in range(int(steps)):
			start = self._displacements()
			O.step()
			end, loads = self._displacements(), self._loads()
			if self._last:  # the step before this one, from x0 to x1 under P0, now that its end's loads are known
				x0, x1, P0 = self._last
				for name, k in (('horizontal', 0), ('vertical', 1), ('moment', 2)):
					self.work[name] += 0.5 * (P0[k] + loads[k]) * (x1[k] - x0[k])
			self._last = (start, end, loads)

	def compress(self, duration, tolerance=1e-4, chunk=200, maxTime=None, report=None):
		"""Apply $\\sigma_0$: the vertical load grows along a half cosine from 0 to $N$ over ``duration`` [s] while the top
		beam is held along $x$, then stays constant until the top beam's vertical velocity times ``duration`` is below
		``tolerance`` times its settlement (the wall at rest), or ``maxTime`` [s] (default 20 × duration) has passed.
		Then the origin of :meth:`topDisplacement` is set. ``report(test)`` is called after every ``chunk`` steps.
		Returns the time it took [s]."""
		if not (math.isfinite(duration) and duration > 0):
			raise ValueError('duration = %r: must be finite and > 0 [s]' % (duration, ))
		maxTime = 20 * duration if maxTime is None else maxTime
		s = O.bodies[self.top].state
		self._setVelocity(0.0)
		t0 = O.time
		while True:
			self._setLoad(halfCosineRamp(O.time - t0, duration))
			self.advance(chunk)
			if report:
				report(self)
			settled = abs(s.vel[2]) * duration <= tolerance * max(abs(self.verticalDisplacement()), 1e-12)
			if O.time - t0 >= duration and (settled or O.time - t0 >= maxTime):
				break
		self._setLoad(1.0)
		self.origin = Vector3(s.pos)
		return O.time - t0

	def push(self, targets, rate, ramp, chunk=100, record=None, stop=None):
		"""Move the top beam along $x$ through the displacement ``targets`` [m] in turn (monotonic: one target; cycles:
		:func:`cycleTargets`), at the speed ``rate`` [m/s], the velocity ramped along a half cosine over ``ramp`` [s] at the
		start and at every reversal (:func:`halfCosineRamp`). ``record(test)`` is called every ``chunk`` steps;
		``stop(test)`` returning True ends the test early. Returns the number of steps run."""
		if not (math.isfinite(rate) and rate > 0):
			raise ValueError('rate = %r: must be finite and > 0 [m/s]' % (rate, ))
		if not (math.isfinite(ramp) and ramp >= 0):
			raise ValueError('ramp = %r: must be finite and >= 0 [s]' % (ramp, ))
		n0 = O.iter
		for target in targets:
			direction = 1.0 if target > self.topDisplacement() else -1.0
			v0, t0 = self._velocity, O.time
			while direction * (target - self.topDisplacement()) > 0:
				# from the velocity at the reversal to direction*rate along the ramp
				f = halfCosineRamp(O.time - t0, ramp)
				self._setVelocity(v0 + f * (direction * rate - v0))
				left = direction * (target - self.topDisplacement())
				self.advance(max(1, min(chunk, int(left / (rate * O.dt)) + 1)))
				if record:
					record(self)
				if stop and stop(self):
					return O.iter - n0
		return O.iter - n0

	def hold(self, steps, chunk=100, record=None):
		"""Stop the top beam (a cantilever's: the lever's pin) along $x$ and run ``steps`` steps (e.g. to let the wall come to rest)."""
		self._setVelocity(0.0)
		for _ in range(0, int(steps), chunk):
			self.advance(chunk)
			if record:
				record(self)


def scaleRotationalInertia(ids):
	"""Multiply the principal moments of inertia of the blocks ``ids`` by :func:`rdem.quasi_static.rotationalInertiaScale`
	of their half-extents (the rotational inertia scaling of the quasi-static scheme, :ref:`validation <rdem-validation>`); their masses,
	and so their weights and every static state, stay as they are. Call it before the time step is set (RdemTimeStepper
	reads the inertias). Returns the largest factor applied."""
	largest = 1.0
	for i in ids:
		b = O.bodies[i]
		f = quasi_static.rotationalInertiaScale(b.shape.extents)
		b.state.inertia = b.state.inertia * f
		largest = max(largest, f)
	return largest


def scaleDensity(ids, factor):
	"""Partial density scaling of the blocks ``ids`` (the quasi-static scheme's ``densityScaling``, :ref:`validation
	<rdem-validation>`): each block gets the smallest factor $\\mu_b \\ge 1$ of its mass and moments of inertia that brings
	its own damped limit up to ``factor`` times the smallest such limit among ``ids``
	(:func:`rdem.quasi_static.densityScalingTarget`, :func:`rdem.quasi_static.inertialScales`, from the rows of
	:yref:`RdemTimeStepper.blockRows` of the current configuration, its contacts and dashpots), set as
	:yref:`State::densityScaling` $= 1/\\mu_b$; every other block of ``ids`` is reset to none (-1). An
	:yref:`RdemDensityScaling` is put right before the integrator (once): gravity and the loads keep the true masses, so
	the weight and every static state are unchanged. Call it once the contacts that set the step exist (for a wall test,
	after the vertical load: its head joints carry then their dashpots); the time stepper takes the new masses at its
	next update. ``factor`` 1 removes the scaling of ``ids``.

	Returns a dict: ``target`` the step the blocks were brought to (their own limits, a bound below the Lanczos limit)
	[s], ``scaled`` how many blocks were scaled, ``largest`` the largest $\\mu_b$, ``addedMass`` the inertial mass added
	over the scaled blocks' true mass [-]. ValueError if ``factor`` is not finite and >= 1."""
	f = float(factor)
	if not (math.isfinite(f) and f >= 1):
		raise ValueError('factor = %r: must be finite and >= 1 (the gain on the time step)' % (factor, ))
	ids = list(ids)
	for i in ids:
		O.bodies[i].state.densityScaling = -1  # the unscaled rows
	if f == 1:
		return dict(target=None, scaled=0, largest=1.0, addedMass=0.0)
	rows = build.timeStepper().blockRows()
	omega2, dashpots = [rows[i][0] for i in ids], [rows[i][1] for i in ids]
	target = quasi_static.densityScalingTarget(omega2, dashpots, f)
	mu = quasi_static.inertialScales(omega2, dashpots, target)
	mass = added = 0.0
	for i, m in zip(ids, mu):
		if m > 1:
			s = O.bodies[i].state
			s.densityScaling = 1 / m
			mass += s.mass
			added += (m - 1) * s.mass
	if not any(e.label == DENSITY_SCALING for e in O.engines):
		engines = O.engines
		k = next(k for k, e in enumerate(engines) if e.label == build.LABELS['newton'])
		O.engines = engines[:k] + [RdemDensityScaling(integrator=engines[k], label=DENSITY_SCALING)] + engines[k:]
	return dict(target=target, scaled=sum(1 for m in mu if m > 1), largest=max(mu, default=1.0), addedMass=added / mass if mass else 0.0)


def unbondJoints(wall, kind='head'):
	"""Start the joints of one ``kind`` of ``wall`` (``'head'``, ``'bed'``, ``'collar'`` or ``'beam'``, the keys of
	``wall.joints``) without bond: every restoring spring of their bonds in the broken state, so that these joints carry
	compression and friction through their contact springs (:ref:`theory §3 <rdem-theory-3>`; with softening, the residual friction) and no
	tension or cohesion. For head joints this is the assumption of [MannMuller1982]_ in their theory of the stair-stepped
	shear failure of masonry: head joints are not compressed while their mortar hardens, shrink away from the bricks and
	transmit no bond. Returns the set of the pairs (smaller id, larger id) made so, to leave them out of the crack counts.
	Call it after the wall is built and before the test is loaded. ValueError naming ``kind`` if the wall has no such joints."""
	if kind not in wall.joints or kind in ('internal', 'mortar'):
		raise ValueError('kind = %r: must be one of head, bed, collar, beam (the mortar joints of the wall)' % (kind, ))
	pairs = set()
	for a, b in wall.joints[kind]:
		I = O.interactions[a, b]
		I.phys.segState = [1] * len(I.phys.segState)
		pairs.add((min(a, b), max(a, b)))
	return pairs


def smoothedPeak(drift, shear, window):
	"""The largest $|V|$ of the centred moving average of ``shear`` over ``window`` samples (odd, >= 1), and the drift
	there: the peak without the spikes of single samples after crack bursts (the wall rings at its first period for a
	few cycles). Returns (V, drift) in the units given. ValueError if ``window`` is not an odd integer >= 1 or the
	lists are empty or of different lengths."""
	if not (isinstance(window, int) and window >= 1 and window % 2 == 1):
		raise ValueError('window = %r: must be an odd integer >= 1' % (window, ))
	if not shear or len(drift) != len(shear):
		raise ValueError('drift and shear: must be non-empty lists of the same length (%d, %d)' % (len(drift), len(shear)))
	h = window // 2
	best = None
	for k in range(len(shear)):
		part = shear[max(0, k - h):k + h + 1]
		v = sum(part) / len(part)
		if best is None or abs(v) > abs(best[0]):
			best = (v, drift[k])
	return best


def travel(drift):
	"""The drift travelled up to each sample, $\\sum |\\Delta d|$ (monotonic also through the reversals of a cyclic
	test), in the units of ``drift``."""
	out, total = [], 0.0
	for k, d in enumerate(drift):
		total += abs(d - drift[k - 1]) if k else 0.0
		out.append(total)
	return out


def smoothedPeakOverDrift(drift, shear, width):
	"""As :func:`smoothedPeak`, the moving average centred on each sample taken over the samples within ``width``/2 of
	drift travelled (:func:`travel`) on either side instead of a number of samples, so that it means the same whatever
	the time step and the loading rate. Returns (V, drift) in the units given; ValueError for ``width`` <= 0 or lists
	that are empty or of different lengths."""
	if not (math.isfinite(width) and width > 0):
		raise ValueError('width = %r: must be finite and > 0 (drift)' % (width, ))
	if not shear or len(drift) != len(shear):
		raise ValueError('drift and shear: must be non-empty lists of the same length (%d, %d)' % (len(drift), len(shear)))
	s = travel(drift)
	best, lo, hi, total = None, 0, 0, 0.0
	for k in range(len(shear)):
		while hi < len(shear) and s[hi] <= s[k] + width / 2:
			total += shear[hi]
			hi += 1
		while s[lo] < s[k] - width / 2:
			total -= shear[lo]
			lo += 1
		v = total / (hi - lo)
		if best is None or abs(v) > abs(best[0]):
			best = (v, drift[k])
	return best


def trailingMean(drift, shear, width):
	"""The mean of ``shear`` over the last samples within ``width`` of drift travelled (:func:`travel`) of the last one:
	the load a stop criterion compares with its peak, without the spikes of single samples."""
	s = travel(drift)
	part = [v for v, x in zip(shear, s) if x >= s[-1] - width]
	return sum(part) / len(part)


def failureIndicators(wall, segments):
	"""What :func:`rdem.wall_database.failureClass` decides the failure mode from, for the broken springs ``segments``
	(:func:`rdem.measure.brokenSegments`) of ``wall`` (the masonry from $z = 0$ to $H$, $x = 0$ to $L$):
	``(horizontalTensionArea, coreCourses, coreCoursesCracked, jointArea)``: the larger of the areas [m²] of the bed
	faces (normal within 25° of $z$) broken in tension or released in the bottom and in the top tenth of the wall, the
	number of courses whose middle lies in the core (the middle half of the height), how many of them hold a broken
	spring in the core (the middle half of the length too), and $L t$."""
	lay = wall.layout
	L, H = lay.length, lay.height
	pitch = lay.brick[2] + lay.joint
	bands = [0.0, 0.0]
	cracked = set()
	for sg in segments:
		x, z = sg['point'][0], sg['point'][2]
		if abs(sg['normal'][2]) > 0.9 and sg['state'] in (1, 3):
			area = 4 * sg['halfSizes'][0] * sg['halfSizes'][1]
			if z < 0.1 * H:
				bands[0] += area
			elif z > 0.9 * H:
				bands[1] += area
		if L / 4 < x < 3 * L / 4 and H / 4 < z < 3 * H / 4:
			cracked.add(int(math.floor((z + lay.joint / 2) / pitch)))
	core = [k for k in range(lay.courseCount) if H / 4 <= k * pitch + lay.brick[2] / 2 <= 3 * H / 4]
	return max(bands), len(core), len(cracked.intersection(core)), L * lay.thickness


def crackClasses(wall, segments):
	"""The broken segments ``segments`` (:func:`rdem.measure.brokenSegments`) counted by where and how they broke:
	``{'joint': {'tension': n, 'shear': n, 'released': n}, 'brick': {...}}``; *joint* = bed, head, collar and beam joints,
	*brick* = springs inside a brick (blocks per brick > 1). ``tension`` and ``shear`` count every broken segment by
	what broke it; ``released`` counts those of them whose bond has broken through and opened."""
	kindOf = {(min(a, b), max(a, b)): kind for kind, pairs in wall.joints.items() for a, b in pairs}
	out = {w: {'tension': 0, 'shear': 0, 'released': 0} for w in ('joint', 'brick')}
	mode = {1: 'tension', 2: 'shear'}
	for sg in segments:
		where = 'brick' if kindOf.get((min(sg['id1'], sg['id2']), max(sg['id1'], sg['id2']))) == 'internal' else 'joint'
		if sg['state'] in mode:
			out[where][mode[sg['state']]] += 1
		if sg.get('released', sg['state'] == 3):
			out[where]['released'] += 1
	return out
