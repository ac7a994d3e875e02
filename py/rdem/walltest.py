"""In-plane shear tests of masonry walls, as in the laboratory: a wall (:func:`rdem.masonry.wall`) between a fixed base
beam and a top beam, a constant vertical stress $\\sigma_0$ applied first, then a horizontal displacement of the top beam
(monotonic, or cycles of growing amplitude), with the boundary condition of the top beam chosen by the test.

Typical use (scripts/shear_wall.py does all of it with every parameter an option)::

    O.engines = rdem.engines(poisson='consistent', failureStress='total', damping=0.2)
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
the shear span is $H_0 = H/2$, as in Magenes & Calvi 1992); ``'cantilever'``: the top beam may rotate in the wall's
plane (about $y$), so that no moment acts at the top ($H_0 = H$). The base beam is fixed.

Quasi-static loading: the top beam's velocity rises from 0 to ``rate`` along a half cosine over ``ramp`` seconds at the
start and at every reversal, and Cundall's non-viscous damping of :yref:`NewtonIntegrator` (``rdem.engines(damping=...)``)
takes out the vibrations; it acts on unbalanced forces only, so it does not change a static state. Whether a run is slow
enough is checked by running it again at half the rate (scripts/shear_wall.py ``--rate``; doc/validation.md).
"""
import math
from yade import O, Vector3, Quaternion
from yade.wrapper import ForceEngine, NewtonIntegrator
from . import build  # relative: the package is also yade.rdem (doc/upstream.md)

