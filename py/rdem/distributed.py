"""The refined DEM on YADE's MPI (:mod:`yade.mpy`): subdomains for the blocks, the checks, and the engines mpy does not
add itself. See :ref:`the MPI page <rdem-mpi>` of the user guide.

Every rank runs the same script (``mpiexec -n 3 build-mpi/bin/yade -n script.py``: the master, rank 0, and two workers);
each builds the scene, mpy then replaces the workers' scenes by the master's when it splits it. Typical use::

    from yade import mpy, rdem
    from yade.rdem import distributed, scenes
    test = scenes.CompressionTest(formulation=None)
    distributed.prepare()              # subdomains by bisection, bonds across the cuts kept, collider, checks
    mpy.mpirun(1000, withMerge=True)    # the master's O.bodies hold every block afterwards

A large scene need not exist on one rank: with :class:`PerRank` each rank makes only its own blocks and their
neighbours (mpy's distributed insertion, ``DISTRIBUTED_INSERT``)::

    part = distributed.PerRank(master=lambda layout: [b for u in layout.beams() for b in layout.units[u].blocks])
    wall = scenes.runningBondWall(1e5, only=part)   # or rdem.masonry.wall(..., only=part)
    part.assign(wall['ids'])
    distributed.prepare(perRank=part)
    mpy.mpirun(1000)

Needs YADE built with MPI (``tools/setup.sh --mpi``): the plain YADE has no :yref:`Body.subdomain`.
"""
import math
from yade import O, Body
from yade.wrapper import RdemBlock, RdemMat, RdemPoissonEngine, RdemCellStrainUpdater, InsertionSortCollider, InteractionLoop, Bo1_Box_Aabb
from .partition import neighbourhood, ranks, refusals

__all__ = ['assign', 'PerRank', 'features', 'check', 'prepare', 'localBreakCounts', 'countedHere', 'breakCounts', 'energies']


def _fixed(b):
	s = b.state
	return s.blockedDOFs == 'xyzXYZ' and s.vel.norm() == 0 and s.angVel.norm() == 0


def assign(workers, master=()):
	"""Set :yref:`Body.subdomain` of every block: ``master`` (ids of fixed blocks) stay on rank 0, the others go to ranks
	1 … ``workers`` by a bisection of their centroids (:func:`rdem.partition.ranks`). Returns the number of blocks of each worker.

	:raises ValueError: a body that is not a block, a master body that is not fixed, or what ``bisect`` refuses."""
	if not hasattr(Body(), 'subdomain'):
		raise RuntimeError('rdem.distributed.assign: this YADE has no Body.subdomain (built without MPI); use build-mpi/bin/yade (tools/setup.sh --mpi)')
	master = set(master)
	blocks = [b for b in O.bodies if b is not None and not b.isSubdomain]
	for b in blocks:
		if not isinstance(b.shape, RdemBlock):
			raise ValueError('assign: body %d is not an RdemBlock; only blocks can be assigned to subdomains' % b.id)
		if b.id in master and not _fixed(b):
			raise ValueError('assign: body %d on the master moves (blockedDOFs %r, vel %s): mpy sends the master\'s states to no worker, '
			                 'only fixed bodies may stay there' % (b.id, b.state.blockedDOFs, b.state.vel))
	rank, perWorker = ranks([b.state.pos for b in blocks], set(k for k, b in enumerate(blocks) if b.id in master), workers)
	for b, r in zip(blocks, rank):
		b.subdomain = r
	return perWorker


