# -*- coding: utf-8 -*-
"""Steady-state speed of the refined DEM: the paper's scene, each effect alone, YADE's CpmMat as a reference, scaling.

Problem
    How many steps per second, and how many microseconds per block and step, does a scene cost, and what does each
    effect (springs, failure, contact detection, Poisson elements, corotation, energy tracking) add? Every case runs in
    a fresh YADE process (``build/bin/yade -jN``), builds its scene, runs ``--warmup`` steps, then times 20 windows
    of ``--steps``/20 steps of ``O.step()`` and reports the fastest (the speed of the code) and the median (what a run
    sees on a busy host); see timed(). The scenes are loaded as the paper's compression test
    (1 mm/s; Δt = 2e-6 s, or 0.8 of RdemTimeStepper's estimate for the other cube sizes) and no spring breaks in the
    timed window (column "breaks").

Cases
    paper       the paper's §5 scene: 1200 blocks, 3260 bonds (2×2 springs), 891 Poisson elements, with failure and
                the contact gate (rdem.scenes.CompressionTest defaults), 1 and 2 threads;
    crack       the same scene run from the start to its first broken spring (about 70 000 steps), 1 and 2 threads;
    phases      the paper's main job (scripts/compression.py without its recording: 1 mm/s to 0.25 mm, about 125 000
                steps), one thread, timed in windows of 1000 steps: µs per block-step before the first broken spring
                (intact) and after it (cracked: the collider runs, contacts come and go), median and range of the
                windows, and the wall time of each phase and of the whole run;
    collapse    a dry-stacked cube of --collapse-blocks³ loose blocks (default 22: 10 648 blocks) on a fixed floor under
                gravity tilted by 45° (friction 0.6, so it slides and topples), contacts only, 1 and 2 threads;
    cpm         YADE's concrete model on the same grid: 10×10×12 CpmMat spheres of radius 1 cm, bonded to their face
                neighbours (interactionDetectionFactor 1.2), bottom layer fixed, top layer at 1 mm/s, collider on,
                O.dt = 0.8 PWaveTimeStep: what a YADE user runs today for concrete, 1 and 2 threads;
    effects     the paper's geometry with one more effect at a time (see EFFECTS);
    scaling     springs + failure + contact gate + Poisson on cubes of --sizes blocks per edge (default 10, 22, 46:
                1.2e3 … 1.0e5 blocks with the platens), one thread, and YADE's CpmMat spheres (as in "cpm") on the
                same grids as the reference; with the memory per body (peak resident set after building, over the
                body count), the exponent of the wall time per step against the body count between neighbouring
                sizes, and a plot (figures/<name>.png beside --out, e.g. doc/figures/scaling.png);
    heavy       the paper's cube loaded at 20 mm/s to three times its first-break displacement (saved once per build, see
                heavyCrackedState), timed after loading, 1 and 2 threads;
    heavy-instructions  the same state's instructions per block-step under callgrind (120 minus 20 steps after loading);
    instructions  the paper scene's instructions per block-step under valgrind's callgrind: the one figure that does
                not move with the machine's load (needs valgrind); intact (200 steps from the start) and cracked (the
                state 5000 steps after the first broken spring, saved by a native run first, then 100 steps counted as
                the difference of 120 and 20 steps after loading, so that the first steps after loading, which test
                every pair again, are not counted).
    wall        the validated Magenes & Calvi MI1 test (scripts/shear_wall.py with its defaults: 1087 blocks, softening,
                cells, the quasi-static scheme) saved once per build at 0.02 % drift (intact, just after the push
                starts) and at 0.30 % drift (joints cracked, on the plateau before the peak at 0.60 %), timed after
                loading, 1 and 2 threads;
    bigwall     a running-bond brick wall of about --wall-blocks blocks (default 1e5: 200 bricks × 250 courses, two
                blocks per brick, 250 × 120 × 55 mm bricks, 10 mm joints; MI1's materials; cells, softening,
                total-stress failure, Cundall's damping 0.2, the automatic step) on a fixed base beam under gravity
                applied at once (a few joints crack: column "breaks"), 1 and 2 threads;
                with its set-up time and memory per block;
    wall-instructions  the same two states' instructions per block-step under callgrind (120 minus 20 steps after loading);
    misses      memory traffic of the 22³ cube (11 616 blocks, beyond this machine's 32 MB L3 cache): last-level data
                cache misses per block-step under callgrind's cache simulation with a 32 MB, 16-way last level, over 11
                steps (needs valgrind; about 5 minutes; not in the default plan).

Expected result
    Figures of this machine in doc/benchmark.md; doc/performance.md discusses them and the profile.

How to run (about 9 minutes with the default two rounds; --quick --repeat 1: 2 minutes, no 46³ cube)
    build/bin/yade -n scripts/benchmark.py [--cases paper crack cpm effects scaling] [--sizes 10 22 46] [--quick] [--repeat N] [--out doc/benchmark.md]
    build/bin/yade -n scripts/benchmark.py --cases phases collapse instructions --repeat 3 --out doc/contact-phase.md   the contact phase
    build/bin/yade -n scripts/benchmark.py --save-collapse 300 /tmp/collapse-300.yade.gz   the collapse's state, for scripts/profile_step.py
"""
import argparse
import json
import math
import os
import resource
import statistics
import sys
import time
from yade import rdem
import yade.rdem.batch

