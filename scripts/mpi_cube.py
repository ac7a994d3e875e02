# -*- coding: utf-8 -*-
"""The paper's compression cube (rdem.scenes.CompressionTest) serially or on YADE's MPI (yade.mpy): block positions after
a number of steps, for the comparison of doc/mpi.md.

    build-mpi/bin/yade -n -x scripts/mpi_cube.py --poisson cells --steps 200 --out output/mpi/serial.json
    mpiexec --allow-run-as-root --oversubscribe -n 3 build-mpi/bin/yade -n -x scripts/mpi_cube.py --poisson cells --steps 200 --mpi --out output/mpi/mpi.json
    /usr/bin/python3 scripts/mpi_cube.py --compare output/mpi/serial.json output/mpi/mpi.json

Needs the plugin built against YADE with MPI (tools/setup.sh --mpi). The serial run uses the same binary without mpy.
Writes a JSON file: input, steps, O.dt, and per block id its position and orientation (exact: float.hex) and the
displacement from the start. --compare prints the largest position difference of two such files, absolute and over the
largest displacement, and whether they are identical bit for bit (exit status 1 if not).
"""
import argparse
import json
import math
import os
import sys

parser = argparse.ArgumentParser(prog='yade scripts/mpi_cube.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--blocks', type=int, default=10, help='blocks per edge of the cube (default 10, as in the paper)')
parser.add_argument('--poisson', choices=['off', 'hex8', 'cells'], default='cells',
                    help="Poisson effect: off (springs only), hex8 (the paper's elements), cells (consistent formulation; default)")
parser.add_argument('--steps', type=int, default=200, help='time steps (default 200)')
parser.add_argument('--rate', type=float, default=0.05, help='loading rate [m/s] (default 0.05: a visible Poisson effect in 200 steps)')
parser.add_argument('--contacts', choices=['gate', 'always'], default='gate',
                    help="contact detection: gate (RdemContactGate keeps the collider off until a spring breaks; default) or always (the "
                    "collider from the first step, as mpy does on its workers: its split runs the collider whatever the gate says)")
parser.add_argument('--mpi', action='store_true', help='run on yade.mpy (under mpiexec -n 3 or more)')
parser.add_argument('--no-exchange', action='store_true', help='RdemGhostExchange off (wrong at the subdomain boundary: for the test)')
parser.add_argument('--out', default='output/mpi/cube.json', help='result file (default output/mpi/cube.json)')
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
	return same


if args.compare:
	sys.exit(0 if compare(*args.compare) else 1)

from yade import O
from yade.rdem import scenes, build

formulation = {'off': None, 'hex8': 'paper', 'cells': 'consistent'}[args.poisson]
test = scenes.CompressionTest(blocksPerEdge=args.blocks, formulation=formulation, rate=args.rate)
if args.poisson == 'cells':
	build.poissonEngine().elements = 'cells'
	build.poissonEngine().build(test.ids)
if args.contacts == 'always':
	build.contactGate().open = True
start = {i: O.bodies[i].state.pos for i in test.ids}

rank = 0
if args.mpi:
	from yade import mpy
	from yade.rdem import distributed
	mpy.VERBOSE_OUTPUT = False
	perWorker = distributed.prepare(exchange=not args.no_exchange)
	rank = mpy.rank
	mpy.mpirun(args.steps)
else:
	O.run(args.steps, True)


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


if args.mpi:
	own = record([i for i in test.ids if O.bodies[i] is not None and O.bodies[i].subdomain == rank])
	parts = mpy.comm.gather(own, root=0)
else:
	parts = [record(test.ids)]
if rank == 0:
	blocks = {}
	for p in parts:
		blocks.update(p)
	if len(blocks) != len(test.ids):
		raise RuntimeError('mpi_cube: %d of %d blocks gathered' % (len(blocks), len(test.ids)))
	res = dict(input=vars(args), dt=O.dt, steps=args.steps, ranks=len(parts), blocks=blocks)
	if args.mpi:
		res['blocksPerWorker'] = perWorker
	os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
	json.dump(res, open(args.out, 'w'), indent=0)
	print('mpi_cube: %d blocks after %d steps (dt %.3g s) written to %s' % (len(blocks), args.steps, O.dt, args.out))