BOUNDARIES = ('fixed', 'cantilever')
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

	:ivar top: id of the top beam; :ivar base: ids of the base beam's blocks; :ivar height: $H$ [m];
	:ivar area: $L t$, the masonry's horizontal cross-section [m²]; :ivar axialForce: $N = \\sigma_0 L t$ [N].
	:ivar work: work of the actuator on the top beam, $\\int V\\,du$, and of the applied vertical force (the top beam's
	    weight is in YADE's ``gravWork``), since the test began [J] (``{'horizontal': ..., 'vertical': ...}``), by the
	    trapezoid rule over the chunks of :meth:`advance` (the force is held constant within a chunk except while it is
	    ramped).
	"""

	def __init__(self, wall, sigma0, boundary='fixed'):
		if boundary not in BOUNDARIES:
			raise ValueError('boundary = %r: must be one of %s' % (boundary, ', '.join(repr(b) for b in BOUNDARIES)))
		if not (math.isfinite(sigma0) and sigma0 >= 0):
			raise ValueError('sigma0 = %r: must be finite and >= 0 [Pa] (compression positive)' % (sigma0, ))
		if not wall.beams['base'] or len(wall.beams['top']) != 1:
			raise ValueError('wall: a shear test needs a base beam and a top beam of one block (rdem.masonry.wall(baseBeam=..., topBeam=..., '
			                 'beamBlocks=1)); this wall has %d base and %d top beam blocks' % (len(wall.beams['base']), len(wall.beams['top'])))
		self.wall, self.sigma0, self.boundary = wall, float(sigma0), boundary
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
		# Not damped: NewtonIntegrator books |F_i||v_i| D dt as damping energy on blocked DOFs too, which on the driven
		# beam is the actuator's work, not a loss (the wall's blocks are damped as usual).
		s.isDamped = False
		self._weight = -s.mass * build.newtonIntegrator().gravity[2]  # the top beam's own weight [N] (gravity along -z)
		self._load = ForceEngine(ids=[self.top], force=Vector3.Zero)
		engines = O.engines
		k = next(k for k, e in enumerate(engines) if isinstance(e, NewtonIntegrator))
		O.engines = engines[:k] + [self._load] + engines[k:]  # after the force assembler, before the integrator
		self.origin = Vector3(s.pos)
		self.work = {'horizontal': 0.0, 'vertical': 0.0}
		self._last = None

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

	def advance(self, steps):
		"""Run ``steps`` steps and add the work of the actuator and of the vertical load over them (trapezoid rule on
		the values before and after)."""
		before = (self.topDisplacement(), self.shear(), self.verticalDisplacement(), self._load.force[2])
		O.run(int(steps), True)
		u, V, w, F = self.topDisplacement(), self.shear(), self.verticalDisplacement(), self._load.force[2]
		self.work['horizontal'] += 0.5 * (before[1] + V) * (u - before[0])
		self.work['vertical'] += 0.5 * (before[3] + F) * (w - before[2])

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
		s.vel = Vector3(0, 0, s.vel[2])
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
		s = O.bodies[self.top].state
		n0 = O.iter
		for target in targets:
			direction = 1.0 if target > self.topDisplacement() else -1.0
			v0, t0 = s.vel[0], O.time
			while direction * (target - self.topDisplacement()) > 0:
				# from the velocity at the reversal to direction*rate along the ramp
				f = halfCosineRamp(O.time - t0, ramp)
				s.vel = Vector3(v0 + f * (direction * rate - v0), 0, s.vel[2])
				left = direction * (target - self.topDisplacement())
				self.advance(max(1, min(chunk, int(left / (rate * O.dt)) + 1)))
				if record:
					record(self)
				if stop and stop(self):
					return O.iter - n0
		return O.iter - n0

	def hold(self, steps, chunk=100, record=None):
		"""Stop the top beam along $x$ and run ``steps`` steps (e.g. to let the wall come to rest)."""
		s = O.bodies[self.top].state
		s.vel = Vector3(0, 0, s.vel[2])
		for _ in range(0, int(steps), chunk):
			self.advance(chunk)
			if record:
				record(self)


def unbondJoints(wall, kind='head'):
	"""Start the joints of one ``kind`` of ``wall`` (``'head'``, ``'bed'``, ``'collar'`` or ``'beam'``, the keys of
	``wall.joints``) without bond: every restoring spring of their bonds in the broken state, so that these joints carry
	compression and friction through their contact springs (doc/theory.md §3; with softening, the residual friction) and no
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


#: One parameter set for the Magenes & Calvi (1992) walls MI1 and MI2 (doc/validation.md §2), every value with its
#: source. Lengths m, stresses and moduli Pa, densities kg/m³; ``mu`` a friction coefficient.
MAGENES_CALVI = {
        'geometry': dict(length=1.55, height=2.005, thickness=0.38, brick=(0.25, 0.12, 0.055), joint=0.01, bond='english', beam=0.2),
        'brick': dict(young=2991e6, poisson=0.25, density=1800, tensileStrength=1.28e6, cohesion=1.79e6, mu=0.81),
        'joint': dict(young=2991e6, poisson=0.25, tensileStrength=0.15e6, cohesion=0.21e6, mu=0.81, headJoints='unbonded'),
        'beam': dict(young=30e9, poisson=0.2, density=2400),
        'softening': dict(jointGfI=18.0, jointGfII=125.0, jointFc=7.92e6, Gfc=5000.0, brickGfI=80.0, brickGfII=800.0, brickFc=19.72e6, residual=0.2),
        'sources': {
                'brick 250x120x55 mm, 31 courses, H = 2.0 m, t = 0.38 m (one and a half bricks)': 'MagenesCalvi1992 via the EPFL database',
                'length 1.55 m (tested: 1.5 m)': 'the nearest length of English bond with whole 250 mm bricks and 10 mm joints (1.29 or 1.55 m); '
                'the database gives no bond, English bond is the usual bond of a one-and-a-half-brick wall',
                'height 2.005 m': '31 courses of 55 mm bricks and 10 mm joints (tested: 2.0 m)',
                'joint thickness 10 mm': 'assumed: the usual thickness of a bed joint (not in the database)',
                'E = 2991 MPa for brick and mortar': 'the masonry modulus of the database; brick and mortar moduli are not given, so both get the '
                'masonry modulus and the model wall has exactly the measured E',
                'nu = 0.25 for brick and mortar': 'EN1996-1-1 (Eurocode 6) 3.7.3: G = 0.4 E, i.e. nu = 0.25',
                'joint cohesion 0.21 MPa, friction 0.81': 'f_v0 and mu of the database (MagenesCalvi1992)',
                'head joints without bond (--head-joints unbonded)': 'MannMuller1982: head joints are not compressed while their mortar '
                'hardens and shrink away from the bricks, so they carry no bond; they keep compression and friction (contact springs)',
                'joint tensile bond strength 0.15 MPa': 'c = 1.4 f_t (LourencoRots1997, the TU Eindhoven walls: f_t = 0.25, c = 0.35 MPa), '
                'so f_t = 0.21/1.4',
                'brick tensile strength 1.28 MPa': '0.065 f_b, f_b = 19.72 MPa (database): the middle of the range 0.03-0.10 of the ratio of a '
                "unit's tensile to compressive strength (attributed to Schubert1988 via Lourenco1996, ch. 2; not verified: neither text was available to the project)",
                'brick cohesion 1.79 MPa, friction 0.81': 'c = 1.4 f_t as for the joints (LourencoRots1997, potential cracks in the units); friction '
                'of the joints (database)',
                'density 1800 kg/m3': 'assumed, solid clay brick masonry (self-weight 0.035 MPa at the base)',
                'softening (--softening on): joint G_f^I 18 J/m2, G_f^II 125 J/m2, cap G_fc 5000 J/m2': 'the interface values of '
                'LourencoRots1997 for the TU Eindhoven walls (not measured by MagenesCalvi1992); the residual friction equals the initial',
                'softening: joint cap f_c = 7.92 MPa, residual 0.2 f_c': 'f_m, the masonry compressive strength of the database (the cap of the '
                'interface model is a masonry strength, LourencoRots1997); residual fraction: the default of RdemJoint, assumed',
                'softening: brick G_f^I 80 J/m2, G_f^II 800 J/m2, cap f_c = 19.72 MPa': 'G_f^I of the units of LourencoRots1997 (potential cracks '
                'in the bricks); G_f^II = 10 G_f^I assumed; f_c = f_b of the database',
                'beams: concrete, E = 30 GPa, nu = 0.2, 2400 kg/m3, 0.2 m tall': 'assumed: reinforced concrete beams (EN1992-1-1 Table 3.1, C25/30: '
                'E_cm = 31 GPa); they are rigid against the wall (0.2 % of its compliance)',
        }
}

#: The walls of Magenes & Calvi (1992): vertical stress and the measured peaks (EPFL-ENAC/eesd-modern-masonry-walls-db,
#: rows "Magenes & Calvi (1992)"; ../shared/reference/masonry-benchmarks.md). Both ends fixed.
MAGENES_CALVI_WALLS = {
        'MI1': dict(sigma0=1.2e6, peak=(269.55e3, 259.63e3), driftAtPeak=(0.1995e-2, 0.1795e-2), failure='shear (diagonal cracking)'),
        'MI2': dict(sigma0=0.4e6, peak=(241.62e3, 227.21e3), driftAtPeak=(0.4005e-2, 0.3866e-2), failure='shear (diagonal cracking)'),
}
