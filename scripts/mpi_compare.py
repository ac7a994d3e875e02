# -*- coding: utf-8 -*-
"""A scene serially or on YADE's MPI (yade.mpy): block positions and break counts after a number of steps, for the
comparison of doc/mpi.md. Scenes: the paper's compression cube (rdem.scenes.CompressionTest), or a running-bond wall
with Poisson cells and springs that break on the total stress of their face, compressed between two beams.

    build-mpi/bin/yade -n -x scripts/mpi_compare.py --poisson cells --contacts always --steps 200 --out output/mpi/serial.json
    mpiexec --allow-run-as-root --oversubscribe -n 3 build-mpi/bin/yade -n -x scripts/mpi_compare.py --poisson cells --steps 200 --mpi --out output/mpi/mpi.json
    /usr/bin/python3 scripts/mpi_compare.py --compare output/mpi/serial.json output/mpi/mpi.json

Needs the plugin built against YADE with MPI (tools/setup.sh --mpi); the serial run uses the same binary without mpy.
Writes a JSON file: input, steps, O.dt, break counts (tension, shear; with --every N also their history), with --mpi
the blocks, ghosts, bytes sent per step (mpy's states and RdemGhostExchange's) and bonds across the cut put back
(RdemBondKeeper) of each rank, and per block
id its position and orientation (exact: float.hex) and its displacement from the start. --compare prints the largest
position difference of two such files, absolute and over the largest displacement, whether they are identical bit for
bit and their break counts (exit status 1 unless identical with the same break counts).
"""
import argparse
import json
import math
import os
import sys

parser = argparse.ArgumentParser(prog='yade scripts/mpi_compare.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--scene', choices=['cube', 'wall'], default='cube',
                    help="cube: the paper's compression cube (default); wall: a running-bond wall, cells, total-stress failure")
parser.add_argument('--blocks', type=int, default=10, help='cube: blocks per edge (default 10, as in the paper)')
parser.add_argument('--poisson', choices=['off', 'hex8', 'cells'], default='cells',
                    help="Poisson effect: off (springs only), hex8 (the paper's elements), cells (consistent formulation; default)")
parser.add_argument('--steps', type=int, default=200, help='time steps (default 200)')
parser.add_argument('--every', type=int, default=0, help='also record the break counts every this many steps (0: at the end only)')
parser.add_argument('--rate', type=float, default=0.05, help='loading rate [m/s] (default 0.05: a visible Poisson effect in 200 steps)')
parser.add_argument('--contacts', choices=['gate', 'always'], default='gate',
                    help="cube: contact detection by RdemContactGate (collider off until a spring breaks; default) or always (from the first "
                    "step, as mpy does on its workers: its split runs the collider whatever the gate says); the wall: always")
parser.add_argument('--mpi', action='store_true', help='run on yade.mpy (under mpiexec -n 3 or more)')
parser.add_argument('--energy', action='store_true', help='track the energies (O.trackEnergy) and record them, summed over ranks under --mpi')
parser.add_argument('--no-exchange', action='store_true', help='RdemGhostExchange off (wrong at the subdomain boundary: for the test)')
parser.add_argument('--out', default='output/mpi/result.json', help='result file (default output/mpi/result.json)')
parser.add_argument('--compare', nargs=2, metavar=('A', 'B'), help='compare two result files (plain python3, no YADE)')
args = parser.parse_args(sys.argv[1:])


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
	test = scenes.CompressionTest(blocksPerEdge=args.blocks, formulation=formulation, rate=args.rate)
	if args.poisson == 'cells':
		build.poissonEngine().elements = 'cells'
		build.poissonEngine().build(test.ids)
	if args.contacts == 'always':
		build.contactGate().open = True
	return test.ids


def wall():
	"""A running-bond wall, 10 bricks by 10 courses, one wythe, one block per brick (the bed joints' bonds have centroid
	offsets, which RdemGhostExchange's second message is for), its bottom course fixed and its top course moving down at
	``rate``; consistent formulation, cells, springs breaking on the total stress of their face, contacts detected from
	the first step, with a collider sweep of 5 % of the smallest brick dimension; a fixed step, half the stepper's estimate at set-up (the same on every rank, which all build the
	whole scene)."""
	from yade.wrapper import RdemMat, RdemJoint
	from yade.rdem import masonry
	if args.poisson != 'cells':
		raise SystemExit('mpi_compare: --scene wall has Poisson cells (--poisson cells)')
	brick = RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=2e6, cohesion=4e6, frictionAngle=0.6, label='brick')
	O.materials.append(brick)
	O.engines = build.engines(formulation='consistent', failureStress='total', recontact='always', dt=1e-9)
	mortar = RdemJoint(young=5e9, poisson=0.2, tensileStrength=0.3e6, cohesion=0.5e6, frictionAngle=0.6)
	w = masonry.wall(10 * 0.26 - 0.01, 10 * 0.065 - 0.01, 0.12, bond='running', brickMaterial=brick, jointMaterial=mortar)
	for i in w.courses[0] + w.courses[-1]:
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	for i in w.courses[-1]:
		O.bodies[i].state.vel = Vector3(0, 0, -args.rate)
	build.poissonEngine().elements = 'cells'
	build.poissonEngine().build(w.ids)
	# the collider's sweep that rdem.distributed.prepare gives a collider without one (mpy finds ghosts by overlapping
	# boxes), here in both runs: after the first breaks the serial run itself depends on it (doc/mpi.md)
	build.collider().verletDist = 0.1 * min(min(O.bodies[i].shape.extents) for i in w.ids)
	O.dt = 0.5 * build.timeStepper().estimate()
	return w.ids


ids = cube() if args.scene == 'cube' else wall()
O.trackEnergy = args.energy
start = {i: O.bodies[i].state.pos for i in ids}

rank = 0
if args.mpi:
	from yade import mpy
	from yade.rdem import distributed
	mpy.VERBOSE_OUTPUT = False
	perWorker = distributed.prepare(exchange=not args.no_exchange)
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
if args.mpi:
	traffic = mpy.comm.gather(bytesPerStep(), root=0)
	parts = mpy.comm.gather(record([i for i in ids if O.bodies[i] is not None and O.bodies[i].subdomain == rank]), root=0)
else:
	parts = [record(ids)]
if rank == 0:
	blocks = {}
	for p in parts:
		blocks.update(p)
	if len(blocks) != len(ids):
		raise RuntimeError('mpi_compare: %d of %d blocks gathered' % (len(blocks), len(ids)))
	res = dict(input=vars(args), dt=O.dt, steps=args.steps, ranks=len(parts), blocks=blocks, breaks=finalBreaks, history=history, energy=energy)
	if args.mpi:
		res['blocksPerWorker'] = perWorker
		res['bytesPerStep'] = traffic
		print('mpi_compare: per rank, blocks, ghosts and bytes sent per step:', traffic)
	os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
	json.dump(res, open(args.out, 'w'), indent=0)
	print('mpi_compare: %d blocks after %d steps (dt %.3g s), breaks %s, written to %s' % (len(blocks), args.steps, O.dt, finalBreaks, args.out))
