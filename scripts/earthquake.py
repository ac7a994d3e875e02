# -*- coding: utf-8 -*-
"""A masonry wall under a ground motion: a recorded earthquake (PEER .AT2 or two columns) or a synthetic pulse.

Problem
    A free-standing wall (default: 1.03 m long, 1.225 m tall, one wythe 0.12 m, 19 courses of 250×120×55 mm bricks in
    running bond, one block per brick, 10 mm interface joints; materials as scripts/wall.py) bonded to a base beam. It
    first settles under gravity (damped), then the base beam moves with the ground (prescribed motion, --mode prescribed)
    or the wall feels the equivalent inertial load (--mode inertial), along x (in the wall's plane) or y (out of its
    plane). Consistent formulation with Poisson cells, springs breaking on the total stress of their face, contacts
    sampled at the vertices (contactSamples=1, doc/theory.md §4.2) with critical dashpots, so that blocks that separate
    rock and hit as Housner's. A record is baseline-corrected (degree 2 by default), and any motion can be scaled.

Expected result
    Out of plane, a one-sine pulse of a few times g·t/H cracks the bed joint at the base and rocks or overturns the wall;
    the run reports the top displacement relative to the base, the broken springs and the energy (input, dissipated,
    kinetic) through the motion.

How to run
    build/bin/yade -n scripts/earthquake.py                                   one-sine pulse out of plane (about 2 minutes)
    build/bin/yade -n scripts/earthquake.py --record RSN6.AT2 --scale 1.5 --direction x
    build/bin/yade -n scripts/earthquake.py --help

Outputs (in --out, default output/earthquake): results.json, history.txt (yade.plot's saveDataTxt), earthquake.png
(ground motion, top displacement relative to the base, energy), cracks.png (the wall's broken springs, front and side views), ParaView files in vtk/.
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/earthquake.py', description=__doc__.split('\n\n')[0])
g = parser.add_argument_group('ground motion')
g.add_argument('--record', default=None, help='PEER .AT2 file (default: a synthetic pulse, --pulse)')
g.add_argument('--columns', default=None, help='two-column file time, acceleration (units --units)')
g.add_argument('--units', default='g', choices=['g', 'm/s^2', 'cm/s^2'], help='units of --columns (default g)')
g.add_argument('--pulse', choices=['sine', 'ricker', 'sweep'], default='sine', help='synthetic input when no record is given (default sine)')
g.add_argument('--amplitude', type=float, default=0.6, help='peak ground acceleration of the pulse [g] (default 0.6)')
g.add_argument('--period', type=float, default=0.3, help='period of the sine pulse, 1/peak frequency of the Ricker wavelet, or the sweep duration [s] (default 0.3)')
g.add_argument('--scale', type=float, default=1.0, help='factor on the motion (default 1)')
g.add_argument('--baseline', type=int, default=None, choices=[0, 1, 2, 3],
               help='degree of the baseline correction (rdem.ground_motion.Record.baselineCorrected; default 2 for records, 0 = none for pulses)')
g.add_argument('--direction', choices=['x', 'y'], default='y', help='x: in the wall plane, y: out of it (default y)')
g.add_argument('--mode', choices=['prescribed', 'inertial'], default='prescribed', help='base motion or inertial load (default prescribed)')
w = parser.add_argument_group('structure (m)')
w.add_argument('--structure', choices=['wall', 'building'], default='wall',
               help='a free-standing wall on a base beam, or a one-storey box of four walls with a door and a window (default wall; '
               'scripts/building.py shakes whole buildings)')
w.add_argument('--length', type=float, default=1.03, help='length of the wall, or of the front and back walls (default 1.03)')
w.add_argument('--width', type=float, default=0.77, help='building: depth of the plan, side walls included (default 0.77)')
w.add_argument('--height', type=float, default=1.225, help='height (default 1.225: 19 courses)')
w.add_argument('--thickness', type=float, default=0.12, help='thickness (default 0.12)')
w.add_argument('--bond', choices=['stack', 'running', 'english', 'flemish'], default='running', help='bond pattern (default running; a building: running or english)')
w.add_argument('--blocks', type=lambda s: [int(x) for x in s.split(',')], default=[1, 1, 1], help='blocks per brick (default 1,1,1)')
w.add_argument('--bond-ft', type=float, default=0.2, help='tensile bond strength of the joints [MPa] (default 0.2)')
w.add_argument('--bond-c', type=float, default=0.3, help='cohesion of the joints [MPa] (default 0.3)')
r = parser.add_argument_group('run')
r.add_argument('--duration', type=float, default=1.0, help='simulated time after settling [s] (default 1.0)')
r.add_argument('--out', default='output/earthquake', help='output folder (default output/earthquake)')
r.add_argument('--vtk-every', type=float, default=0.02, help='ParaView output every this time [s] (default 0.02; 0 = none)')
cli = parser.parse_args(sys.argv[1:])
for name in ('amplitude', 'period', 'scale', 'duration'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name, getattr(cli, name)))

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, Vector3, VTKRecorder, plot
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem
from yade.rdem import ground_motion as gm

os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)
G = gm.G

# 1. Ground motion ----------------------------------------------------------------------------------------------------
try:
	if cli.record:
		rec = gm.readAT2(cli.record)
	elif cli.columns:
		rec = gm.readColumns(cli.columns, units=cli.units)
	elif cli.pulse == 'sine':
		rec = gm.sinePulse(cli.amplitude * G, cli.period, dt=cli.period / 200, before=0.05, after=0.05)
	elif cli.pulse == 'ricker':
		rec = gm.rickerWavelet(cli.amplitude * G, 1 / cli.period, dt=cli.period / 200)
	else:
		rec = gm.sweep(cli.amplitude * G, 0.5, 10.0, cli.period, dt=0.002)
	degree = cli.baseline if cli.baseline is not None else (2 if (cli.record or cli.columns) else 0)
	rec = (rec.baselineCorrected(degree) if degree > 0 else rec).scaled(cli.scale)
except (ValueError, FileNotFoundError) as e:
	sys.exit('earthquake: %s' % e)
motion = gm.GroundMotion(**{cli.direction: rec})

# 2. Structure, settled under gravity --------------------------------------------------------------------------------
wall0 = time.time()
brick = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick'))
joint = RdemJoint(young=2e9, poisson=0.25, tensileStrength=cli.bond_ft * 1e6, cohesion=cli.bond_c * 1e6, frictionAngle=math.atan(0.75))


def makeWall():
	"""The wall on its base beam, with Poisson cells and failure on the total stress; returns (the wall, its block ids, the
	base beam's, the top course's)."""
	O.engines = rdem.engines(formulation='consistent', failureStress='total', contactSamples=1, gravity=(0, 0, -9.81), damping=0.5)
	w = rdem.masonry.wall(cli.length, cli.height, cli.thickness, bond=cli.bond, blocksPerBrick=cli.blocks, baseBeam=0.1, brickMaterial=brick,
	                      jointMaterial=joint)
	rdem.poissonEngine().elements = 'cells'
	rdem.poissonEngine().build(w.ids)
	return w, w.ids, w.beams['base'], list(w.courses[-1])


def makeBuilding():
	"""Four walls bonded at the corners (rdem.masonry.building) with a door (front) and a window (back) on a base beam
	under a roof slab; springs break on their own stresses (no Poisson cells: the rocking and overturning of walls do not
	depend on them). Returns (the building, its block ids, the base beam's, the walls' top courses')."""
	O.engines = rdem.engines(formulation=None, contactSamples=1, gravity=(0, 0, -9.81), damping=0.5)
	q, C, t = 0.065, 0.065, 0.01  # quarter module (l + t)/4, course h + t and joint of the default brick [m]
	courses = int(round((cli.height + t) / C))
	door = ('front', 0, 4 * q - t / 2, 0.0, 8 * q, (2 * courses // 3) * C - t / 2)
	window = ('back', 0, 4 * q - t / 2, (courses // 3) * C - t / 2, 8 * q, (courses // 3) * C)
	b = rdem.masonry.building((cli.length, cli.width), [cli.height], brick, joint, thickness=cli.thickness, bond=cli.bond, openings=[door, window],
	                          floors='slab', baseHeight=0.1)
	top = [i for name in b.walls for i in b.of(name) if O.bodies[i].state.pos[2] > cli.height - C]
	return b, b.ids, b.base, top


try:
	structure, ids, baseIds, top = makeWall() if cli.structure == 'wall' else makeBuilding()
except ValueError as e:
	sys.exit('earthquake: %s' % e)
for i in baseIds:
	O.bodies[i].state.blockedDOFs = 'xyzXYZ'
O.dt = -1
newton = rdem.newtonIntegrator()
settle = 0.05  # [s] with Cundall's damping: the structure comes to rest under its weight
while O.time < settle:
	O.step()
newton.damping = 0.0
shaker = rdem.earthquake.shaker(motion, ids=baseIds, mode=cli.mode)
shaker.times = [t + O.time for t in shaker.times]  # the motion starts now
O.trackEnergy = True
x0 = {i: Vector3(O.bodies[i].state.pos) for i in top}
b0 = Vector3(O.bodies[baseIds[0]].state.pos)
t0 = O.time
print('earthquake: %s; %s, PGA %.3g g along %s, %s; settled in %.3f s; step %.3g s' %
      (structure, rec.name or cli.pulse, rec.pga / G, cli.direction, cli.mode, settle, O.dt),
      flush=True)

# 3. Run -------------------------------------------------------------------------------------------------------------
axis = 'xy'.index(cli.direction)
# yade.plot keeps the history (plot.data): live curves with plot.plot() in a YADE with a GUI, history.txt by saveDataTxt.
plot.reset()
plot.plots = {'t': ('topDrift', 'groundDisp'), 't ': ('input', 'dissipated', 'kinetic', 'total')}
history = plot.data


def record():
	base = O.bodies[baseIds[0]].state.pos - b0
	drift = sum((O.bodies[i].state.pos - x0[i])[axis] for i in top) / len(top) - base[axis]
	e = dict(O.energy.items())
	plot.addData(t=O.time - t0,
	             groundAcc=shaker.accelerationAt(O.time)[axis],
	             groundDisp=base[axis],
	             topDrift=drift,
	             breaks=sum(rdem.breakCounts()),
	             input=-e.get('groundWork', 0.0) - e.get('gravWork', 0.0),
	             dissipated=rdem.dissipatedEnergy(e),
	             kinetic=e.get('kinetic', 0.0),
	             total=O.energy.total())


lastReport, vtkNext, cracks = time.time(), 0.0, rdem.CrackExport(os.path.join(cli.out, 'vtk', ''))
runStart = time.time()
while O.time - t0 < cli.duration:
	for _ in range(50):
		O.step()
	record()
	if cli.vtk_every > 0 and O.time - t0 >= vtkNext:
		VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'])()
		cracks.write()
		vtkNext += cli.vtk_every
	if time.time() - lastReport > 5:
		lastReport = time.time()
		print('t = %.3f of %.3g s, top drift %.4f m, broken springs %d' % (O.time - t0, cli.duration, history['topDrift'][-1], history['breaks'][-1]), flush=True)
cracks.close()
runTime = time.time() - runStart
segs = rdem.brokenSegments(cracks.snapshot)
results = dict(input=vars(cli), structure=repr(structure), blocks=len(ids), pga=rec.pga, recordName=rec.name, timeStep=O.dt, steps=O.iter,
               maxTopDrift=max(abs(d) for d in history['topDrift']), finalTopDrift=history['topDrift'][-1], brokenSprings=history['breaks'][-1],
               wallSeconds=runTime, microsecondsPerBlockStep=1e6 * runTime / max(1, O.iter * len(ids)), history=history)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
axes[0].plot(history['t'], [a / G for a in history['groundAcc']])
axes[0].set_ylabel('ground acceleration [g]')
axes[1].plot(history['t'], history['topDrift'], label='top course relative to the base')
axes[1].plot(history['t'], history['groundDisp'], label='ground displacement')
axes[1].set_ylabel('displacement [m]')
axes[1].legend()
for key, label in (('input', 'input (ground work and gravity)'), ('dissipated', 'dissipated (dashpots, friction, breaks)'), ('kinetic', 'kinetic')):
	axes[2].plot(history['t'], history[key], label=label)
axes[2].set_ylabel('energy [J]')
axes[2].set_xlabel('time since the motion began [s]')
axes[2].legend()
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'earthquake.png'), dpi=120)
fig, axes = plt.subplots(1, 2, figsize=(10, 5))
for ax, (u, name) in zip(axes, ((0, 'front (x-z)'), (1, 'side (y-z)'))):
	ax.scatter([s['point'][u] for s in segs], [s['point'][2] for s in segs], s=4, c=['r' if s['state'] == 1 else 'b' for s in segs])
	ax.set_title('%s: %d broken springs' % (name, len(segs)))
	ax.set_aspect('equal')
	ax.set_xlabel('xyz'[u] + ' [m]')
	ax.set_ylabel('z [m]')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'cracks.png'), dpi=120)
print('earthquake: largest top drift %.4f m, final %.4f m; %d broken springs; %d steps in %.1f s (%.3f us per block-step); results in %s' %
      (results['maxTopDrift'], results['finalTopDrift'], results['brokenSprings'], O.iter, runTime, results['microsecondsPerBlockStep'], cli.out))
sys.exit(0)
