# -*- coding: utf-8 -*-
"""A one-way spanning wall pushed out of plane quasi-statically, against the rigid-body relation.

Problem
    A dry-stacked wall strip (--height, --thickness, --courses courses of one block) on a fixed base, held at its top by
    a beam that stays horizontal and may rise (its weight the overburden, --overburden in units of the wall's weight W;
    0: the beam's own 0.02 W), pushed along y at the two courses next to mid-height at --rate (rdem.out_of_plane,
    doc/out-of-plane.md).

Expected result
    The rigid-body relation (rdem.limit_analysis.OneWayWall; Doherty, Griffith, Lam & Wilson 2002): F0 = (W + 2O) t/z_p,
    F falling to 0 at the instability displacement Δu = t; tests/yade/test_out_of_plane.py asserts 5 %.

How to run
    build/bin/yade -n scripts/out_of_plane.py                       without overburden (about a minute)
    build/bin/yade -n scripts/out_of_plane.py --overburden 1
    build/bin/yade -n scripts/out_of_plane.py --help

Outputs (in --out, default output/out_of_plane): results.json, history.txt, out_of_plane.png (F against Δ with the rigid
relation), ParaView files in vtk/.
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/out_of_plane.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--height', type=float, default=1.0, help='wall height [m] (default 1)')
parser.add_argument('--thickness', type=float, default=0.1, help='wall thickness [m] (default 0.1)')
parser.add_argument('--courses', type=int, default=20, help='courses, even (default 20)')
parser.add_argument('--overburden', type=float, default=0.0, help='overburden in units of the wall weight (default 0: the top beam only, 0.02)')
parser.add_argument('--rate', type=float, default=0.02, help='push velocity [m/s] (default 0.02)')
parser.add_argument('--out', default='output/out_of_plane', help='output folder (default output/out_of_plane)')
cli = parser.parse_args(sys.argv[1:])
for name in ('height', 'thickness', 'rate'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name, getattr(cli, name)))
if cli.overburden < 0:
	sys.exit('--overburden = %g: must be >= 0' % cli.overburden)

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, VTKRecorder, plot
from rdem.out_of_plane import OneWayWallPush

os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)
try:
	probe = OneWayWallPush(height=cli.height, thickness=cli.thickness, courses=cli.courses)
	W = probe.weight
	O.reset()
	w = OneWayWallPush(height=cli.height, thickness=cli.thickness, courses=cli.courses, overburden=cli.overburden * W, rate=cli.rate)
except ValueError as e:
	sys.exit('out_of_plane.py: %s' % e)
print('out_of_plane.py: W = %.1f N, O = %.1f N, rigid F0 = %.2f N, instability at %.4f m' % (w.weight, w.overburden, w.rigid.initialForce,
                                                                                              w.rigid.instabilityDisplacement), flush=True)
plot.reset()
plot.plots = {'delta': ('F', 'Frigid')}
vtk = VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'])
wall0, last = time.time(), [time.time(), 0.0]
w.settle()


def progress(row):
	d, F = row
	plot.addData(delta=d, F=F, Frigid=w.rigid.forceAt(max(d, 0.0)), t=O.time)
	if d >= last[1]:
		vtk()
		last[1] += w.t / 10
	if time.time() - last[0] > 5:
		last[0] = time.time()
		print('Δ = %.4f m of %.4f, F = %.2f N (rigid %.2f N)' % (d, 1.05 * w.t, F, w.rigid.forceAt(max(d, 0.0))), flush=True)


hist = w.push(to=1.05 * w.t, callback=progress)
wall = time.time() - wall0
F0 = w.rigid.initialForce
inRange = [(d, F) for d, F in hist if 0.1 * w.t <= d <= 0.9 * w.t]
worst = max(abs(F - w.rigid.forceAt(d)) / F0 for d, F in inRange)
zero = next((d for d, F in hist if d > 0.5 * w.t and F <= 0), None)
results = dict(input=vars(cli), weight=w.weight, overburden=w.overburden, rigidInitialForce=F0, peakForce=max(F for d, F in hist),
               largestDifference=worst, instabilityDisplacement=zero, rigidInstabilityDisplacement=w.rigid.instabilityDisplacement, timeStep=O.dt,
               steps=O.iter, wallSeconds=wall, history=dict(delta=[d for d, F in hist], force=[F for d, F in hist]))
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot([d * 1e3 for d, F in hist], [F for d, F in hist], label='model')
ds = [w.t * 1.05 * k / 200 for k in range(201)]
ax.plot([d * 1e3 for d in ds], [w.rigid.forceAt(d) for d in ds], 'k--', label='rigid body (exact)')
ax.plot([0, w.t * 1e3], [F0, 0], 'k:', lw=0.8, label='linear F0(1 - Δ/t)')
ax.axhline(0, color='0.5', lw=0.5)
ax.set_xlabel('mid-height displacement Δ [mm]')
ax.set_ylabel('push F [N]')
ax.set_title('one-way wall, O = %.3g W' % (w.overburden / w.weight))
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'out_of_plane.png'), dpi=120)
print('out_of_plane.py: peak %.2f N (rigid F0 %.2f N), largest difference from the rigid relation over 0.1-0.9 t: %.4f F0, F = 0 at %s m (rigid %.4f); '
      '%d steps in %.1f s; results in %s' % (results['peakForce'], F0, worst, '%.4f' % zero if zero else 'never', w.rigid.instabilityDisplacement, O.iter, wall,
                                             cli.out))
sys.exit(0)
