"""Building block assemblies: blocks, bonds between face-adjacent blocks, and the engine list.

Every effect is a separate piece of the engine list, so a scene pays only for what it uses: no collider when no spring
can break (all strengths infinite) and ``recontact=False``, a collider kept dead by :yref:`RdemContactGate` until a
spring breaks, no Poisson engine when ``formulation=None``.
"""
import math
import os
from yade import O, utils, Vector3, Quaternion
from yade.wrapper import (Body, RdemBlock, RdemMat, RdemJoint, ForceResetter, InsertionSortCollider, Bo1_Box_Aabb, RdemInteractionLoop, Ig2_RdemBlock_RdemBlock_RdemGeom,
                          Ip2_RdemMat_RdemMat_RdemPhys, Law2_RdemGeom_RdemPhys_FaceSprings, RdemPoissonEngine, RdemCellStrainUpdater, RdemTimeStepper,
                          NewtonIntegrator, RdemContactGate, RdemFiniteGuard, RdemForceAssembler, RdemLeapfrogEnergy, RdemSharedState)

#: The values of ``engines(formulation=...)``: the formulation of the springs (:yref:`Ip2_RdemMat_RdemMat_RdemPhys.formulation`, the
#: scene's one setting) and whether there is a Poisson engine. Without one the springs are the paper's.
POISSON_MODES = {None: ('paper', False), 'off': ('paper', False), 'paper': ('paper', True), 'consistent': ('consistent', True)}


def block(center, halfExtents, material, orientation=Quaternion.Identity, fixed=False, color=None):
	"""A rigid block (:yref:`RdemBlock`) as a :yref:`Body`, not yet in the scene (``O.bodies.append`` it).

	Mass $8\\rho abc$ and principal inertia $m(b^2+c^2)/3$, ... for half-extents $(a, b, c)$ [m]. :yref:`Body::aspherical` is set
	unless the block is a cube: a cube's inertia is isotropic, Euler's equations then have no gyroscopic term, and
	NewtonIntegrator's spherical update is exact for it and cheaper than the aspherical one."""
	a, b, c = (float(h) for h in halfExtents)
	if min(a, b, c) <= 0:
		raise ValueError('halfExtents = %s: every half-extent must be > 0 [m]' % (tuple(halfExtents), ))
	mat = material if not isinstance(material, int) else O.materials[material]
	if not isinstance(mat, RdemMat):
		raise ValueError('material must be an RdemMat (or its index in O.materials), not %s' % type(mat).__name__)
	if not (math.isfinite(mat.density) and mat.density > 0):
		raise ValueError('RdemMat.density = %r: must be finite and > 0 [kg/m3] (it gives the block mass)' % (mat.density, ))
	shape = RdemBlock(extents=Vector3(a, b, c), color=color if color is not None else Vector3(0.7, 0.7, 0.7))
	V = 8 * a * b * c
	body = Body()
	body.shape = shape
	body.material = mat
	body.state = mat.newAssocState()
	body.state.mass = mat.density * V
	body.state.inertia = Vector3(b * b + c * c, a * a + c * c, a * a + b * b) * (body.state.mass / 3.0)
	body.state.pos = body.state.refPos = Vector3(center)
	body.state.ori = body.state.refOri = orientation
	body.aspherical = max(a, b, c) - min(a, b, c) > 1e-12 * max(a, b, c)
	body.bounded = True
	if fixed:
		body.state.blockedDOFs = 'xyzXYZ'
	return body


def blockGrid(counts, sizes, material, origin=(0, 0, 0), orientation=Quaternion.Identity, color=None):
	"""Append a regular grid of ``counts = (nx, ny, nz)`` blocks of ``sizes = (dx, dy, dz)`` [m], the grid's lower corner at
	``origin``, the whole grid rotated by ``orientation`` about that corner. Returns the body ids, block $(i,j,k)$ at
	index ``i + nx*(j + ny*k)``."""
	nx, ny, nz = (int(n) for n in counts)
	if min(nx, ny, nz) < 1:
		raise ValueError('counts = %s: every count must be an integer >= 1' % (tuple(counts), ))
	dx, dy, dz = (float(s) for s in sizes)
	if min(dx, dy, dz) <= 0:
		raise ValueError('sizes = %s: every block size must be > 0 [m]' % (tuple(sizes), ))
	o = Vector3(origin)
	bodies = []
	for k in range(nz):
		for j in range(ny):
			for i in range(nx):
				local = Vector3((i + 0.5) * dx, (j + 0.5) * dy, (k + 0.5) * dz)
				bodies.append(block(o + orientation * local, (dx / 2, dy / 2, dz / 2), material, orientation=orientation, color=color))
	return O.bodies.append(bodies)


