# -*- coding: utf-8 -*-
"""A masonry house under a recorded earthquake: gravity first, then the ground motion, then damage per wall.

Problem
    A brick house (rdem.masonry.building: walls bonded at their corners and T-junctions, doors and windows with lintels,
    an RC slab or timber joists, a base beam). Default: one room, one storey, 2.59 x 2.07 m outside, 1.355 m of masonry
    (21 courses of 250x120x55 mm bricks, 10 mm interface joints), one-wythe running bond, a door and three windows, an RC
    roof slab with 200 kg/m2. --big: two storeys of 2.59 m, 7.79 x 5.71 m, walls one brick thick in English bond with a
    wall across, eight openings, a timber floor on joists and an RC roof: 18 843 blocks. Materials as scripts/wall.py
    (bricks E = 16.7 GPa, mortar E = 2 GPa, bond tensile strength 0.2 MPa, cohesion 0.3 MPa, friction 0.75).
    Consistent formulation with Poisson cells over the whole building, springs breaking on the total stress of their
    face, contacts sampled at the vertices with critical dashpots (doc/theory.md §4.2).
    The house settles under gravity (Cundall damping 0.5 for --settle s), then the base beam follows the ground
    (prescribed motion, no damping): the El Centro 1940 north-south record (data/records/, baseline-corrected, degree 2)
    along x, scaled to --pga, from --start for --duration seconds; --record-y and --record-z add the other components
    from files (.AT2, or values in g at the record's step).

Expected result
    Per wall (doc/building.md defines each measure): the broken joints in its plane and the in-plane drift, the largest
    out-of-plane displacement (failure past half the thickness), and for every corner and T-junction the largest
    relative displacement across it (separated past the joint thickness); the energy balance.

How to run
    build/bin/yade -n scripts/building.py                         the small house (a few minutes on one core)
    build/bin/yade -n scripts/building.py --pga 0.6 --duration 4
    build/bin/yade -n scripts/building.py --big --duration 0.02   a short run of the two-storey house: cost per simulated second
    build/bin/yade -n -j 2 scripts/building.py ...                  on two threads
    build/bin/yade -n scripts/building.py --big --duration 4 --checkpoint-every 0.05
    build/bin/yade -n scripts/building.py --big --duration 4 --resume   continues from the last checkpoint in --out
    build/bin/yade -n scripts/building.py --help

Outputs (in --out, default output/building): results.json, history.txt (yade.plot), drift-<wall>.png and
damage-<wall>.png per wall, energy.png, frames/frame-NNNN.png and collapse.gif (the animation), ParaView files in vtk/;
with --checkpoint-every, checkpoint.yade.gz (the scene, O.save) and checkpoint.pickle (what this script follows: the
history, the reference positions, the outputs written so far), rewritten at every checkpoint and at the end. A run
resumed from them (--resume, the same options; --duration may be longer) continues exactly as the uninterrupted run:
the same steps, history and damage (tests/yade/test_building_resume.py).
"""
import argparse
import json
import math
import os
import pickle
import sys
import time

HERE = os.path.dirname(os.path.abspath(sys.argv[0]))  # this script's folder (under YADE, __file__ names YADE's launcher)
parser = argparse.ArgumentParser(prog='yade scripts/building.py', description=__doc__.split('\n\n')[0])
g = parser.add_argument_group('ground motion')
g.add_argument('--record', default=os.path.join(HERE, '..', 'data', 'records', 'elcentro-1940-ns.txt'),
               help='record along x: .AT2, or accelerations in g, several per line (default: El Centro 1940 NS)')
g.add_argument('--record-dt', type=float, default=0.02, help='time step of a record of values only [s] (default 0.02)')
g.add_argument('--record-y', default=None, help='record along y (same formats; default none)')
g.add_argument('--record-z', default=None, help='record along z, vertical (default none)')
g.add_argument('--pga', type=float, default=0.5, help='peak ground acceleration along x after scaling [g] (default 0.5); the other components keep '
               'their ratio to it')