parser = argparse.ArgumentParser(prog='yade scripts/benchmark.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--cases', nargs='+', default=['paper', 'crack', 'cpm', 'effects', 'scaling', 'instructions'], help='cases to run (default: all)')
parser.add_argument('--steps', type=int, default=6000, help='timed steps per case, in three windows (default 6000; fewer for big cubes)')
parser.add_argument('--warmup', type=int, default=300, help='steps before timing (default 300)')
parser.add_argument('--quick', action='store_true', help='fewer steps, no 46³ cube')
parser.add_argument('--sizes', type=int, nargs='+', default=None, help='blocks per edge of the scaling cubes (default 10 22 46; --quick: 10 22)')
parser.add_argument('--repeat', type=int, default=2, help='run the whole plan this many times, round robin, and keep each case\'s fastest round (default 2)')
parser.add_argument('--out', default='doc/benchmark.md', help='markdown table to write (default doc/benchmark.md)')
parser.add_argument('--collapse-blocks', type=int, default=22, help='blocks per edge of the collapsing cube (default 22)')
parser.add_argument('--save-collapse', nargs=2, metavar=('STEPS', 'PATH'), default=None,
                    help='only save the collapsing cube (--collapse-blocks) after STEPS steps to PATH (O.save; for scripts/profile_step.py --state PATH) and exit')
parser.add_argument('--wall-blocks', type=float, default=1e5, help='blocks of the bigwall case, about (default 1e5)')
parser.add_argument('--child', default=None, help=argparse.SUPPRESS)  # internal: run one case in this process
cli = parser.parse_args(sys.argv[1:])


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


