# -*- coding: utf-8 -*-
"""Vertical compression of a masonry wall of bricks and mortar, with the Poisson effect on any bond pattern.

Problem
    A wall (default: 1.03 m long, 0.77 m tall, one wythe 0.12 m thick, 12 courses of 250×120×55 mm clay bricks in
    running bond, 10 mm interface joints, bricks cut into 2×1×2 blocks so that they can crack) between a base beam and a
    top beam, 100 mm each, of the brick's elastic constants and unbreakable. The base beam is fixed; the top beam moves
    down at a constant rate and is kept horizontal (no rotation). Consistent formulation: springs λ+2μ and Poisson cells
    (doc/theory.md §5.4), so that a wall of one material has exactly the input E and ν; springs break on the total
    normal stress of their face, springs plus cells (doc/theory.md §5.6; --failure-stress spring: the paper's
    criterion). Every geometric, material and loading parameter is an option (rdem.masonry.wall builds the wall).

    Default materials (illustrative, one set for all runs): brick E = 16.7 GPa, ν = 0.15, f_t = 3 MPa, density
    1800 kg/m³; mortar E = 2 GPa, ν = 0.25; unit–mortar bond f_t = 0.2 MPa, cohesion 0.3 MPa, friction coefficient 0.75.

Expected result
    Before cracking the stress grows linearly with the shortening, with the wall's stiffness (bricks and joints in series).
    With a soft mortar the first cracks are vertical, through the bricks above and below the head joints (the
    brick–mortar mismatch of doc/theory.md §5.5, Hilsdorf 1969), and the bed joints stay closed. results.json gives the
    stress at the first cracked joint and at the first cracked brick.

How to run
    build/bin/yade scripts/wall.py                           the default wall (about a minute)
    build/bin/yade scripts/wall.py --help                    every option
    build/bin/yade scripts/wall.py --bond english --thickness 0.25 --blocks 1,1,1 --end 0.3
    build/bin/yade -n scripts/wall.py --openings 0.39,0.26,0.25,0.26   a window; -n: no viewer
    mpiexec -n 3 build-mpi/bin/yade -n scripts/wall.py --mpi   on YADE's MPI (yade.mpy, doc/mpi.md): the base beam and
        its Poisson cell on the master (rank 0), the wall and the top beam over the workers; results written once

Outputs (in --out, default output/wall): results.json, history.txt (yade.plot), stress_displacement.png, cracks.png (front view of the wall
with its broken springs), ParaView files in vtk/ (blocks.*.vtu from YADE's VTKRecorder, cracks.pvd; not with --mpi).
"""
import argparse
import json
import math
import os
import sys
import time
from yade import rdem  # before the options: rdem.masonry.addWallArguments


# 1. Options ---------------------------------------------------------------------------------------------------------
parser = argparse.ArgumentParser(prog='yade scripts/wall.py', description=__doc__.split('\n\n')[0])
rdem.masonry.addWallArguments(parser, length=1.03, height=0.77, thickness=0.12, bond='running', blocks=(2, 1, 2), beam=0.1)
m = parser.add_argument_group('materials (stresses in MPa, moduli in GPa)')
m.add_argument('--brick-E', type=float, default=16.7, help="brick Young's modulus (default 16.7)")
m.add_argument('--brick-nu', type=float, default=0.15, help="brick Poisson's ratio (default 0.15)")
m.add_argument('--brick-ft', type=float, default=3.0, help='brick tensile strength (default 3.0)')
m.add_argument('--brick-density', type=float, default=1800, help='brick density [kg/m3] (default 1800)')
m.add_argument('--mortar-E', type=float, default=2.0, help="mortar Young's modulus (default 2.0)")
m.add_argument('--mortar-nu', type=float, default=0.25, help="mortar Poisson's ratio (default 0.25)")
m.add_argument('--bond-ft', type=float, default=0.2, help='tensile bond strength of the unit-mortar interface (default 0.2)')
m.add_argument('--bond-c', type=float, default=0.3, help='cohesion of the joints (default 0.3)')
m.add_argument('--bond-mu', type=float, default=0.75, help='friction coefficient of the joints (default 0.75)')
r = parser.add_argument_group('model and loading')
r.add_argument('--formulation', choices=['consistent', 'paper', 'off'], default='consistent',
               help="Poisson formulation (default consistent; 'paper' needs a grid of 2x2x2 groups of blocks, e.g. stack bond)")
r.add_argument('--failure-stress', choices=['total', 'spring'], default='total',
               help="springs break on the face's total normal stress, springs plus Poisson cells (default, consistent formulation only), or on "
               "the springs' own stress as in the paper (whose lateral springs carry tension under compression)")