g.add_argument('--start', type=float, default=1.9, help='time of the record where the run starts [s]: the last sign change of the acceleration up to '
               'there (default 1.9: 1.88 s, before the peak at 2.02 s)')
g.add_argument('--duration', type=float, default=0.25, help='simulated time of ground motion [s] (default 0.25)')
h = parser.add_argument_group('house')
h.add_argument('--big', action='store_true', help='the two-storey house of 18 843 blocks instead of the small one')
h.add_argument('--bond-ft', type=float, default=0.2, help='tensile bond strength of the joints [MPa] (default 0.2)')
h.add_argument('--bond-c', type=float, default=0.3, help='cohesion of the joints [MPa] (default 0.3)')
h.add_argument('--floor-load', type=float, default=200.0, help='load on the floors and roof as mass per plan area [kg/m2] (default 200)')
h.add_argument('--ties', action='store_true', help='tie the joists to the walls (--big; default: they rest by friction)')
r = parser.add_argument_group('run')
r.add_argument('--settle', type=float, default=0.02, help='settling time under gravity with damping [s] (default 0.02)')
r.add_argument('--out', default='output/building', help='output folder (default output/building)')
r.add_argument('--frames', type=int, default=40, help='animation frames over the motion (default 40; 0 = none)')
r.add_argument('--vtk-every', type=float, default=0.05, help='ParaView output every this time [s] (default 0.05; 0 = none)')
r.add_argument('--checkpoint-every', type=float, default=0.0,
               help='save the run every this much ground motion [s] and at its end, into --out (default 0: never); see --resume')
r.add_argument('--resume', action='store_true', help='continue the run saved in --out by --checkpoint-every, with the same options (--duration may be '
               'longer), exactly as the uninterrupted run')
cli = parser.parse_args(sys.argv[1:])
for name in ('pga', 'duration', 'settle', 'record_dt'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name.replace('_', '-'), getattr(cli, name)))
if cli.start < 0 or cli.frames < 0 or cli.vtk_every < 0 or cli.checkpoint_every < 0:
	sys.exit('--start, --frames, --vtk-every and --checkpoint-every must be >= 0')
CHECKPOINT, FOLLOWED = os.path.join(cli.out, 'checkpoint.yade.gz'), os.path.join(cli.out, 'checkpoint.pickle')
RESUMABLE = ('duration', 'checkpoint_every', 'resume')  # the options a resumed run may change
if cli.resume and not (os.path.exists(CHECKPOINT) and os.path.exists(FOLLOWED)):
	sys.exit('--resume: no checkpoint in --out = %s (checkpoint.yade.gz and checkpoint.pickle, written by --checkpoint-every)' % cli.out)
from yade.rdem.build import mpiProcesses
if mpiProcesses() > 1:
	sys.exit('building: cannot run on YADE\'s MPI (yade.mpy) yet; this process is one of %d that mpiexec launched. Missing: (1) the '
	         'base beam follows the ground (RdemGroundShaker, a prescribed motion), and mpy sends the master\'s states to no worker: '
	         'its blocks would have to be the workers\' blocks, moved by their owners (a beam of one block makes its worker\'s '
	         'subdomain span the building); not done or tested; (2) the damage measures (drifts, out-of-plane displacements, corner '
	         'separations), the energies, the frames and the ParaView files read every block on one process: they must be gathered '
	         'over the ranks. What is there: the walls, lintels and floors over the workers, and a fixed beam or slab on the master '
	         'with its Poisson cell (doc/mpi.md). Run it serially: build/bin/yade -n scripts/building.py' % mpiProcesses())

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, Vector3, VTKRecorder, plot
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem
from yade.rdem import ground_motion as gm

G = gm.G
q, C, t = 0.065, 0.065, 0.01  # quarter module (l + t)/4, course h + t and joint of the 250x120x55 mm brick [m]
for d in ('vtk', 'frames'):
	os.makedirs(os.path.join(cli.out, d), exist_ok=True)


