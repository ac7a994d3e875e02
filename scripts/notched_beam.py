# -*- coding: utf-8 -*-
"""Notched beam in three-point bending at three block sizes: is the peak load independent of the mesh?

Problem
    A concrete beam (default 0.45 × 0.1 m, 0.05 m thick; E = 30 GPa, ν = 0.2, f_t = 3 MPa, G_f^I = 100 J/m²,
    2400 kg/m³), one block through its thickness and n blocks over its depth, rests on two supports 0.4 m apart (the
    bottom blocks nearest x = ±S/2, held vertically) and is loaded at mid-span by the two top blocks there, moved down at
    a constant speed. A zero-width notch of a quarter of the depth at mid-span (no bonds across x = 0 below it) fixes
    where the crack starts. Each mesh is run with softening springs (rdem.engines(softening=True), doc/theory.md §2.1)
    and with the paper's brittle springs. The Poisson effect is off (bending of a beam one block thick).

Expected result
    With softening, the crack dissipates G_f per unit area whatever the block size, so the peak load converges as the
    blocks shrink (issue #18, must-show 2: within 5 % over the three sizes); with the brittle springs the stress at the
    notch tip grows as the blocks shrink and the peak load falls. Compared as the nominal strength 3PS/(2BD²), S the
    distance between the supports' block centres (it moves slightly with the block size).

How to run (about 9 minutes for the default three sizes, both laws, on this project's shared 2-core machine; the
finest softening run alone 5-6 minutes)
    build/bin/yade -n scripts/notched_beam.py [--depths 4 8 16] [--laws softening brittle] [--out output/notched_beam]
    build/bin/yade -n scripts/notched_beam.py --depths 8 --strength-cov 0.2 --per-segment --seeds 1 2 3 4 5
                                                  heterogeneity: first-crack and peak scatter over five seeds
    build/bin/yade -n scripts/notched_beam.py --help

Outputs (in --out, default output/notched_beam): results.json, load_deflection.png, ParaView files of each run's blocks
at the end in vtk/; the table on stdout; with --doc, the figure in doc/figures/notched_beam.png (doc/validation.md).
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/notched_beam.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--depths', type=int, nargs='+', default=[4, 8, 16], help='blocks over the depth (default 4 8 16)')
parser.add_argument('--laws', nargs='+', choices=['softening', 'brittle'], default=['softening', 'brittle'], help='spring laws (default both)')
parser.add_argument('--length', type=float, default=0.45, help='beam length [m] (default 0.45)')
parser.add_argument('--span', type=float, default=0.4, help='distance between the supports [m] (default 0.4)')
parser.add_argument('--depth', type=float, default=0.1, help='beam depth D [m] (default 0.1)')
parser.add_argument('--thickness', type=float, default=0.05, help='beam thickness B [m] (default 0.05)')
parser.add_argument('--notch', type=float, default=0.25, help='notch depth / D (default 0.25)')
parser.add_argument('--young', type=float, default=30.0, help="Young's modulus E [GPa] (default 30)")
parser.add_argument('--ft', type=float, default=3.0, help='tensile strength [MPa] (default 3)')
parser.add_argument('--gf', type=float, default=100.0, help='mode-I fracture energy [J/m2] (default 100)')
parser.add_argument('--rate', type=float, default=2.0, help='loading rate: speed of the loaded blocks [mm/s] (default 2)')
parser.add_argument('--end', type=float, default=0.12, help='deflection at which a run stops [mm] (default 0.12)')
parser.add_argument('--stop-drop', type=float, default=0.5, help='stop a run once the load has fallen below this fraction of its peak, past a quarter of --end (default 0.5; 0: never)')
parser.add_argument('--strength-cov', type=float, default=0.0, help='coefficient of variation of the strengths (rdem.engines(strengthCoV=); default 0: uniform)')
parser.add_argument('--per-segment', action='store_true', help='with --strength-cov: one strength factor per segment (spring) instead of per bond')
parser.add_argument('--seeds', type=int, nargs='+', default=[0], help='seeds of the strengths: one run per seed (default 0)')
parser.add_argument('--damping', type=float, default=0.2, help="Cundall's non-viscous damping of the integrator (default 0.2)")
parser.add_argument('--out', default='output/notched_beam', help='output folder (default output/notched_beam)')
parser.add_argument('--doc', action='store_true', help='also write the figure to doc/figures/notched_beam.png')
cli = parser.parse_args(sys.argv[1:])
for name in ('length', 'span', 'depth', 'thickness', 'young', 'ft', 'gf', 'rate', 'end'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name, getattr(cli, name)))
if not cli.span < cli.length:
	sys.exit('--span = %g: must be less than --length = %g' % (cli.span, cli.length))
if not cli.strength_cov >= 0:
	sys.exit('--strength-cov = %g: must be >= 0' % cli.strength_cov)
if not 0 <= cli.stop_drop < 1:
	sys.exit('--stop-drop = %g: must be in [0, 1)' % cli.stop_drop)
if not 0 < cli.notch < 1:
	sys.exit('--notch = %g: must be in (0, 1)' % cli.notch)
if any(n < 2 for n in cli.depths):
	sys.exit('--depths: each must be >= 2')

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, Vector3, VTKRecorder
from yade.wrapper import RdemMat
from yade import rdem

os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)


def build(ny, softening, seed):
	"""The beam of ny blocks over the depth (square in the plane of bending); returns (supports, loaded, span)."""
	O.reset()
	b = cli.depth / ny
	nx = 2 * int(round(cli.length / b / 2))  # even: mid-span is a block boundary
	mat = O.materials.append(RdemMat(young=cli.young * 1e9, poisson=0.2, density=2400, tensileStrength=cli.ft * 1e6, cohesion=2 * cli.ft * 1e6, fractureEnergy=cli.gf,
	                                 shearFractureEnergy=10 * cli.gf))
	O.engines = rdem.engines(formulation=None, recontact=True, damping=cli.damping, softening=softening, strengthCoV=cli.strength_cov,
	                         strengthPerSegment=cli.per_segment, seed=seed)
	x0 = -nx * b / 2
	rdem.blockGrid((nx, 1, ny), (b, cli.thickness, b), material=mat, origin=(x0, -cli.thickness / 2, 0))
	rdem.bond(range(len(O.bodies)))
	pos = {body.id: body.state.pos for body in O.bodies}  # blocks by their grid cell (column, row)
	col = lambda x: int(math.floor((x - x0) / b))
	row = lambda z: int(math.floor(z / b))
	grid = {(col(p[0]), row(p[2])): i for i, p in pos.items()}
	notchRows = int(round(cli.notch * ny))
	for k in range(notchRows):  # the notch: no bond across x = 0 in the lowest rows
		O.interactions.erase(grid[(nx // 2 - 1, k)], grid[(nx // 2, k)])
	ia = min(range(nx), key=lambda i: abs(x0 + (i + 0.5) * b + cli.span / 2))
	supports = [grid[(ia, 0)], grid[(nx - 1 - ia, 0)]]
	for i in supports:
		O.bodies[i].state.blockedDOFs = 'z'
	loaded = [grid[(nx // 2 - 1, ny - 1)], grid[(nx // 2, ny - 1)]]
	for i in loaded:
		O.bodies[i].state.blockedDOFs = 'z'
		O.bodies[i].state.vel = Vector3(0, 0, -cli.rate * 1e-3)
	span = (nx - 1 - 2 * ia) * b
	return supports, loaded, span


def cracked(softening):
	"""Whether a spring has cracked: broken (brittle), or begun to soften (softening: the onset of the crack)."""
	if not softening:
		return sum(rdem.breakCounts()) > 0
	return any(x > 0 for i in O.interactions if i.isReal for x in i.phys.segSoftening)


def run(ny, softening, seed):
	supports, loaded, span = build(ny, softening, seed)
	first = None
	O.step()
	z0 = O.bodies[loaded[0]].state.pos[2]
	hist = dict(deflection=[], load=[])
	wall0, last = time.time(), time.time()
	steps = int(cli.end / cli.rate / O.dt)
	while z0 - O.bodies[loaded[0]].state.pos[2] < cli.end * 1e-3:
		O.run(max(1, steps // 400), True)
		hist['deflection'].append(z0 - O.bodies[loaded[0]].state.pos[2])
		hist['load'].append(sum(O.forces.f(i)[2] for i in loaded))
		if first is None and cracked(softening):
			first = hist['load'][-1]
		if hist['deflection'][-1] > cli.end * 1e-3 / 4 and hist['load'][-1] < cli.stop_drop * max(hist['load']):  # past the start's vibrations
			break
		if time.time() - last > 10:
			last = time.time()
			print('  depth %d, %s: step %d of about %d, load %.0f N' % (ny, 'softening' if softening else 'brittle', O.iter, steps, hist['load'][-1]), flush=True)
	wall = time.time() - wall0
	peak = max(hist['load'])
	VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'beam-%d-%s-%d.' % (ny, 'softening' if softening else 'brittle', seed)), recorders=['boxes'])()
	return dict(blocksOverDepth=ny, blocks=len(O.bodies), law='softening' if softening else 'brittle', seed=seed, span=span, peakLoad=peak, firstCrackLoad=first,
	            nominalStrength=3 * peak * span / (2 * cli.thickness * cli.depth**2), dt=O.dt, steps=O.iter, wallSeconds=wall, history=hist)


def meanCoV(x):
	m = sum(x) / len(x)
	return m, (math.sqrt(sum((v - m)**2 for v in x) / (len(x) - 1)) / m if len(x) > 1 else 0.0)


def summarize(runs):
	"""Per law: the spread of the nominal strength over the meshes (first seed); per law and mesh: mean and CoV over the
	seeds of the peak load and of the load at the first crack."""
	summary = {}
	for law in cli.laws:
		s = [r['nominalStrength'] for r in runs if r['law'] == law and r['seed'] == cli.seeds[0]]
		if s:
			summary[law] = dict(spread=(max(s) - min(s)) / max(s), strengths=s, seeds={})
		for ny in cli.depths:
			rs = [r for r in runs if r['law'] == law and r['blocksOverDepth'] == ny]
			if rs:
				peak, first = meanCoV([r['peakLoad'] for r in rs]), meanCoV([r['firstCrackLoad'] or 0.0 for r in rs])
				summary[law]['seeds'][ny] = dict(n=len(rs), peakMean=peak[0], peakCoV=peak[1], firstCrackMean=first[0], firstCrackCoV=first[1])
	return summary


runs = []
for law in cli.laws:
	for ny in cli.depths:
		for seed in cli.seeds:
			print('depth %d blocks, %s springs, seed %d' % (ny, law, seed), flush=True)
			runs.append(run(ny, law == 'softening', seed))
			print('  peak load %.0f N, nominal strength %.3f MPa, first crack at %s, %d steps, %.1f s' %
			      (runs[-1]['peakLoad'], runs[-1]['nominalStrength'] / 1e6, '%.0f N' % runs[-1]['firstCrackLoad'] if runs[-1]['firstCrackLoad'] else '-',
			       runs[-1]['steps'], runs[-1]['wallSeconds']),
			      flush=True)
			with open(os.path.join(cli.out, 'results.json'), 'w') as f:  # after every run: the runs so far
				json.dump(dict(input=vars(cli), runs=runs, summary=summarize(runs)), f, indent=1)
summary = summarize(runs)

fig, ax = plt.subplots(figsize=(7, 4.5))
for r in runs:
	ax.plot([d * 1e3 for d in r['history']['deflection']], [p / 1e3 for p in r['history']['load']], '-' if r['law'] == 'softening' else '--',
	        label='%s, %d blocks over the depth%s' % (r['law'], r['blocksOverDepth'], ', seed %d' % r['seed'] if len(cli.seeds) > 1 else ''))
ax.set_xlabel('mid-span deflection [mm]')
ax.set_ylabel('load [kN]')
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'load_deflection.png'), dpi=120)

lines = ['| law | blocks over depth | seed | blocks | span [m] | first crack [kN] | peak load [kN] | nominal strength [MPa] | steps | wall [s] |',
         '|---|---|---|---|---|---|---|---|---|---|']
for r in runs:
	lines.append('| %s | %d | %d | %d | %.4f | %s | %.3f | %.3f | %d | %.1f |' %
	             (r['law'], r['blocksOverDepth'], r['seed'], r['blocks'], r['span'], '%.3f' % (r['firstCrackLoad'] / 1e3) if r['firstCrackLoad'] else '-',
	              r['peakLoad'] / 1e3, r['nominalStrength'] / 1e6, r['steps'], r['wallSeconds']))
for law, s in summary.items():
	lines.append('')
	lines.append('%s: spread of the nominal strength over the meshes (max - min)/max = %.1f %%' % (law, 100 * s['spread']))
	for ny, q in s['seeds'].items():
		if q['n'] > 1:
			lines.append('%s, %d blocks over the depth, %d seeds: peak %.3f kN (CoV %.2f %%), first crack %.3f kN (CoV %.2f %%)' %
			             (law, ny, q['n'], q['peakMean'] / 1e3, 100 * q['peakCoV'], q['firstCrackMean'] / 1e3, 100 * q['firstCrackCoV']))
print('\n'.join(lines))
if cli.doc:
	fig.savefig('doc/figures/notched_beam.png', dpi=120)
	print('notched_beam: figure in doc/figures/notched_beam.png (the table above goes into doc/validation.md)')
sys.exit(0)
