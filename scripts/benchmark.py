# -*- coding: utf-8 -*-
"""Steady-state speed of the refined DEM: the paper's scene, each effect alone, YADE's CpmMat as a reference, scaling.

Problem
    How many steps per second, and how many microseconds per block and step, does a scene cost, and what does each
    effect (springs, failure, contact detection, Poisson elements, corotation, energy tracking) add? Every case runs in
    a fresh YADE process (``build/bin/yade -jN``), builds its scene, runs ``--warmup`` steps, then times three windows
    of ``--steps``/3 steps of ``O.run(n, True)`` (no Python in the loop) and reports the fastest. The scenes are loaded as the paper's compression test
    (1 mm/s; Δt = 2e-6 s, or 0.8 of RdemTimeStepper's estimate for the other cube sizes) and no spring breaks in the
    timed window (column "breaks").

Cases
    paper       the paper's §5 scene: 1200 blocks, 3260 bonds (2×2 springs), 891 Poisson elements, with failure and
                the contact gate (rdem.scenes.CompressionTest defaults), 1 and 2 threads;
    cpm         YADE's concrete model on the same grid: 10×10×12 CpmMat spheres of radius 1 cm, bonded to their face
                neighbours (interactionDetectionFactor 1.2), bottom layer fixed, top layer at 1 mm/s, collider on,
                O.dt = 0.8 PWaveTimeStep: what a YADE user runs today for concrete, 1 and 2 threads;
    effects     the paper's geometry with one more effect at a time (see EFFECTS);
    scaling     springs + failure + contact gate + Poisson on cubes of 10³, 22³ and 46³ blocks (1.0e3 … 9.7e4), one
                thread, with the memory per block (peak resident set after building, over the block count).

Expected result
    Figures of this machine in doc/benchmark.md; doc/performance.md discusses them and the profile.

How to run (about 4 minutes; --quick: 1 minute, no 46³ cube)
    build/bin/yade -n scripts/benchmark.py [--cases paper cpm effects scaling] [--quick] [--out doc/benchmark.md]
"""
import argparse
import json
import os
import resource
import sys
import time
import rdem.batch

parser = argparse.ArgumentParser(prog='yade scripts/benchmark.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--cases', nargs='+', default=['paper', 'cpm', 'effects', 'scaling'], help='cases to run (default: all)')
parser.add_argument('--steps', type=int, default=6000, help='timed steps per case, in three windows (default 6000; fewer for big cubes)')
parser.add_argument('--warmup', type=int, default=300, help='steps before timing (default 300)')
parser.add_argument('--quick', action='store_true', help='fewer steps, no 46³ cube')
parser.add_argument('--out', default='doc/benchmark.md', help='markdown table to write (default doc/benchmark.md)')
parser.add_argument('--child', default=None, help=argparse.SUPPRESS)  # internal: run one case in this process
opts = parser.parse_args(sys.argv[1:])


# Effects added one at a time to the paper's geometry: (label, CompressionTest / engine options).
EFFECTS = [
    ('springs only', dict(tensileStrength=float('inf'), formulation='off')),
    ('+ failure', dict(formulation='off')),
    ('+ failure, contact detection always on', dict(formulation='off', recontact='always')),
    ('+ Poisson (paper)', dict(formulation='paper')),
    ('+ Poisson (consistent)', dict(formulation='consistent')),
    ('+ Poisson (paper), corotational', dict(formulation='paper', corotational=True)),
    ('+ Poisson (paper), energy tracking', dict(formulation='paper', trackEnergy=True)),
]


