# -*- coding: utf-8 -*-
"""A scene serially or on YADE's MPI (yade.mpy): block positions and break counts after a number of steps, for the
comparison of doc/mpi.md. Scenes: the paper's compression cube (rdem.scenes.CompressionTest), a running-bond wall
with Poisson cells and springs that break on the total stress of their face, compressed between its fixed bottom and
moving top courses (--per-rank: each rank makes only its part, rdem.distributed.PerRank), or the benchmarks' wall under
gravity on a base beam (--scene bigwall, rdem.scenes.runningBondWall). A base beam stays on the master under --mpi;
its Poisson cell (--base-beam, --beam-cell) is completed on every rank from all ranks' parts of its bonds
(RdemGhostExchange.masterCells). A scene that cannot run on mpy yet (the paper's hexahedra: --poisson hex8) is refused
by rdem.distributed.check with the reason.

    build-mpi/bin/yade -n -x scripts/mpi_compare.py --poisson cells --contacts always --steps 200 --out output/mpi/serial.json
    mpiexec --allow-run-as-root --oversubscribe -n 3 build-mpi/bin/yade -n -x scripts/mpi_compare.py --poisson cells --steps 200 --mpi --out output/mpi/mpi.json
    /usr/bin/python3 scripts/mpi_compare.py --compare output/mpi/serial.json output/mpi/mpi.json

Needs the plugin built against YADE with MPI (tools/setup.sh --mpi); the serial run uses the same binary without mpy.
Writes a JSON file: input, steps, O.dt, break counts (tension, shear; with --every N also their history), with --mpi
the blocks, ghosts, bytes sent per step (mpy's states and RdemGhostExchange's) and bonds across the cut put back
(RdemBondKeeper) of each rank, and per block
id its position and orientation (exact: float.hex) and its displacement from the start; for the walls, the set-up's
Poisson cells and bonds (float.hex). Written once, on rank 0; so is --vtk (the blocks at the end, one ParaView file
gathered from every rank). --compare prints the largest position difference of two such files, absolute and over the
largest displacement, whether they are identical bit for bit, their break counts and, for the walls, how many cells
and bonds differ (exit status 1 unless identical with the same break counts, cells and bonds).
"""
import argparse
import json
import math
import os
import sys

parser = argparse.ArgumentParser(prog='yade scripts/mpi_compare.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--scene', choices=['cube', 'wall', 'bigwall'], default='cube',
                    help="cube: the paper's compression cube (default); wall: a running-bond wall, cells, total-stress failure; bigwall: the "
                    "benchmarks' wall (rdem.scenes.runningBondWall: under gravity on a fixed base beam, which stays on the master under --mpi)")
parser.add_argument('--wall-blocks', type=float, default=1000, help='bigwall: about how many blocks (default 1000)')
parser.add_argument('--blocks', type=int, default=10, help='cube: blocks per edge (default 10, as in the paper)')
parser.add_argument('--poisson', choices=['off', 'hex8', 'cells'], default='cells',
                    help="Poisson effect: off (springs only), hex8 (the paper's elements), cells (consistent formulation; default)")
parser.add_argument('--steps', type=int, default=200, help='time steps (default 200)')
parser.add_argument('--every', type=int, default=0, help='also record the break counts every this many steps (0: at the end only)')
parser.add_argument('--rate', type=float, default=0.05, help='loading rate [m/s] (default 0.05: a visible Poisson effect in 200 steps)')
parser.add_argument('--contacts', choices=['gate', 'always'], default='gate',
                    help="cube: contact detection by RdemContactGate (collider off until a spring breaks; default) or always (from the first "
                    "step, as mpy does on its workers: its split runs the collider whatever the gate says); the wall: always")
parser.add_argument('--wall', type=int, nargs=2, default=[10, 10], metavar=('BRICKS', 'COURSES'),
                    help='wall: bricks per course and courses (default 10 10; 50 80 makes about 4000 blocks)')