# 1. Ground motion ----------------------------------------------------------------------------------------------------
def readRecord(path):
	if not os.path.exists(path):
		raise SystemExit('building: --record %s: no such file (El Centro 1940 NS is not in the repository: data/records/README.md says where it '
		                 'comes from and where to put it; --record takes any .AT2 or values-in-g file)' % path)
	return gm.readAT2(path) if path.lower().endswith('.at2') else gm.readValues(path, dt=cli.record_dt)


try:
	records = {'x': readRecord(cli.record)}
	for axis, path in (('y', cli.record_y), ('z', cli.record_z)):
		if path:
			records[axis] = readRecord(path)
	factor = cli.pga * G / records['x'].pga
	records = {a: rec.baselineCorrected(2).scaled(factor) for a, rec in records.items()}
	# start at the last sign change of the x acceleration at or before --start, so that the base does not jerk at first
	ax, tx = records['x'].acc, records['x'].times()
	k0 = max((k for k in range(len(ax) - 1) if tx[k] <= cli.start + 1e-9 and ax[k] * ax[k + 1] <= 0), default=0)
	start = float(tx[k0])
	records = {a: rec.cut(start, start + cli.duration + rec.dt).startingAt(0.0) for a, rec in records.items()}
except (ValueError, FileNotFoundError) as e:
	sys.exit('building: %s' % e)
motion = gm.GroundMotion(**records)


# 2. The house, settled under gravity ------------------------------------------------------------------------------------
def smallHouse():
	L, W, H = 40 * q - t, 32 * q - t, 21 * C - t
	door, window = (12 * q, 15 * C - t / 2), (12 * q, 8 * C)
	openings = [('front', 0, 14 * q - t / 2, 0.0, *door), ('back', 0, 14 * q - t / 2, 6 * C - t / 2, *window),
	            ('left', 0, 10 * q - t / 2, 6 * C - t / 2, 12 * q, 8 * C), ('right', 0, 10 * q - t / 2, 6 * C - t / 2, 12 * q, 8 * C)]
	return dict(plan=(L, W), storeys=[H], thickness=0.12, bond='running', openings=openings, floors='slab', roofLoad=cli.floor_load)


def bigHouse():
	L, W = 120 * q - t, 88 * q - t
	walls = rdem.building_layout.rectangle(L, W, 0.25, 'english') + [
	        dict(name='inner', start=(60 * q + 0.125, 0.125), end=(60 * q + 0.125, W - 0.125), thickness=0.25, bond='english')
	]
	door, window = (12 * q, 33 * C - t / 2), (12 * q, 20 * C)
	openings = [('front', 0, 20 * q - t / 2, 0.0, *door), ('front', 0, 80 * q - t / 2, 10 * C - t / 2, *window), ('back', 0, 40 * q - t / 2, 10 * C - t / 2, *window),
	            ('front', 1, 20 * q - t / 2, 10 * C - t / 2, *window), ('front', 1, 80 * q - t / 2, 10 * C - t / 2, *window),
	            ('back', 1, 40 * q - t / 2, 10 * C - t / 2, *window), ('left', 0, 36 * q - t / 2, 10 * C - t / 2, *window),
	            ('right', 1, 36 * q - t / 2, 10 * C - t / 2, *window)]
	return dict(plan=walls, storeys=[40 * C - t] * 2, openings=openings, floors=['joists', 'slab'], floorLoad=cli.floor_load, roofLoad=cli.floor_load, ties=cli.ties)


wall0 = time.time()
brick = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick'))
joint = RdemJoint(young=2e9, poisson=0.25, tensileStrength=cli.bond_ft * 1e6, cohesion=cli.bond_c * 1e6, frictionAngle=math.atan(0.75))
O.engines = rdem.engines(formulation='consistent', failureStress='total', contactSamples=1, gravity=(0, 0, -9.81), damping=0.5)
# a sampled contact acts only where the blocks lie across each other: the corners of the roof-slab pieces rest on the edges
# of top bricks (doc/building.md "Runs")
rdem.geomFunctor().clipSampleAreas = True
try:
	b = rdem.masonry.building(brickMaterial=brick, jointMaterial=joint, **(bigHouse() if cli.big else smallHouse()))