def peakMemoryMB():
	return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def timed(nBodies, steps, warmup, windows=3):
	"""Run `warmup` steps, then `windows` timed windows of steps/windows each; the fastest window counts (the others
	include whatever else the machine did meanwhile)."""
	from yade import O
	O.run(warmup, True)
	n = max(1, steps // windows)
	walls = []
	for w in range(windows):
		t0 = time.time()
		O.run(n, True)
		walls.append(time.time() - t0)
	wall = min(walls)
	return dict(steps=n, windows=windows, wall=wall, wallSpread=max(walls) / wall - 1, stepsPerSecond=n / wall, usPerBodyStep=wall / n / nBodies * 1e6)


def runRdem(spec):
	"""One refined-DEM case in this process; returns its figures."""
	from yade import O
	import rdem.build
	from rdem.scenes import CompressionTest
	options = dict(spec.get('options', {}))
	recontact = options.pop('recontact', None)
	trackEnergy = options.pop('trackEnergy', False)
	mem0 = peakMemoryMB()
	t0 = time.time()
	test = CompressionTest(blocksPerEdge=spec.get('blocks', 10), **options)
	if recontact == 'always':
		rdem.build.contactGate().open = True
	O.trackEnergy = trackEnergy
	setup = time.time() - t0
	n = len(O.bodies)
	out = dict(bodies=n, bonds=test.nBonds, elements=test.nElements, setupSeconds=setup, memoryPerBodyKB=(peakMemoryMB() - mem0) * 1024 / n)
	out.update(timed(n, spec['steps'], spec['warmup']))
	out['breaks'] = int(rdem.build.law().tensionBreaks + rdem.build.law().shearBreaks)
	return out


def runCpm(spec):
	"""YADE's CpmMat concrete on the paper's grid (see the header)."""
	from yade import O, utils, Vector3
	from yade.wrapper import (CpmMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop, Ig2_Sphere_Sphere_ScGeom,
	                          Ip2_CpmMat_CpmMat_CpmPhys, Law2_ScGeom_CpmPhys_Cpm, NewtonIntegrator)
	O.reset()
	r, nx, nz, factor = 0.01, 10, 12, 1.2
	mat = O.materials.append(CpmMat(young=30e9, poisson=0.2, density=2300, frictionAngle=0.557, epsCrackOnset=1e-4, relDuctility=30, sigmaT=4.5e6))
	ids = {}
	for k in range(nz):
		for j in range(nx):
			for i in range(nx):
				ids[i, j, k] = O.bodies.append(utils.sphere(((2 * i + 1) * r, (2 * j + 1) * r, (2 * k + 1) * r), r, material=mat))
	bo1 = Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)
	ig2 = Ig2_Sphere_Sphere_ScGeom(interactionDetectionFactor=factor)
	O.engines = [
	    ForceResetter(),
	    InsertionSortCollider([bo1], verletDist=0.05 * r),
	    InteractionLoop([ig2], [Ip2_CpmMat_CpmMat_CpmPhys(cohesiveThresholdIter=2)], [Law2_ScGeom_CpmPhys_Cpm()]),
	    NewtonIntegrator(damping=0)
	]
	O.dt = 0.8 * utils.PWaveTimeStep()
	O.step()
	O.step()
	bo1.aabbEnlargeFactor = ig2.interactionDetectionFactor = 1.0  # back to touching spheres; the bonds stay
	for (i, j, k), b in ids.items():
		if k in (0, nz - 1):
			O.bodies[b].state.blockedDOFs = 'xyzXYZ'
			if k == nz - 1:
				O.bodies[b].state.vel = Vector3(0, 0, -1e-3)
	n = len(O.bodies)
	out = dict(bodies=n, bonds=len([I for I in O.interactions if I.isReal]), dt=O.dt)
	out.update(timed(n, spec['steps'], spec['warmup']))
	return out


def child(spec):
	res = runCpm(spec) if spec['kind'] == 'cpm' else runRdem(spec)
	res['threads'] = int(os.environ.get('OMP_NUM_THREADS', '1'))
	rdem.batch.reportChild(res)


if opts.child is not None:
	child(json.loads(opts.child))
	sys.exit(0)

steps = opts.steps // 3 if opts.quick else opts.steps
warmup = opts.warmup
plan = []  # (section, label, spec, threads)
if 'paper' in opts.cases:
	for th in (1, 2):
		plan.append(('paper', 'refined DEM, paper scene', dict(kind='rdem', steps=steps, warmup=warmup), th))
