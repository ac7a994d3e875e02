# -*- coding: utf-8 -*-
"""A free-standing parapet on a roof under one-sine pulses: the smallest overturning amplitude, model against the rigid
block's exact equation of motion with Housner's impacts.

Problem
    A parapet 2b thick and 2h tall (default 0.12 × 0.6 m) stands dry on a roof that moves with a one-sine pulse
    a(t) = A sin(2πt/T) (rdem.out_of_plane.Parapet, doc/out-of-plane.md §3). For each period in --periods the equation
    (rdem.rocking) gives the smallest overturning amplitude A_min; the model is run at --factors × A_min.

Expected result
    The model stands at 0.95 A_min and overturns at 1.05 A_min (tests/yade/test_parapet.py).

How to run
    build/bin/yade -n scripts/parapet.py                               three periods, two factors (a few minutes)
    build/bin/yade -n scripts/parapet.py --periods 0.5 --factors 0.9,0.95,1.05,1.1
    build/bin/yade -n scripts/parapet.py --help

Outputs (in --out, default output/parapet): results.json, parapet.png (A_min against ω_p/p with the model's runs),
rotation histories history-<T>-<factor>.txt, ParaView files of the last run in vtk/.
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/parapet.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--b', type=float, default=0.06, help='half-thickness [m] (default 0.06)')
parser.add_argument('--h', type=float, default=0.3, help='half-height [m] (default 0.3)')
parser.add_argument('--periods', default='0.3,0.5,1.0', help='pulse periods [s], separated by commas (default 0.3,0.5,1.0)')
parser.add_argument('--factors', default='0.95,1.05', help='amplitudes in units of the equation\'s A_min (default 0.95,1.05)')
parser.add_argument('--out', default='output/parapet', help='output folder (default output/parapet)')
cli = parser.parse_args(sys.argv[1:])
try:
	periods = [float(x) for x in cli.periods.split(',')]
	factors = [float(x) for x in cli.factors.split(',')]
except ValueError:
	sys.exit('--periods, --factors: numbers separated by commas')
if not (cli.b > 0 and cli.h > 0 and all(T > 0 for T in periods) and all(f > 0 for f in factors)):
	sys.exit('--b, --h, --periods and --factors must be > 0')

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, VTKRecorder
from rdem.out_of_plane import Parapet
from rdem.rocking import RockingBlockEquation

os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)
eq = RockingBlockEquation(cli.b, cli.h)
a0 = eq.g * math.tan(eq.alpha)
print('parapet.py: alpha = %.4f rad, p = %.3f rad/s, eta = %.4f, uplift at %.3f m/s2' % (eq.alpha, eq.p, eq.eta, a0), flush=True)
runs, curve, wall0 = [], [], time.time()
for T in periods:
	amin = eq.minimumOverturningAmplitude(T, step=0.02)
	curve.append(dict(period=T, omegaOverP=2 * math.pi / T / eq.p, amin=amin, aminOverUplift=amin / a0 if amin else None))
	print('T = %g s (omega_p/p = %.2f): equation A_min = %s m/s2' % (T, 2 * math.pi / T / eq.p, '%.4f' % amin if amin else 'none'), flush=True)
	if amin is None:
		continue
	for f in factors:
		O.reset()
		p = Parapet(b=cli.b, h=cli.h)
		over, largest = p.shake(f * amin, T)
		with open(os.path.join(cli.out, 'history-%g-%g.txt' % (T, f)), 'w') as out:
			out.write('# time [s]  rotation [rad] (pulse A = %.6g m/s2, T = %g s, starting at 0.05 s)\n' % (f * amin, T))
			out.writelines('%.6f %.8f\n' % row for row in p.history)
		pulse = lambda t, A=f * amin: A * math.sin(2 * math.pi * t / T) if t <= T else 0.0
		runs.append(dict(period=T, factor=f, amplitude=f * amin, modelOverturned=over, equationOverturned=eq.overturns(pulse, T), largestRotation=largest,
		                 steps=O.iter, timeStep=O.dt))
		print('  %.2f A_min: model %s (largest rotation %.3f rad), equation %s' % (f, 'overturned' if over else 'standing', largest,
		                                                                           'overturns' if runs[-1]['equationOverturned'] else 'stands'), flush=True)
	VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'parapet-%g.' % T), recorders=['boxes'])()
wall = time.time() - wall0
results = dict(input=vars(cli), alpha=eq.alpha, p=eq.p, eta=eq.eta, upliftAcceleration=a0, equation=curve, runs=runs, wallSeconds=wall)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot([c['omegaOverP'] for c in curve if c['amin']], [c['aminOverUplift'] for c in curve if c['amin']], 'k-o', label='equation: A_min')
for r in runs:
	ax.plot(2 * math.pi / r['period'] / eq.p, r['amplitude'] / a0, 'x' if r['modelOverturned'] else 'o', color='C3' if r['modelOverturned'] else 'C2', mfc='none')
ax.plot([], [], 'x', color='C3', label='model overturned')
ax.plot([], [], 'o', color='C2', mfc='none', label='model standing')
ax.set_xlabel('ω_p / p')
ax.set_ylabel('A / (g tan α)')
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'parapet.png'), dpi=120)
agree = sum(r['modelOverturned'] == r['equationOverturned'] for r in runs)
print('parapet.py: model and equation agree in %d of %d runs; %.1f s; results in %s' % (agree, len(runs), wall, cli.out))
sys.exit(0)
