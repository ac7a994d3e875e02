# -*- coding: utf-8 -*-
"""Cost of a step of one running-bond wall serially and on YADE's MPI (yade.mpy) with 1 and 2 workers: µs per
block-step (median and range of several rounds), bytes sent per worker and step (mpy's states and RdemGhostExchange's),
ghosts per worker and memory per rank; with --big, the same for one large wall (default 10^5 blocks) on three processes.

    /usr/bin/python3 scripts/mpi_scaling.py --blocks 4000 --rounds 5 --doc doc/scaling-mpi.md
    /usr/bin/python3 scripts/mpi_scaling.py --big 1e5 --big-steps 20 --doc doc/scaling-mpi.md

The driver runs under plain python3 and starts the runs itself: serially `build-mpi/bin/yade -n -x scripts/mpi_scaling.py
--child ...` (the same binary as the MPI runs, without mpy) and `mpiexec --allow-run-as-root --oversubscribe -n 2|3
build-mpi/bin/yade -n -x scripts/mpi_scaling.py --child --mpi ...`, one thread per process (OMP_NUM_THREADS=1). The
rounds alternate the three configurations, so that the load of the machine falls on all of them alike.

The scene is the bigwall case of scripts/benchmark.py (rdem.masonry.wall, two blocks per brick, courses : bricks per
course = 5 : 4, 250 × 120 × 55 mm bricks, MI1's materials, Poisson cells, softening, total-stress failure, on a fixed
base beam under gravity applied at once, under which a few springs break in the first steps: doc/scaling-mpi.md), split by
rdem.distributed.prepare (coordinate bisection; a wall taller than long is cut between courses). A timed window is a
loop of O.step() on every rank between two barriers (O.step runs mpy's engines: the states' exchange, the ghost
exchange, the collision check; O.run would add up to 40 ms of polling per window), after mpy.mpirun(warm-up), which
splits the scene. Every rank builds the whole scene and mpy then replaces the workers' scenes by the master's (mpy's
default): the peak resident set of a rank holds the whole scene at least once, the resident set after the run only
what the rank keeps. With --master-builds only the master builds it; with --per-rank each rank makes only its own
blocks and those within two bonds of them (rdem.distributed.PerRank, mpy's DISTRIBUTED_INSERT): no rank holds the
whole wall.

Writes OUT/results.json (every round's figures), OUT/scaling-mpi.png and, with --doc, the markdown tables of
doc/scaling-mpi.md between the markers it finds there (the prose around them is kept).
"""
import argparse
import json
import math
import os
from statistics import median
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
parser = argparse.ArgumentParser(prog='python3 scripts/mpi_scaling.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--blocks', type=float, default=4000, help='blocks of the timed wall, about (default 4000: a serial step of a few ms)')
parser.add_argument('--rounds', type=int, default=5, help='rounds of each configuration (default 5)')
parser.add_argument('--steps', type=int, default=200, help='timed steps per round (default 200)')
parser.add_argument('--windows', type=int, default=5, help='timed windows per round (default 5; a round gives the median window)')
parser.add_argument('--warmup', type=int, default=20, help='steps before timing (default 20; the MPI runs split the scene in them)')
parser.add_argument('--ranks', nargs='+', default=['1', '1a', '2', '3'],
                    help="configurations: process counts, 1 serial without mpy, with RdemContactGate as rdem.engines sets it; 1a serial with contact "
                    "detection from the first step (the gate open), as mpy's workers run (doc/mpi.md); default 1 1a 2 3")
parser.add_argument('--big', type=float, default=0, help='instead: one wall of about this many blocks (e.g. 1e5) on --big-ranks processes')
parser.add_argument('--big-steps', type=int, default=20, help='timed steps of the --big wall (default 20)')
parser.add_argument('--big-ranks', nargs='+', default=['3'], help='configurations of the --big wall, as --ranks (default 3)')
parser.add_argument('--yield-when-idle', action='store_true',
                    help="mpiexec --mca mpi_yield_when_idle 1 (a rank waiting in MPI gives its core away instead of polling; Open MPI does so by itself when oversubscribed)")
