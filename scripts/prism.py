# -*- coding: utf-8 -*-
"""A stack-bonded masonry prism under compression: the brick–mortar Poisson mismatch that splits bricks (Hilsdorf 1969).

Problem
    Three bricks 200×200×50 mm and two mortar layers 10 mm thick, all mortar made of blocks of its own (the *layer*
    model), each layer cut into 4×4 blocks, between frictionless platens (one plate block per column). Brick
    E = 16.7 GPa, ν = 0.15, f_t = 3 MPa; mortar E = 2 GPa, ν = 0.25 (the soft mortar of issue #15's example); brick–mortar
    bond f_t = 0.5 MPa, cohesion 1 MPa. Consistent formulation with Poisson cells (doc/theory.md §5.4), springs breaking on
    the total normal stress of their face (§5.6). The same prism is run a second time with a mortar of the brick's E and ν.

Expected result (doc/theory.md §5.5)
    Elastic phase: the lateral strain of the middle brick's interior equals that of an infinite bonded stack of the same
    layers, e/σ = Σ t λ/M / Σ t (2(λ+μ) - 2λ²/M), within a few %: the soft mortar expands more than the brick and drags it
    along, so the brick is in lateral tension and the mortar in lateral compression. Loaded further, the brick cracks
    vertically at σ ≈ f_t/(its lateral stress per unit σ) (5.5 % of σ in the infinite stack); the prism whose mortar is
    the brick's material has no lateral stress at all and does not crack at that load.

How to run
    build/bin/yade -n scripts/prism.py                 (about a minute)
    build/bin/yade -n scripts/prism.py --help

Outputs (in --out, default output/prism): results.json, prism.png (stress–displacement of both prisms, and the cracks of
the soft-mortar prism seen from the front), ParaView files in vtk/ (blocks and cracks at the end of each run).
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/prism.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--blocks', type=int, default=4, help='blocks across the prism (default 4)')
parser.add_argument('--brick-ft', type=float, default=3.0, help='tensile strength of the brick [MPa] (default 3)')
parser.add_argument('--mortar-E', type=float, default=2.0, help="Young's modulus of the soft mortar [GPa] (default 2)")
parser.add_argument('--mortar-nu', type=float, default=0.25, help="Poisson's ratio of the soft mortar (default 0.25)")
parser.add_argument('--rate', type=float, default=10.0, help='loading rate of the top plate [mm/s] (default 10)')
parser.add_argument('--max-stress', type=float, default=100.0, help='stop a run at this stress if nothing cracked [MPa] (default 100)')
parser.add_argument('--out', default='output/prism', help='output folder (default output/prism)')
cli = parser.parse_args(sys.argv[1:])
for name in ('rate', 'max_stress', 'brick_ft', 'mortar_E'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name.replace('_', '-'), getattr(cli, name)))

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, Vector3, VTKRecorder
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem
from yade.rdem.scenes import MasonryPrism

os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)
BRICK = dict(young=16.7e9, poisson=0.15, density=1800, tensileStrength=cli.brick_ft * 1e6, cohesion=2 * cli.brick_ft * 1e6, label='brick')
BOND = RdemJoint(tensileStrength=0.5e6, cohesion=1e6, frictionAngle=math.atan(0.75))


def run(label, mortarYoung, mortarNu):
	"""Elastic check, then loading to the first brick crack or --max-stress. Returns a dict of results."""
	O.reset()
	brick = RdemMat(**BRICK)
	mortar = RdemMat(young=mortarYoung, poisson=mortarNu, density=1800, tensileStrength=2e6, cohesion=4e6, label='mortar')
	p = MasonryPrism(brick, mortar, BOND, blocks=cli.blocks, rate=cli.rate * 1e-3)
	snapshot = rdem.measure.bondSnapshot()
	t0 = time.time()
	history = dict(disp=[], stress=[])
	# 1. Elastic phase, static: load to 1 MPa, hold the plate and let the prism come to rest with Cundall's damping, then
	#    compare the lateral strain of the middle brick's interior with the infinite stack's.
	while p.stress() < 1e6:
		rdem.run(50)
		history['disp'].append(p.displacement())
		history['stress'].append(p.stress())
	p.settle(1e-5)  # at rest: the measure no longer moves
	elastic = dict(stressMPa=p.stress() * 1e-6, lateralStrain=p.lateralStrain(), closedForm=p.closedForm() * p.stress())
	elastic['ratio'] = elastic['lateralStrain'] / elastic['closedForm']
	inside = [I for I in O.interactions if I.id1 in p.brickSet and I.id2 in p.brickSet]
	elastic['brickLateralStressPerStress'] = max(rdem.measure.totalNormalStress(I) for I in inside) / p.stress()
	elastic['predictedCrackStressMPa'] = BRICK['tensileStrength'] / elastic['brickLateralStressPerStress'] * 1e-6 if elastic[
	        'brickLateralStressPerStress'] > 0 else None
	for i in p.top:
		O.bodies[i].state.vel = Vector3(0, 0, -cli.rate * 1e-3)
	# 2. Loading to the first crack inside a brick (or --max-stress).
	first = None
	while p.stress() < cli.max_stress * 1e6:
		rdem.run(50)
		history['disp'].append(p.displacement())
		history['stress'].append(p.stress())
		cracks = p.brickCracks(snapshot)
		if cracks and first is None:
			first = dict(stressMPa=history['stress'][-2] * 1e-6, displacementMm=history['disp'][-2] * 1e3, springs=len(cracks),
			             vertical=all(abs(s['normal'][2]) < 0.05 for s in cracks))  # faces within 3° of vertical
			rdem.run(200)  # let the crack open for the picture
			break
		if O.iter % 5000 == 0:
			print('%s: step %d, stress %.2f MPa, breaks %s' % (label, O.iter, p.stress() * 1e-6, rdem.breakCounts()), flush=True)
	segs = rdem.brokenSegments(snapshot)
	VTKRecorder(fileName=os.path.join(cli.out, 'vtk', label + '.blocks.'), recorders=['boxes'])()
	exp = rdem.CrackExport(os.path.join(cli.out, 'vtk', label + '.'))
	exp.snapshot = snapshot
	exp.write()
	exp.close()
	res = dict(label=label, layers=p.layers, mortarYoung=mortarYoung, mortarPoisson=mortarNu, elastic=elastic, firstBrickCrack=first,
	           brokenSprings=dict(zip(('tension', 'shear'), rdem.breakCounts())), steps=O.iter, wallSeconds=time.time() - t0, history=history,
	           cracks=[dict(point=list(s['point']), normal=list(s['normal']), state=s['state']) for s in segs])
	print('%s: elastic lateral strain %.4g against %.4g closed form (ratio %.4f) at %.2f MPa; largest total lateral stress in a brick %.4f sigma; '
	      'first brick crack %s; %d steps in %.1f s' %
	      (label, elastic['lateralStrain'], elastic['closedForm'], elastic['ratio'], elastic['stressMPa'], elastic['brickLateralStressPerStress'],
	       'at %.2f MPa (%s)' % (first['stressMPa'], 'vertical' if first['vertical'] else 'not vertical') if first else 'none up to %.0f MPa' % cli.max_stress,
	       O.iter, res['wallSeconds']),
	      flush=True)
	return res


soft = run('soft', cli.mortar_E * 1e9, cli.mortar_nu)
same = run('same', BRICK['young'], BRICK['poisson'])
results = dict(input=vars(cli), soft=soft, sameMaterial=same)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)

fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
ax = axes[0]
for r, name in ((soft, 'soft mortar (E = %g GPa, ν = %g)' % (cli.mortar_E, cli.mortar_nu)), (same, "mortar of the brick's E and ν")):
	ax.plot([1e3 * d for d in r['history']['disp']], [1e-6 * s for s in r['history']['stress']], label=name)
	if r['firstBrickCrack']:
		ax.plot([r['firstBrickCrack']['displacementMm']], [r['firstBrickCrack']['stressMPa']], 'ro')
ax.set_xlabel('displacement of the loading plate [mm]')
ax.set_ylabel('mean compressive stress [MPa]')
ax.legend()
ax = axes[1]
for kind, z0, z1 in soft['layers']:
	ax.add_patch(plt.Rectangle((0, z0), 0.2, z1 - z0, fc=(.72, .33, .22) if kind == 'brick' else (.8, .8, .75), ec='k', lw=0.3))
for c in soft['cracks']:
	if abs(c['normal'][0]) > 0.9:  # faces normal to x: seen edge-on from the front
		ax.plot([c['point'][0]] * 2, [c['point'][2] - 0.012, c['point'][2] + 0.012], 'r-', lw=2)
ax.set_xlim(-0.01, 0.21)
ax.set_ylim(-0.01, 0.18)
ax.set_aspect('equal')
ax.set_title('soft-mortar prism: broken springs (faces normal to x)')
ax.set_xlabel('x [m]')
ax.set_ylabel('z [m]')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'prism.png'), dpi=120)
print('prism: results in %s' % cli.out)
sys.exit(0)