parser.add_argument('--dt', type=float, default=0,
                    help="wall: a fixed time step [s] (default: half RdemTimeStepper's estimate at set-up, on the whole scene; --per-rank needs it)")
parser.add_argument('--mpi', action='store_true', help='run on yade.mpy (under mpiexec -n 3 or more)')
parser.add_argument('--per-rank', action='store_true',
                    help="wall, with --mpi: each rank makes only its blocks and their neighbours (rdem.distributed.PerRank, mpy's DISTRIBUTED_INSERT) "
                    "instead of the whole wall on every rank")
parser.add_argument('--layers', type=int, default=2,
                    help='--per-rank: bonds out from a rank\'s blocks to make (default 2; 1 builds the ghosts\' cells from part of their bonds: for the test)')
parser.add_argument('--energy', action='store_true', help='track the energies (O.trackEnergy) and record them, summed over ranks under --mpi')
parser.add_argument('--no-exchange', action='store_true', help='RdemGhostExchange off (wrong at the subdomain boundary: for the test)')
parser.add_argument('--base-beam', action='store_true',
                    help='wall: on a fixed base beam (one block with a Poisson cell, on the master under --mpi) instead of its fixed bottom course')
parser.add_argument('--beam-cell', action='store_true', help='bigwall: give the base beam (on the master under --mpi) a Poisson cell')
parser.add_argument('--no-master-cells', action='store_true',
                    help='--mpi: do not complete the cells on the master from every rank\'s bonds (RdemGhostExchange.masterCells off: '
                    'each worker takes its own part of their bonds, which is wrong: for the test)')
parser.add_argument('--out', default='output/mpi/result.json', help='result file (default output/mpi/result.json)')
parser.add_argument('--vtk', default='', help='also write the blocks at the end to this ParaView file (.vtu), once (on rank 0, gathered under --mpi)')
parser.add_argument('--compare', nargs=2, metavar=('A', 'B'), help='compare two result files (plain python3, no YADE)')
args = parser.parse_args(sys.argv[1:])
if args.per_rank and not (args.mpi and args.scene != 'cube'):
	parser.error('--per-rank: only the walls (--scene wall, bigwall) are made per rank, and only on mpy (--mpi)')
if args.scene == 'bigwall' and not args.dt > 0:
	parser.error('--scene bigwall needs --dt (a fixed step: RdemTimeStepper\'s automatic step is not the same on mpy, doc/mpi.md)')
if args.per_rank and not args.dt > 0:
	parser.error("--per-rank needs --dt: RdemTimeStepper's estimate at set-up is of the whole scene, which no rank holds (take the serial run's dt)")
if min(args.wall) < 2:
	parser.error('--wall %d %d: at least 2 bricks per course and 2 courses' % tuple(args.wall))


def compare(a, b):
	A, B = json.load(open(a)), json.load(open(b))
	if set(A['blocks']) != set(B['blocks']):
		print('compare: the files hold different blocks (%d, %d)' % (len(A['blocks']), len(B['blocks'])))
		return False
	dmax, umax, same = 0.0, 0.0, True
	for i, ra in A['blocks'].items():
		rb = B['blocks'][i]
		same = same and ra['pos'] == rb['pos'] and ra['ori'] == rb['ori']
		pa = [float.fromhex(x) for x in ra['pos']]
		pb = [float.fromhex(x) for x in rb['pos']]
		dmax = max(dmax, math.sqrt(sum((x - y)**2 for x, y in zip(pa, pb))))
		umax = max(umax, ra['displacement'])
	print('compare: %d blocks, largest position difference %.3e m, largest displacement %.3e m, ratio %.3e, %s' %
	      (len(A['blocks']), dmax, umax, dmax / umax if umax else float('nan'), 'bit for bit identical' if same else 'NOT identical'))
	print('compare: breaks (tension, shear) %s and %s; history %s and %s' % (A['breaks'], B['breaks'], A.get('history'), B.get('history')))
	for what in ('cells', 'bonds'):  # the set-up's cells and bonds (the wall), each as the rank that owns it has it
		if A.get(what) is not None and B.get(what) is not None:
			differ = [k for k in set(A[what]) | set(B[what]) if A[what].get(k) != B[what].get(k)]
			print('compare: %d and %d %s, %d differ%s' % (len(A[what]), len(B[what]), what, len(differ), (' (e.g. %s)' % sorted(differ)[:5]) if differ else ''))
			same = same and not differ
	if A.get('energy') and B.get('energy'):
		ea, eb = A['energy'], B['energy']
		for k in sorted(set(ea) | set(eb)):
			a, b = ea.get(k, 0.0), eb.get(k, 0.0)
			print('compare: energy %s %.17g and %.17g, relative difference %.3e' % (k, a, b, abs(a - b) / max(abs(a), abs(b)) if a or b else 0.0))
	return same and A['breaks'] == B['breaks']


