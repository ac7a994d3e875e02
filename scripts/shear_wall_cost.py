# -*- coding: utf-8 -*-
"""What one step of a shear-wall run costs: µs per block-step of a saved wall, medians over rounds.

Problem
    A state saved by scripts/shear_wall.py (``--save FILE``: the wall, its bonds and cracks, the engines, the top beam
    moving at the loading rate) is loaded and run for ``--steps`` steps, ``--rounds`` times, each round from the saved
    state again (the same work every round), timed with time.perf_counter around O.step() (doc/performance.md, "How to
    read these figures"). The threads are YADE's (``yade -jN``). Under callgrind the instruction count per
    block-step is the figure that does not move with the machine's load (doc/performance.md): run with ``--rounds 1``
    and two step counts, and take the difference (the first step after loading tests every pair again).

Expected result
    A few µs per block-step on one thread for a wall of about 10³ blocks; two threads faster by less than 2× (the
    2-core machine is shared); the softening law costs more per step than the brittle springs only while segments
    soften (an intact softening segment runs the return mapping's elastic branch).

How to run
    build/bin/yade -n scripts/shear_wall.py --softening on --drift 0.1 --stop-drop 0 --vtk-every 0 --save /tmp/wall.yade.gz
    build/bin/yade -n -j1 scripts/shear_wall_cost.py --state /tmp/wall.yade.gz --steps 300 --rounds 3
    build/bin/yade -n -j2 scripts/shear_wall_cost.py --state /tmp/wall.yade.gz --steps 300 --rounds 3
    valgrind --tool=callgrind --collect-atstart=no --toggle-collect='yade::Scene::moveToNextTimeStep()' \\
        build/bin/yade -n scripts/shear_wall_cost.py --state /tmp/wall.yade.gz --steps 40 --rounds 1

Outputs: one line per round and a summary (median, min, max µs per block-step, threads) on stdout; with ``--json``, the
same in that file.
"""
import argparse
import json
import statistics
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/shear_wall_cost.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--state', required=True, help='a scene saved by scripts/shear_wall.py --save')
parser.add_argument('--steps', type=int, default=300, help='steps per round (default 300)')
parser.add_argument('--rounds', type=int, default=3, help='rounds, each from the saved state (default 3)')
parser.add_argument('--json', default='', help='also write the figures to this JSON file (default none)')
cli = parser.parse_args(sys.argv[1:])
if cli.steps < 1 or cli.rounds < 1:
	sys.exit('--steps = %d, --rounds = %d: both must be >= 1' % (cli.steps, cli.rounds))

from yade import rdem  # noqa: F401 (the plugin's classes for O.load)
from yade import O

perBlockStep = []
for k in range(cli.rounds):
	O.load(cli.state)
	blocks = len(O.bodies)
	t0 = time.perf_counter()
	for _ in range(cli.steps):
		O.step()
	seconds = time.perf_counter() - t0
	perBlockStep.append(1e6 * seconds / (cli.steps * blocks))
	print('shear_wall_cost: round %d: %d steps of %d bodies in %.3f s, %.3f us per block-step (%d threads)' %
	      (k + 1, cli.steps, blocks, seconds, perBlockStep[-1], O.numThreads),
	      flush=True)
summary = dict(state=cli.state, steps=cli.steps, rounds=cli.rounds, threads=O.numThreads, bodies=len(O.bodies), microsecondsPerBlockStep=perBlockStep,
               median=statistics.median(perBlockStep), min=min(perBlockStep), max=max(perBlockStep))
print('shear_wall_cost: median %.3f us per block-step (%.3f-%.3f over %d rounds), %d threads, %s' %
      (summary['median'], summary['min'], summary['max'], cli.rounds, O.numThreads, cli.state))
if cli.json:
	with open(cli.json, 'w') as f:
		json.dump(summary, f, indent=1)
sys.exit(0)