r.add_argument('--springs', type=int, default=2, help='springs per face edge (default 2)')
r.add_argument('--rate', type=float, default=20.0, help='shortening rate of the wall [mm/s] (default 20)')
r.add_argument('--end', type=float, default=1.5, help='end shortening [mm] (default 1.5)')
r.add_argument('--damping', type=float, default=0.0, help="Cundall's non-viscous damping of the integrator, in [0, 1) (default 0, as in the paper)")
r.add_argument('--out', default='output/wall', help='output folder (default output/wall)')
r.add_argument('--vtk-every', type=float, default=0.05, help='ParaView output every this shortening [mm] (default 0.05; 0 = none; not with --mpi)')
r.add_argument('--contacts', choices=['gate', 'always'], default='gate',
               help="contact detection by RdemContactGate, from the first broken spring on (default), or always (from the first step, as "
               "on mpy, whose split runs the collider whatever the gate says, with the sweep rdem.distributed.prepare gives the collider: "
               "the serial run to compare an --mpi run with)")
r.add_argument('--dt', type=float, default=0,
               help="a fixed time step [s] (default 0: RdemTimeStepper's, updated as springs break; a fixed one makes the --mpi run the serial one)")
r.add_argument('--mpi', action='store_true',
               help="run on YADE's MPI (mpiexec -n 3 or more, build-mpi/bin/yade): the base beam stays on the master, the rest is cut into "
               "the workers' subdomains (rdem.distributed.prepare); no ParaView output")
cli = parser.parse_args(sys.argv[1:])
for name in ('rate', 'end', 'beam'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name, getattr(cli, name)))
if cli.dt < 0:
	sys.exit('--dt = %g: must be >= 0 (0: automatic)' % cli.dt)
rank = 0
if cli.mpi:
	from yade import mpy
	from yade.rdem import distributed
	mpy.VERBOSE_OUTPUT = False
	mpy.configure()
	if mpy.numThreads < 2:
		sys.exit('wall: --mpi runs on YADE\'s MPI: mpiexec -n 3 build-mpi/bin/yade -n -x scripts/wall.py --mpi (the master and at least one worker)')
	rank = mpy.rank
	cli.vtk_every = 0

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, PyRunner, VTKRecorder, Vector3, plot
from yade.wrapper import RdemMat, RdemJoint

os.makedirs(cli.out, exist_ok=True)

# 2. Scene ------------------------------------------------------------------------------------------------------------
O.reset()
wall0 = time.time()
try:
	brick = O.materials.append(
	        RdemMat(young=cli.brick_E * 1e9, poisson=cli.brick_nu, density=cli.brick_density, tensileStrength=cli.brick_ft * 1e6, label='brick'))
	joint = RdemJoint(young=cli.mortar_E * 1e9, poisson=cli.mortar_nu, tensileStrength=cli.bond_ft * 1e6, cohesion=cli.bond_c * 1e6,
	                  frictionAngle=math.atan(cli.bond_mu))
	total = cli.failure_stress == 'total' and cli.formulation == 'consistent'
	O.engines = rdem.engines(segmentsPerEdge=cli.springs,
	                         formulation=None if cli.formulation == 'off' else cli.formulation,
	                         damping=cli.damping,
	                         failureStress='total' if total else 'spring',
	                         dt=cli.dt if cli.dt > 0 else None,
	                         distributed=cli.mpi)
	w = rdem.masonry.wall(cli.length, cli.height, cli.thickness, brick=cli.brick, joint=cli.joint, bond=cli.bond, blocksPerBrick=cli.blocks,
	                      mortar=cli.mortar, openings=cli.openings, baseBeam=cli.beam, topBeam=cli.beam, brickMaterial=brick, jointMaterial=joint)
	for i in w.beams['base']:
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	for i in w.beams['top']:
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
		O.bodies[i].state.vel = Vector3(0, 0, -cli.rate * 1e-3)
	if cli.formulation != 'off':
		if total:
			rdem.poissonEngine().elements = 'cells'  # also on a grid (stack bond): the total stress of a face needs the cells
		rdem.poissonEngine().build(w.ids)
	if cli.contacts == 'always' or cli.mpi:
		# what a run on mpy has: contacts from the first step (its split), a collider sweep (rdem.distributed.prepare's)
		rdem.contactGate().open = True
		if not rdem.collider().verletDist > 0:
			rdem.collider().verletDist = 0.1 * min(min(O.bodies[i].shape.extents) for i in w.ids)
except ValueError as e:
	sys.exit('wall: %s' % e)