class PerRank:
	"""Which blocks of a layout this rank makes, for a set-up on mpy in which no rank holds the whole scene (mpy's
	``DISTRIBUTED_INSERT``; YADE's user manual, *MPI parallelization*, "Centralized versus distributed scene
	construction"). Every rank lays out the whole scene (the boxes and their touching pairs: geometry only, no bodies),
	cuts it into subdomains as :func:`assign` does (:func:`rdem.partition.ranks`: a bisection of the block centroids, ``master``
	blocks on rank 0), and makes only its own blocks and those within two bonds of them
	(:func:`rdem.partition.neighbourhood`), each with the id the whole scene gives it. A bond across a cut is thus made on
	both of its ranks from the same two blocks, as the serial set-up makes it, and :func:`prepare` keeps it through mpy's
	split (:yref:`RdemBondKeeper`); the Poisson cells of the rank's blocks and of its ghosts are built from all their
	bonds. mpy's split erases the blocks the rank does not own and receives its ghosts from their owners.

	Pass it as ``only`` to the generator (:func:`rdem.masonry.wall`, :func:`rdem.scenes.runningBondWall`), then
	:meth:`assign` the generator's ids and call :func:`prepare` with ``perRank=`` it.

	:param master: the layout's indices of the blocks that stay on the master (fixed ones: mpy sends the master's states
	    to no worker), or a function of the layout that returns them; default none.
	:param workers: number of workers (default: every rank but the master).
	:param layers: bonds out from a rank's own blocks to make (2: its ghosts with all their bonds; see
	    :func:`rdem.partition.neighbourhood`).
	:ivar subdomain: the subdomain of each block of the layout (after the generator called it).
	:ivar perWorker: blocks of each worker."""

	def __init__(self, master=(), workers=None, layers=2):
		self.master, self.workers, self.layers = master, workers, layers
		self.subdomain, self.perWorker = None, None

	def __call__(self, layout):
		from yade import mpy
		if mpy.comm is None:
			mpy.configure()
		workers = mpy.numThreads - 1 if self.workers is None else self.workers
		if workers < 1:
			raise ValueError('workers = %r: mpy needs at least one worker besides the master (mpiexec -n 2 or more)' % (workers, ))
		master = set(self.master(layout) if callable(self.master) else self.master)
		centres = [tuple((lo[d] + hi[d]) / 2 for d in range(3)) for lo, hi in layout.blocks]
		self.subdomain, self.perWorker = ranks(centres, master, workers)
		return neighbourhood(self.subdomain, [(p[0], p[1]) for p in layout.pairs], mpy.rank, self.layers)

	def assign(self, ids):
		"""Set :yref:`Body.subdomain` of the blocks made: ``ids`` are the generator's ids of the layout's blocks (the whole
		scene's, :attr:`rdem.masonry.Wall.ids`), in the layout's order. Returns the blocks of each worker."""
		if self.subdomain is None:
			raise RuntimeError('PerRank.assign: no layout yet; pass this PerRank as only= to the generator first')
		if len(ids) != len(self.subdomain):
			raise ValueError('PerRank.assign: %d ids for the %d blocks of the layout' % (len(ids), len(self.subdomain)))
		for i, p in zip(ids, self.subdomain):
			if i < len(O.bodies) and O.bodies[i] is not None:
				O.bodies[i].subdomain = p
		return self.perWorker


def features():
	"""What the scene has that matters for a distributed run (the keys of :func:`rdem.partition.refusals`)."""
	f = dict(others=[], masterMoving=[], masterCells=[], hex8=0, cells=0, exchange=False, masterCellsReduced=False, breakable=False)
	for b in O.bodies:
		if b is None or getattr(b, 'isSubdomain', False):  # (a YADE without MPI has neither attribute: all on the master)
			continue
		if not isinstance(b.shape, RdemBlock):
			f['others'].append(b.id)
		elif getattr(b, 'subdomain', 0) == 0:
			if not _fixed(b):
				f['masterMoving'].append(b.id)
			if getattr(b.state, 'cellVolume', 0) > 0:
				f['masterCells'].append(b.id)
	for e in O.engines:
		if isinstance(e, RdemPoissonEngine) and not e.dead:
			f['hex8'] += e.nElements
			f['cells'] += e.nCells
		if type(e).__name__ == 'RdemGhostExchange' and not e.dead:
			f['exchange'] = f['exchange'] or e.exchange
			f['masterCellsReduced'] = f['masterCellsReduced'] or e.masterCells
	f['breakable'] = any(isinstance(m, RdemMat) and (math.isfinite(m.tensileStrength) or math.isfinite(m.cohesion)) for m in O.materials)
	return f