parser.add_argument('--profile', action='store_true', help="O.timingEnabled in the timed windows: each rank's time per engine and step (slows the step a little)")
parser.add_argument('--target', type=float, nargs=2, default=[1e6, 64], metavar=('BLOCKS', 'CORES'), help='projection: blocks and cores (default 1e6 64)')
parser.add_argument('--latency-us', type=float, default=10.0, help='projection: assumed latency of one MPI message [µs] (default 10: Ethernet class)')
parser.add_argument('--bandwidth', type=float, default=1.25, help='projection: assumed bandwidth per rank [GB/s] (default 1.25: 10 Gb/s)')
parser.add_argument('--kb-per-block', type=float, default=7.7, help='projection: memory per block [kB] (default 7.7: doc/performance.md, serial, 10^3-10^5 blocks)')
parser.add_argument('--launcher', default=os.path.join(ROOT, 'build-mpi', 'bin', 'yade'), help='YADE with MPI and the plugin (default build-mpi/bin/yade)')
parser.add_argument('--out', default=os.path.join(ROOT, 'output', 'mpi-scaling'), help='output directory (default output/mpi-scaling)')
parser.add_argument('--master-builds', action='store_true',
                    help="only the master builds the scene, the workers receive it from mpy's split (default: every rank builds it, as scripts/mpi_compare.py does)")
parser.add_argument('--per-rank', action='store_true',
                    help="each rank makes only its own blocks and those within two bonds of them (rdem.distributed.PerRank, mpy's DISTRIBUTED_INSERT): "
                    "no rank holds the whole wall")
parser.add_argument('--dt', type=float, default=-1, help="O.dt [s] (default -1: RdemTimeStepper's, the minimum over the ranks on mpy)")
parser.add_argument('--tables-only', action='store_true', help="write the tables, figure and projection again from OUT/results.json, without running")
parser.add_argument('--doc', default='', help='markdown file whose generated tables to rewrite (e.g. doc/scaling-mpi.md)')
parser.add_argument('--child', action='store_true', help=argparse.SUPPRESS)
parser.add_argument('--mpi', action='store_true', help=argparse.SUPPRESS)
parser.add_argument('--contacts-always', action='store_true', help=argparse.SUPPRESS)
parser.add_argument('--result', default='', help=argparse.SUPPRESS)
args = parser.parse_args(sys.argv[1:])
if args.master_builds and args.per_rank:
	parser.error('--master-builds and --per-rank: one way of building the scene at a time')
for name in ('rounds', 'steps', 'windows'):
	if getattr(args, name) < 1:
		parser.error('--%s %d: must be >= 1' % (name, getattr(args, name)))
for name in ('blocks', 'latency_us', 'bandwidth', 'kb_per_block'):
	if not getattr(args, name) > 0:
		parser.error('--%s %g: must be > 0' % (name.replace('_', '-'), getattr(args, name)))
if args.warmup < 0 or args.big < 0:
	parser.error('--warmup and --big must be >= 0')
for config in args.ranks + args.big_ranks:
	if config not in ('1', '1a') and not (config.isdigit() and int(config) >= 2):
		parser.error("--ranks/--big-ranks %s: each must be 1, 1a (serial) or a process count >= 2" % config)


def rssMB():
	"""(peak, current) resident set of this process [MB], from /proc/self/status (VmHWM, VmRSS)."""
	out = {}
	with open('/proc/self/status') as f:
		for line in f:
			k, _, v = line.partition(':')
			if k in ('VmHWM', 'VmRSS'):
				out[k] = int(v.split()[0]) / 1024.0
	return out['VmHWM'], out['VmRSS']