def timed(nBodies, steps, warmup, windows=20):
	"""Run `warmup` steps, then `windows` timed windows of steps/windows steps each. Steps are made with O.step() (0.24 µs
	of Python each, 0.04 % of a step of the paper scene) and timed with time.perf_counter(): O.run(n, True) returns only
	at the next 40 ms poll of Omega's wait (py/wrapper/yadeWrapper.cpp), which adds up to 40 ms to a window. The
	speed of this virtual machine varies by up to 1.5× from one second to the next (its host runs other work): the
	fastest window is the speed of the code, the median what a run sees."""
	from yade import O
	O.run(warmup, True)
	n = max(1, steps // windows)
	walls = []
	for w in range(windows):
		t0 = time.perf_counter()
		for i in range(n):
			O.step()
		walls.append(time.perf_counter() - t0)
	walls.sort()
	wall, median = walls[0], walls[len(walls) // 2]
	return dict(steps=n,
	            windows=windows,
	            wall=wall,
	            wallMedian=median,
	            stepsPerSecond=n / wall,
	            usPerBodyStep=wall / n / nBodies * 1e6,
	            usPerBodyStepMedian=median / n / nBodies * 1e6)


def runRdem(spec):
	"""One refined-DEM case in this process; returns its figures."""
	from yade import O
	from yade import rdem
	from yade.rdem.scenes import CompressionTest
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
	"""YADE's CpmMat concrete on the paper's grid, or on the grid of a scaling cube of spec['blocks'] per edge (see the
	header)."""
	from yade import O, utils, Vector3
	from yade.wrapper import (CpmMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop, Ig2_Sphere_Sphere_ScGeom,
	                          Ip2_CpmMat_CpmMat_CpmPhys, Law2_ScGeom_CpmPhys_Cpm, NewtonIntegrator)
	O.reset()
	mem0 = peakMemoryMB()
	t0 = time.time()
	nx = spec.get('blocks', 10)
	r, nz, factor = 0.01, nx + 2, 1.2
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
	out = dict(bodies=n, bonds=len([I for I in O.interactions if I.isReal]), dt=O.dt, setupSeconds=time.time() - t0,
	           memoryPerBodyKB=(peakMemoryMB() - mem0) * 1024 / n)
	out.update(timed(n, spec['steps'], spec['warmup']))
	return out


def runCrack(spec):
	"""The paper scene from the start to its first broken spring, stepped with O.step() (see timed()), a check every 1000
	steps; prints its progress."""
	from yade import O
	from yade import rdem
	from yade.rdem.scenes import CompressionTest
	test = CompressionTest()
	law = rdem.build.law()
	t0 = time.perf_counter()
	while law.tensionBreaks + law.shearBreaks == 0 and O.iter < 200000:
		for i in range(1000):
			O.step()
		if O.iter % 10000 == 0:
			print('    step %d, %.1f MPa, %.0f s' % (O.iter, test.stress() / 1e6, time.perf_counter() - t0), flush=True)
	wall = time.perf_counter() - t0
	n = len(O.bodies)
	return dict(bodies=n, steps=O.iter, wall=wall, stress=test.stress(), stepsPerSecond=O.iter / wall, usPerBodyStep=wall / O.iter / n * 1e6,
	            breaks=int(law.tensionBreaks + law.shearBreaks))


def runPhases(spec):
	"""The paper's main job without its recording (1 mm/s to spec['end'] m, default 0.25 mm), one window of
	spec['window'] steps after another: each window's time goes to the intact phase (no broken spring at its end) or
	the cracked one (broken springs at its start); the window of the first break to neither. With spec['save'], the
	state spec['saveAfter'] steps after the first broken spring is saved there, and the run stops."""
	from yade import O
	from yade import rdem
	from yade.rdem.scenes import CompressionTest
	test = CompressionTest()
	law = rdem.build.law()
	broken = lambda: int(law.tensionBreaks + law.shearBreaks)
	window, end, n = spec.get('window', 1000), spec.get('end', 0.25e-3), len(O.bodies)
	phases = dict(intact=[], cracked=[])
	first = None
	t0 = time.perf_counter()
	while O.time * test.rate < end:
		before = broken()
		w0 = time.perf_counter()
		for i in range(window):
			O.step()
		wall = time.perf_counter() - w0
		if broken() == 0:
			phases['intact'].append(wall)
		elif before > 0:
			phases['cracked'].append(wall)
		else:
			first = dict(iter=O.iter, stress=test.stress())
		if O.iter % 10000 == 0:
			print('    step %d, %.1f MPa, %d breaks, %d interactions, %.0f s' % (O.iter, test.stress() / 1e6, broken(), len(O.interactions.all()),
			                                                                 time.perf_counter() - t0), flush=True)
		if spec.get('save') and first and O.iter >= first['iter'] + spec.get('saveAfter', 5000):
			O.save(spec['save'])
			return dict(bodies=n, steps=O.iter, saved=spec['save'], wall=time.perf_counter() - t0, stepsPerSecond=0, usPerBodyStep=0)
	out = dict(bodies=n, steps=O.iter, wall=time.perf_counter() - t0, window=window, firstBreak=first, breaks=broken(), stress=test.stress())
	for name, walls in phases.items():
		us = sorted(w / window / n * 1e6 for w in walls)
		out[name] = dict(windows=len(us), wall=sum(walls), median=us[len(us) // 2] if us else None, fastest=us[0] if us else None, slowest=us[-1] if us else None)
	out['ratio'] = out['cracked']['median'] / out['intact']['median'] if out['cracked']['median'] else None
	out['stepsPerSecond'] = O.iter / out['wall']
	out['usPerBodyStep'] = out['cracked']['median'] or 0  # the figure the rounds keep the fastest of
	return out


def collapseScene(n, h=0.02):
	"""A dry-stacked cube of n³ loose cubic blocks of side h [m] on a fixed floor block, gravity tilted by 45° about y
	(friction 0.6 < tan 45°: the cube slides and topples); concrete-like blocks, contacts sampled at the vertices
	(rdem.engines(contactSamples=1), as for rocking and collapse), collider with a sweep distance of 5 % of a block.
	Returns the number of moving blocks."""
	from yade import O
	from yade.wrapper import RdemMat
	from yade.rdem import build
	O.reset()
	mat = O.materials.append(RdemMat(young=30e9, poisson=0.2, density=2300, frictionAngle=math.atan(0.6), label='dry'))
	tilt = math.radians(45)
	O.engines = build.engines(formulation=None, gravity=(9.81 * math.sin(tilt), 0, -9.81 * math.cos(tilt)), verletDist=0.05 * h, contactSamples=1)
	O.bodies.append(build.block((1.5 * n * h, n * h / 2, -h / 2), (1.5 * n * h, n * h / 2 + h, h / 2), mat, fixed=True))
	return len(build.blockGrid((n, n, n), (h, h, h), mat))


def runCollapse(spec):
	"""The collapsing cube (collapseScene), timed as the steady-state cases after spec['warmup'] steps."""
	from yade import O
	t0 = time.time()
	collapseScene(spec['blocks'])
	setup = time.time() - t0
	n = len(O.bodies)
	out = dict(bodies=n, setupSeconds=setup)
	out.update(timed(n, spec['steps'], spec['warmup']))
	out['dt'] = O.dt  # RdemTimeStepper's, set at the first step (before it O.dt is YADE's default 1e-8 s)
	out.update(interactions=len(O.interactions.all()), contacts=sum(1 for I in O.interactions if I.isReal), time=O.time)
	return out


def runCollapseSave(spec):
	"""The collapsing cube (collapseScene) run spec['steps'] steps and saved to spec['save']."""
	from yade import O
	collapseScene(spec['blocks'])
	O.run(spec['steps'], True)
	O.save(spec['save'])
	return dict(bodies=len(O.bodies), steps=O.iter, dt=O.dt, interactions=len(O.interactions.all()), real=sum(1 for I in O.interactions if I.isReal))


def runCount(spec):
	"""The paper scene (or a cube of spec['blocks'] per edge, time step from RdemTimeStepper; or the state saved in
	spec['load']), built and stepped spec['steps'] times under callgrind (see countInstructions)."""
	from yade import O
	from yade.rdem.scenes import CompressionTest
	blocks = spec.get('blocks', 10)
	if spec.get('load'):
		O.load(spec['load'])
	else:
		CompressionTest(blocksPerEdge=blocks) if blocks == 10 else CompressionTest(blocksPerEdge=blocks, dt=None)
	O.run(spec['steps'], True)
	return dict(bodies=len(O.bodies), steps=spec['steps'], interactions=len(O.interactions.all()), real=sum(1 for I in O.interactions if I.isReal))


def pluginLibrary():
	"""Path of the plugin library this process loaded (libpkg_rdem.so, from /proc/self/maps), else the checkout's build."""
	try:
		with open('/proc/self/maps') as f:
			for line in f:
				if line.rstrip().endswith('libpkg_rdem.so'):
					return line.split()[-1]
	except OSError:
		pass
	return os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build', 'lib', 'libpkg_rdem.so')


def buildStatePath(name):
	"""Path of the state `name` saved by this build in the system's temporary folder: `rdem-<name>-<build>` with the first
	12 hex digits of the SHA-1 of the plugin library this process loaded (a saved scene's attributes follow the build)."""
	import hashlib
	import tempfile
	with open(pluginLibrary(), 'rb') as f:
		build = hashlib.sha1(f.read()).hexdigest()[:12]
	return os.path.join(tempfile.gettempdir(), 'rdem-%s-%s' % (name, build))


def crackedState():
	"""Path of the paper scene 5000 steps after its first broken spring, saved by a native run of this build (the saved
	attributes follow the build) into the system's temporary folder; made if missing (about a minute)."""
	path = buildStatePath('paper-cracked') + '.yade.gz'
	if not os.path.exists(path):
		print('benchmark: saving the cracked paper scene to %s (about a minute) ...' % path, flush=True)
		rdem.batch.runChild(dict(kind='phases', save=path, saveAfter=5000), 1)
	return path


def countInstructions(steps=200, blocks=10, cacheSim=False, load=None):
	"""Instructions per block-step of the paper scene (or of a cube of `blocks` per edge, or of the saved state `load`),
	counted by valgrind's callgrind over the time steps only (yade::Scene::moveToNextTimeStep): unlike seconds, the same
	on every run of the same build, whatever else the machine does. With cacheSim, also the last-level data cache
	misses (reads + writes) per block-step, for a 32 MB, 16-way, 64-byte-line last level like this machine's L3. A fresh
	process under valgrind, one thread."""
	import re
	import subprocess
	spec = dict(kind='count', steps=steps, blocks=blocks, load=load)
	cmd = ['valgrind', '--tool=callgrind', '--trace-children=yes', '--callgrind-out-file=/dev/null', '--collect-atstart=no']
	if cacheSim:
		cmd += ['--cache-sim=yes', '--LL=33554432,16,64']
	cmd += ['--toggle-collect=yade::Scene::moveToNextTimeStep()'] + rdem.batch.yadeCommand() + ['-j1', '-n', '-x', sys.argv[0], '--child', json.dumps(spec)]
	proc = subprocess.run(cmd, env=dict(os.environ, OMP_NUM_THREADS='1'), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
	# "Collected : Ir [Dr Dw I1mr D1mr D1mw ILmr DLmr DLmw]" of the process that ran the steps (the one with most Ir)
	collected = [[int(c) for c in line.split()] for line in re.findall(r'Collected : ([0-9 ]+)', proc.stdout.replace(',', ''))]
	report = [l for l in proc.stdout.splitlines() if l.startswith(rdem.batch.MARKER)]
	if not collected or not report:
		raise RuntimeError('callgrind run failed:\n%s' % proc.stdout[-3000:])
	events = max(collected, key=lambda c: c[0])
	res = json.loads(report[-1][len(rdem.batch.MARKER):])
	out = dict(instructions=events[0], steps=steps, bodies=res['bodies'], perBlockStep=events[0] / steps / res['bodies'], interactions=res['interactions'],
	           real=res['real'])
	if cacheSim:
		out['llMissesPerBlockStep'] = (events[7] + events[8]) / steps / res['bodies']
	return out


def runHeavySave(spec):
	"""The paper's cube loaded at spec['rate'] (default 20 mm/s) to spec['factor'] (default 3) times the platen
	displacement of its first broken spring, saved to spec['save']: the heavily cracked state (what a collapse looks like)."""
	from yade import O
	import rdem.build
	from rdem.scenes import CompressionTest
	test = CompressionTest(rate=spec.get('rate', 0.02))
	law = rdem.build.law()
	while law.tensionBreaks + law.shearBreaks == 0 and O.iter < 400000:
		O.run(100, True)
	first = test.displacement()
	while test.displacement() < spec.get('factor', 3) * first and O.iter < 400000:
		O.run(100, True)
	O.save(spec['save'])
	return dict(bodies=len(O.bodies), steps=O.iter, firstBreak=first, displacement=test.displacement(), interactions=len(O.interactions.all()),
	            real=sum(1 for I in O.interactions if I.isReal), breaks=int(law.tensionBreaks + law.shearBreaks), stepsPerSecond=0, usPerBodyStep=0)


def runBigWall(spec):
	"""The running-bond wall of about spec['blocks'] blocks (rdem.scenes.runningBondWall: MI1's materials, Poisson cells,
	softening and total-stress failure, on a fixed base beam under gravity applied at once); timed as the steady-state
	cases. A few joints break in the first steps under that shock (column "breaks"); the rest of the wall stays intact."""
	from yade import O
	from yade import rdem
	from yade.rdem import scenes
	O.reset()
	t0 = time.time()
	scenes.runningBondWall(spec['blocks'])
	n = len(O.bodies)
	out = dict(bodies=n, setupSeconds=time.time() - t0, memoryKBPerBody=peakMemoryMB() * 1024 / n)
	out.update(timed(n, spec['steps'], spec['warmup']))
	out.update(dt=O.dt, interactions=len(O.interactions.all()), real=sum(1 for I in O.interactions if I.isReal), breaks=sum(rdem.breakCounts()))
	return out


def runLoaded(spec):
	"""A saved state (spec['load']) timed as the steady-state cases."""
	from yade import O
	O.load(spec['load'])
	n = len(O.bodies)
	out = dict(bodies=n)
	out.update(timed(n, spec['steps'], spec['warmup']))
	out.update(interactions=len(O.interactions.all()), real=sum(1 for I in O.interactions if I.isReal))
	return out


def wallState(drift):
	"""Path of the validated MI1 run (scripts/shear_wall.py with its defaults, one thread) saved when the push reaches
	``drift`` [%], by a native run of this build into the system's temporary folder; made if missing (0.3 %: several
	minutes)."""
	import subprocess
	out = buildStatePath('mi1-%.2f' % drift)  # the run's output folder; the state beside it
	path = out + '.yade.gz'
	if not os.path.exists(path):
		print('benchmark: saving MI1 at %.2f %% drift to %s ...' % (drift, path), flush=True)
		script = os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), 'shear_wall.py')
		cmd = rdem.batch.yadeCommand() + ['-j1', '-n', '-x', script, '--max-drift', str(drift), '--save', path, '--vtk-every', '0', '--out', out]
		proc = subprocess.run(cmd, env=dict(os.environ, OMP_NUM_THREADS='1'), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
		if proc.returncode != 0 or not os.path.exists(path):
			raise RuntimeError('scripts/shear_wall.py failed:\n%s' % proc.stdout[-3000:])
	return path


WALL_STATES = ((0.02, 'MI1 intact (0.02 % drift)'), (0.30, 'MI1 cracked (0.30 % drift)'))


def heavyCrackedState():
	"""Path of the paper's cube at 20 mm/s to three times its first-break displacement (runHeavySave), saved by a native
	run of this build into the system's temporary folder; made if missing (a few minutes)."""
	path = buildStatePath('paper-heavy') + '.yade.gz'
	if not os.path.exists(path):
		print('benchmark: saving the heavily cracked cube to %s (a few minutes) ...' % path, flush=True)
		res = rdem.batch.runChild(dict(kind='heavysave', save=path), 1)
		print('    first break at %.3g mm, saved at %.3g mm after %d steps: %d interactions, %d real, %d broken springs' %
		      (res['firstBreak'] * 1e3, res['displacement'] * 1e3, res['steps'], res['interactions'], res['real'], res['breaks']), flush=True)
	return path


def child(spec):
	res = dict(cpm=runCpm, crack=runCrack, count=runCount, phases=runPhases, collapse=runCollapse, collapsesave=runCollapseSave, heavysave=runHeavySave,
	           loaded=runLoaded, bigwall=runBigWall).get(spec['kind'], runRdem)(spec)
	res['threads'] = int(os.environ.get('OMP_NUM_THREADS', '1'))
	rdem.batch.reportChild(res)


if cli.child is not None:
	child(json.loads(cli.child))
	sys.exit(0)
if cli.save_collapse:
	res = rdem.batch.runChild(dict(kind='collapsesave', blocks=cli.collapse_blocks, steps=int(cli.save_collapse[0]), save=cli.save_collapse[1]), 1)
	print('benchmark: the collapse (%d bodies) saved after %d steps to %s: dt %.3g s, %d interactions, %d real' %
	      (res['bodies'], res['steps'], cli.save_collapse[1], res['dt'], res['interactions'], res['real']))
	sys.exit(0)

steps = cli.steps // 3 if cli.quick else cli.steps
warmup = cli.warmup
plan = []  # (section, label, spec, threads)
if 'paper' in cli.cases:
	for th in (1, 2):
		plan.append(('paper', 'refined DEM, paper scene', dict(kind='rdem', steps=steps, warmup=warmup), th))
if 'crack' in cli.cases:
	for th in (1, 2):
		plan.append(('crack', 'paper scene to its first broken spring', dict(kind='crack'), th))
if 'phases' in cli.cases:
	plan.append(('phases', 'paper main job, intact and cracked phases', dict(kind='phases'), 1))
if 'collapse' in cli.cases:
	nc = cli.collapse_blocks
	if nc < 2:
		sys.exit('--collapse-blocks %d: must be >= 2' % nc)
	for th in (1, 2):
		plan.append(('collapse', 'collapsing cube, %d³ blocks' % nc,
		             dict(kind='collapse', blocks=nc, steps=max(50, int(steps * 1200 / nc**3)), warmup=min(warmup, max(50, int(steps * 1200 / nc**3)))), th))
if 'heavy' in cli.cases:
	heavyState = heavyCrackedState()
	for th in (1, 2):
		plan.append(('paper', 'paper cube heavily cracked (20 mm/s, 3× first break)', dict(kind='loaded', load=heavyState, steps=steps // 3, warmup=warmup), th))
if 'wall' in cli.cases:
	for drift, label in WALL_STATES:
		state = wallState(drift)
		for th in (1, 2):
			plan.append(('wall', label, dict(kind='loaded', load=state, steps=steps // 3, warmup=warmup), th))
if 'bigwall' in cli.cases:
	if not cli.wall_blocks >= 100:
		sys.exit('--wall-blocks %g: must be >= 100' % cli.wall_blocks)
	for th in (1, 2):
		nb = cli.wall_blocks
		plan.append(('bigwall', 'running-bond wall, about %.0f blocks' % nb,
		             dict(kind='bigwall', blocks=nb, steps=max(20, int(steps * 1200 / nb)), warmup=min(warmup, max(20, int(steps * 1200 / nb)))), th))
if 'cpm' in cli.cases:
	for th in (1, 2):
		plan.append(('paper', 'YADE CpmMat spheres, same grid', dict(kind='cpm', steps=steps, warmup=warmup), th))
if 'effects' in cli.cases:
	for label, options in EFFECTS:
		plan.append(('effects', label, dict(kind='rdem', options=options, steps=steps, warmup=warmup), 1))
if 'scaling' in cli.cases:
	sizes = cli.sizes or ((10, 22) if cli.quick else (10, 22, 46))
	if min(sizes) < 2 or len(set(sizes)) != len(sizes):
		sys.exit('--sizes %s: blocks per edge must be distinct integers >= 2' % ' '.join(map(str, sizes)))
	for n in sorted(sizes):
		nSteps = max(50, int(steps * 1200 / (n * n * (n + 2))))  # about the same wall time per cube
		spec = dict(kind='rdem', blocks=n, options=dict(dt=None), steps=nSteps, warmup=min(warmup, nSteps))  # dt: RdemTimeStepper
		plan.append(('scaling', '%d³ blocks' % n, spec, 1))
		plan.append(('scaling-cpm', '%d³ CpmMat spheres' % n, dict(spec, kind='cpm'), 1))

if cli.repeat < 1:
	sys.exit('--repeat %d: must be >= 1' % cli.repeat)
# Round robin: every case once per round, so that a slow phase of the machine does not hit one case only; each case
# keeps its fastest round, and the spread over the rounds is reported.
results = [None] * len(plan)
start = time.time()
for rnd in range(cli.repeat):
	for k, (section, label, spec, th) in enumerate(plan):
		print('benchmark round %d/%d, case %d/%d: %s, %d thread(s) ...' % (rnd + 1, cli.repeat, k + 1, len(plan), label, th), flush=True)
		res = rdem.batch.runChild(spec, th)
		res.update(section=section, label=label)
		print('    %.0f steps/s, %.3f us per body-step (%.0f s so far)' % (res['stepsPerSecond'], res['usPerBodyStep'], time.time() - start), flush=True)
		best = results[k]
		rounds = (best['rounds'] if best else []) + [res['usPerBodyStep']]
		if best is None or res['usPerBodyStep'] < best['usPerBodyStep']:
			best = res
		best['rounds'] = rounds
		results[k] = best

count = None
cracked = None
if 'instructions' in cli.cases:
	print('benchmark: instructions per block-step under callgrind (about a minute) ...', flush=True)
	# difference of 220 and 20 steps: the first step's cold Lanczos estimate of the time step (RdemTimeStepper checks the
	# fixed 2 µs) alone costs about 0.4e9 instructions, a fifth of 200 steps
	first, long_ = countInstructions(steps=20), countInstructions(steps=220)
	count = dict(long_, steps=200, instructions=long_['instructions'] - first['instructions'])
	count['perBlockStep'] = count['instructions'] / 200 / count['bodies']
	print('    %.0f instructions per block-step' % count['perBlockStep'], flush=True)
	state = crackedState()
	print('benchmark: instructions per block-step of the cracked scene under callgrind (a few minutes) ...', flush=True)
	short, long_ = countInstructions(steps=20, load=state), countInstructions(steps=120, load=state)
	cracked = dict(long_, steps=100, instructions=long_['instructions'] - short['instructions'])
	cracked['perBlockStep'] = cracked['instructions'] / 100 / cracked['bodies']
	print('    %.0f instructions per block-step (%.2f x intact)' % (cracked['perBlockStep'], cracked['perBlockStep'] / count['perBlockStep']), flush=True)
heavy = None
if 'heavy-instructions' in cli.cases:
	state = heavyCrackedState()
	print('benchmark: instructions per block-step of the heavily cracked cube under callgrind (a few minutes) ...', flush=True)
	short, long_ = countInstructions(steps=20, load=state), countInstructions(steps=120, load=state)
	heavy = dict(long_, steps=100, instructions=long_['instructions'] - short['instructions'])
	heavy['perBlockStep'] = heavy['instructions'] / 100 / heavy['bodies']
	print('    %.0f instructions per block-step' % heavy['perBlockStep'], flush=True)
wallCounts = []
if 'wall-instructions' in cli.cases:
	for drift, label in WALL_STATES:
		state = wallState(drift)
		print('benchmark: instructions per block-step of %s under callgrind (a few minutes) ...' % label, flush=True)
		short, long_ = countInstructions(steps=20, load=state), countInstructions(steps=120, load=state)
		c = dict(long_, steps=100, instructions=long_['instructions'] - short['instructions'], label=label)
		c['perBlockStep'] = c['instructions'] / 100 / c['bodies']
		wallCounts.append(c)
		print('    %.0f instructions per block-step' % c['perBlockStep'], flush=True)
misses = None
if 'misses' in cli.cases:
	print('benchmark: last-level cache misses per block-step of the 22³ cube under callgrind (about 5 minutes) ...', flush=True)
	misses = countInstructions(steps=11, blocks=22, cacheSim=True)
	print('    %.1f last-level misses (%.0f instructions) per block-step' % (misses['llMissesPerBlockStep'], misses['perBlockStep']), flush=True)

try:
	load = os.getloadavg()[0]
except OSError:
	load = float('nan')
lines = [
    '# Benchmark figures', '',
    'Made by `build/bin/yade -n scripts/benchmark.py %s` on %s (%d cores, load average %.2f at the end); '
    'each row a fresh process, %d warm-up steps, then 20 timed windows of `O.step()` loops: the fastest window (the speed of the code) and the median one '
    '(this virtual machine\'s speed varies by up to 1.5× from second to second); the whole plan ran %d times round robin, each row is its case\'s '
    'fastest round and "rounds" gives the median of the rounds\' fastest windows, their range, and every round\'s [µs per body-step]. See doc/performance.md for the discussion.' %
    (' '.join(sys.argv[1:]), time.strftime('%Y-%m-%d'), os.cpu_count(), load, warmup, cli.repeat), ''
]
def rounds(r):
	"""The rounds column: the median of the rounds' fastest windows, their range, then each round's [µs per body-step]."""
	x = r['rounds']
	return '**%.3f** (%.3f–%.3f): %s' % (statistics.median(x), min(x), max(x), ' '.join('%.3f' % v for v in x))

paper = [r for r in results if r['section'] == 'paper']
if paper:
	lines += ['## Paper scene and the YADE reference', '', '| model | bodies | threads | steps/s | µs per body-step | median window | rounds | speed-up | breaks |', '|---|---|---|---|---|---|---|---|---|']
	for r in paper:
		one = next(x for x in paper if x['label'] == r['label'] and x['threads'] == 1)
		lines.append('| %s | %d | %d | %.0f | %.3f | %.3f | %s | %.2f | %s |' % (r['label'], r['bodies'], r['threads'], r['stepsPerSecond'], r['usPerBodyStep'],
		                                                                        r['usPerBodyStepMedian'], rounds(r), r['stepsPerSecond'] / one['stepsPerSecond'],
		                                                                        r.get('breaks', '–')))
	lines.append('')
if count:
	lines += [
	    '## Instructions per block-step (deterministic)', '',
	    'The paper scene, %d steps under `valgrind --tool=callgrind`, counting only inside `yade::Scene::moveToNextTimeStep` (one thread): '
	    '**%.0f instructions per block-step** (%.3g in all). Unlike the timings this figure is the same on every run of the same build; it moves only '
	    'when the code does.' % (count['steps'], count['perBlockStep'], count['instructions']), ''
	]
if cracked:
	lines += [
	    'Cracked: the paper scene 5000 steps after its first broken spring (%d interactions, %d of them real), 100 steps (the difference of 120 '
	    'and 20 steps after loading the saved state): **%.0f instructions per block-step**, %.2f× intact.' %
	    (cracked['interactions'], cracked['real'], cracked['perBlockStep'], cracked['perBlockStep'] / count['perBlockStep']), ''
	]
if heavy:
	lines += [
	    'Heavily cracked: the paper\'s cube loaded at 20 mm/s to three times its first-break displacement (%d interactions, %d of them real), '
	    '100 steps (the difference of 120 and 20 steps after loading the saved state): **%.0f instructions per block-step**%s.' %
	    (heavy['interactions'], heavy['real'], heavy['perBlockStep'], ', %.2f× intact' % (heavy['perBlockStep'] / count['perBlockStep']) if count else ''), ''
	]
bigwall = [r for r in results if r['section'] == 'bigwall']
if bigwall:
	lines += [
	    '## A large wall, intact', '', 'See the header of scripts/benchmark.py (case bigwall); 20 windows of %d steps after the warm-up.' % bigwall[0]['steps'], '',
	    '| blocks | threads | set-up [s] | memory [kB per block] | Δt [s] | interactions (real) | steps/s | µs per block-step | median window | rounds | speed-up | breaks |',
	    '|---|---|---|---|---|---|---|---|---|---|---|---|'
	]
	for r in bigwall:
		one = next(x for x in bigwall if x['threads'] == 1)
		lines.append('| %d | %d | %.0f | %.1f | %.3g | %d (%d) | %.1f | %.3f | %.3f | %s | %.2f | %d |' %
		             (r['bodies'], r['threads'], r['setupSeconds'], r['memoryKBPerBody'], r['dt'], r['interactions'], r['real'], r['stepsPerSecond'], r['usPerBodyStep'],
		              r['usPerBodyStepMedian'], rounds(r), r['stepsPerSecond'] / one['stepsPerSecond'], r['breaks']))
	lines.append('')
wall = [r for r in results if r['section'] == 'wall']
if wall or wallCounts:
	lines += [
	    '## A wall test: MI1 (Magenes & Calvi), the validated configuration', '',
	    '`scripts/shear_wall.py` with its defaults saved at two points of its push and timed after loading (20 windows of `O.step()`); '
	    'instructions under callgrind as the difference of 120 and 20 steps after loading (one thread).', ''
	]
if wall:
	lines += ['| state | blocks | threads | interactions (real) | steps/s | µs per block-step | median window | rounds | speed-up |', '|---|---|---|---|---|---|---|---|---|']
	for r in wall:
		one = next(x for x in wall if x['label'] == r['label'] and x['threads'] == 1)
		lines.append('| %s | %d | %d | %d (%d) | %.0f | %.3f | %.3f | %s | %.2f |' % (r['label'], r['bodies'], r['threads'], r['interactions'], r['real'], r['stepsPerSecond'],
		                                                                           r['usPerBodyStep'], r['usPerBodyStepMedian'], rounds(r), r['stepsPerSecond'] / one['stepsPerSecond']))
	lines.append('')
for c in wallCounts:
	lines += [
	    '%s: %d interactions, %d of them real: **%.0f instructions per block-step**%s.' %
	    (c['label'], c['interactions'], c['real'], c['perBlockStep'], ', %.2f× the intact paper cube' % (c['perBlockStep'] / count['perBlockStep']) if count else ''), ''
	]
phases = [r for r in results if r['section'] == 'phases']
if phases:
	lines += [
	    '## The main job: intact and cracked phases (one thread)', '',
	    'The paper scene loaded at 1 mm/s to 0.25 mm as `scripts/compression.py` without its recording, timed in windows of %d steps; µs per '
	    'block-step, median (fastest–slowest window) of each phase; "ratio" cracked over intact medians.' % phases[0]['window'], '',
	    '| steps | first break (step, MPa) | intact | intact wall [s] | cracked | cracked wall [s] | ratio | whole run [s] | breaks |', '|---|---|---|---|---|---|---|---|---|'
	]
	for r in phases:
		i, c = r['intact'], r['cracked']
		lines.append('| %d | %d, %.2f | %.3f (%.3f–%.3f) | %.1f | %.3f (%.3f–%.3f) | %.1f | %.2f | %.1f | %d |' %
		             (r['steps'], r['firstBreak']['iter'], r['firstBreak']['stress'] / 1e6, i['median'], i['fastest'], i['slowest'], i['wall'], c['median'],
		              c['fastest'], c['slowest'], c['wall'], r['ratio'], r['wall'], r['breaks']))
	lines.append('')
collapse = [r for r in results if r['section'] == 'collapse']
if collapse:
	lines += [
	    '## A collapse: loose blocks, contacts only', '',
	    'A dry-stacked cube of loose blocks on a fixed floor under gravity tilted by 45° (see the header of scripts/benchmark.py), 20 windows of %d '
	    'steps after the warm-up.' % collapse[0]['steps'], '', '| blocks | threads | Δt [s] | interactions (real) | steps/s | µs per block-step | median window | rounds | speed-up |',
	    '|---|---|---|---|---|---|---|---|---|'
	]
	for r in collapse:
		one = next(x for x in collapse if x['threads'] == 1)
		lines.append('| %d | %d | %.3g | %d (%d) | %.0f | %.3f | %.3f | %s | %.2f |' % (r['bodies'], r['threads'], r['dt'], r['interactions'], r['contacts'], r['stepsPerSecond'],
		                                                                           r['usPerBodyStep'], r['usPerBodyStepMedian'], rounds(r), r['stepsPerSecond'] / one['stepsPerSecond']))
	lines.append('')
if misses:
	lines += [
	    '## Memory traffic beyond the cache (deterministic)', '',
	    'The 22³ cube (%d blocks), %d steps under `valgrind --tool=callgrind --cache-sim=yes --LL=33554432,16,64` (a 32 MB last level like this '
	    'machine\'s L3), one thread: **%.1f last-level data cache misses per block-step** (reads and writes; %.1f kB from memory per block-step), '
	    '%.0f instructions per block-step.' % (misses['bodies'], misses['steps'], misses['llMissesPerBlockStep'], misses['llMissesPerBlockStep'] * 64 / 1024,
	                                            misses['perBlockStep']), ''
	]
crack = [r for r in results if r['section'] == 'crack']
if crack:
	lines += ['## The paper scene to its first broken spring', '', '| threads | steps | wall [s] | steps/s | µs per block-step | rounds | stress at the break [MPa] |', '|---|---|---|---|---|---|---|']
	for r in crack:
		lines.append('| %d | %d | %.1f | %.0f | %.3f | %s | %.2f |' % (r['threads'], r['steps'], r['wall'], r['stepsPerSecond'], r['usPerBodyStep'], rounds(r),
		                                                             r['stress'] / 1e6))
	lines.append('')
eff = [r for r in results if r['section'] == 'effects']
if eff:
	base = eff[0]['usPerBodyStep']
	lines += ['## Cost of each effect (paper geometry, one thread)', '', '| scene | steps/s | µs per block-step | median window | rounds | × springs only | breaks |', '|---|---|---|---|---|---|---|']
	for r in eff:
		lines.append('| %s | %.0f | %.3f | %.3f | %s | %.2f | %d |' % (r['label'], r['stepsPerSecond'], r['usPerBodyStep'], r['usPerBodyStepMedian'], rounds(r),
		                                                             r['usPerBodyStep'] / base, r['breaks']))
	lines.append('')
# Wall time per step w = µs per body-step × bodies; between neighbouring sizes, w grows as N^p with p = ln(w₂/w₁)/ln(N₂/N₁)
# (1 for a cost linear in the number of bodies).
models = [(label, [r for r in results if r['section'] == section]) for label, section in (('refined DEM', 'scaling'), ('YADE CpmMat', 'scaling-cpm'))]
models = [(label, rows) for label, rows in models if rows]
wallPerStep = lambda rows: [r['usPerBodyStep'] * r['bodies'] for r in rows]
if models:
	lines += [
	    '## Scaling with the number of blocks (one thread)', '',
	    'The refined DEM on cubes of $n^3$ blocks between two platen layers ($n\\times n\\times(n+2)$ bodies), and YADE\'s `CpmMat` spheres on '
	    'the same grids (see the header of scripts/benchmark.py). "exponent": $p$ of the wall time per step $\\propto N^p$ from the row above '
	    '(1: linear in the number of bodies $N$); "× smallest": µs per body-step over the smallest cube\'s.', '',
	    '| model | cube | bodies | Poisson elements | set-up [s] | steps/s | µs per body-step | median window | rounds | exponent | × smallest | memory per body [kB] | breaks |',
	    '|---|---|---|---|---|---|---|---|---|---|---|---|---|'
	]
	for label, rows in models:
		wall = wallPerStep(rows)
		exponent = ['–'] + ['%.2f' % (math.log(wall[i] / wall[i - 1]) / math.log(rows[i]['bodies'] / rows[i - 1]['bodies'])) for i in range(1, len(rows))]
		for r, p in zip(rows, exponent):
			lines.append('| %s | %s | %d | %s | %.1f | %.1f | %.3f | %.3f | %s | %s | %.2f | %.1f | %s |' %
			             (label, r['label'].split(' ')[0], r['bodies'], r.get('elements', '–'), r['setupSeconds'], r['stepsPerSecond'], r['usPerBodyStep'],
			              r['usPerBodyStepMedian'], rounds(r), p, r['usPerBodyStep'] / rows[0]['usPerBodyStep'], r['memoryPerBodyKB'], r.get('breaks', '–')))
	lines.append('')
	if max(len(rows) for label, rows in models) >= 2:
		import matplotlib
		matplotlib.use('Agg')
		import matplotlib.pyplot as plt
		figure = os.path.join(os.path.dirname(cli.out), 'figures', os.path.splitext(os.path.basename(cli.out))[0] + '.png')
		os.makedirs(os.path.dirname(figure), exist_ok=True)
		fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
		for (label, rows), colour in zip(models, ('C0', 'C1')):
			bodies, wall = [r['bodies'] for r in rows], wallPerStep(rows)
			left.loglog(bodies, [w / 1e3 for w in wall], 'o-', color=colour, label=label)
			left.loglog(bodies, [wall[0] / 1e3 * b / bodies[0] for b in bodies], '--', color=colour, lw=0.8, label=label + ', linear from the smallest')
			right.semilogx(bodies, [r['usPerBodyStep'] for r in rows], 'o-', color=colour, label=label + ', fastest round')
			right.semilogx(bodies, [r['usPerBodyStepMedian'] for r in rows], 's:', color=colour, label=label + ', median window')
		left.set_xlabel('bodies')
		left.set_ylabel('wall time per step [ms]')
		left.legend(fontsize='small')
		rdemRows = dict(models).get('refined DEM')
		if rdemRows:
			cacheBlocks = 32 * 1024 / (sum(r['memoryPerBodyKB'] for r in rdemRows) / len(rdemRows))  # blocks whose memory fills a 32 MB L3
			right.axvline(cacheBlocks, color='grey', lw=0.8)
			right.text(cacheBlocks, 0.05, ' 32 MB of blocks', color='grey', transform=right.get_xaxis_transform())
		right.set_ylim(bottom=0)
		right.set_xlabel('bodies')
		right.set_ylabel('µs per body-step')
		right.legend(fontsize='small', loc='upper left')
		fig.tight_layout()
		fig.savefig(figure, dpi=110)
		lines += ['![scaling](%s)' % os.path.relpath(figure, os.path.dirname(cli.out) or '.'), '']
with open(cli.out, 'w') as f:
	f.write('\n'.join(lines))
with open(os.path.splitext(cli.out)[0] + '.json', 'w') as f:
	json.dump(results, f, indent=1)
print('benchmark: %d cases in %.0f s; table in %s' % (len(results), time.time() - start, cli.out))
sys.exit(0)
