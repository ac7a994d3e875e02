"""Building block assemblies: blocks, bonds between face-adjacent blocks, and the engine list.

Every effect is a separate piece of the engine list, so a scene pays only for what it uses: no collider when no spring
can break (all strengths infinite) and ``recontact=False``, no Poisson engine when ``poisson=None``.
"""
import math
from yade import O, utils, Vector3, Quaternion
from yade.wrapper import (Body, RdemBlock, RdemMat, ForceResetter, InsertionSortCollider, Bo1_Box_Aabb, InteractionLoop, Ig2_RdemBlock_RdemBlock_RdemGeom,
                          Ip2_RdemMat_RdemMat_RdemPhys, Law2_RdemGeom_RdemPhys_FaceSprings, RdemPoissonEngine, RdemTimeStepper, NewtonIntegrator)

POISSON_MODES = {None: None, 'off': None, 'paper': 0, 'consistent': 1}


def block(center, halfExtents, material, orientation=Quaternion.Identity, fixed=False, color=None):
	"""A rigid block (:yref:`RdemBlock`) as a :yref:`Body`, not yet in the scene (``O.bodies.append`` it).

	Mass $8\\rho abc$ and principal inertia $m(b^2+c^2)/3$, ... for half-extents $(a, b, c)$ [m]; :yref:`Body::aspherical` set."""
	a, b, c = (float(h) for h in halfExtents)
	if min(a, b, c) <= 0:
		raise ValueError('halfExtents = %s: every half-extent must be > 0 [m]' % (tuple(halfExtents), ))
	mat = material if not isinstance(material, int) else O.materials[material]
	if not isinstance(mat, RdemMat):
		raise ValueError('material must be an RdemMat (or its index in O.materials), not %s' % type(mat).__name__)
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
	body.aspherical = True
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


def _functor(cls, dispatcher, hint):
	"""The functor of class ``cls`` in the ``dispatcher`` of the InteractionLoop of O.engines; RuntimeError with ``hint``."""
	for e in O.engines:
		if isinstance(e, InteractionLoop):
			for f in getattr(e, dispatcher).functors:
				if isinstance(f, cls):
					return f
	raise RuntimeError('no %s in O.engines%s' % (cls.__name__, hint))


def _engine(cls, hint):
	"""The engine of class ``cls`` in O.engines; RuntimeError with ``hint``."""
	for e in O.engines:
		if isinstance(e, cls):
			return e
	raise RuntimeError('no %s in O.engines%s' % (cls.__name__, hint))


def geomFunctor():
	"""The :yref:`Ig2_RdemBlock_RdemBlock_RdemGeom` of the current engine list (it makes the bonds)."""
	return _functor(Ig2_RdemBlock_RdemBlock_RdemGeom, 'geomDispatcher', ': set O.engines = rdem.engines(...) before bonding')


def law():
	"""The :yref:`Law2_RdemGeom_RdemPhys_FaceSprings` of the current engine list."""
	return _functor(Law2_RdemGeom_RdemPhys_FaceSprings, 'lawDispatcher', '')


def poissonEngine():
	"""The :yref:`RdemPoissonEngine` of the current engine list."""
	return _engine(RdemPoissonEngine, ': make the engines with rdem.engines(poisson="paper" or "consistent")')


def timeStepper():
	"""The :yref:`RdemTimeStepper` of the current engine list."""
	return _engine(RdemTimeStepper, '')


def _aabb(b):
	"""Axis-aligned bounding box (min, max) of a block body."""
	R = b.state.ori.toRotationMatrix()
	h = b.shape.extents
	ext = Vector3(*(sum(abs(R[i, j]) * h[j] for j in range(3)) for i in range(3)))
	return b.state.pos - ext, b.state.pos + ext