# --------------------------------------------------------------------------------------------------- one run (in YADE)
def buildWall(blocks, only=None):
	"""The bigwall case of scripts/benchmark.py (rdem.scenes.runningBondWall, its base beam without a Poisson cell), at the fixed --dt if one is given; with
	``only`` (an rdem.distributed.PerRank), the blocks it chooses."""
	from yade.rdem import scenes
	# the base beam stays on the master (rdem.distributed.prepare(master=)), without a Poisson cell in every run, serial ones
	# too, as doc/scaling-mpi.md's figures were measured (its cell would now run: RdemGhostExchange.masterCells, doc/mpi.md)
	return scenes.runningBondWall(blocks, dt=args.dt if args.dt > 0 else None, only=only, beamCell=False, distributed=args.mpi)


def child():
	from yade import O
	t0 = time.time()
	if args.mpi and args.master_builds:
		from yade import mpy
		mpy.configure()
		if mpy.rank > 0:  # the scene (blocks, engines, RdemBondKeeper's records) arrives with mpy's split; mpy's parallel
			# collision detection needs the module's collider, which rdem.distributed.prepare sets on the ranks that call it
			from yade.rdem import distributed
			mpy.VERBOSE_OUTPUT = False
			mpy.collider = distributed._SceneCollider()
			return worker()
	perRank = None
	if args.mpi and args.per_rank:  # the base beam stays on the master, as with prepare(master=base)
		from yade.rdem import distributed
		perRank = distributed.PerRank(master=lambda layout: [b for u in layout.beams() if layout.units[u].piece == 'base' for b in layout.units[u].blocks])
	layout = buildWall(args.blocks, perRank)
	nBlocks = len(layout['ids'])
	if perRank is not None:
		perRank.assign(layout['ids'])
	if args.contacts_always:
		from yade import rdem
		rdem.contactGate().open = True
	base = layout.pop('base')
	layout['baseBlocks'] = len(base)
	made = len(layout.pop('made'))
	del layout['ids']
	return timedRun(nBlocks, layout, base, setup=time.time() - t0, perRank=perRank, made=made)


def worker():
	"""A worker that did not build the scene (--master-builds)."""
	return timedRun(0, {}, None, setup=0.0)


