# -*- coding: utf-8 -*-
"""What accuracy costs in time: the compression specimen under every knob that trades accuracy for speed.

Problem
    The paper's compression test (rdem.scenes.CompressionTest: cube between 4 cm platens, f_t = 4.5 MPa, loaded at
    10 mm/s so that every point fits in minutes) is run to its first broken spring for one knob changed at a time from
    a base setting: blocks per edge, springs per face, Poisson formulation, corotation, time step as a fraction of
    RdemTimeStepper's estimate. For every point: errors of the apparent ν and E (paper §5.3.1, centroid strains,
    averaged between 30 % and 80 % of the displacement at the first crack) against the input; the mean stress at the
    first crack and its change against the finest point of the same knob; steps, wall time of the run, µs per
    block-step and peak memory. Each point runs in a fresh YADE process with one thread.

Expected result
    doc/accuracy-vs-cost.md (table, recommendation) and doc/figures/accuracy-vs-cost.png (Pareto plot: error against
    wall time, one curve per knob).

How to run (about 15 minutes on one core; --quick: 3 minutes, coarse sweeps)
    build/bin/yade -n scripts/accuracy_vs_cost.py [--quick] [--out doc/accuracy-vs-cost.md]
"""
import argparse
import json
import os
import resource
import sys
import time
from yade import rdem
import yade.rdem.batch

parser = argparse.ArgumentParser(prog='yade scripts/accuracy_vs_cost.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--quick', action='store_true', help='coarse sweeps (about 3 minutes)')
parser.add_argument('--out', default='doc/accuracy-vs-cost.md', help='markdown report to write (default doc/accuracy-vs-cost.md)')
parser.add_argument('--figure', default='doc/figures/accuracy-vs-cost.png', help='Pareto plot to write')
parser.add_argument('--replot', default=None, help='re-make the report and plot from the .json of an earlier run, without running')
parser.add_argument('--child', default=None, help=argparse.SUPPRESS)  # internal: run one point in this process
cli = parser.parse_args(sys.argv[1:])

E, NU, RATE, MAX_DISP = 30e9, 0.2, 10e-3, 0.4e-3  # input modulus [Pa] and ratio, loading rate [m/s], give-up displacement [m]
BASE = dict(blocks=10, springs=2, formulation='consistent', corotational=False, safety=0.8)


def runPoint(point):
	"""One point in this process: run to the first broken spring (or MAX_DISP); returns its figures."""
	from yade import O
	from yade import rdem
	from yade.rdem.scenes import CompressionTest
	test = CompressionTest(blocksPerEdge=point['blocks'], segmentsPerEdge=point['springs'], poisson=NU, young=E, formulation=point['formulation'],
	                       corotational=point['corotational'], rate=RATE, dt=None)
	rdem.timeStepper().safety = point['safety']
	hist = []  # (displacement, nu, E)
	crack = {}

	def check():
		"""Record the apparent constants every 20 steps; True once the first spring broke or the plate went MAX_DISP."""
		d = test.displacement()
		if O.iter % 20 == 0 and d > 0:
			hist.append((d, test.apparentPoisson(), test.apparentYoung()))
		nT, nS = rdem.breakCounts()
		if nT + nS > 0 and not crack:
			crack.update(stress=test.stress(), disp=d, time=O.time)
		return bool(crack) or d > MAX_DISP

	# Stepped with O.step() and timed with perf_counter: O.run() + O.wait() returns only at the next 40 ms poll of
	# Omega's wait loop, up to 8 % of a short point (doc/changelog.md, 2026-11-22, "How to read timings on this machine").
	t0 = time.perf_counter()
	while True:
		for i in range(5):
			O.step()
		if check():
			break
	wall = time.perf_counter() - t0
	dRef = crack.get('disp', MAX_DISP)
	window = [h for h in hist if 0.3 * dRef <= h[0] <= 0.8 * dRef]
	nuApp = sum(h[1] for h in window) / len(window) if window else float('nan')
	eApp = sum(h[2] for h in window) / len(window) if window else float('nan')
	return dict(point=point,
	            bodies=len(O.bodies),
	            elements=test.nElements,
	            dt=O.dt,
	            steps=O.iter,
	            wall=wall,
	            usPerBlockStep=wall / O.iter / len(O.bodies) * 1e6,
	            memoryMB=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
	            nuError=nuApp / NU - 1,
	            eError=eApp / E - 1,
	            crackStressMPa=crack['stress'] * 1e-6 if crack else None,
	            crackDispMm=crack['disp'] * 1e3 if crack else None)


if cli.child is not None:
	rdem.batch.reportChild(runPoint(json.loads(cli.child)))
	sys.exit(0)

# Sweeps: knob -> list of (label, changes to BASE); the first point of each list is its finest (reference) setting.
if cli.quick:
	SWEEPS = {
	    'blocks per edge': [('%d' % n, dict(blocks=n)) for n in (10, 6, 4)],
	    'springs per face': [('%d×%d' % (n, n), dict(springs=n)) for n in (3, 2, 1)],
	    'Poisson formulation': [(f, dict(formulation=f)) for f in ('consistent', 'paper', 'off')],
	}
else:
	SWEEPS = {
	    'blocks per edge': [('%d' % n, dict(blocks=n)) for n in (20, 14, 10, 8, 6, 4)],
	    'blocks per edge, paper formulation': [('%d' % n, dict(blocks=n, formulation='paper')) for n in (20, 14, 10, 8, 6, 4)],
	    'springs per face': [('%d×%d' % (n, n), dict(springs=n)) for n in (4, 3, 2, 1)],
	    'Poisson formulation': [(f, dict(formulation=f)) for f in ('consistent', 'paper', 'off')],
	    'corotational': [('on', dict(corotational=True)), ('off', dict(corotational=False))],
	    'time step / estimate': [('%.2f' % s, dict(safety=s)) for s in (0.25, 0.5, 0.8, 1.0)],
	}