if args.compare:
	sys.exit(0 if compare(*args.compare) else 1)

from yade import O, Vector3
from yade.rdem import scenes, build


def cube():
	formulation = {'off': None, 'hex8': 'paper', 'cells': 'consistent'}[args.poisson]
	test = scenes.CompressionTest(blocksPerEdge=args.blocks, formulation=formulation, rate=args.rate, distributed=args.mpi)
	if args.poisson == 'cells':
		build.poissonEngine().elements = 'cells'
		build.poissonEngine().build(test.ids)
	if args.contacts == 'always':
		build.contactGate().open = True
	return test.ids


def wall():
	"""A running-bond wall, 10 bricks by 10 courses, one wythe, one block per brick (the bed joints' bonds have centroid
	offsets, which RdemGhostExchange's second message is for), its bottom course fixed (``--base-beam``: standing on a
	fixed base beam of one block with a Poisson cell, which stays on the master under --mpi) and its top course moving
	down at ``rate``; consistent formulation, cells, springs breaking on the total stress of their face, contacts detected from
	the first step, with a collider sweep of 5 % of the smallest brick dimension; a fixed step, ``--dt`` or half the
	stepper's estimate at set-up (the same on every rank, which all build the whole scene). ``--wall`` sets its size;
	with ``--per-rank`` each rank makes only its own bricks and those within two bonds of them."""
	from yade.wrapper import RdemMat, RdemJoint
	from yade.rdem import masonry
	if args.poisson != 'cells':
		raise SystemExit('mpi_compare: --scene wall has Poisson cells (--poisson cells)')
	brick = RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=2e6, cohesion=4e6, frictionAngle=0.6, label='brick')
	O.materials.append(brick)
	O.engines = build.engines(formulation='consistent', failureStress='total', recontact='always', dt=1e-9, distributed=args.mpi)
	mortar = RdemJoint(young=5e9, poisson=0.2, tensileStrength=0.3e6, cohesion=0.5e6, frictionAngle=0.6)
	global perRank
	if args.per_rank:
		from yade.rdem import distributed
		base = (lambda layout: [b for u in layout.beams() if layout.units[u].piece == 'base' for b in layout.units[u].blocks]) if args.base_beam else ()
		perRank = distributed.PerRank(master=base, layers=args.layers)  # the base beam on the master
	bricks, courses = args.wall
	global master
	w = masonry.wall(bricks * 0.26 - 0.01, courses * 0.065 - 0.01, 0.12, bond='running', brickMaterial=brick, jointMaterial=mortar, only=perRank,
	                 baseBeam=0.1 if args.base_beam else None)
	made = set(w.made)
	if args.base_beam:
		master = w.beams['base']  # fixed, it stays on the master under --mpi, with its Poisson cell
	for i in (list(master) if args.base_beam else w.courses[0]) + w.courses[-1]:  # fixed before the cells are built (they read the DOFs)
		if i in made:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	for i in w.courses[-1]:
		if i in made:
			O.bodies[i].state.vel = Vector3(0, 0, -args.rate)
	build.poissonEngine().elements = 'cells'
	build.poissonEngine().build(w.made)
	# the collider's sweep that rdem.distributed.prepare gives a collider without one (mpy finds ghosts by overlapping
	# boxes), here in both runs: after the first breaks the serial run itself depends on it (doc/mpi.md); the bricks of the
	# wall are all of one size, so that the smallest a rank made is the whole wall's (the master makes none here)
	size = min([min(O.bodies[i].shape.extents) for i in w.made] + [float('inf')])
	if perRank is not None:
		from yade import mpy
		size = mpy.comm.allreduce(size, op=mpy.MPI.MIN)
	build.collider().verletDist = 0.1 * size
	O.dt = args.dt if args.dt > 0 else 0.5 * build.timeStepper().estimate()
	if perRank is not None:
		perRank.assign(w.ids)
	return w.ids, w.made