def bond(ids, tolerance=1e-6):
	"""Bond every pair of face-adjacent blocks among ``ids`` with restoring springs (through ``utils.createInteraction``,
	so ``O.engines`` must come from :func:`engines` first). Returns the number of bonds.

	Raises ValueError if two blocks overlap by more than ``tolerance`` times the smaller half-extent, or if ``ids``
	contains a body that is not a block."""
	ids = list(ids)
	geomFunctor()  # fail early and clearly if the engines are not there
	blocks = []
	for i in ids:
		b = O.bodies[i]
		if b is None or not isinstance(b.shape, RdemBlock):
			raise ValueError('bond: body %s is not an RdemBlock' % i)
		lo, hi = _aabb(b)
		blocks.append((i, lo, hi, min(b.shape.extents)))
	# Spatial hashing on a cell as large as the largest block: neighbours are in the 27 surrounding cells.
	cell = 2 * max(max(b.shape.extents) for b in (O.bodies[i] for i in ids)) * math.sqrt(3)
	grid = {}
	key = lambda p: tuple(int(math.floor(p[d] / cell)) for d in range(3))
	for entry in blocks:
		grid.setdefault(key((entry[1] + entry[2]) / 2), []).append(entry)
	n = 0
	for (i, lo, hi, hmin) in blocks:
		c = key((lo + hi) / 2)
		for dx in (-1, 0, 1):
			for dy in (-1, 0, 1):
				for dz in (-1, 0, 1):
					for (j, lo2, hi2, hmin2) in grid.get((c[0] + dx, c[1] + dy, c[2] + dz), []):
						if j <= i:
							continue
						tol = tolerance * min(hmin, hmin2)
						overlap = [min(hi[d], hi2[d]) - max(lo[d], lo2[d]) for d in range(3)]
						if min(overlap) < -tol:
							continue  # apart
						if sorted(overlap)[0] > tol and _aligned(O.bodies[i], O.bodies[j]):
							raise ValueError('bond: blocks %d and %d overlap by %.3g m (tolerance %.3g m); blocks must touch face to face' %
							                 (i, j, sorted(overlap)[0], tol))
						if sum(1 for o in overlap if o > tol) < 2:
							continue  # touch along an edge or at a corner only
						try:
							utils.createInteraction(i, j)
							n += 1
						except RuntimeError:
							pass  # parallel faces not aligned or no shared area: not bonded
	return n


def _aligned(a, b):
	"""Whether two blocks have the same orientation up to axis permutations (so that their bounding boxes are exact)."""
	R = (a.state.ori.conjugate() * b.state.ori).toRotationMatrix()
	return all(min(abs(abs(R[i, j]) - 1), abs(R[i, j])) < 1e-9 for i in range(3) for j in range(3))


def engines(segmentsPerEdge=2, poisson='paper', corotational=False, recontact=True, damping=0.0, gravity=(0, 0, 0), dt=None, safety=0.8,
            verletDist=None):
	"""The engine list of a refined-DEM scene.

	:param segmentsPerEdge: $n$, each bonded face carries $n\\times n$ springs (paper: 2).
	:param poisson: ``'paper'`` (springs $E/(1-\\nu^2)$ + $D_p$ elements, as published), ``'consistent'`` (springs $\\lambda+2\\mu$ + $D_p$: the
	    full isotropic tensor, see doc/theory.md) or ``None`` (refined DEM without the Poisson effect, springs as in the paper).
	:param corotational: remove rigid rotations of the Poisson elements (needed for large rotations).
	:param recontact: include the collider, so that separated blocks can touch again anywhere. Without it no new contact
	    is ever made (cheaper; right when nothing can break or separate).
	:param damping: Cundall's non-viscous damping of :yref:`NewtonIntegrator` (0 = none, as in the paper).
	:param dt: ``None``: :yref:`RdemTimeStepper` sets ``O.dt = safety·Δt_crit``; a number: fixed ``O.dt`` [s] (the stepper then
	    only warns if it exceeds the estimate).
	:param verletDist: collider sweep distance [m] (default: none, the collider runs every step; set it to about 5 % of the
	    block size for speed)."""
	if poisson not in POISSON_MODES:
		raise ValueError('poisson = %r: must be one of %s' % (poisson, sorted(k for k in POISSON_MODES if k)))
	if not (isinstance(segmentsPerEdge, int) and segmentsPerEdge >= 1):
		raise ValueError('segmentsPerEdge = %r: must be an integer >= 1' % (segmentsPerEdge, ))
	if not (0 <= damping < 1):
		raise ValueError('damping = %r: must be in [0, 1)' % (damping, ))
	if dt is not None and not dt > 0:
		raise ValueError('dt = %r: must be > 0 [s] (or None for the automatic time step)' % (dt, ))
	if not (0 < safety <= 1):
		raise ValueError('safety = %r: must be in (0, 1]' % (safety, ))
	mode = POISSON_MODES[poisson]
	loop = InteractionLoop([Ig2_RdemBlock_RdemBlock_RdemGeom(segmentsPerEdge=segmentsPerEdge)],
	                       [Ip2_RdemMat_RdemMat_RdemPhys(springModulus=1 if mode == 1 else 0)], [Law2_RdemGeom_RdemPhys_FaceSprings()])
	eng = [ForceResetter()]
	if recontact:
		eng.append(InsertionSortCollider([Bo1_Box_Aabb()], verletDist=verletDist if verletDist is not None else 0.0))
	eng.append(loop)
	if mode is not None:
		eng.append(RdemPoissonEngine(corotational=corotational, consistent=mode == 1))
	stepper = RdemTimeStepper(safety=safety, timeStepUpdateInterval=100, active=dt is None, contactBound=recontact)
	eng += [stepper, NewtonIntegrator(damping=damping, gravity=Vector3(gravity))]
	if dt is not None:
		O.dt = dt
	return eng
