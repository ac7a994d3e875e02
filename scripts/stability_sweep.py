# -*- coding: utf-8 -*-
"""Largest stable time step of each stability case, as a fraction of RdemTimeStepper's estimate (doc/stability.md).

Problem
    The elastic cases of tests/yade/test_stability.py (free bonded grids of 2 cm concrete cubes at ν = 0.2, 0.45, 0.49
    and a brick/mortar stack with a 1:100 and 1:1000 stiffness contrast, all perturbed by random velocities without
    rigid motion) are run for ``--steps`` steps at O.dt = f × estimate. A run is stable when the state stays finite and
    the shadow energy of leapfrog (tests/yade/stability_cases.py) stays within ``--tol`` of its start. f goes up in
    steps of 0.25 until a run is unstable, then is bisected to 0.01. The fast compression scene (4×4×4 blocks,
    0.1 m/s) is swept the same way with its energy balance (work of the platen) in place of the shadow energy.
    For each elastic case the linear limit 2/ω_max is also computed exactly, from the eigenvalues of the
    mass-normalised stiffness matrix assembled by finite differences of the forces.

Expected result
    Stable at and below f = 1 for every case (the estimate is a Gershgorin bound, doc/theory.md §6); the largest stable
    f close to the linear limit divided by the estimate.

How to run (about 5 minutes on one core)
    build/bin/yade -n scripts/stability_sweep.py [--steps 20000] [--out output/stability] [--guard-cost]
    ``--guard-cost`` also times RdemFiniteGuard on the paper's 1200-block scene (one more minute).
"""
import argparse
import json
import math
import os
import sys
import time
import numpy as np
from yade import O, Vector3, Quaternion
from yade.wrapper import PyRunner, RdemFiniteGuard

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(sys.argv[0])))
sys.path.insert(0, os.path.join(ROOT, 'tests', 'yade'))
import stability_cases as sc
import rdem
import rdem.measure
from rdem.scenes import CompressionTest

parser = argparse.ArgumentParser(prog='yade scripts/stability_sweep.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--steps', type=int, default=20000, help='steps per elastic run (default 20000)')
parser.add_argument('--tol', type=float, default=1e-3, help='largest shadow-energy error of a stable run (default 1e-3)')
parser.add_argument('--out', default='output/stability', help='folder of sweep.json and sweep.md')
parser.add_argument('--guard-cost', action='store_true', help="time RdemFiniteGuard on the paper's 1200-block scene")
cli = parser.parse_args(sys.argv[1:])  # not "opts": scripts share the launcher's globals, which has its own opts

ELASTIC = {
        'grid nu=0.2, no Poisson': lambda: sc.grid(0.2, None),
        'grid nu=0.2, paper': lambda: sc.grid(0.2, 'paper'),
        'grid nu=0.2, consistent': lambda: sc.grid(0.2, 'consistent'),
        'grid nu=0.45, consistent': lambda: sc.grid(0.45, 'consistent'),
        'grid nu=0.49, consistent': lambda: sc.grid(0.49, 'consistent'),
        'brick/mortar 1:100': lambda: sc.brickMortar(100),
        'brick/mortar 1:1000': lambda: sc.brickMortar(1000),
}


def elasticRun(build, fraction):
	"""(worst shadow-energy error, None if stable, else the step at which the run ended: the guard stopped it at a
	non-finite value, or it ran to the end with an error above the tolerance)."""
	ids = build()
	sc.perturb(ids, 0.01)
	sc.setDtFraction(fraction)
	H0, hist = sc.energyRun(cli.steps)
	err = sc.worstEnergyError(H0, hist)
	return err, None if err < cli.tol else O.iter


PLATEN = dict(work=0.0, top=[])


def platenWork():
	PLATEN['work'] += sum(O.forces.f(i)[2] for i in PLATEN['top']) * 0.1 * O.dt


def compressionRun(fraction):
	"""(worst |energy balance| / W, step at which the run blew up or None) of the fast compression scene."""
	O.reset()
	test = CompressionTest(blocksPerEdge=4, rate=0.1, formulation='paper')
	O.trackEnergy = True
	PLATEN.update(work=0.0, top=test.top)
	O.engines = O.engines + [PyRunner(iterPeriod=1, command='platenWork()')]
	O.step()
	O.dt = fraction * rdem.timeStepper().estimate()
	kin0, worst = O.energy['kinetic'], 0
	while test.displacement() < 0.3e-3:
		try:
			O.run(50, True)
		except RuntimeError:
			return math.inf, O.iter
		bal = O.energy['kinetic'] - kin0 + sc.elasticEnergy() + sc.dissipatedEnergy() - PLATEN['work']
		worst = max(worst, abs(bal) / max(PLATEN['work'], 1e-30) if PLATEN['work'] > 1 else 0)
		if not (worst < 0.05 and sc.stateIsFinite()):
			return worst, O.iter
	return worst, None