area = w.layout.length * w.layout.thickness
dt = cli.dt if cli.dt > 0 else rdem.timeStepper().safety * rdem.timeStepper().estimate()
nSteps = int(math.ceil(cli.end / cli.rate / dt))
nElements = rdem.poissonEngine().nElements if cli.formulation != 'off' else 0  # of the whole scene (on mpy each rank holds a part)
nCells = rdem.poissonEngine().nCells if cli.formulation != 'off' else 0
if rank == 0:
	print('wall: %s; %d Poisson elements, %d cells; about %d steps of %.3g s; set-up %.1f s' % (w, nElements, nCells, nSteps, dt, time.time() - wall0), flush=True)

# 3. Recording -------------------------------------------------------------------------------------------------------
kindOf = {}
for kind, pairs in w.joints.items():
	for a, b in pairs:
		kindOf[(min(a, b), max(a, b))] = kind
cracks = rdem.CrackExport(os.path.join(cli.out, 'vtk', ''))
plot.reset()  # yade.plot keeps the history (plot.data): live plot.plot() in a GUI, history.txt by saveDataTxt
plot.plots = {'shortening': ('stress', )}
history = plot.data
first = {}


def owned(ids):
	"""The blocks of ids this process integrates (all of them serially; on mpy its own: their state and the force on them
	are right on their owner only)."""
	return [i for i in ids if not cli.mpi or (i < len(O.bodies) and O.bodies[i] is not None and O.bodies[i].subdomain == rank)]


def overRanks(x):
	"""x summed over the ranks on mpy (collective: every rank calls it at the same point), else x."""
	return mpy.comm.allreduce(x) if cli.mpi else x


def shortening():
	return overRanks(sum(O.bodies[i].state.refPos[2] - O.bodies[i].state.pos[2] for i in owned(w.beams['top']))) / len(w.beams['top'])


def stress():
	"""Mean compressive stress on the wall: the force the wall exerts on the top beam over the cross-section [Pa]."""
	return overRanks(sum(O.forces.f(i)[2] for i in owned(w.beams['top']))) / area


def breaks():
	"""Broken springs of joints (bed, head, collar, beam, mortar) and inside bricks (internal) so far, and this process's
	broken segments (on mpy those of the bonds it counts: each bond on one rank, summed over the ranks)."""
	segs = rdem.brokenSegments(snapshot)
	inBricks = sum(1 for s in segs if kindOf.get((min(s['id1'], s['id2']), max(s['id1'], s['id2']))) == 'internal')
	return overRanks(len(segs) - inBricks), overRanks(inBricks), segs


def record():
	nJ, nB, segs = breaks()
	plot.addData(t=O.time, shortening=shortening(), stress=stress(), jointBreaks=nJ, brickBreaks=nB)
	for key, n in (('joint', nJ), ('brick', nB)):
		if n > 0 and key not in first:
			first[key] = dict(time=O.time, stressMPa=history['stress'][-1] * 1e-6, shorteningMm=history['shortening'][-1] * 1e3)


progress = dict(wall=time.time(), iter=0)


def report():
	if rank != 0 or not history.get('t'):
		return
	now = time.time()
	rate = (O.iter - progress['iter']) / max(now - progress['wall'], 1e-9)
	progress.update(wall=now, iter=O.iter)
	left = (nSteps - O.iter) / rate if rate > 0 else float('nan')
	# the last record's values (a report every 5 s of the wall clock is not at the same step on every rank of mpy)
	print('step %7d/%d  shortening %.4f mm  stress %6.2f MPa  broken springs: joints %d, bricks %d  %.0f steps/s  %.0f s left' %
	      (O.iter, nSteps, 1e3 * history['shortening'][-1], 1e-6 * history['stress'][-1], history['jointBreaks'][-1], history['brickBreaks'][-1], rate, left),
	      flush=True)


