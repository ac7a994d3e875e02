# -*- coding: utf-8 -*-
"""The Poisson elements on a prism of two materials: RdemPoissonEngine.build's default against the paper's hexahedra.

Problem
    The stack-bonded prism of scripts/prism.py (rdem.scenes.MasonryPrism: three bricks E = 16.7 GPa, ν = 0.15, two
    10 mm layers of mortar E = 2 GPa, ν = 0.25, each layer its own blocks, frictionless platens), consistent formulation,
    every engine at its default (springs break on their own stress), built with ``--blocks`` × ``--blocks`` blocks in
    plan and with each of ``--elements``: ``auto`` (the default, which chooses Poisson cells for two materials), ``hex8``
    (the paper's hexahedra, which straddle brick and mortar with one blended λ) or ``cells``. Loaded to 1 MPa and left
    to come to rest.

Expected result (doc/theory.md §5.5, doc/defaults.md)
    The interior lateral strain of the middle brick over that of the infinite layered medium: within a few % of 1 with
    cells; the hexahedra miss the mortar's lateral push on the brick.

How to run (about a minute for 20 × 20 blocks)
    build/bin/yade -n scripts/prism_elements.py [--blocks 20] [--elements auto hex8] [--out output/prism-elements]

Outputs (in --out): results.json (per choice: what build chose and why, the ratio, steps).
"""
import argparse
import json
import math
import os
import sys

parser = argparse.ArgumentParser(prog='yade scripts/prism_elements.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--blocks', type=int, default=20, help='blocks across the prism (default 20)')
parser.add_argument('--elements', nargs='+', choices=['auto', 'hex8', 'cells'], default=['auto', 'hex8'], help='what build makes (default: auto hex8)')
parser.add_argument('--out', default='output/prism-elements', help='output folder (default output/prism-elements)')
cli = parser.parse_args(sys.argv[1:])
if cli.blocks < 2:
	sys.exit('--blocks = %d: must be >= 2 (the interior strain needs two blocks across)' % cli.blocks)

from yade import O  # noqa: E402
from yade.wrapper import RdemMat, RdemJoint  # noqa: E402
from yade import rdem  # noqa: E402
from yade.rdem import scenes  # noqa: E402

results = {}
for elements in cli.elements:
	O.reset()
	brick = RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, cohesion=6e6, label='brick')
	mortar = RdemMat(young=2e9, poisson=0.25, density=1800, tensileStrength=2e6, cohesion=4e6, label='mortar')
	bond = RdemJoint(tensileStrength=0.5e6, cohesion=1e6, frictionAngle=math.atan(0.75))
	poissonEngine = scenes.build.poissonEngine
	if elements != 'auto':  # MasonryPrism calls build with the engine's elements: set them on the way
		scenes.build.poissonEngine = lambda: (lambda e: (setattr(e, 'elements', elements), e)[1])(poissonEngine())
	try:
		p = scenes.MasonryPrism(brick, mortar, bond, blocks=cli.blocks, rate=0.05, failureStress='spring')
	finally:
		scenes.build.poissonEngine = poissonEngine
	while p.stress() < 1e6:
		rdem.run(50)
	p.settle(1e-5)
	ratio = p.lateralStrain() / (p.closedForm() * p.stress())
	results[elements] = dict(chosen=rdem.poissonEngine().chosen, ratio=ratio, steps=O.iter)
	print('%s: %s; lateral strain / layered medium %.4f (%d steps)' % (elements, rdem.poissonEngine().chosen, ratio, O.iter), flush=True)
os.makedirs(cli.out, exist_ok=True)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(dict(blocks=cli.blocks, results=results), f, indent=1)
print('prism elements: results in %s' % cli.out)
sys.exit(0)