if 'cpm' in opts.cases:
	for th in (1, 2):
		plan.append(('paper', 'YADE CpmMat spheres, same grid', dict(kind='cpm', steps=steps, warmup=warmup), th))
if 'effects' in opts.cases:
	for label, options in EFFECTS:
		plan.append(('effects', label, dict(kind='rdem', options=options, steps=steps, warmup=warmup), 1))
if 'scaling' in opts.cases:
	for n in ((10, 22) if opts.quick else (10, 22, 46)):
		nSteps = max(50, int(steps * 1200 / (n * n * (n + 2))))  # about the same wall time per cube
		spec = dict(kind='rdem', blocks=n, options=dict(dt=None), steps=nSteps, warmup=min(warmup, nSteps))  # dt: RdemTimeStepper
		plan.append(('scaling', '%d³ blocks' % n, spec, 1))

results = []
start = time.time()
for k, (section, label, spec, th) in enumerate(plan):
	print('benchmark %d/%d: %s, %d thread(s) ...' % (k + 1, len(plan), label, th), flush=True)
	res = rdem.batch.runChild(spec, th)
	res.update(section=section, label=label)
	results.append(res)
	print('    %.0f steps/s, %.3f us per body-step (%.0f s so far)' % (res['stepsPerSecond'], res['usPerBodyStep'], time.time() - start), flush=True)

try:
	load = os.getloadavg()[0]
except OSError:
	load = float('nan')
lines = [
    '# Benchmark figures', '',
    'Made by `build/bin/yade -n scripts/benchmark.py %s` on %s (%d cores, load average %.2f at the end); '
    'each row a fresh process, %d warm-up steps, then the fastest of three timed windows of `O.run(n, True)`. See doc/performance.md for the discussion.' %
    (' '.join(sys.argv[1:]), time.strftime('%Y-%m-%d'), os.cpu_count(), load, warmup), ''
]
paper = [r for r in results if r['section'] == 'paper']
if paper:
	lines += ['## Paper scene and the YADE reference', '', '| model | bodies | threads | steps/s | µs per body-step | speed-up | breaks |', '|---|---|---|---|---|---|---|']
	for r in paper:
		one = next(x for x in paper if x['label'] == r['label'] and x['threads'] == 1)
		lines.append('| %s | %d | %d | %.0f | %.3f | %.2f | %s |' % (r['label'], r['bodies'], r['threads'], r['stepsPerSecond'], r['usPerBodyStep'],
		                                                            r['stepsPerSecond'] / one['stepsPerSecond'], r.get('breaks', '–')))
	lines.append('')
eff = [r for r in results if r['section'] == 'effects']
if eff:
	base = eff[0]['usPerBodyStep']
	lines += ['## Cost of each effect (paper geometry, one thread)', '', '| scene | steps/s | µs per block-step | × springs only | breaks |', '|---|---|---|---|---|']
	for r in eff:
		lines.append('| %s | %.0f | %.3f | %.2f | %d |' % (r['label'], r['stepsPerSecond'], r['usPerBodyStep'], r['usPerBodyStep'] / base, r['breaks']))
	lines.append('')
sc = [r for r in results if r['section'] == 'scaling']
if sc:
	lines += ['## Scaling with the number of blocks (one thread)', '', '| cube | blocks | Poisson elements | set-up [s] | steps/s | µs per block-step | memory per block [kB] | breaks |',
	          '|---|---|---|---|---|---|---|---|']
	for r in sc:
		lines.append('| %s | %d | %d | %.1f | %.1f | %.3f | %.1f | %d |' % (r['label'], r['bodies'], r['elements'], r['setupSeconds'], r['stepsPerSecond'],
		                                                                 r['usPerBodyStep'], r['memoryPerBodyKB'], r['breaks']))
	lines.append('')
with open(opts.out, 'w') as f:
	f.write('\n'.join(lines))
with open(os.path.splitext(opts.out)[0] + '.json', 'w') as f:
	json.dump(results, f, indent=1)
print('benchmark: %d cases in %.0f s; table in %s' % (len(results), time.time() - start, opts.out))
sys.exit(0)