def check():
	"""Raise RuntimeError naming everything that keeps the scene from a distributed run identical to the serial one."""
	r = refusals(features())
	if r:
		raise RuntimeError('rdem.distributed: this scene cannot run on yade.mpy yet:\n  - ' + '\n  - '.join(r))


class _SceneCollider:
	"""The scene's InsertionSortCollider, looked up at each use: mpy's parallelCollide uses a global ``collider`` (the
	engine labelled so in YADE's examples); the plugin's is labelled ``rdemCollider``, and the workers' engines are
	replaced when mpy splits the scene."""

	def _engine(self):
		return next(e for e in O.engines if isinstance(e, InsertionSortCollider))

	def __getattr__(self, name):
		return getattr(self._engine(), name)

	def __setattr__(self, name, value):
		setattr(self._engine(), name, value)

	def __call__(self):
		self._engine()()


def prepare(workers=None, master=(), exchange=True, perRank=None, masterCells=True):
	"""Make the current scene ready for :func:`yade.mpy.mpirun` on every rank: assign the blocks (:func:`assign`, to
	``workers`` ranks, default: all but the master), put an :yref:`RdemBondKeeper` first in the engines and record the
	bonds across the cuts (mpy's split erases them; it puts them back), insert an :yref:`RdemGhostExchange` after the
	:yref:`RdemCellStrainUpdater` (with ``exchange=False`` one that does not exchange, which is wrong at the boundary:
	for tests), which also completes the Poisson cells of blocks on the master from every rank's part of their bonds
	(:yref:`RdemGhostExchange::masterCells`, if the scene has such cells; ``masterCells=False``: it does not, which is
	wrong: for tests), a collider if there is none (mpy's parallel collision detection needs an :yref:`InsertionSortCollider`),
	with a sweep distance (``verletDist``) of 5 % of the smallest block if it has none (mpy's ghosts are the blocks whose
	bounding boxes overlap a subdomain's: without a sweep, blocks face to face across the cut only touch); then :func:`check`. :yref:`RdemTimeStepper` takes one step for all ranks
	itself (the minimum of their limits). With ``perRank`` (a :class:`PerRank` that chose the blocks each rank made, and
	assigned them), the subdomains are its own and mpy inserts nothing (``mpy.DISTRIBUTED_INSERT``). Returns the blocks
	per worker."""
	from yade import mpy
	if mpy.comm is None:
		mpy.configure()
	if workers is None:
		workers = mpy.numThreads - 1
	if workers < 1:
		raise ValueError('workers = %r: mpy needs at least one worker besides the master (mpiexec -n 2 or more)' % (workers, ))
	if perRank is None:
		perWorker = assign(workers, master)
	else:
		if perRank.perWorker is None:
			raise RuntimeError('prepare: perRank made no layout; pass it as only= to the generator and call its assign() first')
		if len(perRank.perWorker) != workers:
			raise ValueError('prepare: perRank cut the scene for %d workers, mpy has %d' % (len(perRank.perWorker), workers))
		perWorker = perRank.perWorker
		mpy.DISTRIBUTED_INSERT = True
	from yade.wrapper import RdemBondKeeper
	eng = [e for e in O.engines if not isinstance(e, RdemBondKeeper)]
	keeper = RdemBondKeeper(label='rdemBondKeeper')
	keeper.keep()
	eng.insert(0, keeper)
	# cells on the master: the same decision on every rank (each may hold another part of the scene: perRank)
	onMaster = any(b.subdomain == 0 and getattr(b.state, 'cellVolume', 0) > 0 for b in O.bodies
	               if b is not None and not b.isSubdomain and isinstance(b.shape, RdemBlock))
	reduce = bool(masterCells) and bool(mpy.comm.allreduce(onMaster, op=mpy.MPI.LOR))
	names = [type(e).__name__ for e in eng]
	if 'RdemGhostExchange' not in names:
		at = next((k + 1 for k, e in enumerate(eng) if isinstance(e, RdemCellStrainUpdater)), None)
		if at is not None:
			from yade.wrapper import RdemGhostExchange
			eng.insert(at, RdemGhostExchange(exchange=bool(exchange), masterCells=reduce, label='rdemGhosts'))
	else:
		eng[names.index('RdemGhostExchange')].masterCells = reduce
	size = min([min(b.shape.extents) for b in O.bodies if b is not None and isinstance(b.shape, RdemBlock)] + [float('inf')])  # smallest half-extent
	if perRank is not None:  # each rank holds a part: the scene's smallest
		size = mpy.comm.allreduce(size, op=mpy.MPI.MIN)
	collider = next((e for e in eng if isinstance(e, InsertionSortCollider)), None)
	if collider is None:
		at = next(k for k, e in enumerate(eng) if isinstance(e, InteractionLoop))
		eng.insert(at, InsertionSortCollider([Bo1_Box_Aabb()], verletDist=0.1 * size, label='rdemCollider'))
	elif not collider.verletDist > 0:
		# mpy finds a subdomain's ghosts by the overlap of bounding boxes: without a sweep, the boxes of blocks face to face
		# only touch, and some bonded neighbours across the cut would not become ghosts (their bonds then missing)
		collider.verletDist = 0.1 * size
	O.engines = eng
	if not hasattr(mpy, 'collider'):
		mpy.collider = _SceneCollider()
	if exchange and masterCells:
		check()
	return perWorker