def timedRun(nBlocks, layout, base, setup, perRank=None, made=0):
	from yade import O
	rank, comm = 0, None
	setupPeak = rssMB()[0]  # the set-up's (before mpy's split)
	if args.mpi:
		from yade import mpy
		from yade.rdem import distributed
		mpy.VERBOSE_OUTPUT = False
		if perRank is not None:
			distributed.prepare(perRank=perRank)
		elif base is not None:
			distributed.prepare(master=base)  # the fixed base beam on the master: a beam as long as the wall would make its
		# worker's subdomain box span the whole wall, and every block of the other worker its ghost
		rank, comm = mpy.rank, mpy.comm
		t1 = time.time()
		mpy.mpirun(args.warmup)  # splits the scene, then steps
		split = time.time() - t1
	else:
		O.run(args.warmup, True)
		split = 0.0
	n = max(1, args.steps // args.windows)
	if args.profile:
		O.timingEnabled = True
		for e in O.engines:
			e.execTime, e.execCount = 0, 0
	walls = []
	cpu0 = time.process_time()
	for w in range(args.windows):
		if comm is not None:
			comm.barrier()
		t = time.perf_counter()
		for i in range(n):
			O.step()
		if comm is not None:
			comm.barrier()
		walls.append(time.perf_counter() - t)
	cpu = (time.process_time() - cpu0) / (n * args.windows)
	peak, current = rssMB()
	mine = dict(rank=rank, peakMB=peak, rssMB=current, setupPeakMB=setupPeak, madeBlocks=made, setupSeconds=setup, cpuMsPerStep=cpu * 1e3, realInteractions=sum(1 for I in O.interactions if I.isReal),
	            interactions=len(O.interactions.all()))
	if args.profile:  # ms per timed step of each engine (execTime is in ns), and how often it ran
		mine['engines'] = [[e.label or type(e).__name__, e.execTime * 1e-6 / (n * args.windows), e.execCount] for e in O.engines if e.execCount]
	if args.mpi:
		sd = O.subD
		own = sum(1 for b in O.bodies if b is not None and not b.isSubdomain and b.subdomain == rank)
		ghosts = sum(1 for b in O.bodies if b is not None and not b.isSubdomain and b.subdomain != rank)
		states = 0
		if rank > 0:  # 13 reals (position, velocity, angular velocity, orientation) per boundary body and neighbouring worker
			states = sum(13 * 8 * len(sd.intersections[k]) for k in sd.intersections[rank] if k not in (0, rank))
		ghostBytes = next((e.bytesSent for e in O.engines if type(e).__name__ == 'RdemGhostExchange'), 0)
		mine.update(ownBlocks=own, ghosts=ghosts, mpyStateBytes=states, ghostExchangeBytes=ghostBytes)
		from yade.rdem import distributed
		breaks = list(distributed.breakCounts())
		ranks = comm.gather(mine, root=0)
	else:
		from yade import rdem
		from yade.rdem import distributed
		breaks = list(distributed.localBreakCounts())  # as rdem.distributed.breakCounts counts on mpy; and the law's counters
		mine['lawBreaks'] = list(rdem.breakCounts())
		ranks = [mine]
	if rank == 0:
		walls.sort()
		stepper = [next((e for e in r.get('engines', []) if e[0] == 'rdemStepper'), None) for r in ranks]
		stepper = [e for e in stepper if e]
		res = dict(blocks=nBlocks, layout=layout, processes=len(ranks), steps=n, windows=args.windows, warmup=args.warmup, dt=O.dt, setupSeconds=setup,
		           splitSeconds=split, perRank=perRank is not None, windowSeconds=walls, usPerBlockStep=walls[len(walls) // 2] / n / nBlocks * 1e6,
		           usPerBlockStepFastest=walls[0] / n / nBlocks * 1e6, breaks=breaks, ranks=ranks)
		if args.profile:  # RdemTimeStepper's new estimates (Lanczos) in the timed steps: their share, and the step without them
			res['stepperRuns'] = max([e[2] for e in stepper] + [0])
			res['stepperMsPerStep'] = max([e[1] for e in stepper] + [0.0])
			res['usPerBlockStepWithoutStepper'] = res['usPerBlockStep'] - res['stepperMsPerStep'] * 1e3 / nBlocks
		with open(args.result, 'w') as f:
			json.dump(res, f, indent=1)
		print('mpi_scaling: %d processes, %d blocks, %.3f µs per block-step (median of %d windows of %d steps)' % (len(ranks), nBlocks, res['usPerBlockStep'], len(walls), n))


# ------------------------------------------------------------------------------------------------- driver (python3)
def launch(config, blocks, steps, windows, warmup, tag):
	processes = int(config.rstrip('a'))
	os.makedirs(args.out, exist_ok=True)
	result = os.path.join(args.out, 'run-%s-%s.json' % (tag, config))
	if os.path.exists(result):
		os.remove(result)
	cmd = [args.launcher, '-n', '-x', os.path.abspath(__file__), '--child', '--dt', repr(args.dt)] + (['--profile'] if args.profile else []) + [ '--blocks', str(blocks), '--steps', str(steps), '--windows', str(windows), '--warmup',
	       str(warmup), '--result', result] + (['--contacts-always'] if config.endswith('a') else [])
	env = dict(os.environ, OMP_NUM_THREADS='1')
	if processes > 1:
		cmd = ['mpiexec', '--allow-run-as-root', '--oversubscribe'] + (['--mca', 'mpi_yield_when_idle', '1'] if args.yield_when_idle else []) + ['-n', str(processes)
		                                                                                                                                   ] + cmd + ['--mpi'] + (['--master-builds'] if args.master_builds else []) + (['--per-rank'] if args.per_rank else [])
		env = {k: v for k, v in env.items() if not k.startswith(('OMPI_', 'PMIX_'))}
	t = time.time()
	r = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
	if r.returncode != 0 or not os.path.exists(result):
		raise SystemExit('mpi_scaling: %s failed (%d):\n%s' % (' '.join(cmd), r.returncode, r.stdout[-4000:]))
	with open(result) as f:
		res = json.load(f)
	res['command'] = ' '.join(cmd)
	res['config'] = config
	res['masterBuilds'] = bool(args.master_builds and processes > 1)
	res['perRank'] = bool(args.per_rank and processes > 1)
	res['seconds'] = time.time() - t
	return res


def label(config):
	p = int(config.rstrip('a'))
	if p == 1:
		return 'serial, contacts always' if config.endswith('a') else 'serial (contact gate)'
	return 'mpy, %d worker%s' % (p - 1, '' if p == 2 else 's')


def summarize(runs):
	"""Per process count: median and range over rounds, and the per-rank figures of the first round."""
	out = []
	for cf in args.ranks:
		rs = [r for r in runs if r['config'] == cf]
		p = rs[0]['processes']
		us = [r['usPerBlockStep'] for r in rs]
		out.append(dict(config=cf, processes=p, label=label(cf), rounds=len(rs), blocks=rs[0]['blocks'], usMedian=median(us), usMin=min(us), usMax=max(us), dt=rs[0]['dt'],
		                ranks=rs[0]['ranks'], peakMB=[median([r['ranks'][k]['peakMB'] for r in rs]) for k in range(p)],
		                rssMB=[median([r['ranks'][k]['rssMB'] for r in rs]) for k in range(p)],
		                cpuMs=[median([r['ranks'][k]['cpuMsPerStep'] for r in rs]) for k in range(p)], setupSeconds=median([r['setupSeconds'] for r in rs]),
		                splitSeconds=median([r['splitSeconds'] for r in rs]), breaks=rs[-1]['breaks']))
	return out


def tables(summary):
	serial = next((s for s in summary if s['config'] == '1'), None)
	lines = ['| run | processes | blocks | µs per block-step, median (range) of %d rounds | speed-up (medians) | ms per step | CPU ms per step of the busiest rank |' %
	         summary[0]['rounds'], '|---|---|---|---|---|---|---|']
	for s in summary:
		sp = '%.2f×' % (serial['usMedian'] / s['usMedian']) if serial else '–'
		lines.append('| %s | %d | %d | %.3f (%.3f – %.3f) | %s | %.2f | %.1f |' % (s['label'], s['processes'], s['blocks'], s['usMedian'], s['usMin'], s['usMax'], sp,
		                                                                           s['usMedian'] * s['blocks'] * 1e-3, max(s['cpuMs'])))
	lines += ['', '| run | rank | own blocks | ghosts | interactions, real / all | mpy states [bytes/step] | RdemGhostExchange [bytes/step] | peak RSS [MB] | RSS after the run [MB] |',
	          '|---|---|---|---|---|---|---|---|---|']
	for s in summary:
		for k, r in enumerate(s['ranks']):
			lines.append('| %s | %d | %s | %s | %s / %s | %s | %s | %.0f | %.0f |' % (s['label'], r['rank'], r.get('ownBlocks', s['blocks']), r.get('ghosts', 0),
			                                                                r['realInteractions'], r['interactions'],
			                                                                r.get('mpyStateBytes', 0), r.get('ghostExchangeBytes', 0), s['peakMB'][k], s['rssMB'][k]))
	return '\n'.join(lines)


def plot(summary, path):
	import matplotlib
	matplotlib.use('Agg')
	import matplotlib.pyplot as plt
	fig, ax = plt.subplots(figsize=(6, 4))
	x = list(range(len(summary)))
	y = [s['usMedian'] for s in summary]
	err = [[s['usMedian'] - s['usMin'] for s in summary], [s['usMax'] - s['usMedian'] for s in summary]]
	ax.errorbar(x, y, yerr=err, fmt='o-', capsize=4, label='wall clock (median, range of rounds)')
	ax.plot(x, [max(s['cpuMs']) * 1e3 / s['blocks'] for s in summary], 's--', label='CPU time of the busiest rank')
	ax.set_xticks(x)
	ax.set_xticklabels([s['label'].replace(', ', ',\n').replace(' (', '\n(') for s in summary], fontsize=8)
	ax.set_ylabel('µs per block-step')
	ax.legend(fontsize=8)
	ax.set_title('%d-block running-bond wall, 2-core machine, 1 thread per process' % summary[0]['blocks'], fontsize=9)
	ax.set_ylim(bottom=0)
	fig.tight_layout()
	fig.savefig(path, dpi=120)


def writeDoc(path, marker, text):
	"""Replace the text between <!-- marker --> and <!-- /marker --> in path (append both if absent)."""
	begin, end = '<!-- %s -->' % marker, '<!-- /%s -->' % marker
	doc = open(path).read() if os.path.exists(path) else ''
	if begin in doc and end in doc:
		doc = doc[:doc.index(begin) + len(begin)] + '\n' + text + '\n' + doc[doc.index(end):]
	else:
		doc += '\n%s\n%s\n%s\n' % (begin, text, end)
	with open(path, 'w') as f:
		f.write(doc)


def projection(timed, big):
	"""Per-step time and memory of a wall of args.target[0] blocks on args.target[1] cores (one master, the others
	workers), from the measured figures (see doc/scaling-mpi.md for the model)."""
	N, cores = args.target
	P = int(cores) - 1
	# CPU time, not wall-clock time: on this loaded two-core machine a rank's wall-clock step is mostly waiting for a core
	S = {s['config']: s for s in timed['summary']}
	ref = S['1a'] if '1a' in S else S['1']  # the serial run as mpy's workers run it: contacts detected from the first step
	c = ref['cpuMs'][0] * 1e3 / ref['blocks']  # serial CPU µs per block-step
	w = next(r for r in S['3']['ranks'] if r['rank'] == 1)
	# mpy's own cost per worker and step: a worker's CPU time less its blocks' and ghosts' serial cost (median over rounds;
	# an upper bound: it includes the polling of a rank waiting in MPI)
	fixed = median([max(x['cpuMsPerStep'] - c * 1e-3 * (x['ownBlocks'] + x['ghosts']) for x in r['ranks'] if x['rank'] > 0)
	                for r in timed['runs'] if r['config'] == '3'])
	overhead = max(0.0, fixed)
	perBoundary = (w['mpyStateBytes'] + w['ghostExchangeBytes']) / (w['mpyStateBytes'] / 104.0)
	n = N / P
	bw, bh = 0.13, 0.065  # a block's pitch in the wall's plane [m] (half a 250 mm brick + joint; a 55 mm course + joint)
	side = math.sqrt(n * bw * bh)  # a square patch of n blocks
	boundary = 2 * (side / bh + side / bw)  # one block per course on each vertical cut, one per block on each bed cut
	neighbours = 8  # 4 sides, 4 corners
	messages = 3 * neighbours  # mpy's states, RdemGhostExchange's two messages
	collectives = 2 * math.ceil(math.log2(P + 1))  # mpy's barrier and its collision vote each step, as log2 rounds
	compute = (n + boundary) * c * 1e-3  # ms: own blocks and the ghosts' duplicated bonds (upper bound: a ghost costs a block)
	comm = (messages + collectives) * args.latency_us * 1e-3 + boundary * perBoundary / (args.bandwidth * 1e9) * 1e3
	step = compute + comm + overhead
	serial = N * c * 1e-3
	kb = args.kb_per_block
	bigSerial = next((r for r in (big or {}).get('runs', []) if r['config'] == ref['config']), None)
	if bigSerial:  # measured: the marginal peak memory per block between the timed wall and the big one, run serially
		kb = (bigSerial['ranks'][0]['peakMB'] - ref['peakMB'][0]) * 1024 / (bigSerial['blocks'] - ref['blocks'])
	base = ref['peakMB'][0] - ref['blocks'] * kb / 1024
	return dict(blocks=N, cores=cores, workers=P, blocksPerWorker=n, boundaryPerWorker=boundary, bytesPerBoundaryBlock=perBoundary, measuredBoundary=w['mpyStateBytes'] / 104,
	            bytesPerWorkerStep=boundary * perBoundary, usPerBlockStepSerial=c, computeMs=compute, commMs=comm, overheadMs=overhead, stepMs=step, serialStepMs=serial,
	            speedup=serial / step, efficiency=serial / step / P, baseMB=base, kbPerBlock=kb, kbMeasured=bigSerial is not None,
	            memoryPerWorkerMB=base + (n + boundary) * kb / 1024, memoryWholeSceneMB=base + N * kb / 1024, latencyUs=args.latency_us, bandwidthGBs=args.bandwidth)


def projectionTable(p):
	rows = [('workers (one more core: the master)', '%d' % p['workers']), ('blocks per worker', '%.0f' % p['blocksPerWorker']),
	        ('boundary blocks sent per worker and step (surface-to-volume, a square patch of the wall)', '%.0f' % p['boundaryPerWorker']),
	        ('bytes per boundary block (measured: mpy 104, RdemGhostExchange 80)', '%.0f' % p['bytesPerBoundaryBlock']),
	        ('bytes sent per worker and step', '%.0f' % p['bytesPerWorkerStep']),
	        ('compute per step: own blocks + ghosts at the serial run\'s %.2f µs of CPU per block-step [ms]' % p['usPerBlockStepSerial'], '%.1f' % p['computeMs']),
	        ('communication per step at %.0f µs per message, %.2f GB/s [ms]' % (p['latencyUs'], p['bandwidthGBs']), '%.2f' % p['commMs']),
	        ("mpy's own cost per worker and step (measured: a worker's CPU time less its blocks' and ghosts' serial cost) [ms]", '%.1f' % p['overheadMs']),
	        ('step [ms]', '%.1f' % p['stepMs']),
	        ('serial step of the same wall [ms]', '%.0f' % p['serialStepMs']), ('speed-up, parallel efficiency', '%.0f×, %.0f %%' % (p['speedup'], 100 * p['efficiency'])),
	        ('memory per block: %s [kB]' % ('measured, the serial 10^5 wall\'s peak less the 4000-block wall\'s over the blocks between' if p['kbMeasured'] else
	                                          'assumed (--kb-per-block)'), '%.1f' % p['kbPerBlock']), ('a rank\'s base (the 4000-block wall\'s peak less its blocks) [MB]', '%.0f' % p['baseMB']),
	        ('peak memory per worker with per-rank insertion [MB]', '%.0f' % p['memoryPerWorkerMB']),
	        ("peak memory per rank when every rank holds the whole scene once (mpy's default split) [MB]", '%.0f' % p['memoryWholeSceneMB'])]
	return '\n'.join(['| %.0e blocks on %d cores | |' % (p['blocks'], p['cores']), '|---|---|'] + ['| %s | %s |' % r for r in rows])


def built(r):
	"""How a run's scene was made, for the tables."""
	if r['processes'] == 1:
		return ''
	return ', made per rank' if r.get('perRank') else ', built on the master' if r.get('masterBuilds') else ', built on every rank'


def bigTable(runs):
	lines = ['| run | blocks | steps timed | µs per block-step | of which RdemTimeStepper (its runs) | s per step | set-up [s] | split + warm-up [s] | rank | own blocks | ghosts | '
	         'bytes sent per step (mpy + RdemGhostExchange) | CPU ms per step | peak RSS [MB] | RSS after [MB] |', '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|']
	for r in runs:
		for k, x in enumerate(r['ranks']):
			st = '%.3f (%d)' % (r['stepperMsPerStep'] * 1e3 / r['blocks'], r['stepperRuns']) if 'stepperRuns' in r else '–'
			head = ('%s | %d | %d | %.3f | %s | %.3f | %.1f | %.1f' % (label(r['config']) + built(r), r['blocks'], r['steps'] * r['windows'], r['usPerBlockStep'], st,
			                                                           r['usPerBlockStep'] * r['blocks'] * 1e-6, r['setupSeconds'], r['splitSeconds'])) if k == 0 else ' | | | | | | |'
			lines.append('| %s | %d | %s | %s | %s + %s | %.0f | %.0f | %.0f |' % (head, x['rank'], x.get('ownBlocks', r['blocks']), x.get('ghosts', 0), x.get('mpyStateBytes', 0),
		                                                                       x.get('ghostExchangeBytes', 0), x['cpuMsPerStep'], x['peakMB'],
			                                                              x['rssMB']))
	return '\n'.join(lines)


def writeTimed(summary):
	"""The timed runs' figure (in --out, and beside --doc) and tables (into --doc); returns the tables' text."""
	plot(summary, os.path.join(args.out, 'scaling-mpi.png'))
	if args.doc:
		plot(summary, os.path.join(os.path.dirname(os.path.abspath(args.doc)), 'figures', 'scaling-mpi.png'))
	text = tables(summary)
	if args.doc:
		writeDoc(args.doc, 'mpi_scaling tables', text)
	return text


def driver():
	os.makedirs(args.out, exist_ok=True)
	resultsPath = os.path.join(args.out, 'results.json')
	results = json.load(open(resultsPath)) if os.path.exists(resultsPath) else {}
	if args.tables_only and 'big' in results:
		text = bigTable(results['big']['runs'])
		if args.doc:
			writeDoc(args.doc, 'mpi_scaling big', text)
	if args.tables_only:
		summary = summarize(results['timed']['runs'])
		results['timed']['summary'] = summary
		text = writeTimed(summary)
	elif args.big:
		runs = []
		for p in args.big_ranks:
			print('mpi_scaling: the %.0f-block wall, %s ...' % (args.big, label(p)), flush=True)
			r = launch(p, args.big, args.big_steps, 2, args.warmup, 'big')
			print('mpi_scaling:   %.3f µs per block-step, peak RSS per rank %s MB (%.0f s)' % (r['usPerBlockStep'], [round(x['peakMB']) for x in r['ranks']], r['seconds']),
			      flush=True)
			runs.append(r)
		key = lambda r: (r['config'], r.get('masterBuilds', False), r.get('perRank', False))
		new = {key(r) for r in runs}
		old = [r for r in results.get('big', {}).get('runs', []) if key(r) not in new and r['blocks'] == runs[0]['blocks']]
		runs = old + runs  # other configurations or ways of building the same wall, measured before
		results['big'] = dict(input=vars(args), runs=runs)
		text = bigTable(runs)
		if args.doc:
			writeDoc(args.doc, 'mpi_scaling big', text)
	else:
		runs = []
		for k in range(args.rounds):
			for p in args.ranks:
				r = launch(p, args.blocks, args.steps, args.windows, args.warmup, 'r%d' % k)
				runs.append(r)
				print('mpi_scaling: round %d/%d, %s: %.3f µs per block-step (%.0f s)' % (k + 1, args.rounds, label(p), r['usPerBlockStep'], r['seconds']), flush=True)
		summary = summarize(runs)
		results['timed'] = dict(input=vars(args), runs=runs, summary=summary)
		text = writeTimed(summary)
	print(text)
	if 'timed' in results:
		results['timed']['summary'] = summarize(results['timed']['runs'])
		results['projection'] = projection(results['timed'], results.get('big'))
		text = projectionTable(results['projection'])
		print(text)
		if args.doc:
			writeDoc(args.doc, 'mpi_scaling projection', text)
	with open(resultsPath, 'w') as f:
		json.dump(results, f, indent=1)
	print('mpi_scaling: written %s' % resultsPath)


if args.child:
	child()
else:
	driver()
