# -*- coding: utf-8 -*-
"""What the Poisson effect costs on masonry: cells on a running-bond wall against the paper's hexahedra on a grid of the
same block count, and the set-up time of a 10⁵-block wall.

Problem
    1. Two walls of the same size and bricks (250×120×55 mm, 10 mm interface joints, two wythes, one block per brick):
       stack bond, a grid of 2×2×2 groups, which gets the paper's hexahedra (consistent formulation with skin), and
       running bond, which gets Poisson cells (doc/theory.md §5.4) and the offset correction of its bed joints. Both in
       vertical compression between beams, elastic. Per-engine times from YADE's O.timingEnabled over --steps steps,
       in --rounds rounds alternating the two walls: the Poisson part (RdemCellStrainUpdater + RdemPoissonEngine), the
       interaction loop (which applies the offset correction) and the whole step, in µs per block and step; medians and
       spread over the rounds (this virtual machine's speed varies from minute to minute).
    2. Set-up time of a running-bond wall of about 10⁵ blocks (bricks cut into 3×1×6 blocks, which do not line up across
       the joints, so cells): layout, bodies and bonds (rdem.masonry.wall), cells (RdemPoissonEngine.build), first step.

Expected result
    Goals of issue #15: the Poisson part of a step per block on the running-bond wall no more than 1.3 times the grid's;
    the 10⁵-block wall set up in under 30 s.

How to run (about two minutes)
    build/bin/yade -n scripts/masonry_cost.py [--bricks 20 --courses 25] [--rounds 5] [--out doc/masonry-cost.md]
"""
import argparse
import json
import math
import os
import statistics
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/masonry_cost.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--bricks', type=int, default=20, help='stretchers per course (default 20)')
parser.add_argument('--courses', type=int, default=25, help='courses (default 25)')
parser.add_argument('--steps', type=int, default=2000, help='timed steps per round and wall (default 2000)')
parser.add_argument('--rounds', type=int, default=5, help='rounds, alternating the walls (default 5)')
parser.add_argument('--no-setup', action='store_true', help='skip the 1e5-block set-up timing')
parser.add_argument('--out', default='doc/masonry-cost.md', help='markdown report (default doc/masonry-cost.md; a .json beside it)')
cli = parser.parse_args(sys.argv[1:])
for name in ('bricks', 'courses', 'steps', 'rounds'):
	if getattr(cli, name) < 1:
		sys.exit('--%s = %d: must be >= 1' % (name, getattr(cli, name)))

from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem

L, W, H, T = 0.25, 0.12, 0.055, 0.01


def wall(bond, bricks, courses, blocks=(1, 1, 1), thickness=2 * W + T, elements='auto'):
	"""A wall in vertical compression between beams, elastic (infinite strengths); returns (wall, set-up breakdown)."""
	O.reset()
	times = {}
	t = time.time()
	brick = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=float('inf'), cohesion=float('inf'), label='brick'))
	joint = RdemJoint(young=2e9, poisson=0.25, tensileStrength=float('inf'), cohesion=float('inf'))
	O.engines = rdem.engines(formulation='consistent', recontact=False)
	w = rdem.masonry.wall(bricks * (L + T) - T, courses * (H + T) - T, thickness, bond=bond, blocksPerBrick=blocks, baseBeam=0.1, topBeam=0.1,
	                      brickMaterial=brick, jointMaterial=joint)
	times['wall'] = time.time() - t
	for i in w.beams['base'] + w.beams['top']:
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	for i in w.beams['top']:
		O.bodies[i].state.vel = Vector3(0, 0, -0.01)
	t = time.time()
	rdem.poissonEngine().elements = elements
	rdem.poissonEngine().build(w.masonry())  # the beams, one block over many bricks, stay out: the stack-bond wall is then a grid
	times['poisson'] = time.time() - t
	t = time.time()
	O.step()
	times['firstStep'] = time.time() - t
	return w, times


class _Ids:
	def __init__(self, ids):
		self.ids = ids


def cube():
	"""The paper's scene with the consistent formulation (rdem.scenes.CompressionTest, 10³ blocks and two plates, 891
	hexahedra): a 2×2×2 grid with about one element per block, elastic."""
	O.reset()
	from yade.rdem.scenes import CompressionTest
	test = CompressionTest(blocksPerEdge=10, formulation='consistent', tensileStrength=float('inf'))
	O.step()
	return _Ids(test.ids)


def timing(w):
	"""µs per block-step of the Poisson part, the interaction loop and the whole step over --steps steps."""
	O.run(200, True)  # warm-up
	O.timingEnabled = True
	for e in O.engines:
		e.execTime = 0
	t = time.perf_counter()
	for _ in range(cli.steps):
		O.step()
	total = time.perf_counter() - t
	O.timingEnabled = False
	byName = {type(e).__name__: e.execTime * 1e-9 for e in O.engines}  # execTime in ns
	per = 1e6 / (cli.steps * len(w.ids))
	return dict(poisson=(byName.get('RdemCellStrainUpdater', 0) + byName['RdemPoissonEngine']) * per, loop=byName.get('RdemInteractionLoop', byName.get('InteractionLoop', 0)) * per, step=total * per)