O.engines += [PyRunner(command='record()', iterPeriod=max(1, nSteps // 400)), PyRunner(command='report()', realPeriod=5)]
vtkEvery = int(round(cli.vtk_every / cli.rate / dt)) if cli.vtk_every > 0 else 0
if vtkEvery:
	O.engines += [
	        VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'], iterPeriod=vtkEvery),
	        PyRunner(command='cracks.write()', iterPeriod=vtkEvery)
	]

snapshot = cracks.snapshot
if cli.mpi:
	distributed.prepare(master=w.beams['base'])  # the fixed base beam (with its Poisson cell) on the master
	snapshot = [row for row in snapshot if distributed.countedHere(row[0], row[1])]

# 4. Run --------------------------------------------------------------------------------------------------------------
wallRun = time.time()
while shortening() < cli.end * 1e-3:
	if cli.mpi:
		mpy.mpirun(max(1, nSteps // 100))
	else:
		rdem.run(max(1, nSteps // 100))
wallTime = time.time() - wallRun
record()
if not cli.mpi:
	cracks.close()

# 5. Results (on mpy: gathered on the master and written there once) -------------------------------------------------
nJ, nB, segs = breaks()
tension, shear = distributed.breakCounts() if cli.mpi else rdem.breakCounts()
# the blocks seen from the front (x-z: lower corner, upper corner, colour) and the broken segments, for the figure
front = {
        i: ([O.bodies[i].state.pos[d] - O.bodies[i].shape.extents[d] for d in (0, 2)], [O.bodies[i].state.pos[d] + O.bodies[i].shape.extents[d]
                                                                                      for d in (0, 2)], tuple(O.bodies[i].shape.color))
        for i in owned(w.ids)
}
lines = [(tuple(s['point']), tuple(s['normal']), tuple(s['t1']), tuple(s['t2']), tuple(s['halfSizes']), s['state']) for s in segs]
endShortening = shortening()
if cli.mpi:
	parts = mpy.comm.gather((front, lines), root=0)
	if rank != 0:
		sys.exit(0)
	front = {i: v for f, _ in parts for i, v in f.items()}
	lines = [x for _, l in parts for x in l]
elastic = [(d, s) for d, s, j, b in zip(history['shortening'], history['stress'], history['jointBreaks'], history['brickBreaks']) if j + b == 0 and d > 0]
stiffness = sum(s for _, s in elastic[len(elastic) // 2:]) / sum(d for d, _ in elastic[len(elastic) // 2:]) if len(elastic) > 1 else float('nan')
results = dict(input=vars(cli),
               blocks=len(w.ids),
               bonds=w.nBonds,
               bricks=len(w.bricks),
               courses=len(w.courses),
               joints={k: len(v) for k, v in w.joints.items()},
               cells=nCells,
               poissonElements=nElements,
               elasticStiffnessMPaPerMm=stiffness * 1e-9,
               firstJointCrack=first.get('joint'),
               firstBrickCrack=first.get('brick'),
               peakStressMPa=max(history['stress']) * 1e-6,
               brokenSprings=dict(joints=nJ, bricks=nB, tension=tension, shear=shear),
               processes=mpy.numThreads if cli.mpi else 1,
               steps=O.iter,
               timeStep=O.dt,
               wallSeconds=wallTime,
               microsecondsPerBlockStep=1e6 * wallTime / max(1, O.iter * len(w.ids)),
               history=history)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot([1e3 * d for d in history['shortening']], [1e-6 * s for s in history['stress']], 'k-')
for key, colour in (('joint', 'tab:blue'), ('brick', 'tab:red')):
	if key in first:
		ax.plot([first[key]['shorteningMm']], [first[key]['stressMPa']], 'o', color=colour, label='first cracked %s, %.2f MPa' % (key, first[key]['stressMPa']))
if first:
	ax.legend()
ax.set_xlabel('shortening of the wall [mm]')
ax.set_ylabel('mean compressive stress [MPa]')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'stress_displacement.png'), dpi=120)

fig, ax = plt.subplots(figsize=(6, 6 * (w.layout.height + 2 * cli.beam) / w.layout.length))
for ids in w.units:
	lo = [min(front[i][0][d] for i in ids) for d in (0, 1)]
	hi = [max(front[i][1][d] for i in ids) for d in (0, 1)]
	ax.add_patch(plt.Rectangle((lo[0], lo[1]), hi[0] - lo[0], hi[1] - lo[1], fc=front[ids[0]][2], ec='k', lw=0.3))
for p, normal, t1, t2, halfSizes, state in lines:
	if abs(normal[1]) > 0.9:
		continue  # collar faces are not seen from the front
	h = halfSizes[0] if abs(t1[1]) < 0.9 else halfSizes[1]
	t = t1 if abs(t1[1]) < 0.9 else t2
	ax.plot([p[0] - h * t[0], p[0] + h * t[0]], [p[2] - h * t[2], p[2] + h * t[2]], '-', color='r' if state == 1 else 'b', lw=1.5)
ax.set_xlim(-0.02, w.layout.length + 0.02)
ax.set_ylim(-cli.beam - 0.02, w.layout.height + cli.beam + 0.02)
ax.set_aspect('equal')
ax.set_title('%d broken springs at %.2f mm (red tension, blue shear)' % (len(lines), 1e3 * endShortening))
ax.set_xlabel('x [m]')
ax.set_ylabel('z [m]')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'cracks.png'), dpi=120)

fmt = lambda d, k: '%.2f MPa' % d[k] if d else 'none'
print('wall: elastic stiffness %.1f MPa/mm; first cracked joint %s, first cracked brick %s; peak %.2f MPa; %d steps in %.1f s (%.3f us per block-step); '
      'results in %s' % (stiffness * 1e-9, fmt(first.get('joint'), 'stressMPa'), fmt(first.get('brick'), 'stressMPa'), results['peakStressMPa'], O.iter,
                         wallTime, results['microsecondsPerBlockStep'], cli.out))
sys.exit(0)