except ValueError as e:
	sys.exit('building: %s' % e)
lay = b.layout
b.fixBase()
rdem.poissonEngine().elements = 'cells'
rdem.poissonEngine().build(b.bonded())
O.dt = -1
buildSeconds = time.time() - wall0
print('building: %r, built in %.1f s; %s' % (b, buildSeconds, 'resuming from %s' % CHECKPOINT if cli.resume else 'settling %.3g s under gravity' % cli.settle),
      flush=True)
if cli.resume:
	# the same options build the same house, with the same ids; the scene is then the saved one
	with open(FOLLOWED, 'rb') as f:
		followed = pickle.load(f)
	changed = [k for k, v in followed['options'].items() if k not in RESUMABLE and getattr(cli, k) != v]
	if changed:
		sys.exit('--resume: the run in %s was made with other options: %s' % (cli.out, ', '.join('--%s %s (now %s)' % (k.replace('_', '-'), followed['options'][k], getattr(cli, k))
		                                                                                         for k in changed)))
	O.load(CHECKPOINT)
	shaker = O.labeledEngine('groundShaker')
	settleReaction, settleBreaks, snapshot, t0, step0, ref, base0 = (followed[k] for k in ('settleReaction', 'settleBreaks', 'snapshot', 't0', 'step0', 'ref', 'base0'))
else:
	newton = rdem.newtonIntegrator()
	while O.time < cli.settle:
		rdem.run(100)
	settleReaction = -sum(O.forces.f(i)[2] for i in b.base) / b.weight()  # the base's upward reaction over the weight
	newton.damping = 0.0
	shaker = rdem.earthquake.shaker(motion, ids=b.base)
	shaker.times = [x + O.time for x in shaker.times]  # the motion starts now
	settleBreaks = sum(rdem.breakCounts())
	O.trackEnergy = True
	snapshot = rdem.bondSnapshot()
	rdem.run(1)  # the energies exist from here on (the springs' elastic energy, a current value, appears at once)
	t0, step0 = O.time, O.iter
	ref = {i: Vector3(O.bodies[i].state.pos) for i in b.ids}
	base0 = Vector3(O.bodies[b.base[0]].state.pos)
print('building: settled (base reaction %.5f of the weight, %d springs broken); %s, PGA %.3g g along x%s, %.3g s from t = %.3g s of the record; step %.3g s' %
      (settleReaction, settleBreaks, records['x'].name, cli.pga, ''.join(', %s %.3g g' % (a, r.pga / G) for a, r in records.items() if a != 'x'), cli.duration, start,
       O.dt), flush=True)

# 3. What is watched: per wall and storey, the top course's middle third; per junction, the pairs across it -----------------
watch = {}
for w in lay.walls:
	for s in lay.storeys:
		units = [i for i in lay.unitsOf('masonry', wall=w.index, storey=s.index) if lay.units[i].course == s.firstCourse + s.courses - 1]
		mid = [i for i in units if w.u0 + w.length / 3 <= (lay.units[i].lo[w.along] + lay.units[i].hi[w.along]) / 2 <= w.u0 + 2 * w.length / 3]
		watch[(w.name, s.index)] = [b.ids[k] for i in (mid or units) for k in lay.units[i].blocks]
junctions = []
for kind, i, j, point in lay.junctions:
	pairs = [(b.ids[p[0]], b.ids[p[1]]) for p in lay.pairs if p[2] in ('bed', 'head') and set(lay.pairWalls(p)) == {i, j}]
	junctions.append(dict(kind=kind, walls=(lay.walls[i].name, lay.walls[j].name), point=point, pairs=pairs))


def disp(i):
	return O.bodies[i].state.pos - ref[i] - (O.bodies[b.base[0]].state.pos - base0)


def drift(w, s):
	"""Mean displacement relative to the ground of the watched blocks of wall w in storey s: (in plane, out of plane) [m]."""
	ids = watch[(w.name, s)]
	m = sum((disp(i) for i in ids), Vector3(0, 0, 0)) / len(ids)
	return m[w.along], m[1 - w.along]