results = dict(input=vars(cli), rounds=[])
for r in range(cli.rounds):
	for case in ('cube', 'stack', 'stack-cells', 'running'):
		bond = case.split('-')[0]
		w = cube() if case == 'cube' else wall(bond, cli.bricks, cli.courses, elements='cells' if case.endswith('cells') else 'auto')[0]
		eng = rdem.poissonEngine()
		row = dict(round=r, bond=case, blocks=len(w.ids), elements=eng.nElements, cells=eng.nCells, **timing(w))
		results['rounds'].append(row)
		print('round %d %-12s %5d blocks, %4d elements, %4d cells: Poisson %.4f, interaction loop %.4f, step %.4f us per block-step' %
		      (r, case, row['blocks'], row['elements'], row['cells'], row['poisson'], row['loop'], row['step']),
		      flush=True)


def stats(bond, key):
	v = [x[key] for x in results['rounds'] if x['bond'] == bond]
	return statistics.median(v), min(v), max(v)


summary = {bond: {key: stats(bond, key) for key in ('poisson', 'loop', 'step')} for bond in ('cube', 'stack', 'stack-cells', 'running')}
def ratio(a, b):
	r = [x['poisson'] / y['poisson'] for x, y in zip([x for x in results['rounds'] if x['bond'] == a], [x for x in results['rounds'] if x['bond'] == b])]
	return statistics.median(r), min(r), max(r)


summary['poissonRatio'] = ratio('running', 'stack')
summary['poissonRatioCube'] = ratio('running', 'cube')
results['summary'] = summary
if not cli.no_setup:
	w, setup = wall('running', 60, 45, blocks=(3, 1, 6))
	results['setup'] = dict(blocks=len(w.ids), bonds=w.nBonds, cells=rdem.poissonEngine().nCells, **setup)
	print('set-up of a %d-block wall: rdem.masonry.wall %.1f s, Poisson cells %.1f s, first step %.2f s' %
	      (len(w.ids), setup['wall'], setup['poisson'], setup['firstStep']),
	      flush=True)

with open(os.path.splitext(cli.out)[0] + '.json', 'w') as f:
	json.dump(results, f, indent=1)
fmt = lambda t: '%.4f (%.4f–%.4f)' % t
with open(cli.out, 'w') as f:
	f.write('# What the Poisson effect costs on masonry\n\n')
	f.write('Made by `build/bin/yade -n scripts/masonry_cost.py --bricks %d --courses %d --steps %d --rounds %d` on %s (one thread). '
	        'Walls of %d stretchers × %d courses, two wythes, 250×120×55 mm bricks, one block per brick, 10 mm interface joints, '
	        'elastic vertical compression between beams. µs per block and step: median (min–max) over the rounds.\n\n' %
	        (cli.bricks, cli.courses, cli.steps, cli.rounds, time.strftime('%Y-%m-%d'), cli.bricks, cli.courses))
	f.write('| wall | blocks | Poisson | Poisson part (updater + engine) | interaction loop | whole step |\n|---|---|---|---|---|---|\n')
	for bond, label in (('cube', "the paper's scene, consistent (a cube of 10³ blocks and two plates)"), ('stack', 'stack bond (grid)'),
	                    ('stack-cells', 'stack bond (grid), cells asked for'), ('running', 'running bond')):
		row = [x for x in results['rounds'] if x['bond'] == bond][0]
		kind = '%d hexahedra' % row['elements'] if row['elements'] else '%d cells' % row['cells']
		f.write('| %s | %d | %s | %s | %s | %s |\n' % (label, row['blocks'], kind, fmt(summary[bond]['poisson']), fmt(summary[bond]['loop']), fmt(summary[bond]['step'])))
	f.write('\nPoisson part per block, running bond (cells) over the stack-bond wall (hexahedra): **%.2f** (%.2f–%.2f over the rounds); over the '
	        'cube of hexahedra: **%.2f** (%.2f–%.2f); goal ≤ 1.3.\n' % (summary['poissonRatio'] + summary['poissonRatioCube']))
	if 'setup' in results:
		s = results['setup']
		f.write('\nSet-up of a running-bond wall of %d blocks (60 stretchers × 45 courses, two wythes, bricks of 3×1×6 blocks, %d bonds, %d cells): '
		        '`rdem.masonry.wall` (layout, bodies, bonds) %.1f s, `RdemPoissonEngine.build` %.1f s, first step %.2f s: **%.1f s** in all; goal < 30 s.\n' %
		        (s['blocks'], s['bonds'], s['cells'], s['wall'], s['poisson'], s['firstStep'], s['wall'] + s['poisson'] + s['firstStep']))
print('masonry_cost: report in %s' % cli.out)
sys.exit(0)
