# -*- coding: utf-8 -*-
"""Largest stable time step of each stability case, as a fraction of RdemTimeStepper's Lanczos estimate (doc/stability.md).

Problem
    The elastic cases of tests/yade/test_stability.py (free bonded grids of 2 cm concrete cubes at ν = 0.2, 0.45, 0.49
    and a brick/mortar stack with a 1:100 and 1:1000 stiffness contrast, all perturbed by random velocities without
    rigid motion) are run for ``--steps`` steps at O.dt = f × estimate (RdemTimeStepper's default, Lanczos). A run is
    stable when the state stays finite and the shadow energy of leapfrog (tests/yade/stability_cases.py) stays within
    ``--tol`` of its start. f goes 0.5, 0.9, 0.95, 0.99, then up in steps of 0.02 until a run is unstable, then is
    bisected to 0.002. The fast compression scene (4×4×4 blocks, 0.1 m/s) is swept the same way with its energy balance
    (work of the platen) in place of the shadow energy. For each elastic case the linear limit 2/ω_max is also computed
    exactly (stability_cases.exactCriticalDt: the eigenvalues of the mass-normalised stiffness matrix assembled by
    finite differences of the forces), and the Gershgorin bound (the fallback) is given as a fraction of it.

Expected result
    Stable at and below f = 1 for every elastic case, unstable just above (the estimate is within 0.1 % below the
    exact limit); Gershgorin 2.2–2.7 times below the limit.

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
from yade import rdem
from yade import rdem
from yade.rdem.scenes import CompressionTest

parser = argparse.ArgumentParser(prog='yade scripts/stability_sweep.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--steps', type=int, default=20000, help='steps per elastic run (default 20000)')
parser.add_argument('--tol', type=float, default=1e-3, help='largest shadow-energy error of a stable run (default 1e-3)')
parser.add_argument('--out', default='output/stability', help='folder of sweep.json and sweep.md')
parser.add_argument('--guard-cost', action='store_true', help="time RdemFiniteGuard on the paper's 1200-block scene")
parser.add_argument('--no-elastic', action='store_true', help='skip the elastic cases and the fast compression (with --contact or --guard-cost)')
parser.add_argument('--contact', action='store_true', help='also run the contact tests (cracked column, fast oblique impact, oblique drop) '
                    'with the automatic step at safety 0.8, 0.9 and 1.0')
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
	sc.setDtFraction(fraction)
	kin0, worst = O.energy['kinetic'], 0
	while test.displacement() < 0.3e-3:
		try:
			rdem.run(50)
		except RuntimeError:
			return math.inf, O.iter
		bal = O.energy['kinetic'] - kin0 + sc.elasticEnergy() + sc.dissipatedEnergy() - PLATEN['work']
		worst = max(worst, abs(bal) / max(PLATEN['work'], 1e-30) if PLATEN['work'] > 1 else 0)
		if not (worst < 0.05 and sc.stateIsFinite()):
			return worst, O.iter
	return worst, None


def linearFraction(build):
	"""(exact limit 2/omega_max, Lanczos estimate, Gershgorin estimate, Lanczos steps) of a fresh scene [s]."""
	ids = build()
	ts = rdem.timeStepper()
	lanczos, gershgorin = ts.estimate('lanczos'), ts.estimate('gershgorin')
	steps = ts.lanczosSteps
	return sc.exactCriticalDt(ids), lanczos, gershgorin, steps


def sweep(run):
	"""Runs at 0.5, 0.9, 0.95, 0.99, then up by 0.02 to the first unstable fraction, then bisection to 0.002."""
	runs = {}
	for f in (0.5, 0.9, 0.95, 0.99):
		runs[f] = run(f)
	f = 0.99
	while runs[f][1] is None and f < 3:
		f = round(f + 0.02, 4)
		runs[f] = run(f)
	lo, hi = max(k for k in runs if k < f), f
	while hi - lo > 0.002 and runs[hi][1] is not None:
		mid = round((lo + hi) / 2, 4)
		runs[mid] = run(mid)
		lo, hi = (mid, hi) if runs[mid][1] is None else (lo, mid)
	stable = max(k for k, v in runs.items() if v[1] is None)
	beyond = min((k for k, v in runs.items() if v[1] is not None and k > stable), default=None)
	return dict(runs={str(k): v for k, v in sorted(runs.items())}, largestStable=stable, firstUnstable=beyond, worstBelow1=max(runs[f][0] for f in (0.5, 0.9, 0.95, 0.99)))


results = {}
t0 = time.time()
if not cli.no_elastic:
	for name, build in ELASTIC.items():
		r = sweep(lambda f: elasticRun(build, f))
		exact, lanczos, gershgorin, steps = linearFraction(build)
		r.update(exactLimit=exact, lanczos=lanczos, gershgorin=gershgorin, lanczosSteps=steps, linear=exact / lanczos)
		results[name] = r
		print('%-28s worst(<1) %.2g  stable up to %.3f  unstable at %s (after %s steps)  Lanczos/exact %.5f (%d steps)  Gershgorin/exact %.3f  [%.0f s]' %
		      (name, r['worstBelow1'], r['largestStable'], r['firstUnstable'], r['runs'].get(str(r['firstUnstable']), [0, None])[1], lanczos / exact,
		       steps, gershgorin / exact, time.time() - t0),
		      flush=True)
	r = sweep(compressionRun)
	results['fast compression 4x4x4, 0.1 m/s'] = r
	print('%-28s worst(<1) %.2g  stable up to %.3f  unstable at %s (at step %s)' %
	      ('fast compression', r['worstBelow1'], r['largestStable'], r['firstUnstable'], r['runs'].get(str(r['firstUnstable']), [0, None])[1]),
	      flush=True)


def contactRuns():
	"""The contact cases of tests/yade/test_stability_contact.py and test_contact.py (their own checks: energy growth,
	penetration, rest) with rdem.engines(safety=s): (passed, what the test printed) per case and safety."""
	import contextlib
	import io
	import unittest
	import test_contact
	import test_stability_contact
	cases = [(test_stability_contact.StabilityContact, 'testCrackedColumnCollapses'), (test_stability_contact.StabilityContact, 'testFastObliqueImpact'),
	         (test_contact.Contact, 'testObliqueDropComesToRest')]
	engines, out = rdem.engines, {}
	try:
		for safety in (0.8, 0.9, 1.0):
			rdem.engines = lambda *a, **k: engines(*a, **dict(k, safety=safety))
			for cls, name in cases:
				text, result = io.StringIO(), unittest.TestResult()
				with contextlib.redirect_stdout(text):
					cls(name).run(result)
				ok = result.wasSuccessful()
				out['%s at %.1f' % (name, safety)] = dict(passed=ok, printed=text.getvalue().strip(), failures=[f[1][-400:] for f in result.failures + result.errors])
				print('%-28s safety %.1f: %s  %s' % (name, safety, 'passed' if ok else 'FAILED', text.getvalue().strip()), flush=True)
	finally:
		rdem.engines = engines
	return out


if cli.contact:
	sys.path.insert(0, os.path.join(ROOT, 'tests', 'yade'))
	results['contact'] = contactRuns()

if cli.guard_cost:
	O.reset()
	CompressionTest(blocksPerEdge=10, rate=1e-3)
	rdem.run(5)
	share, guardUs, stepUs = rdem.measure.engineShare(RdemFiniteGuard, 100)
	results['guard cost, 1200 blocks'] = dict(share=share, guardMicroseconds=guardUs, stepMicroseconds=stepUs)
	print('guard: %.2f %% of the step (%.1f us of %.0f us), 1200-block paper scene' % (100 * share, guardUs, stepUs), flush=True)

os.makedirs(cli.out, exist_ok=True)
with open(os.path.join(cli.out, 'sweep.json'), 'w') as f:
	json.dump(results, f, indent=1, default=lambda x: None if x is None else float(x))
print('wrote %s (%.0f s)' % (os.path.join(cli.out, 'sweep.json'), time.time() - t0))