rows = []
start = time.time()
cache = {}
nPoints = sum(len(v) for v in SWEEPS.values())
k = 0
if cli.replot:
	rows = json.load(open(cli.replot))
	SWEEPS = {r['knob']: None for r in rows}
	cache = {json.dumps(r['point'], sort_keys=True): r for r in rows}
for knob, points in ([] if cli.replot else SWEEPS.items()):
	for label, change in points:
		k += 1
		point = dict(BASE, **change)
		key = json.dumps(point, sort_keys=True)
		if key not in cache:
			print('accuracy %d/%d: %s = %s ...' % (k, nPoints, knob, label), flush=True)
			cache[key] = rdem.batch.runChild(point, threads=1)
			r = cache[key]
			print('    nu %+.2f %%, E %+.2f %%, crack %s MPa, %.1f s (%.0f s so far)' %
			      (100 * r['nuError'], 100 * r['eError'], '%.2f' % r['crackStressMPa'] if r['crackStressMPa'] else '-', r['wall'], time.time() - start),
			      flush=True)
		rows.append(dict(cache[key], knob=knob, label=label))

# Crack-stress change against one reference for all points: the finest setting of all (the first point of the first
# knob), so that no knob's own reference counts as exact.
ref = rows[0]['crackStressMPa']
for r in rows:
	r['crackChange'] = (r['crackStressMPa'] / ref - 1) if (ref and r['crackStressMPa']) else None


def worst(r):
	"""The point's error for the recommendation: the largest of |ν error|, |E error| and |crack-stress change|."""
	errs = [abs(r['nuError']), abs(r['eError'])] + ([abs(r['crackChange'])] if r['crackChange'] is not None else [1.0])
	return max(errs)


import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
fig, ax = plt.subplots(figsize=(7, 4.5))
for knob in SWEEPS:
	pts = sorted([r for r in rows if r['knob'] == knob], key=lambda r: r['wall'])
	ax.plot([r['wall'] for r in pts], [100 * max(worst(r), 1e-4) for r in pts], 'o-', label=knob)
	for r in pts:
		ax.annotate(r['label'], (r['wall'], 100 * max(worst(r), 1e-4)), fontsize=7, xytext=(3, 3), textcoords='offset points')
ax.set_xscale('log')
ax.set_yscale('log')
ax.set_xlabel('wall time of the run to the first crack [s] (one core)')
ax.set_ylabel('worst of |ν error|, |E error|, |crack-stress change| [%]')
ax.grid(True, which='both', alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
os.makedirs(os.path.dirname(cli.figure), exist_ok=True)
fig.savefig(cli.figure, dpi=120)

pct = lambda x: '%+.2f %%' % (100 * x) if x is not None else '–'
lines = [
    '# What accuracy costs in time', '',
    'Made by `build/bin/yade -n scripts/accuracy_vs_cost.py %s` (%.0f s, %s, one thread per point, %d cores, load average %.2f at the end). '
    'Compression specimen of rdem.scenes.CompressionTest, E = 30 GPa, ν = 0.2, f_t = 4.5 MPa, loaded at 10 mm/s to the first broken spring; '
    'base setting: %s. Errors of the apparent ν and E against the input; crack change: mean stress at the first broken spring against the '
    'finest point of all (the first row).' % (' '.join(sys.argv[1:]), time.time() - start, time.strftime('%Y-%m-%d'), os.cpu_count(), os.getloadavg()[0],
                                                 ', '.join('%s = %s' % kv for kv in BASE.items())), '',
    '![Pareto plot](figures/%s)' % os.path.basename(cli.figure), '',
    '| knob | value | blocks | Δt [µs] | steps | wall [s] | µs per block-step | memory [MB] | ν error | E error | first crack [MPa] | crack change |',
    '|---|---|---|---|---|---|---|---|---|---|---|---|'
]
for r in rows:
	lines.append('| %s | %s | %d | %.2f | %d | %.1f | %.3f | %.0f | %s | %s | %s | %s |' %
	             (r['knob'], r['label'], r['bodies'], r['dt'] * 1e6, r['steps'], r['wall'], r['usPerBlockStep'], r['memoryMB'], pct(r['nuError']), pct(
	                 r['eError']), '%.2f' % r['crackStressMPa'] if r['crackStressMPa'] else 'none', pct(r['crackChange'])))
lines += [
    '', '## Cheapest setting for a target accuracy', '',
    'Worst of |ν error|, |E error| and |crack change| (a point without a crack counts as 100 %). The first-crack stress '
    'is the most sensitive figure: it moves by several per cent with the time step alone, so the targets below are '
    'met by single runs and should be read with that scatter in mind.', '', '| target | cheapest point | wall [s] | worst error |', '|---|---|---|---|'
]
for target in (0.01, 0.05, 0.10):
	ok = [r for r in rows if worst(r) <= target]
	if ok:
		best = min(ok, key=lambda r: r['wall'])
		lines.append('| %d %% | %s = %s | %.1f | %.2f %% |' % (round(100 * target), best['knob'], best['label'], best['wall'], 100 * worst(best)))
	else:
		lines.append('| %d %% | none of the points | | |' % round(100 * target))
with open(cli.out, 'w') as f:
	f.write('\n'.join(lines) + '\n')
with open(os.path.splitext(cli.out)[0] + '.json', 'w') as f:
	json.dump(rows, f, indent=1)
print('accuracy_vs_cost: %d points in %.0f s; report in %s, plot in %s' % (len(cache), time.time() - start, cli.out, cli.figure))
sys.exit(0)