def bigwall():
	"""rdem.scenes.runningBondWall of about ``--wall-blocks`` blocks at the fixed step ``--dt``; its base beam stays on the
	master under --mpi (as scripts/mpi_scaling.py runs it), without a Poisson cell unless ``--beam-cell`` (serially too);
	contact detection from the first step (``--contacts``
	applies to the serial run: mpy detects contacts from its split)."""
	from yade.rdem import scenes
	global perRank, master
	if args.per_rank:
		from yade.rdem import distributed
		perRank = distributed.PerRank(master=lambda layout: [b for u in layout.beams() if layout.units[u].piece == 'base' for b in layout.units[u].blocks],
		                              layers=args.layers)
	w = scenes.runningBondWall(args.wall_blocks, dt=args.dt, only=perRank, beamCell=args.beam_cell, distributed=args.mpi)
	if perRank is not None:
		perRank.assign(w['ids'])
	if args.contacts == 'always':
		build.contactGate().open = True
	master = w['base']
	return w['ids'], w['made']


perRank, master = None, ()
if args.scene == 'cube':
	ids = made = cube()
elif args.scene == 'wall':
	ids, made = wall()
else:
	ids, made = bigwall()
O.trackEnergy = args.energy
start = {i: O.bodies[i].state.pos for i in made}

rank = 0
if args.mpi:
	from yade import mpy
	from yade.rdem import distributed
	mpy.VERBOSE_OUTPUT = False
	perWorker = distributed.prepare(exchange=not args.no_exchange, perRank=perRank, master=master, masterCells=not args.no_master_cells)
	rank = mpy.rank


def breaks():
	if args.mpi:
		return list(distributed.breakCounts())
	law = build.law()
	return [int(law.tensionBreaks), int(law.shearBreaks)]


history = []
done = 0
while done < args.steps:
	n = min(args.every or args.steps, args.steps - done)
	if args.mpi:
		mpy.mpirun(n)
	else:
		O.run(n, True)
	done += n
	if args.every:
		history.append([done] + breaks())
finalBreaks = breaks()


def record(ids):
	out = {}
	for i in ids:
		b = O.bodies[i]
		if b is None:
			continue
		p, q = b.state.pos, b.state.ori
		out[str(i)] = dict(pos=[float(p[k]).hex() for k in range(3)], ori=[float(x).hex() for x in (q[0], q[1], q[2], q[3])],
		                   displacement=(p - start[i]).norm())
	return out


def setUp(ids):
	"""The Poisson cells of the blocks ``ids`` and the bonds of which they hold the body of higher id (each bond once over
	the ranks, on a worker: the master keeps only fixed bodies, and no bonds after mpy's split), as the set-up made them
	(float.hex): a cell's volume, stiffness and condensation, a bond's cell coefficients, spring weights and whichever of
	its offset correction's inputs the plugin has (the centroid offset, or the flag and the face centres)."""
	from yade.wrapper import RdemPhys
	matrix = lambda m: [float(m[i, j]).hex() for i in range(3) for j in range(3)]

	def hexes(obj, names):
		out = []
		for name in names:
			if hasattr(obj, name):
				v = getattr(obj, name)
				out += [float(x).hex() for x in v] if hasattr(v, '__len__') else [float(v).hex()]
		return out
	cells, bonds = {}, {}
	for i in ids:
		st = O.bodies[i].state
		cells[str(i)] = [float(st.cellVolume).hex()] + matrix(st.cellStiffness) + matrix(st.cellCondensation)
		for I in O.interactions.withBody(i):
			if I.isReal and isinstance(I.phys, RdemPhys) and max(I.id1, I.id2) == i:
				p = I.phys
				bonds['%d-%d' % (I.id1, I.id2)] = (hexes(p, ('cellCoef1', 'cellCoef2', 'weightNormal', 'weightShear', 'offsetCorrection')) +
				                                   hexes(I.geom, ('faceCentre1', 'faceCentre2')))
	return cells, bonds