def linearFraction(build):
	"""(2/omega_max) / estimate, omega_max from the finite-difference stiffness of the reference configuration."""
	ids = build()
	est = rdem.timeStepper().estimate()
	O.dt = 1e-12
	for i in ids:
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	base = [(Vector3(O.bodies[i].state.pos), Quaternion(O.bodies[i].state.ori)) for i in ids]
	h = 1e-9  # [m] and h/0.01 [rad]: linear range, 7 digits above round-off of the forces

	def forces():
		O.step()
		return np.array([c for i in ids for c in list(O.forces.f(i)) + list(O.forces.t(i))])

	f0 = forces()
	K = np.zeros((6 * len(ids), 6 * len(ids)))
	for a, i in enumerate(ids):
		s = O.bodies[i].state
		for d in range(6):
			axis = Vector3(*[1.0 if k == d % 3 else 0.0 for k in range(3)])
			if d < 3:
				s.pos, step = base[a][0] + axis * h, h
			else:
				s.ori, step = Quaternion(axis, h / 0.01) * base[a][1], h / 0.01
			K[:, 6 * a + d] = -(forces() - f0) / step
			s.pos, s.ori = base[a]
	m = np.array([c for i in ids for c in [O.bodies[i].state.mass] * 3 + list(O.bodies[i].state.inertia)])
	A = K / np.sqrt(np.outer(m, m))
	w2 = np.linalg.eigvalsh((A + A.T) / 2)
	return 2 / math.sqrt(w2.max()) / est, w2.min() / w2.max()


def sweep(run):
	"""Runs at 0.5, 0.9, 1.0, then up by 0.25 to the first unstable fraction, then bisection to 0.01."""
	runs = {}
	for f in (0.5, 0.9, 1.0):
		runs[f] = run(f)
	f = 1.0
	while runs[f][1] is None and f < 6:
		f += 0.25
		runs[f] = run(f)
	lo, hi = f - 0.25, f
	while hi - lo > 0.01 and runs[hi][1] is not None:
		mid = round((lo + hi) / 2, 4)
		runs[mid] = run(mid)
		lo, hi = (mid, hi) if runs[mid][1] is None else (lo, mid)
	stable = max(k for k, v in runs.items() if v[1] is None)
	beyond = min((k for k, v in runs.items() if v[1] is not None and k > stable), default=None)
	return dict(runs={str(k): v for k, v in sorted(runs.items())}, largestStable=stable, firstUnstable=beyond, worstBelow1=max(runs[f][0] for f in (0.5, 0.9, 1.0)))


results = {}
t0 = time.time()
for name, build in ELASTIC.items():
	r = sweep(lambda f: elasticRun(build, f))
	r['linear'], r['minEigRatio'] = linearFraction(build)
	results[name] = r
	print('%-28s worst(<=1) %.2g  stable up to %.2f  unstable at %s (after %s steps)  linear limit %.2f  [%.0f s]' %
	      (name, r['worstBelow1'], r['largestStable'], r['firstUnstable'], r['runs'].get(str(r['firstUnstable']), [0, None])[1], r['linear'],
	       time.time() - t0),
	      flush=True)
r = sweep(compressionRun)
results['fast compression 4x4x4, 0.1 m/s'] = r
print('%-28s worst(<=1) %.2g  stable up to %.2f  unstable at %s (at step %s)' %
      ('fast compression', r['worstBelow1'], r['largestStable'], r['firstUnstable'], r['runs'].get(str(r['firstUnstable']), [0, None])[1]),
      flush=True)

if cli.guard_cost:
	O.reset()
	CompressionTest(blocksPerEdge=10, rate=1e-3)
	O.run(5, True)
	share, guardUs, stepUs = rdem.measure.engineShare(RdemFiniteGuard, 100)
	results['guard cost, 1200 blocks'] = dict(share=share, guardMicroseconds=guardUs, stepMicroseconds=stepUs)
	print('guard: %.2f %% of the step (%.1f us of %.0f us), 1200-block paper scene' % (100 * share, guardUs, stepUs), flush=True)

os.makedirs(cli.out, exist_ok=True)
with open(os.path.join(cli.out, 'sweep.json'), 'w') as f:
	json.dump(results, f, indent=1, default=lambda x: None if x is None else float(x))
print('wrote %s (%.0f s)' % (os.path.join(cli.out, 'sweep.json'), time.time() - t0))