#: The labels :func:`engines` gives its engines and functors (:yref:`Engine.label`): the helpers below, and any script,
#: find them by these (``O.labeledEngine(label)``, or the label as a variable in a YADE script), not by scanning O.engines.
LABELS = dict(gate='rdemGate',
              collider='rdemCollider',
              cellStrains='rdemCellStrains',
              loop='rdemLoop',
              geom='rdemIg2',
              phys='rdemIp2',
              law='rdemLaw2',
              forces='rdemForces',
              poisson='rdemPoisson',
              stepper='rdemStepper',
              newton='rdemNewton',
              guard='rdemGuard',
              energy='rdemEnergy')


def _labeled(key, cls, hint):
	"""The engine or functor that :func:`engines` labelled ``LABELS[key]``, checked to be a ``cls``; RuntimeError with ``hint``."""
	try:
		e = O.labeledEngine(LABELS[key])
	except (ValueError, RuntimeError):
		e = None
	if not isinstance(e, cls):
		raise RuntimeError('no %s labelled %r in O.engines (set O.engines = rdem.engines(...)%s)' % (cls.__name__, LABELS[key], hint))
	return e


def geomFunctor():
	"""The :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` of the current engine list (it makes the bonds)."""
	return _labeled('geom', Ig2_RdemBlock_RdemBlock_RdemGeom, ' before bonding')


def law():
	"""The :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` of the current engine list."""
	return _labeled('law', Law2_RdemGeom_RdemPhys_FaceSprings, '')


def poissonEngine():
	"""The :yref:`RdemPoissonEngine` of the current engine list."""
	return _labeled('poisson', RdemPoissonEngine, ' with formulation="paper" or "consistent"')


def contactGate():
	"""The :yref:`RdemContactGate` of the current engine list (set ``open=True`` to run the collider from the start)."""
	return _labeled('gate', RdemContactGate, ' with recontact=True')


def collider():
	"""The :yref:`InsertionSortCollider` of the current engine list."""
	return _labeled('collider', InsertionSortCollider, ' with recontact=True or "always"')


def newtonIntegrator():
	"""The :yref:`NewtonIntegrator` of the current engine list (its ``damping`` and ``gravity``)."""
	return _labeled('newton', NewtonIntegrator, '')


def run(steps):
	"""Make ``steps`` time steps and return when they are done, as ``O.run(steps, True)`` does, but with ``O.step()`` in
	this thread: ``O.wait()`` checks every 40 ms whether YADE's simulation thread has finished (yadeWrapper.cpp,
	``wait``), so each ``O.run(n, True)`` costs at least 40 ms, more than the run itself for the short chunks of a script
	that measures between chunks; ``O.step()`` costs about 3 µs of Python. An error of an engine is raised here with its
	own type (``O.run`` turns it into ``RuntimeError``). A ``PyRunner`` calling ``O.pause()`` does not stop this loop.

	:param steps: number of steps, an integer >= 1."""
	if not (isinstance(steps, int) and steps >= 1):
		raise ValueError('steps = %r: must be an integer >= 1' % (steps, ))
	for _ in range(steps):
		O.step()


def timeStepper():
	"""The :yref:`RdemTimeStepper` of the current engine list."""
	return _labeled('stepper', RdemTimeStepper, '')


def _aabb(b):
	"""Axis-aligned bounding box (min, max) of a block body."""
	R = b.state.ori.toRotationMatrix()
	h = b.shape.extents
	ext = Vector3(*(sum(abs(R[i, j]) * h[j] for j in range(3)) for i in range(3)))
	return b.state.pos - ext, b.state.pos + ext