def bytesPerStep():
	"""This rank's blocks and ghosts, bytes sent per step to the other workers: mpy's states (13 reals per boundary block
	and neighbour) and RdemGhostExchange's last step (both its messages), and the bonds across the cut RdemBondKeeper put
	back after mpy's split."""
	sd = O.subD
	states = 0
	if rank > 0:
		states = sum(13 * 8 * len(sd.intersections[k]) for k in sd.intersections[rank] if k not in (0, rank))
	ghost = next((e.bytesSent for e in O.engines if type(e).__name__ == 'RdemGhostExchange'), 0)
	kept = next((e.restored for e in O.engines if type(e).__name__ == 'RdemBondKeeper'), 0)
	return dict(rank=rank, ownBlocks=sum(1 for b in O.bodies if b is not None and not b.isSubdomain and b.subdomain == rank),
	            ghosts=sum(1 for b in O.bodies if b is not None and not b.isSubdomain and b.subdomain != rank), mpyStates=states, ghostExchange=ghost,
	            bondsRestored=kept)


energy = None
if args.energy:
	energy = distributed.energies() if args.mpi else dict(O.energy.items())
if args.vtk:  # the blocks of every rank in one file, written once
	from yade.rdem import export
	mine = [i for i in ids if i < len(O.bodies) and O.bodies[i] is not None and (not args.mpi or O.bodies[i].subdomain == rank)]
	part = [(i, rank, export.blockCorners(O.bodies[i])) for i in mine]
	parts = mpy.comm.gather(part, root=0) if args.mpi else [part]
	if rank == 0:
		export.writeBlocks(args.vtk, [b for p in parts for b in p])
if args.mpi:
	traffic = mpy.comm.gather(bytesPerStep(), root=0)
	mine = [i for i in ids if i < len(O.bodies) and O.bodies[i] is not None and O.bodies[i].subdomain == rank]
	parts = mpy.comm.gather(record(mine), root=0)
	setUps = mpy.comm.gather(setUp(mine) if args.scene != 'cube' else ({}, {}), root=0)
else:
	parts = [record(ids)]
	setUps = [setUp(ids) if args.scene != 'cube' else ({}, {})]
if rank == 0:
	blocks, cells, bonds = {}, {}, {}
	for p, (c, b) in zip(parts, setUps):
		blocks.update(p)
		cells.update(c)
		bonds.update(b)
	if len(blocks) != len(ids):
		raise RuntimeError('mpi_compare: %d of %d blocks gathered' % (len(blocks), len(ids)))
	res = dict(input=vars(args), dt=O.dt, steps=args.steps, ranks=len(parts), blocks=blocks, breaks=finalBreaks, history=history, energy=energy)
	if args.scene != 'cube':
		res.update(cells=cells, bonds=bonds)
	if args.mpi:
		res['blocksPerWorker'] = perWorker
		res['bytesPerStep'] = traffic
		print('mpi_compare: per rank, blocks, ghosts and bytes sent per step:', traffic)
	os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
	json.dump(res, open(args.out, 'w'), indent=0)
	print('mpi_compare: %d blocks after %d steps (dt %.3g s), breaks %s, written to %s' % (len(blocks), args.steps, O.dt, finalBreaks, args.out))
