# -*- coding: utf-8 -*-
"""Wall time of the stability cases of tests/yade/test_stability.py, which the tests do not assert (it depends on the
machine and on what else runs on it).

Problem
    The elastic cases of the stability suite (tests/yade/stability_cases.py: free bonded grids of 2 cm concrete cubes
    at ν = 0.45 and 0.49, consistent formulation; the brick/mortar stack at 1:100 and 1:1000 stiffness contrast; the
    2×2×2 grid vibrating for 10⁶ steps), each run as in the test at 0.8 (0.9 for the stack) of the estimated critical
    step, and the fast compression scene (4×4×4 blocks at 0.1 m/s to 0.3 mm).

Expected result
    Each elastic case of 20 000 steps takes about a second on an idle core; the long vibration about a minute; the
    fast compression a few tens of seconds. On a loaded machine all of them take longer: compare medians of several
    rounds (--repeat), not single runs.

How to run
    build/bin/yade -n scripts/stability_timing.py [--cases nu45 nu49 contrast100 contrast1000 long compression] [--repeat 3]

Outputs (in --out, default output/stability-timing): results.json (per case: the wall times of the rounds, their
median, the steps and the time per step).
"""
import argparse
import json
import os
import statistics
import sys
import time

CASES = ('nu45', 'nu49', 'contrast100', 'contrast1000', 'long', 'compression')
parser = argparse.ArgumentParser(prog='yade scripts/stability_timing.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--cases', nargs='+', choices=CASES, default=list(CASES[:4]) + ['compression'], help='cases to time (default: all but long)')
parser.add_argument('--repeat', type=int, default=3, help='rounds per case; the median is reported (default 3)')
parser.add_argument('--out', default='output/stability-timing', help='output folder (default output/stability-timing)')
cli = parser.parse_args(sys.argv[1:])
if cli.repeat < 1:
	sys.exit('--repeat = %d: must be >= 1' % cli.repeat)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', 'tests', 'yade'))  # under YADE, __file__ names YADE's launcher
import stability_cases as sc  # noqa: E402 (the scenes of the test suite)
from yade import O  # noqa: E402
from yade import rdem  # noqa: E402
from yade.rdem.scenes import CompressionTest  # noqa: E402


def elastic(build, fraction, steps):
	ids = build()
	sc.perturb(ids, 0.01)
	if fraction:
		sc.setDtFraction(*fraction)
	t0 = time.time()
	sc.energyRun(steps)
	return time.time() - t0, steps


def compression():
	O.reset()
	test = CompressionTest(blocksPerEdge=4, rate=0.1, formulation='paper')
	t0 = time.time()
	while test.displacement() < 0.3e-3:
		rdem.run(100)
	return time.time() - t0, O.iter


RUNS = {
        'nu45': lambda: elastic(lambda: sc.grid(0.45, 'consistent'), (0.8, ), 20000),
        'nu49': lambda: elastic(lambda: sc.grid(0.49, 'consistent'), (0.8, ), 20000),
        'contrast100': lambda: elastic(lambda: sc.brickMortar(100), (0.9, 'gershgorin'), 20000),
        'contrast1000': lambda: elastic(lambda: sc.brickMortar(1000), (0.9, 'gershgorin'), 20000),
        'long': lambda: elastic(lambda: sc.grid(0.3, 'consistent', counts=(2, 2, 2)), (0.8, ), 10**6),
        'compression': compression,
}

os.makedirs(cli.out, exist_ok=True)
results = {}
for case in cli.cases:
	rounds = []
	for _ in range(cli.repeat):
		seconds, steps = RUNS[case]()
		rounds.append(seconds)
	median = statistics.median(rounds)
	results[case] = dict(seconds=rounds, median=median, steps=steps, secondsPerStep=median / steps)
	print('%-13s median %.2f s over %d rounds (%s), %d steps, %.3g s/step' % (case, median, cli.repeat, ', '.join('%.2f' % s for s in rounds), steps,
	                                                                         median / steps),
	      flush=True)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
print('stability timing: results in %s' % cli.out)
sys.exit(0)