def bond(ids, tolerance=1e-6, joint=None):
	"""Bond every pair of face-adjacent blocks among ``ids`` with restoring springs (through ``utils.createInteraction``,
	so ``O.engines`` must come from :func:`engines` first). Returns the number of bonds.

	:param joint: an :yref:`RdemJoint` (mortar thickness and elastic constants, bond strengths) given to every bond made, or
	    ``None``: blocks bonded directly (eq. 12, the weaker material's strengths).

	Raises ValueError if two blocks overlap by more than ``tolerance`` times the smaller half-extent, if ``ids``
	contains a body that is not a block, or if a block of ``ids`` shares no face with any other (not adjacent: nothing
	would hold it)."""
	ids = list(ids)
	if not tolerance >= 0:
		raise ValueError('tolerance = %r: must be >= 0 (relative to the smaller half-extent)' % (tolerance, ))
	geomFunctor()  # fail early and clearly if the engines are not there
	blocks = []
	for i in ids:
		b = O.bodies[i]
		if b is None or not isinstance(b.shape, RdemBlock):
			raise ValueError('bond: body %s is not an RdemBlock' % i)
		lo, hi = _aabb(b)
		blocks.append((i, lo, hi, min(b.shape.extents)))
	# Spatial hashing on cells of the median block size; each block is entered in every cell its bounding box touches,
	# so that blocks of very different sizes (a plate over small blocks) do not make every cell crowded.
	sizes = sorted(2 * max(O.bodies[i].shape.extents) for i in ids)
	cell = sizes[len(sizes) // 2] if sizes else 1.0
	grid = {}
	margin = 1e-3 * cell  # blocks that touch must share a cell even when round-off puts their common face on a cell border
	cellRange = lambda lo, hi: [range(int(math.floor((lo[d] - margin) / cell)), int(math.floor((hi[d] + margin) / cell)) + 1) for d in range(3)]
	for entry in blocks:
		rx, ry, rz = cellRange(entry[1], entry[2])
		for cx in rx:
			for cy in ry:
				for cz in rz:
					grid.setdefault((cx, cy, cz), []).append(entry)
	candidates = []  # face-to-face pairs; all checks come before the first bond is made
	for (i, lo, hi, hmin) in blocks:
		seen = set()
		rx, ry, rz = cellRange(lo, hi)
		for cx in rx:
			for cy in ry:
				for cz in rz:
					for (j, lo2, hi2, hmin2) in grid.get((cx, cy, cz), []):
						if j <= i or j in seen:
							continue
						seen.add(j)
						tol = tolerance * min(hmin, hmin2)
						overlap = [min(hi[d], hi2[d]) - max(lo[d], lo2[d]) for d in range(3)]
						if min(overlap) < -tol:
							continue  # apart
						if sorted(overlap)[0] > tol and _aligned(O.bodies[i], O.bodies[j]):
							raise ValueError('bond: blocks %d and %d overlap by %.3g m (tolerance %.3g m); blocks must touch face to face' %
							                 (i, j, sorted(overlap)[0], tol))
						if sum(1 for o in overlap if o > tol) < 2:
							continue  # touch along an edge or at a corner only
						candidates.append((i, j))
	touching = set(k for pair in candidates for k in pair)
	alone = [i for i in ids if i not in touching]
	if len(ids) > 1 and alone:
		raise ValueError('bond: block %d shares no face with any other of the %d blocks given (ids must be face-adjacent blocks; '
		                 '%d such blocks: %s)' % (alone[0], len(ids), len(alone), alone[:10]))
	return bondPairs(candidates, joint=joint, strict=False)


def bondPairs(pairs, joint=None, strict=True):
	"""Bond the given pairs ``(id1, id2)`` of face-adjacent blocks (e.g. ``rdem.wall_layout``'s touching pairs), every bond
	with the :yref:`RdemJoint` ``joint`` (or none). Returns the number of bonds made.

	:param strict: raise ValueError naming the pair if two blocks of a pair share no face (else such pairs are skipped)."""
	if joint is not None and not isinstance(joint, RdemJoint):
		raise ValueError('joint = %r: must be an RdemJoint or None' % (joint, ))
	ig2 = geomFunctor()
	ig2.joint = joint
	n = 0
	try:
		for i, j in pairs:
			try:
				utils.createInteraction(int(i), int(j))
				n += 1
			except RuntimeError:
				if strict:
					raise ValueError('bondPairs: blocks %d and %d share no face (parallel, aligned faces within bondGapTolerance); '
					                 'only face-adjacent blocks can be bonded' % (i, j))
	finally:
		ig2.joint = None
	return n


def _aligned(a, b):
	"""Whether two blocks have the same orientation up to axis permutations (so that their bounding boxes are exact)."""
	R = (a.state.ori.conjugate() * b.state.ori).toRotationMatrix()
	return all(min(abs(abs(R[i, j]) - 1), abs(R[i, j])) < 1e-9 for i in range(3) for j in range(3))


def mpiProcesses():
	"""How many processes ``mpiexec`` launched together with this one: the size of MPI's world from the launcher's
	environment (Open MPI's ``OMPI_COMM_WORLD_SIZE``, MPICH's and Intel MPI's ``PMI_SIZE``), 1 when not launched by it."""
	for name in ('OMPI_COMM_WORLD_SIZE', 'PMI_SIZE'):
		value = os.environ.get(name, '')
		if value.isdigit():
			return int(value)
	return 1


def engines(segmentsPerEdge=2,
            formulation='paper',
            corotational=False,
            recontact=True,
            damping=0.0,
            gravity=(0, 0, 0),
            dt=None,
            safety=0.8,
            verletDist=None,
            finiteGuard=True,
            failureStress='spring',
            contactSamples=1,
            softening=False,
            crackBand=False,
            strengthCoV=0.0,
            strengthPerSegment=False,
            stiffnessCoV=0.0,
            seed=0,
            distributed=False,
            **removed):
	"""The engine list of a refined-DEM scene. Every engine and functor carries a label of :data:`LABELS` (``rdemNewton``,
	``rdemPoisson``, ...), by which :func:`poissonEngine`, :func:`newtonIntegrator` and the others find it.

	:param segmentsPerEdge: $n$, each bonded face carries $n\\times n$ springs (paper: 2).
	:param formulation: ``'paper'`` (springs $E/(1-\\nu^2)$ + $D_p$ elements on $2\\times2\\times2$ grids, as published), ``'consistent'``
	    (springs $\\lambda+2\\mu$ + $D_p$ elements on grids, Poisson cells on any other layout: the full isotropic tensor, see
	    :ref:`theory §5.2 <rdem-theory-5-2>`, :ref:`§5.4 <rdem-theory-5-4>`) or ``None`` (refined DEM without the Poisson effect, springs as in the paper).
	:param corotational: remove rigid rotations of the Poisson elements (needed for large rotations).
	:param recontact: ``True``: the collider, so that separated blocks can touch again anywhere, switched on by
	    :yref:`RdemContactGate` only once contacts can occur (the first broken spring, a free block, a second assembly);
	    ``'always'``: the collider runs from the first step; ``False``: no new contact is ever made.
	:param damping: Cundall's non-viscous damping of :yref:`NewtonIntegrator` (0 = none, as in the paper).
	:param dt: ``None``: :yref:`RdemTimeStepper` sets ``O.dt = safety·Δt_crit`` with its Lanczos estimate of Δt_crit (the tight
	    limit, dashpots included), kept below the limit of a critically damped stiffest mode, (√2 − 1)·2/ω_max, while contacts act
	    or can form (``contactLimit``); a number:
	    fixed ``O.dt`` [s], checked against the stepper's Lanczos estimate (with the contact dashpots): refused above it
	    (:ref:`stability <rdem-stability>`).
	:param verletDist: collider sweep distance [m] (default: none, the collider runs every step; set it to about 5 % of the
	    block size for speed).
	:param contactSamples: $m$, sample grid of the contacts of blocks that are not bonded, $(m+1)^2$ points per face
	    (:yref:`Ig2_RdemBlock_RdemBlock_RdemGeom.contactSamplesPerEdge`). 1 (default): the vertices, as UDEC and 3DEC, which
	    makes rocking impacts dissipate what Housner's theory says (:ref:`theory §4.2 <rdem-theory-4-2>`), with the face grid of
	    ``segmentsPerEdge`` for the contacts of faces that cross (no vertex of either block inside the other); $m > 1$: a
	    face grid (inner samples store impact energy and give it back: +6 to +8 % energy kept at a rocking impact);
	    ``None``: ``segmentsPerEdge``.
	:param failureStress: ``'spring'`` (default, the paper's): restoring springs break on their own stresses (eqs. 15-16);
	    ``'total'``: on the total normal stress of the face, springs plus Poisson cells
	    (:yref:`Law2_RdemGeom_RdemPhys_FaceSprings.totalStress`, :ref:`theory §5.6 <rdem-theory-5-6>`; needs ``formulation='consistent'`` and
	    cells, which ``rdem.poissonEngine().build`` then chooses).
	:param poisson: not a parameter (it was the formulation's name, which ``poisson``, Poisson's ratio everywhere else,
	    made a surprise): refused with a TypeError naming ``formulation``.
	:param softening: ``False`` (default): the paper's brittle springs; ``True``: softening springs (tension, cohesion and
	    a compression cap that soften with the fracture energies of the :yref:`RdemJoint` or :yref:`RdemMat`, the energy per
	    unit crack area independent of the block size: :yref:`Ip2_RdemMat_RdemMat_RdemPhys.softening`, :ref:`theory §2.1 <rdem-theory-2-1>`).
	:param crackBand: with ``softening``: a bond whose springs would snap back (blocks too large for the fracture energy) gets
	    the lowered strengths of Bažant & Oh's crack-band remedy instead of an error
	    (:yref:`Ip2_RdemMat_RdemMat_RdemPhys.crackBand`); ``False`` (default): refused.
	:param strengthCoV: coefficient of variation of the bonds' strengths (one lognormal factor of mean 1 per bond,
	    :yref:`Ip2_RdemMat_RdemMat_RdemPhys.strengthCoV`); 0: uniform.
	:param strengthPerSegment: with ``strengthCoV``: one factor per segment (spring) instead of per bond
	    (:yref:`Ip2_RdemMat_RdemMat_RdemPhys.strengthPerSegment`).
	:param stiffnessCoV: the same for the bonds' spring stiffnesses.
	:param seed: seed of the random factors; a fixed seed reproduces a scene bit for bit.
	:param finiteGuard: append :yref:`RdemFiniteGuard` after the integrator: the run stops at the first NaN or infinite
	    position, velocity or force, naming the body and interactions (costs < 1 % of a step).
	:param distributed: ``True`` for a scene made to run on YADE's MPI (``yade.mpy``; distributed by
	    :func:`rdem.distributed.prepare`, :ref:`rdem-mpi`). ``False`` (default): a serial scene, refused with a RuntimeError
	    when the process is one of several that ``mpiexec`` launched (:func:`mpiProcesses`), since each would run all of it."""
	if 'poisson' in removed:
		raise TypeError("rdem.engines(poisson=%r): the formulation's keyword is formulation=, e.g. rdem.engines(formulation=%r) "
		                "('paper', 'consistent' or None); poisson is Poisson's ratio (RdemMat.poisson)" % (removed['poisson'], removed['poisson']))
	if removed:
		raise TypeError('rdem.engines() got an unexpected keyword argument %r' % sorted(removed)[0])
	if not isinstance(distributed, bool):
		raise ValueError('distributed = %r: must be True or False' % (distributed, ))
	processes = mpiProcesses()
	if processes > 1 and not distributed:
		raise RuntimeError('rdem.engines: this process is one of %d that mpiexec launched, but the scene is serial (distributed=False): '
		                   'each process would run all of it. Run it without mpiexec, or make it for YADE\'s MPI with '
		                   'rdem.engines(distributed=True) and rdem.distributed.prepare() (the MPI page of the user guide; scripts/mpi_compare.py)' % processes)
	if formulation not in POISSON_MODES:
		raise ValueError('formulation = %r: must be one of %s or None' % (formulation, sorted(k for k in POISSON_MODES if k)))
	if not (isinstance(segmentsPerEdge, int) and segmentsPerEdge >= 1):
		raise ValueError('segmentsPerEdge = %r: must be an integer >= 1' % (segmentsPerEdge, ))
	if not (0 <= damping < 1):
		raise ValueError('damping = %r: must be in [0, 1)' % (damping, ))
	if dt is not None and not dt > 0:
		raise ValueError('dt = %r: must be > 0 [s] (or None for the automatic time step)' % (dt, ))
	if not (0 < safety <= 1):
		raise ValueError('safety = %r: must be in (0, 1]' % (safety, ))
	if verletDist is not None and not (math.isfinite(verletDist) and verletDist >= 0):
		raise ValueError('verletDist = %r: must be finite and >= 0 [m] (or None)' % (verletDist, ))
	if len(gravity) != 3 or not all(math.isfinite(g) for g in gravity):
		raise ValueError('gravity = %r: must be 3 finite numbers [m/s2]' % (gravity, ))
	if failureStress not in ('spring', 'total'):
		raise ValueError("failureStress = %r: must be 'spring' or 'total'" % (failureStress, ))
	if failureStress == 'total' and formulation != 'consistent':
		raise ValueError("failureStress = 'total' needs formulation = 'consistent' (the total stress of a face comes from the Poisson cells), not %r" % (formulation, ))
	formulation, withPoisson = POISSON_MODES[formulation]
	if contactSamples is not None and not (isinstance(contactSamples, int) and contactSamples >= 1):
		raise ValueError('contactSamples = %r: must be an integer >= 1 (or None: segmentsPerEdge)' % (contactSamples, ))
	L = LABELS
	# one RdemSharedState for every engine and functor of the plugin: the crack state, the deferred forces' record, the travel
	shared = RdemSharedState()
	loop = RdemInteractionLoop([Ig2_RdemBlock_RdemBlock_RdemGeom(segmentsPerEdge=segmentsPerEdge, contactSamplesPerEdge=contactSamples or 0, shared=shared, label=L['geom'])], [Ip2_RdemMat_RdemMat_RdemPhys(formulation=formulation, softening=bool(softening), crackBand=bool(crackBand), strengthCoV=strengthCoV, strengthPerSegment=bool(strengthPerSegment), stiffnessCoV=stiffnessCoV, seed=int(seed), label=L['phys'])],
	                       [Law2_RdemGeom_RdemPhys_FaceSprings(deferForces=True, totalStress=failureStress == 'total', shared=shared, label=L['law'])], shared=shared, label=L['loop'])
	eng = [ForceResetter()]
	if recontact not in (True, False, 'always'):
		raise ValueError("recontact = %r: must be True, False or 'always'" % (recontact, ))
	if recontact is True:
		eng.append(RdemContactGate(shared=shared, label=L['gate']))
	if recontact:
		eng.append(InsertionSortCollider([Bo1_Box_Aabb()], verletDist=verletDist if verletDist is not None else 0.0, label=L['collider']))
	if withPoisson and formulation == 'consistent':
		eng.append(RdemCellStrainUpdater(shared=shared, label=L['cellStrains']))  # Poisson cells of layouts that are not grids: strains before the law reads them
	eng += [loop, RdemForceAssembler(shared=shared, label=L['forces'])]  # forces summed per body in a fixed order: O.load continues bit for bit
	if withPoisson:
		eng.append(RdemPoissonEngine(corotational=corotational, shared=shared, label=L['poisson']))
	# The automatic step is 0.8 of the tight (Lanczos) limit, also below the critically damped limit while contacts act or can form
	# (RdemTimeStepper.contactLimit); a fixed step is checked against the Lanczos estimate, refused above it
	stepper = RdemTimeStepper(safety=safety, timeStepUpdateInterval=100, active=dt is None, contactBound=bool(recontact),
	                          method='lanczos', shared=shared, label=L['stepper'])
	newton = NewtonIntegrator(damping=damping, gravity=Vector3(gravity), label=L['newton'])
	eng += [stepper, newton]
	if finiteGuard:
		eng.append(RdemFiniteGuard(label=L['guard']))
	# with O.trackEnergy, the kinetic energy and the damping's work booked so that O.energy's total balances exactly
	eng.append(RdemLeapfrogEnergy(integrator=newton, label=L['energy']))
	if dt is not None:
		O.dt = dt
	return eng