plot.reset()
plot.plots = {'t': ['oop_%s_%d' % (w.name, s.index) for w in lay.walls for s in lay.storeys], 't ': ('input', 'dissipated', 'kinetic', 'total')}
history = plot.data


def record():
	e = dict(O.energy.items())
	data = dict(t=O.time - t0, groundX=shaker.accelerationAt(O.time)[0], breaks=sum(rdem.breakCounts()), input=-e.get('groundWork', 0.0) - e.get('gravWork', 0.0),
	            dissipated=rdem.dissipatedEnergy(e),
	            kinetic=e.get('kinetic', 0.0), total=O.energy.total())
	for w in lay.walls:
		for s in lay.storeys:
			data['ip_%s_%d' % (w.name, s.index)], data['oop_%s_%d' % (w.name, s.index)] = drift(w, s.index)
	plot.addData(**data)


lo, hi = lay.bounds()


def frame(n):
	"""Front (x-z) and side (y-z) views of the block centres, coloured by their displacement relative to the ground."""
	pos = [O.bodies[i].state.pos for i in b.ids]
	d = [min(disp(i).norm(), 0.05) for i in b.ids]
	fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
	for ax, (u, name) in zip(axes, ((0, 'front, x-z'), (1, 'side, y-z'))):
		ax.scatter([p[u] for p in pos], [p[2] for p in pos], c=d, s=2, cmap='inferno_r', vmin=0, vmax=0.05)
		ax.set_xlim(lo[u] - 0.5, hi[u] + 0.5)
		ax.set_ylim(lo[2] - 0.3, hi[2] + 0.3)
		ax.set_aspect('equal')
		ax.set_title('%s, t = %.2f s' % (name, O.time - t0))
	fig.tight_layout()
	fig.savefig(os.path.join(cli.out, 'frames', 'frame-%04d.png' % n), dpi=80)
	plt.close(fig)




def checkpoint():
	"""The scene (O.save) and what this script follows, each written whole before it replaces the last."""
	O.save(CHECKPOINT + '.new.yade.gz')
	with open(FOLLOWED + '.new', 'wb') as f:
		pickle.dump(dict(options=vars(cli), settleReaction=settleReaction, settleBreaks=settleBreaks, snapshot=snapshot, t0=t0, step0=step0, ref=ref,
		                 base0=base0, history=dict(plot.data), cracks=cracks, vtkNext=vtkNext, frameNext=frameNext, nFrame=nFrame, checkpointNext=checkpointNext,
		                 runSeconds=runSecondsBefore + time.time() - runStart), f)
	os.replace(CHECKPOINT + '.new.yade.gz', CHECKPOINT)
	os.replace(FOLLOWED + '.new', FOLLOWED)


# 4. Run -------------------------------------------------------------------------------------------------------------
lastReport, runStart = time.time(), time.time()
if cli.resume:
	plot.data.update(followed['history'])
	cracks, vtkNext, frameNext, nFrame, checkpointNext, runSecondsBefore = (followed[k] for k in ('cracks', 'vtkNext', 'frameNext', 'nFrame', 'checkpointNext', 'runSeconds'))
	checkpointNext = min(checkpointNext, O.time - t0 + cli.checkpoint_every) if cli.checkpoint_every > 0 else float('inf')
else:
	vtkNext, frameNext, nFrame, runSecondsBefore = 0.0, 0.0, 0, 0.0
	checkpointNext = cli.checkpoint_every if cli.checkpoint_every > 0 else float('inf')
	cracks = rdem.CrackExport(os.path.join(cli.out, 'vtk', ''))
	record()
while O.time - t0 < cli.duration:
	rdem.run(50)
	record()
	if O.time - t0 >= checkpointNext:
		checkpointNext += cli.checkpoint_every
		checkpoint()
	if cli.vtk_every > 0 and O.time - t0 >= vtkNext:
		VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'])()
		cracks.write()
		vtkNext += cli.vtk_every
	if cli.frames and O.time - t0 >= frameNext:
		frame(nFrame)
		nFrame += 1
		frameNext += cli.duration / cli.frames
	if time.time() - lastReport > 10:
		lastReport = time.time()
		print('t = %.3f of %.3g s, broken springs %d, largest out-of-plane drift %.4f m, %.0f s so far' %
		      (O.time - t0, cli.duration, history['breaks'][-1], max(abs(history[k][-1]) for k in history if k.startswith('oop_')), lastReport - runStart),
		      flush=True)
