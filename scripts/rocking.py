# -*- coding: utf-8 -*-
"""Housner's rocking block: free rocking from a tilt, or rocking and overturning under a ground pulse.

Problem
    A rigid block of half-width b and half-height h (default 0.1 × 0.5 m, 0.2 m deep; E = 30 GPa, 2500 kg/m³) stands on
    a fixed base; the two touch through contact springs only, sampled at the vertices (contactSamples=1, doc/theory.md
    §4.2), with critical dashpots and friction 0.8. Either it is released at rest from a tilt θ0 (default α/2) and rocks
    freely, or it starts at rest and the base moves with a one-sine or Ricker pulse of horizontal acceleration
    (--pulse; amplitude in units of g tan α, the uplift threshold), applied as prescribed motion of the base block
    (--mode prescribed) or as the equivalent inertial load (--mode inertial).

Expected result (Housner 1963; ../shared figures for the default block)
    Free rocking: first impact after 0.3471 s; energy kept through each impact η² = (1 − 1.5 sin²α)² = 0.8879, so the
    amplitudes decay as cos(α − θ_{k+1}) − cos α = η² (cos(α − θ_k) − cos α). Under a pulse: no uplift below g tan α; a
    pulse strong and long enough overturns the block.

How to run
    build/bin/yade -n scripts/rocking.py                        free rocking (about 30 s)
    build/bin/yade -n scripts/rocking.py --pulse sine --amplitude 3 --period 0.5 --duration 3
    build/bin/yade -n scripts/rocking.py --help

Outputs (in --out, default output/rocking): results.json, history.txt (yade.plot's saveDataTxt), rocking.png (rotation against time with Housner's amplitudes,
ground motion, energy), ParaView files in vtk/.
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/rocking.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--b', type=float, default=0.1, help='half-width of the block [m] (default 0.1)')
parser.add_argument('--h', type=float, default=0.5, help='half-height of the block [m] (default 0.5)')
parser.add_argument('--theta0', type=float, default=0.5, help='initial tilt, as a fraction of alpha (default 0.5; 0 with a pulse)')
parser.add_argument('--pulse', choices=['none', 'sine', 'ricker'], default='none', help='ground pulse (default none: free rocking)')
parser.add_argument('--amplitude', type=float, default=2.0, help='peak ground acceleration in units of g tan(alpha) (default 2)')
parser.add_argument('--period', type=float, default=0.5, help='period of the sine pulse, or 1/peak frequency of the Ricker wavelet [s] (default 0.5)')
parser.add_argument('--mode', choices=['prescribed', 'inertial'], default='prescribed', help='base motion or inertial load (default prescribed)')
parser.add_argument('--contact-samples', type=int, default=1, help="contact sample grid per face edge (default 1: the vertices, rdem.engines' default)")
parser.add_argument('--damping-constant', type=float, default=1.0, help='contact dashpots, 1 = critical (default 1)')
parser.add_argument('--duration', type=float, default=2.0, help='simulated time [s] (default 2)')
parser.add_argument('--out', default='output/rocking', help='output folder (default output/rocking)')
cli = parser.parse_args(sys.argv[1:])
for name in ('b', 'h', 'period', 'duration'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name, getattr(cli, name)))
if not 0 <= cli.theta0 < 1:
	sys.exit('--theta0 = %g: must be in [0, 1) (a fraction of alpha)' % cli.theta0)

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, VTKRecorder, plot
from yade import rdem
from yade.rdem import ground_motion as gm
from yade.rdem.scenes import RockingBlock

os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)
alpha = math.atan(cli.b / cli.h)
theta0 = cli.theta0 * alpha if cli.pulse == 'none' else 0.0
rock = RockingBlock(b=cli.b, h=cli.h, theta0=theta0, contactSamples=cli.contact_samples, dampingConstant=cli.damping_constant)
motion = None
if cli.pulse != 'none':
	amp = cli.amplitude * rock.upliftAcceleration()
	dt = 1e-3
	record = gm.sinePulse(amp, cli.period, dt=dt, before=0.1) if cli.pulse == 'sine' else gm.rickerWavelet(amp, 1 / cli.period, dt)
	motion = gm.GroundMotion(x=record)
	rdem.earthquake.shaker(motion, ids=[rock.base], mode=cli.mode)
O.trackEnergy = True
shaker = [O.labeledEngine('groundShaker')] if cli.pulse != 'none' else []  # rdem.earthquake.shaker labels it
# yade.plot keeps the history (plot.data): live curves with plot.plot() in a YADE with a GUI, history.txt by saveDataTxt.
plot.reset()
plot.plots = {'t': ('theta', ), 't ': ('energy', 'kinetic')}
history = plot.data


def record():
	plot.addData(t=O.time,
	             theta=rock.angle(),
	             groundAcc=shaker[0].accelerationAt(O.time)[0] if shaker else 0.0,
	             groundDisp=shaker[0].displacementAt(O.time)[0] if shaker else 0.0,
	             energy=O.energy.total(),
	             kinetic=O.energy['kinetic'] if 'kinetic' in O.energy.keys() else 0.0)


wall0, lastReport, vtkNext = time.time(), time.time(), 0.0
O.step()
steps = int(math.ceil(cli.duration / O.dt))
while O.time < cli.duration:
	for _ in range(20):
		O.step()
	record()
	if O.time >= vtkNext:
		VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'])()
		vtkNext += 0.05
	if time.time() - lastReport > 5:
		lastReport = time.time()
		print('t = %.3f s of %.3g (step %d of about %d), theta = %.5f rad' % (O.time, cli.duration, O.iter, steps, rock.angle()), flush=True)
wall = time.time() - wall0

# Impacts: zero crossings of theta, and the amplitude of each half cycle between them.
crossings, amplitudes, lastSign, peak = [], [], 0, 0.0
for t, th in zip(history['t'], history['theta']):
	sign = 1 if th > 0 else -1
	if lastSign and sign != lastSign:
		crossings.append(t)
		amplitudes.append(peak)
		peak = 0.0
	peak = max(peak, abs(th))
	lastSign = sign
overturned = abs(history['theta'][-1]) > alpha
ratios = [rock.energyRatio(a0, a1) for a0, a1 in zip(amplitudes[:-1], amplitudes[1:])] if cli.pulse == 'none' else []
results = dict(input=vars(cli), alpha=alpha, eta=rock.eta(), housnerEnergyRatio=rock.eta()**2, quarterCycleExact=rock.quarterCycle(theta0) if theta0 > 0 else None,
               firstImpact=crossings[0] if crossings else None, amplitudes=amplitudes, energyRatios=ratios, overturned=overturned, timeStep=O.dt,
               steps=O.iter, wallSeconds=wall, history=history)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
axes[0].plot(history['t'], history['theta'], label='model')
if cli.pulse == 'none' and amplitudes:
	th, amps, t0 = theta0, [], 0
	for k in range(len(amplitudes)):  # Housner's amplitudes: energy η² kept through every impact
		amps.append(th)
		th = alpha - math.acos(rock.eta()**2 * (math.cos(alpha - th) - math.cos(alpha)) + math.cos(alpha))
	for k, a in enumerate(amps):
		axes[0].plot([crossings[k - 1] if k else 0, crossings[k] if k < len(crossings) else history['t'][-1]], [a * (-1)**k] * 2, 'k:', lw=1,
		             label="Housner's amplitudes" if k == 0 else None)
axes[0].axhline(alpha, color='r', lw=0.5)
axes[0].axhline(-alpha, color='r', lw=0.5)
axes[0].set_ylabel('rotation [rad]')
axes[0].legend()
axes[1].plot(history['t'], history['groundAcc'])
axes[1].set_ylabel('ground acceleration [m/s²]')
axes[2].plot(history['t'], [e - history['energy'][0] for e in history['energy']], label='total energy change')
axes[2].plot(history['t'], history['kinetic'], label='kinetic')
axes[2].set_ylabel('energy [J]')
axes[2].set_xlabel('time [s]')
axes[2].legend()
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'rocking.png'), dpi=120)
print('rocking: alpha %.4f rad; first impact %s s (exact %s); energy kept through the impacts %s (Housner %.4f); %s; %d steps in %.1f s; results in %s' %
      (alpha, '%.4f' % crossings[0] if crossings else 'none', '%.4f' % results['quarterCycleExact'] if results['quarterCycleExact'] else '-',
       ', '.join('%.4f' % r for r in ratios[:4]) or '-', rock.eta()**2, 'overturned' if overturned else 'standing', O.iter, wall, cli.out))
sys.exit(0)