def localBreakCounts(counted=lambda id1, id2: True):
	"""(tension, shear): restoring springs broken so far in this process's scene, read from the springs' states
	(:yref:`RdemPhys.segState`, and the release records of bonds broken through), of the bonds for which
	``counted(id1, id2)`` is true. Serial runs count every bond; :func:`breakCounts` counts each bond on one rank."""
	from yade.wrapper import RdemPhys
	from . import build
	states = [I.phys.segState for I in O.interactions if I.isReal and isinstance(I.phys, RdemPhys) and counted(I.id1, I.id2)]
	states += [r.segState for r in build.law().releasedBonds if counted(r.id1, r.id2)]
	return sum(1 for seg in states for x in seg if x == 1), sum(1 for seg in states for x in seg if x == 2)


def countedHere(id1, id2):
	"""Whether this rank counts the bond between bodies ``id1`` and ``id2`` in a sum over the ranks: the rank that owns its
	body of lower id, or the other body's if the master owns that one (a bond across a subdomain boundary exists on two
	ranks; the master keeps its fixed bodies but none of their bonds). Before and after mpy's split alike."""
	from yade import mpy
	a, b = O.bodies[min(id1, id2)], O.bodies[max(id1, id2)]
	if a is None or b is None:
		return False
	return (a.subdomain if a.subdomain != 0 else b.subdomain) == mpy.rank


def breakCounts():
	"""(tension, shear): restoring springs broken so far over all ranks, each bond counted once (:func:`countedHere`; each
	rank's :yref:`Law2_RdemGeom_RdemPhys_FaceSprings.tensionBreaks` counts the bonds across its boundary). Collective:
	call it on every rank."""
	from yade import mpy
	tension, shear = localBreakCounts(countedHere)
	return mpy.comm.allreduce(tension), mpy.comm.allreduce(shear)


def energies():
	"""O.energy summed over all ranks, as a dict (name: value [J]); collective: call it on every rank. Each rank books its
	own blocks' kinetic energy and cells and, of an interaction between one of its blocks and a ghost, half (the rank of
	the ghost books the other half: :yref:`Law2_RdemGeom_RdemPhys_FaceSprings`, :yref:`RdemLeapfrogEnergy`,
	:yref:`RdemPoissonEngine`'s cells). The sums equal the serial run's up to the order of summation."""
	from yade import mpy
	mine = dict(O.energy.items())
	out = {}
	for part in mpy.comm.allgather(mine):
		for k, v in part.items():
			out[k] = out.get(k, 0.0) + v
	return out