if cli.checkpoint_every > 0:
	checkpoint()  # the end: a longer --duration --resume continues from here
runSeconds = runSecondsBefore + time.time() - runStart
cracks.close()
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

# 5. Damage per wall (doc/building.md) -----------------------------------------------------------------------------------
broken = rdem.brokenSegments(snapshot)
brokenPairs = {(s['id1'], s['id2']) for s in broken} | {(s['id2'], s['id1']) for s in broken}
wallOf = {bid: lay.unitWall[lay.blockUnit[k]] for k, bid in enumerate(b.ids)}
kindOf = {p: kind for kind, pairs in b.joints.items() for p in pairs}
brokenByKind = {}
for s in broken:
	kind = kindOf.get((s['id1'], s['id2']), kindOf.get((s['id2'], s['id1']), 'contact'))
	brokenByKind[kind] = brokenByKind.get(kind, 0) + 1
walls = {}
for w in lay.walls:
	own = [(i, j) for kind in ('bed', 'head', 'collar') for i, j in b.joints.get(kind, []) if wallOf[i] == w.index and wallOf[j] == w.index]
	cracked = sum(1 for p in own if p in brokenPairs)
	oop = max(abs(disp(i)[1 - w.along]) for i in b.walls[w.name])
	ipDrift = max(abs(history['ip_%s_%d' % (w.name, s.index)][k]) / s.height for s in lay.storeys for k in range(len(history['t'])))
	walls[w.name] = dict(joints=len(own), crackedJoints=cracked, crackedFraction=cracked / max(1, len(own)), maxInPlaneDriftRatio=ipDrift,
	                     crackedInPlane=cracked / max(1, len(own)) > 0.01 and ipDrift > 1e-3, maxOutOfPlane=oop,
	                     failedOutOfPlane=oop > w.thickness / 2)
corners = []
for j in junctions:
	rel = max((((O.bodies[a].state.pos - ref[a]) - (O.bodies[c].state.pos - ref[c])).norm() for a, c in j['pairs']), default=0.0)
	corners.append(dict(kind=j['kind'], walls=j['walls'], point=j['point'], pairs=len(j['pairs']), brokenPairs=sum(1 for p in j['pairs'] if p in brokenPairs),
	                    maxRelativeDisplacement=rel, separated=rel > t))
E = history['total']
inputMax = max(max(abs(x) for x in history['input']), 1e-30)
steps = O.iter - step0
results = dict(input=vars(cli), building=repr(b), blocks=len(b.ids), bonds=b.nBonds, layout=lay.counts(), weight=b.weight(), settleReaction=settleReaction,
               records={a: dict(name=r.name, pga=r.pga, dt=r.dt, duration=r.duration) for a, r in records.items()}, timeStep=O.dt, steps=steps,
               brokenSprings=history['breaks'][-1], settleBreaks=settleBreaks, brokenSpringsByJoint=brokenByKind, motionStart=start, walls=walls,
               junctions=corners,
               energy=dict(inputMax=inputMax, finalError=(E[-1] - E[0]) / inputMax, maxRise=max(E[k] - min(E[:k + 1]) for k in range(len(E))) / inputMax),
               buildSeconds=buildSeconds, runSeconds=runSeconds, threads=getattr(O, 'numThreads', None), microsecondsPerBlockStep=1e6 * runSeconds / max(1, steps * len(b.ids)),
               wallSecondsPerSimulatedSecond=runSeconds / (O.time - t0))
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1, default=str)

