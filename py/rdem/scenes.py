"""Ready-made scenes. :class:`CompressionTest` is the paper's §5 compression test of a concrete cube.

Specimen: ``blocksPerEdge``³ cubic blocks forming a cube of side ``size``, between a bottom (fixed) and a top (loading)
plate of ``blocksPerEdge``² blocks, ``plateHeight`` tall, of the same material, all face-bonded (so the Poisson grid
spans both plates: 10×10×12 blocks give 9×9×11 = 891 elements, as in the paper's §5.2). Plate blocks are rigidly guided
in z and cannot rotate; they are free in x and y (frictionless platens), so the specimen is in uniaxial stress. The
top plate moves down at ``rate``. The plates are of the specimen's material unless ``plateYoung`` / ``platePoisson``
give them their own (joints then combine both materials by eq. 12).
"""
import math
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat
from . import build, measure


class CompressionTest:
	"""Build the compression scene into the current (empty) scene. Lengths in m, stresses in Pa, rate in m/s, time in s.

	``contactSamples``: the sample grid of the contacts between blocks that are not bonded; ``None``: ``segmentsPerEdge``,
	the grid with which the paper's fixed ``dt`` of 2 µs was validated (not ``rdem.engines``' vertices: their corner
	contacts need a smaller step, which ``dt=None`` takes)."""

	def __init__(self,
	             blocksPerEdge=10,
	             size=0.2,
	             plateHeight=0.04,
	             segmentsPerEdge=2,
	             young=30e9,
	             poisson=0.2,
	             density=2300,
	             tensileStrength=4.5e6,
	             cohesion=float('inf'),
	             frictionCoefficient=0.624,
	             dampingConstant=1.0,
	             formulation='paper',
	             corotational=False,
	             plateYoung=None,
	             platePoisson=None,
	             rate=1.0e-3,
	             dt=2.0e-6,
	             contactSamples=None,
	             distributed=False):
		if not (isinstance(blocksPerEdge, int) and blocksPerEdge >= 2):
			raise ValueError('blocksPerEdge = %r: must be an integer >= 2' % (blocksPerEdge, ))
		for name, value in (('size', size), ('plateHeight', plateHeight), ('rate', rate)):
			if not value > 0:
				raise ValueError('%s = %r: must be > 0' % (name, value))
		if plateYoung is not None and not (math.isfinite(plateYoung) and plateYoung > 0):
			raise ValueError('plateYoung = %r: must be finite and > 0 [Pa] (or None: the specimen\'s material)' % (plateYoung, ))
		if platePoisson is not None and not (-1 < platePoisson < 0.5):
			raise ValueError('platePoisson = %r: must be in (-1, 0.5) (or None: the specimen\'s)' % (platePoisson, ))
		if not frictionCoefficient >= 0:
			raise ValueError('frictionCoefficient = %r: must be >= 0' % (frictionCoefficient, ))
		if len(O.bodies) or len(O.interactions):
			raise RuntimeError('CompressionTest builds into an empty scene: call O.reset() first')
		self.n, self.size, self.plateHeight, self.rate = blocksPerEdge, size, plateHeight, rate
		self.formulation = formulation
		self.material = RdemMat(young=young,
		                        poisson=poisson,
		                        density=density,
		                        tensileStrength=tensileStrength,
		                        cohesion=cohesion,
		                        frictionAngle=math.atan(frictionCoefficient),
		                        dampingNormal=dampingConstant,
		                        dampingShear=dampingConstant,
		                        label='concrete')
		O.materials.append(self.material)
		# Platens: of the specimen's material (the paper's Table 1 lists one material), or of their own (e.g. steel), which
		# does not crack: joints inside a plate are unbreakable, plate-specimen joints take the specimen's strengths (eq. 15-16).
		self.plateMaterial = self.material
		if plateYoung is not None or platePoisson is not None:
			self.plateMaterial = RdemMat(young=plateYoung if plateYoung is not None else young,
			                             poisson=platePoisson if platePoisson is not None else poisson,
			                             density=density,
			                             tensileStrength=float('inf'),
			                             cohesion=float('inf'),
			                             frictionAngle=math.atan(frictionCoefficient),
			                             dampingNormal=dampingConstant,
			                             dampingShear=dampingConstant,
			                             label='platen')
			O.materials.append(self.plateMaterial)
		breakable = tensileStrength < float('inf') or cohesion < float('inf')
		h = size / blocksPerEdge
		# Contacts of blocks that are not bonded on the face grid of the springs, unless told: the paper's fixed 2 µs step
		# was validated with it. With rdem.engines' vertex samples the corners of diagonal neighbours that touch after
		# the first crack are four times stiffer, the critical step falls to 1.89 µs, and at 2 µs the cube blows apart
		# (the user guide's defaults page, "Where the face grid stays"); with dt=None the time stepper follows them.
		O.engines = build.engines(segmentsPerEdge=segmentsPerEdge,
		                          contactSamples=contactSamples if contactSamples is not None else segmentsPerEdge,
		                          formulation=formulation,
		                          corotational=corotational,
		                          recontact=breakable,
		                          dt=dt,
		                          verletDist=0.05 * h,
		                          distributed=distributed)
		n = blocksPerEdge
		grey, red, blue = Vector3(.7, .7, .7), Vector3(.9, .2, .2), Vector3(.5, .7, 1)
		self.bottom = build.blockGrid((n, n, 1), (h, h, plateHeight), self.plateMaterial, color=blue)
		self.specimen = build.blockGrid((n, n, n), (h, h, h), self.material, origin=(0, 0, plateHeight), color=grey)
		self.top = build.blockGrid((n, n, 1), (h, h, plateHeight), self.plateMaterial, origin=(0, 0, plateHeight + size), color=red)
		self.ids = self.bottom + self.specimen + self.top
		self.nBonds = build.bond(self.ids)
		for i in self.bottom + self.top:
			O.bodies[i].state.blockedDOFs = 'zXYZ'  # before the Poisson elements: the consistent formulation reads platens
		self.nElements = 0
		if build.POISSON_MODES[formulation][1]:
			build.poissonEngine().build(self.ids)
			self.nElements = build.poissonEngine().nElements
		for i in self.top:
			O.bodies[i].state.vel = Vector3(0, 0, -rate)
		self.area = size * size

	def block(self, i, j, k):
		"""Body id of specimen block (i, j, k)."""
		return self.specimen[i + self.n * (j + self.n * k)]

	def stress(self):
		"""Mean compressive stress on the loading plate [Pa], positive in compression: the z-force the specimen exerts on
		the top plate over the cross-section (paper §5.3.2)."""
		return sum(O.forces.f(i)[2] for i in self.top) / self.area

	def displacement(self):
		"""Downward displacement of the loading plate [m]."""
		return sum(O.bodies[i].state.refPos[2] - O.bodies[i].state.pos[2] for i in self.top) / len(self.top)

	def axialPairs(self):
		"""Pairs of specimen blocks, bottom and top layer of every column: their centroid distance gives the axial strain."""
		n = self.n
		return [(self.block(i, j, 0), self.block(i, j, n - 1)) for i in range(n) for j in range(n)]

	def lateralPairs(self):
		"""Pairs of opposite surface blocks of the mid-height layer(s), along x and along y: the lateral strain."""
		n, mid = self.n, [self.n // 2] if self.n % 2 else [self.n // 2 - 1, self.n // 2]
		return [(self.block(0, j, k), self.block(n - 1, j, k)) for j in range(n) for k in mid] + \
		       [(self.block(i, 0, k), self.block(i, n - 1, k)) for i in range(n) for k in mid]

	def apparentPoisson(self):
		"""Apparent Poisson's ratio -ε_lat/ε_ax (paper §5.3.1) from centroid distances (:meth:`lateralPairs`,
		:meth:`axialPairs`)."""
		return measure.apparentPoisson(self.lateralPairs(), self.axialPairs())

	def apparentYoung(self):
		"""Apparent Young's modulus: mean stress over the axial centroid strain of the specimen [Pa]."""
		axial = self.axialPairs()
		eAx = sum(measure.pairStrain(a, b) for a, b in axial) / len(axial)
		return -self.stress() / eAx if eAx else float('nan')


class MasonryPrism:
	"""A stack-bonded masonry prism with mortar layers of their own (the *layer* model, :ref:`theory §1.1 <rdem-theory-1-1>`, :ref:`theory §5.5 <rdem-theory-5-5>`): ``courses``
	bricks of height ``brickHeight`` and ``courses - 1`` mortar layers of thickness ``mortarThickness``, all of the same
	``width`` × ``width`` cross-section, each brick cut into ``blocks`` × ``blocks`` × ``blocksPerBrickHeight`` blocks and
	each mortar layer into ``blocks`` × ``blocks`` × 1, between a bottom (fixed) and a top (loading) plate of one plate
	block per column (free across the load: frictionless platens). Consistent formulation with Poisson cells (what
	:yref:`RdemPoissonEngine.elements` ``'auto'`` chooses for two materials), springs breaking on the total normal stress
	of their face (``failureStress='total'``, or ``'spring'``: the paper's criterion, the default of ``rdem.engines``); brick–mortar faces are
	:yref:`RdemJoint` interfaces of thickness 0 with the bond's strengths. Lengths in m, stresses in Pa, rate in m/s.

	:meth:`lateralStrain` measures the lateral strain of the middle brick's interior, :meth:`closedForm` gives that of an
	infinite stack of the same layers (:ref:`theory §5.5 <rdem-theory-5-5>`)."""

	def __init__(self,
	             brick,
	             mortar,
	             bond,
	             courses=3,
	             width=0.2,
	             brickHeight=0.05,
	             mortarThickness=0.01,
	             blocks=4,
	             blocksPerBrickHeight=1,
	             plateHeight=0.02,
	             rate=0.02,
	             segmentsPerEdge=2,
	             damping=0.0,
	             failureStress='total'):
		for name, value in (('width', width), ('brickHeight', brickHeight), ('mortarThickness', mortarThickness), ('plateHeight', plateHeight), ('rate', rate)):
			if not (math.isfinite(value) and value > 0):
				raise ValueError('%s = %r: must be finite and > 0 [m, m/s]' % (name, value))
		for name, value in (('courses', courses), ('blocks', blocks), ('blocksPerBrickHeight', blocksPerBrickHeight)):
			if not (isinstance(value, int) and value >= 1):
				raise ValueError('%s = %r: must be an integer >= 1' % (name, value))
		if courses < 2:
			raise ValueError('courses = %d: must be >= 2 (a prism has at least one mortar layer)' % courses)
		if len(O.bodies) or len(O.interactions):
			raise RuntimeError('MasonryPrism builds into an empty scene: call O.reset() first')
		from yade.wrapper import RdemJoint
		if not isinstance(bond, RdemJoint):
			raise ValueError('bond = %r: must be an RdemJoint (the strengths of the brick-mortar interface)' % (bond, ))
		self.brick, self.mortar, self.width, self.rate = brick, mortar, width, rate
		self.layers = []  # (kind, z0, z1)
		self.plateMaterial = RdemMat(young=brick.young, poisson=brick.poisson, density=brick.density, tensileStrength=float('inf'), cohesion=float('inf'),
		                             label='plate')
		for m in (brick, mortar, self.plateMaterial):
			if m.id < 0:
				O.materials.append(m)
		O.engines = build.engines(segmentsPerEdge=segmentsPerEdge, formulation='consistent', damping=damping, failureStress=failureStress, recontact=True)
		d = width / blocks
		z = 0.0
		self.bottom = build.blockGrid((blocks, blocks, 1), (d, d, plateHeight), self.plateMaterial, origin=(0, 0, -plateHeight))
		self.brickIds, self.mortarIds = [], []
		for k in range(courses):
			ids = build.blockGrid((blocks, blocks, blocksPerBrickHeight), (d, d, brickHeight / blocksPerBrickHeight), brick, origin=(0, 0, z),
			                      color=Vector3(.72, .33, .22))
			self.brickIds.append(ids)
			self.layers.append(('brick', z, z + brickHeight))
			z += brickHeight
			if k < courses - 1:
				self.mortarIds.append(build.blockGrid((blocks, blocks, 1), (d, d, mortarThickness), mortar, origin=(0, 0, z), color=Vector3(.8, .8, .75)))
				self.layers.append(('mortar', z, z + mortarThickness))
				z += mortarThickness
		self.height = z
		self.top = build.blockGrid((blocks, blocks, 1), (d, d, plateHeight), self.plateMaterial, origin=(0, 0, z))
		masonry = [i for ids in self.brickIds + self.mortarIds for i in ids]
		self.ids = self.bottom + masonry + self.top
		# Bonds: inside bricks, inside mortar layers and to the plates directly; brick-mortar faces with the bond's strengths.
		mortarSet = set(i for ids in self.mortarIds for i in ids)
		brickSet = set(i for ids in self.brickIds for i in ids)
		for ids in self.brickIds + self.mortarIds + [self.bottom, self.top]:
			build.bond(ids)
		interfacePairs, platePairs = [], []
		n = blocks * blocks
		for k in range(courses):
			lowest, highest = self.brickIds[k][:n], self.brickIds[k][-n:]
			if k < courses - 1:
				interfacePairs += list(zip(highest, self.mortarIds[k]))
			if k > 0:
				interfacePairs += list(zip(self.mortarIds[k - 1], lowest))
		platePairs = list(zip(self.bottom, self.brickIds[0][:n])) + list(zip(self.brickIds[-1][-n:], self.top))
		self.interface = RdemJoint(thickness=0, young=mortar.young, poisson=mortar.poisson, tensileStrength=bond.tensileStrength, cohesion=bond.cohesion,
		                           frictionAngle=bond.frictionAngle, label='bed')
		build.bondPairs(interfacePairs, joint=self.interface)
		build.bondPairs(platePairs)
		for i in self.bottom + self.top:
			O.bodies[i].state.blockedDOFs = 'zXYZ'  # frictionless platens, before the cells: they are half cells
		build.poissonEngine().build(self.ids)  # 'auto': cells, since brick and mortar differ
		for i in self.top:
			O.bodies[i].state.vel = Vector3(0, 0, -rate)
		self.area = width * width
		self.blocks = blocks
		self.brickSet, self.mortarSet = brickSet, mortarSet

	def stress(self):
		"""Mean compressive stress on the loading plate [Pa], positive in compression."""
		return sum(O.forces.f(i)[2] for i in self.top) / self.area

	def displacement(self):
		"""Downward displacement of the loading plate [m]."""
		return sum(O.bodies[i].state.refPos[2] - O.bodies[i].state.pos[2] for i in self.top) / len(self.top)

	def settle(self, tolerance=1e-5):
		"""Hold the loading plate and let the prism come to rest with Cundall's damping (0.5), until the interior lateral
		strain changes by less than ``tolerance`` relative over 500 steps; then the damping is off again and the plate
		stays held (set the velocity of :attr:`top` to load further)."""
		newton = build.newtonIntegrator()
		for i in self.top:
			O.bodies[i].state.vel = Vector3.Zero
		newton.damping = 0.5
		previous = float('nan')
		while not abs(self.lateralStrain() / previous - 1) < tolerance:
			previous = self.lateralStrain()
			for _ in range(500):
				O.step()
		newton.damping = 0.0

	def brickCracks(self, snapshot):
		"""The springs broken inside bricks (bonds between two brick blocks) since ``snapshot`` (rdem.measure.bondSnapshot)."""
		return [s for s in measure.brokenSegments(snapshot) if s['id1'] in self.brickSet and s['id2'] in self.brickSet]

	def lateralStrain(self):
		"""Lateral strain of the interior of the middle brick: the slope of the x-displacement of the centroids of its two
		central rows of blocks (along x, at the central y), over x [-] (positive = expansion)."""
		ids = self.brickIds[len(self.brickIds) // 2]
		d = self.width / self.blocks
		centre = self.width / 2
		pts = [(O.bodies[i].state.refPos[0], O.bodies[i].state.pos[0] - O.bodies[i].state.refPos[0]) for i in ids
		       if abs(O.bodies[i].state.refPos[1] - centre) < d and abs(O.bodies[i].state.refPos[0] - centre) < 1.01 * d]
		xs = sorted(set(round(x, 12) for x, _ in pts))
		if len(xs) < 2:
			raise ValueError('blocks = %d: the interior lateral strain needs at least 2 blocks across' % self.blocks)
		lo = [u for x, u in pts if round(x, 12) == xs[0]]
		hi = [u for x, u in pts if round(x, 12) == xs[-1]]
		return (sum(hi) / len(hi) - sum(lo) / len(lo)) / (xs[-1] - xs[0])

	def closedForm(self):
		"""Lateral strain per unit compressive stress of an infinite stack of the prism's brick and mortar layers under uniform
		vertical stress, bonded (equal lateral strain e in all layers, zero mean lateral stress) [1/Pa] (:ref:`theory §5.5 <rdem-theory-5-5>`):
		e/σ = Σ t_i λ_i/M_i / Σ t_i (2(λ_i + μ_i) - 2λ_i²/M_i), over one period of the stack."""
		num = den = 0.0
		for m, t in ((self.brick, self.layers[0][2] - self.layers[0][1]), (self.mortar, self.layers[1][2] - self.layers[1][1])):
			lam, mu = m.young * m.poisson / ((1 + m.poisson) * (1 - 2 * m.poisson)), m.young / (2 * (1 + m.poisson))
			M = lam + 2 * mu
			num += t * lam / M
			den += t * (2 * (lam + mu) - 2 * lam * lam / M)
		return num / den


class RockingBlock:
	"""Housner's rigid block (Housner 1963, Bull. Seismol. Soc. Am. 53(2):403-417): a block of half-width ``b``, half-height
	``h`` and half-depth ``depth`` standing on a fixed base block, the two touching through sampled contacts only (no bond),
	released at rest tilted by ``theta0`` about its +x corner (positive: resting on that corner). Contact springs with
	critical dashpots (eq. 13, ``dampingConstant``) and Coulomb friction; the contact sample grid ``contactSamples`` (None:
	``rdem.engines``' default, the vertices; :ref:`theory §4.2 <rdem-theory-4-2>`). Lengths in m, angles in rad, SI units.

	:meth:`angle` is the block's rotation about y (positive: tilted onto the +x corner)."""

	def __init__(self, b=0.1, h=0.5, depth=0.1, theta0=0.0, young=30e9, poisson=0.2, density=2500, friction=0.8, dampingConstant=1.0,
	             contactSamples=None, gravity=9.81):
		for name, value in (('b', b), ('h', h), ('depth', depth), ('young', young), ('density', density), ('gravity', gravity)):
			if not (math.isfinite(value) and value > 0):
				raise ValueError('%s = %r: must be finite and > 0' % (name, value))
		self.b, self.h, self.g = b, h, gravity
		self.alpha, self.R = math.atan(b / h), math.hypot(b, h)
		if not (0 <= theta0 < self.alpha):
			raise ValueError('theta0 = %r: must be in [0, alpha) = [0, %.4f) rad (beyond alpha the block falls over)' % (theta0, self.alpha))
		if len(O.bodies) or len(O.interactions):
			raise RuntimeError('RockingBlock builds into an empty scene: call O.reset() first')
		self.material = O.materials.append(
		        RdemMat(young=young, poisson=poisson, density=density, tensileStrength=float('inf'), cohesion=float('inf'), frictionAngle=math.atan(friction),
		                dampingNormal=dampingConstant, dampingShear=dampingConstant, label='block'))
		O.engines = build.engines(formulation=None, recontact='always', gravity=(0, 0, -gravity), **({} if contactSamples is None else dict(contactSamples=contactSamples)))
		# A base wide enough for the block to land on when it overturns either way (falling about a corner, it reaches 2h + b).
		self.base = O.bodies.append(build.block((0, 0, -0.1), (2 * h + 2 * b + 0.2, depth + 0.2, 0.1), self.material, fixed=True))
		q = Quaternion(Vector3(0, 1, 0), theta0)
		pivot = Vector3(b, 0, 0)
		self.block = O.bodies.append(build.block(pivot + q * (Vector3(0, 0, h) - pivot), (b, depth, h), self.material, orientation=q))
		O.dt = -1

	def angle(self):
		"""Rotation of the block about y [rad], positive when it rests on its +x corner."""
		axis, angle = O.bodies[self.block].state.ori.toAxisAngle()
		return angle * axis[1]

	def eta(self):
		"""Housner's ratio of angular velocities across an impact, η = 1 - (3/2) sin²α (angular momentum about the new corner)."""
		return 1 - 1.5 * math.sin(self.alpha)**2

	def upliftAcceleration(self):
		"""Horizontal ground acceleration above which the block lifts off a corner, g tan α [m/s²]."""
		return self.g * math.tan(self.alpha)

	def energyRatio(self, theta0, theta1):
		"""Energy kept through an impact, from the amplitudes before and after it: (cos(α-θ1) - cos α)/(cos(α-θ0) - cos α)."""
		return (math.cos(self.alpha - theta1) - math.cos(self.alpha)) / (math.cos(self.alpha - theta0) - math.cos(self.alpha))

	def quarterCycle(self, theta0, steps=20000):
		"""Time for the rigid block released at rest from theta0 to reach θ = 0 [s]: the exact equation of motion about the
		corner, I_O θ̈ = -m g R sin(α - θ) with I_O = (4/3) m R², integrated by fourth-order Runge-Kutta (``steps`` steps over
		a first guess of the duration, then refined by interpolation at the crossing)."""
		p2 = 3 * self.g / (4 * self.R)  # p², Housner's frequency parameter
		f = lambda th, om: (om, -p2 * math.sin(self.alpha - th))
		th, om, t = theta0, 0.0, 0.0
		dt = 4.0 / math.sqrt(p2) / steps
		while th > 0:
			k1 = f(th, om)
			k2 = f(th + dt / 2 * k1[0], om + dt / 2 * k1[1])
			k3 = f(th + dt / 2 * k2[0], om + dt / 2 * k2[1])
			k4 = f(th + dt * k3[0], om + dt * k3[1])
			thNew = th + dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
			omNew = om + dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
			if thNew <= 0:
				return t + dt * th / (th - thNew)
			th, om, t = thNew, omNew, t + dt
		return t


def runningBondWall(blocks, dt=None, only=None, beamCell=True, distributed=False):
	"""A running-bond brick wall of about ``blocks`` blocks standing on a fixed base beam under gravity: the large wall
	of the benchmarks (``scripts/benchmark.py --cases bigwall``, ``scripts/mpi_scaling.py``).

	Two blocks per 250 × 120 × 55 mm brick with 10 mm joints, courses : bricks per course = 5 : 4; MI1's materials by
	the rule set of :ref:`rdem-validation` (:func:`rdem.wall_database.materials`; head joints bonded here: E 2.991 GPa,
	ν 0.25, 1800 kg/m³), Poisson cells, softening, total-stress failure, Cundall's damping 0.2 (the validated
	quasi-static scheme). Gravity acts at once, so a few joints break in the first steps.

	:param blocks: about how many blocks (> 0).
	:param dt: a fixed time step [s], or None for :yref:`RdemTimeStepper`'s.
	:param only: make only some blocks (:func:`rdem.masonry.wall`'s ``only``: a set-up per rank on YADE's MPI,
	    :class:`rdem.distributed.PerRank`); the Poisson cells are built on the blocks made.
	:param beamCell: give the base beam a Poisson cell too (default, the benchmarks' scene); ``False``: the beam without
	    one (``scripts/mpi_scaling.py``, whose figures were measured so).
	:param distributed: made to run on YADE's MPI (:func:`rdem.engines`' ``distributed``).
	:return: dict ``perCourse``, ``courses`` (bricks), ``ids`` (the wall's blocks), ``base`` (the fixed beam's blocks),
	    ``made`` (the blocks made in this scene: ``ids``, or those ``only`` chose).
	"""
	from yade.wrapper import RdemJoint
	from . import masonry
	if not blocks > 0:
		raise ValueError('blocks = %r: must be > 0' % blocks)
	if not isinstance(beamCell, bool):
		raise ValueError('beamCell = %r: must be True or False' % (beamCell, ))
	bricks = blocks / 2
	perCourse = max(2, int(round(math.sqrt(bricks * 4 / 5))))
	courses = max(2, int(round(bricks / perCourse)))
	brick = O.materials.append(
	        RdemMat(young=2.991e9, poisson=0.25, density=1800, tensileStrength=1.2818e6, cohesion=1.7945e6, frictionAngle=math.atan(0.81), fractureEnergy=80,
	                shearFractureEnergy=800, compressiveStrength=19.72e6, compressiveFractureEnergy=5000))
	joint = RdemJoint(young=2.991e9, poisson=0.25, tensileStrength=0.15e6, cohesion=0.21e6, frictionAngle=math.atan(0.81), fractureEnergy=18,
	                  shearFractureEnergy=125, compressiveStrength=7.92e6, compressiveFractureEnergy=5000)
	O.engines = build.engines(segmentsPerEdge=2, contactSamples=2, formulation='consistent', failureStress='total', softening=True, gravity=(0, 0, -9.81),
	                          damping=0.2, verletDist=0.003, dt=dt, distributed=distributed)
	w = masonry.wall(perCourse * 0.26 - 0.01, courses * 0.065 - 0.01, 0.12, blocksPerBrick=(2, 1, 1), baseBeam=0.1, brickMaterial=brick, jointMaterial=joint,
	                 only=only)
	for i in w.beams['base']:  # fixed before the cells are built, which read the prescribed axes from the DOFs
		if i < len(O.bodies) and O.bodies[i] is not None:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	build.poissonEngine().elements = 'cells'
	base = set(w.beams['base'])
	build.poissonEngine().build(w.made if beamCell else [i for i in w.made if i not in base])
	O.dt = dt if dt else -1
	return dict(perCourse=perCourse, courses=courses, ids=list(w.ids), base=list(w.beams['base']), made=list(w.made))
