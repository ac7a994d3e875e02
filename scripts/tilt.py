# -*- coding: utf-8 -*-
"""A dry-stacked brick wall on a tilting base: the tilt at which it falls over, against rigid-block limit analysis.

Problem
    A free-standing wall of bricks laid dry (no mortar; default 0.75 m long, 6 courses of 250×120×55 mm bricks in
    running bond, 0.33 m tall, one wythe 0.12 m thick, one block per brick; E = 16.7 GPa, 1800 kg/m³, friction 0.75)
    stands on a fixed base; every joint is a contact sampled at the vertices (contactSamples=1, doc/theory.md §4.2) with
    critical dashpots. The base is tilted about the wall's length, out of its plane, as on a tilting table (de Felice
    2011): gravity is turned by θ in the base's frame. The tilt is raised quickly to --start times the limit-analysis
    angle, then in steps of --step degrees, each held for --hold seconds, until the wall lifts off its downhill edge
    (its bottom course turns by more than --uplift rad); the tilt is then held while the wall falls over.

Expected result (rdem.limit_analysis.stackTilt: Heyman 1966, Housner 1963)
    Every course spans the thickness, so the part above any bed joint overturns about that joint's downhill edge when
    tan θ = t/(H − z); the base joint governs, tan θc = t/H (19.98° for the default wall), unless the joints slide first
    (tan θ = μ = 0.75, 36.9°). The wall stands at every level below θc and lifts off at the first level above it.

How to run
    build/bin/yade -n scripts/tilt.py                                     (about a minute)
    build/bin/yade -n scripts/tilt.py --height 0.825 --step 0.05          15 courses (12.31°), finer steps
    build/bin/yade -n scripts/tilt.py --help

Outputs (in --out, default output/tilt): results.json, history.txt (yade.plot's saveDataTxt), tilt.png (the wall's lean against the tilt and against time, the
limit-analysis angle), ParaView files in vtk/ (the blocks).
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/tilt.py', description=__doc__.split('\n\n')[0])
w = parser.add_argument_group('wall (m, one wythe laid dry)')
w.add_argument('--length', type=float, default=0.75, help='length (default 0.75: three bricks)')
w.add_argument('--height', type=float, default=0.33, help='height (default 0.33: 6 courses)')
w.add_argument('--brick', type=lambda s: tuple(float(x) for x in s.split(',')), default=(0.25, 0.12, 0.055),
               help='brick length,width,height; the width is the thickness (default 0.25,0.12,0.055)')
w.add_argument('--bond', choices=['stack', 'running'], default='running', help='bond (default running)')
w.add_argument('--friction', type=float, default=0.75, help='friction coefficient of the joints (default 0.75)')
w.add_argument('--young', type=float, default=16.7, help="bricks' Young's modulus, which sets the contact stiffness [GPa] (default 16.7)")
r = parser.add_argument_group('tilt')
r.add_argument('--start', type=float, default=0.95, help='tilt reached by the first ramp, as a fraction of the limit-analysis angle (default 0.95)')
r.add_argument('--step', type=float, default=0.2, help='tilt increment [deg] (default 0.2)')
r.add_argument('--hold', type=float, default=0.2, help='time each tilt is held [s] (default 0.2)')
r.add_argument('--uplift', type=float, default=1e-3, help='rotation of the bottom course that counts as lift-off [rad] (default 1e-3)')
r.add_argument('--fall', type=float, default=1.0, help='the run ends when the wall leans this far [rad] (default 1.0), or --hold x 10 after lift-off')
r.add_argument('--out', default='output/tilt', help='output folder (default output/tilt)')
r.add_argument('--vtk-every', type=float, default=0.05, help='ParaView output every this time [s] (default 0.05; 0 = none)')
cli = parser.parse_args(sys.argv[1:])
for name in ('length', 'height', 'friction', 'young', 'step', 'hold', 'uplift', 'fall'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name, getattr(cli, name)))
if not 0 < cli.start < 1:
	sys.exit('--start = %g: must be in (0, 1) (a fraction of the limit-analysis angle)' % cli.start)
if len(cli.brick) != 3 or min(cli.brick) <= 0:
	sys.exit('--brick = %s: must be three sizes > 0 [m]' % (cli.brick, ))

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, VTKRecorder, plot
from yade.rdem.earthquake import DryWall

os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)
try:
	wall = DryWall(length=cli.length, height=cli.height, thickness=cli.brick[1], brick=cli.brick, bond=cli.bond, young=cli.young * 1e9,
	               friction=cli.friction)
except ValueError as e:
	sys.exit('tilt: %s' % e)
limit = wall.limit
print('tilt: %d bricks in %d courses, %.3g x %.3g x %.3g m; limit analysis: %s at joint %d, tilt %.3f deg (tan %.4f)' %
      (len(wall.ids), len(wall.courses), wall.layout.length, wall.layout.thickness, wall.layout.height, limit.mechanism, limit.joint,
       math.degrees(limit.angle), limit.multiplier),
      flush=True)

# yade.plot keeps the history (plot.data): live curves with plot.plot() in a YADE with a GUI, history.txt by saveDataTxt.
plot.reset()
plot.plots = {'tilt': ('lean', 'uplift')}
history = plot.data
state = dict(vtkNext=0.0, report=time.time())


def advance(duration, theta0, theta1, ramp):
	"""Run for ``duration`` [s], the tilt going linearly from theta0 to theta1 [rad] over the first ``ramp`` [s]; stops
	early once the bottom course has lifted off. Returns whether it did."""
	t0 = O.time
	while O.time - t0 < duration:
		theta = theta0 + (theta1 - theta0) * min(1.0, (O.time - t0) / ramp)
		wall.tilt(theta)
		for _ in range(20):
			O.step()
		plot.addData(t=O.time, tilt=theta, lean=wall.lean(), uplift=wall.lean(wall.courses[0]))
		if cli.vtk_every > 0 and O.time >= state['vtkNext']:
			VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'])()
			state['vtkNext'] += cli.vtk_every
		if time.time() - state['report'] > 5:
			state['report'] = time.time()
			print('t = %.3f s, tilt %.3f deg, lean %.5f rad, bottom course %.2e rad' % (O.time, math.degrees(theta), history['lean'][-1], history['uplift'][-1]),
			      flush=True)
		if history['uplift'][-1] > cli.uplift:
			return True
	return False


wall0 = time.time()
advance(0.05, 0.0, 0.0, 1.0)  # settle under gravity
level = cli.start * limit.angle
lifted = advance(cli.hold + 0.2, 0.0, level, 0.2)
held = []  # the levels at which the wall stood through the whole hold [rad]
while not lifted and level < math.pi / 2:
	held.append(level)
	step = math.radians(cli.step)
	lifted = advance(cli.hold, level, level + step, cli.hold / 10)
	level += step
liftTime, liftTilt = O.time, level
fallTime = None
while lifted and O.time - liftTime < 10 * cli.hold:
	advance(0.02, level, level, 1.0)
	if history['lean'][-1] > cli.fall:
		fallTime = O.time
		break
wallSeconds = time.time() - wall0

lastHeld = held[-1] if held else None
error = liftTilt / limit.angle - 1
results = dict(input=vars(cli), blocks=len(wall.ids), courses=len(wall.courses), length=wall.layout.length, height=wall.layout.height,
               thickness=wall.layout.thickness, limitAnalysis=dict(angleDeg=math.degrees(limit.angle), multiplier=limit.multiplier, mechanism=limit.mechanism,
                                                                    joint=limit.joint),
               liftOffTiltDeg=math.degrees(liftTilt) if lifted else None, lastStandingTiltDeg=math.degrees(lastHeld) if lastHeld else None,
               relativeError=error if lifted else None, fellOver=fallTime is not None, fallTime=fallTime, timeStep=O.dt, steps=O.iter, wallSeconds=wallSeconds,
               history=history)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

fig, axes = plt.subplots(2, 1, figsize=(7, 7))
axes[0].plot([math.degrees(a) for a in history['tilt']], history['lean'], '.', ms=2, label='wall (mean of all blocks)')
axes[0].plot([math.degrees(a) for a in history['tilt']], history['uplift'], '.', ms=2, label='bottom course')
axes[0].axvline(math.degrees(limit.angle), color='r', lw=1, label='limit analysis %.2f°' % math.degrees(limit.angle))
axes[0].set_yscale('symlog', linthresh=1e-5)
axes[0].set_xlabel('tilt [deg]')
axes[0].set_ylabel('lean [rad]')
axes[0].legend()
axes[1].plot(history['t'], [math.degrees(a) for a in history['tilt']], label='tilt [deg]')
axes[1].plot(history['t'], [math.degrees(a) for a in history['lean']], label='lean of the wall [deg]')
axes[1].axhline(math.degrees(limit.angle), color='r', lw=0.5)
axes[1].set_xlabel('time [s]')
axes[1].legend()
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'tilt.png'), dpi=120)
print('tilt: limit analysis %.3f deg; stood at %s deg, lifted off at %s deg (%s); %s; %d steps in %.1f s; results in %s' %
      (math.degrees(limit.angle), '%.3f' % math.degrees(lastHeld) if lastHeld else '-', '%.3f' % math.degrees(liftTilt) if lifted else 'never',
       '%+.2f %%' % (100 * error) if lifted else '-', 'fell over at t = %.2f s' % fallTime if fallTime else 'did not fall over', O.iter, wallSeconds, cli.out))
sys.exit(0)