# 6. Figures -----------------------------------------------------------------------------------------------------------
tt = history['t']
for w in lay.walls:
	fig, ax = plt.subplots(figsize=(7, 4))
	for s in lay.storeys:
		ax.plot(tt, history['oop_%s_%d' % (w.name, s.index)], label='out of plane, storey %d' % s.index)
		ax.plot(tt, history['ip_%s_%d' % (w.name, s.index)], '--', label='in plane, storey %d' % s.index)
	ax.set_xlabel('time since the motion began [s]')
	ax.set_ylabel('top course, middle third, relative to the ground [m]')
	ax.set_title('wall %s' % w.name)
	ax.legend(fontsize=8)
	fig.tight_layout()
	fig.savefig(os.path.join(cli.out, 'drift-%s.png' % w.name), dpi=110)
	plt.close(fig)
	fig, ax = plt.subplots(figsize=(8, 2 + 6 * (hi[2] - lo[2]) / max(w.length, 1)))
	mine = [s for s in broken if wallOf[s['id1']] == w.index or wallOf[s['id2']] == w.index]
	for k in lay.blocksOf('masonry', wall=w.index):
		blo, bhi = lay.blocks[k]
		ax.add_patch(plt.Rectangle((blo[w.along] - w.u0, blo[2]), bhi[w.along] - blo[w.along], bhi[2] - blo[2], fill=False, lw=0.2, ec='0.6'))
	ax.scatter([s['point'][w.along] - w.u0 for s in mine], [s['point'][2] for s in mine], s=5, c=['r' if s['state'] == 1 else 'b' for s in mine])
	ax.set_xlim(-0.1, w.length + 0.1)
	ax.set_ylim(lo[2], hi[2])
	ax.set_aspect('equal')
	ax.set_title('wall %s: %d broken springs (red tension, blue shear); %.1f %% of its joints cracked' % (w.name, len(mine), 100 * walls[w.name]['crackedFraction']),
	             fontsize=9)
	ax.set_xlabel('along the wall from its outer end [m]')
	ax.set_ylabel('z [m]')
	fig.tight_layout()
	fig.savefig(os.path.join(cli.out, 'damage-%s.png' % w.name), dpi=110)
	plt.close(fig)
fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
axes[0].plot(tt, [a / G for a in history['groundX']])
axes[0].set_ylabel('ground acceleration x [g]')
for key, label in (('input', 'input (ground work and gravity)'), ('dissipated', 'dissipated'), ('kinetic', 'kinetic'), ('total', 'total (balance)')):
	axes[1].plot(tt, history[key], label=label)
axes[1].set_ylabel('energy [J]')
axes[1].set_xlabel('time since the motion began [s]')
axes[1].legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'energy.png'), dpi=110)
plt.close(fig)
if nFrame:
	from PIL import Image
	images = [Image.open(os.path.join(cli.out, 'frames', 'frame-%04d.png' % k)) for k in range(nFrame)]
	images[0].save(os.path.join(cli.out, 'collapse.gif'), save_all=True, append_images=images[1:], duration=150, loop=0)
print('building: %d steps in %.1f s (%.3f us per block-step, %.0f s per simulated second); %d broken springs; energy error %.2e of the input' %
      (steps, runSeconds, results['microsecondsPerBlockStep'], results['wallSecondsPerSimulatedSecond'], results['brokenSprings'], results['energy']['finalError']))
for name, d in walls.items():
	print('  wall %-6s cracked joints %5.1f %%, in-plane drift %.2e, out of plane %.4f m%s%s' %
	      (name, 100 * d['crackedFraction'], d['maxInPlaneDriftRatio'], d['maxOutOfPlane'], ', CRACKED IN PLANE' if d['crackedInPlane'] else '',
	       ', FAILED OUT OF PLANE' if d['failedOutOfPlane'] else ''))
for c in corners:
	print('  %s %s/%s: %d of %d pairs broken, relative displacement %.4f m%s' %
	      (c['kind'], c['walls'][0], c['walls'][1], c['brokenPairs'], c['pairs'], c['maxRelativeDisplacement'], ', SEPARATED' if c['separated'] else ''))
print('results in %s' % cli.out)
sys.exit(0)
