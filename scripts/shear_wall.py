# -*- coding: utf-8 -*-
"""In-plane shear test of a masonry wall: constant vertical stress, then a horizontal displacement of the top beam.

Problem
    A wall of the validation set (data/walls/walls.csv, --wall: Magenes & Calvi 1992 MI1, Magenes et al. 2008 CS01-CS08,
    Petry & Beyer 2014 PUP1-PUP6) between a fixed base beam and a top beam of one rigid block, built by the one rule set
    of rdem.wall_database from its row of the table (geometry, bond, joints, materials, sigma0, shear span; each value
    with its source, doc/validation.md "Fifteen walls"). First the vertical stress sigma0 is ramped up on the top beam
    and held until the wall is at rest; then the top beam moves along the wall (monotonic, or cycles of growing drift):
    kept horizontal (--shear-span 0.5: both ends fixed) or free to rotate in the wall's plane as a lever pinned at H0,
    with the moment V (H0 - H) at the masonry's top (any other --shear-span H0/H; 1: a cantilever). Quasi-static loading (doc/validation.md,
    "Quasi-static loading in fewer steps"): the velocity of the top beam is ramped up along a half cosine (--ramp) at
    the start and at every reversal, and Cundall's non-viscous damping (--damping) takes out the vibrations.

    Defaults: the validated configuration of doc/validation.md for the wall chosen (MI1 unless --wall): the rule set's
    geometry and materials, softening springs, two blocks per unit along its length, head joints by the rule set
    (MI1: without bond, Mann & Müller 1982), the consistent Poisson formulation with cells and failure on the total stress
    of a face, the loading scheme and the stop criteria of the validation. An option given changes that configuration
    (the run is then no longer the validated one; results.json records every option).

Expected result
    MI1: linear up to the first cracks in the joints at the wall's corners, then diagonal, stair-stepped cracking through
    the bed and head joints and bricks split along it; the load peaks at about 300 kN (doc/validation.md; measured
    269.6 / 259.6 kN in the two directions at 0.20 / 0.18 % drift, diagonal shear cracking).

How to run
    build/bin/yade -n scripts/shear_wall.py                        MI1, the figure of doc/validation.md
    build/bin/yade -n scripts/shear_wall.py --wall PUP3 --out output/shear_wall_PUP3
    build/bin/yade -n scripts/shear_wall.py --shear-span 1 --sigma0 0.5 --cycles 0.05,0.1,0.2
    build/bin/yade -n scripts/wall_database.py                     every wall of the table, one after the other
    build/bin/yade -n scripts/shear_wall.py --wall PUP1 --setup-only   build the scene only (every bond made and checked)
    build/bin/yade -n scripts/shear_wall.py --help                 every option

Outputs (in --out, default output/shear_wall): results.json (inputs and the rule set's sources, peak load and drift,
initial stiffness, first crack, cracks by joint/brick and mode, failure mode, energy balance, cost), history.txt
(yade.plot's saveDataTxt), load_drift.png (load against drift with the measured peaks, energy, broken springs),
cracks.png (the front of the wall with every broken spring, coloured by mode, at the peak and at the end), ParaView
files in vtk/ (blocks.*.vtu from YADE's VTKRecorder, cracks.pvd); with --setup-only only setup.json (blocks, bonds, the bonds
whose strengths the crack band lowered).
"""
import argparse
import json
import math
import os
import sys
import time
from yade import rdem  # before the options: rdem.masonry.addWallArguments
from yade.rdem import wall_database

# 1. Options (defaults: the rule set of rdem.wall_database for --wall, so that --help shows the validated values) -------
pre = argparse.ArgumentParser(add_help=False)
pre.add_argument('--wall', default='MI1')
pre.add_argument('--table', default=wall_database.TABLE)
known, _ = pre.parse_known_args(sys.argv[1:])
try:
	rows = wall_database.readTable(known.table)
except (OSError, ValueError) as e:
	sys.exit('shear_wall: --table: %s' % e)
if known.wall not in rows:
	sys.exit('shear_wall: --wall = %r: must be one of %s (the specimens of --table)' % (known.wall, ', '.join(rows)))
spec = wall_database.model(rows[known.wall])
geo, mats, scheme = spec['geometry'], spec['materials'], wall_database.rule('quasiStatic')
brk, jnt, bm = mats['brick'], mats['joint'], mats['beam']

parser = argparse.ArgumentParser(prog='yade scripts/shear_wall.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--wall', choices=list(rows), default='MI1',
                    help='the wall of --table: its model by the rule set, its sigma0 and shear span, its measured peaks for comparison (default MI1)')
parser.add_argument('--table', default=wall_database.TABLE, help='table of walls in the columns of the EPFL database (default data/walls/walls.csv)')
rdem.masonry.addWallArguments(parser, length=geo['length'], height=geo['height'], thickness=geo['thickness'], bond=geo['bond'], blocks=geo['blocksPerBrick'],
                              beam=geo['beam'], brick=geo['brick'], joint=geo['joint'])
m = parser.add_argument_group('materials (stresses in MPa, moduli in GPa, densities in kg/m3; defaults: the rule set for --wall)')
m.add_argument('--brick-E', type=float, default=brk['young'] * 1e-9, help="brick Young's modulus (default %(default).4g)")
m.add_argument('--brick-nu', type=float, default=brk['poisson'], help="brick Poisson's ratio (default %(default)g)")
m.add_argument('--brick-ft', type=float, default=brk['tensileStrength'] * 1e-6, help='brick tensile strength (default %(default).4g)')
m.add_argument('--brick-c', type=float, default=brk['cohesion'] * 1e-6, help='brick cohesion (default %(default).4g)')
m.add_argument('--brick-mu', type=float, default=brk['mu'], help='brick friction coefficient (default %(default)g)')
m.add_argument('--brick-density', type=float, default=brk['density'], help='brick (masonry) density (default %(default).4g)')
m.add_argument('--mortar-E', type=float, default=jnt['young'] * 1e-9, help="mortar Young's modulus (default %(default).4g)")
m.add_argument('--mortar-nu', type=float, default=jnt['poisson'], help="mortar Poisson's ratio (default %(default)g)")
m.add_argument('--bond-ft', type=float, default=jnt['tensileStrength'] * 1e-6, help='tensile bond strength of the joints (default %(default).4g)')
m.add_argument('--bond-c', type=float, default=jnt['cohesion'] * 1e-6, help='cohesion of the joints (default %(default).4g)')
m.add_argument('--bond-mu', type=float, default=jnt['mu'], help='friction coefficient of the joints (default %(default)g)')
m.add_argument('--bond-GfI', type=float, default=jnt['GfI'], help='mode-I fracture energy of the joints [J/m2] (softening; default %(default)g)')
m.add_argument('--bond-GfII', type=float, default=jnt['GfII'], help='mode-II fracture energy of the joints [J/m2] (softening; default %(default)g)')
m.add_argument('--bond-fc', type=float, default=jnt['fc'] * 1e-6, help="compressive strength of the joints' cap (softening; default %(default).4g, f_m; 0: no cap)")
m.add_argument('--bond-Gfc', type=float, default=jnt['Gfc'], help='compressive fracture energy of the cap [J/m2] (softening; default %(default)g)')
m.add_argument('--brick-GfI', type=float, default=brk['GfI'], help='mode-I fracture energy of the bricks [J/m2] (softening; default %(default)g)')
m.add_argument('--brick-GfII', type=float, default=brk['GfII'], help='mode-II fracture energy of the bricks [J/m2] (softening; default %(default)g)')
m.add_argument('--brick-fc', type=float, default=brk['fc'] * 1e-6, help="compressive strength of the bricks' cap (softening; default %(default).4g, f_b; 0: no cap)")
m.add_argument('--beam-E', type=float, default=bm['young'] * 1e-9, help="beams' Young's modulus (default %(default)g, concrete)")
m.add_argument('--beam-nu', type=float, default=bm['poisson'], help="beams' Poisson's ratio (default %(default)g)")
m.add_argument('--beam-density', type=float, default=bm['density'], help="beams' density (default %(default)g)")
r = parser.add_argument_group('test')
r.add_argument('--sigma0', type=float, default=spec['test']['sigma0'] * 1e-6, help='vertical stress on the masonry [MPa] (default %(default)g, the table\'s)')
r.add_argument('--shear-span', type=float, default=spec['test']['shearSpan'],
               help='shear span ratio H0/H: 0.5 keeps the top beam horizontal (both ends fixed), any other value lets it rotate under the moment '
               'V (H0 - H) at the masonry\'s top, 1 a cantilever (default %(default)g, the table\'s)')
r.add_argument('--drift', type=float, default=scheme['drift'] * 100,
               help='monotonic test: the push ends past this drift [%%] once it is also past --past-peak times the drift of the smoothed peak so far '
               '(default %(default)g)')
r.add_argument('--past-peak', type=float, default=scheme['pastPeak'], help='see --drift (default %(default)g)')
r.add_argument('--max-drift', type=float, default=scheme['maxDrift'] * 100, help='monotonic test: the push ends at this drift at the latest [%%] (default %(default)g)')
r.add_argument('--cycles', type=str, default='', help='cyclic test instead: drift amplitudes [%%] separated by commas, e.g. 0.05,0.1,0.2 (default none)')
r.add_argument('--repeat', type=int, default=1, help='cycles per amplitude (default 1)')
r.add_argument('--stop-drop', type=float, default=scheme['stopDrop'],
               help='monotonic test: stop once the load (averaged over --smooth) has dropped by this fraction of its peak (default %(default)g; 0 = never)')
r.add_argument('--max-wall', type=float, default=0, help='end the loading after this wall-clock time [s] and write the results so far (default 0: no limit)')
r.add_argument('--rate', type=float, default=scheme['rate'] * 1e3, help='speed of the top beam [mm/s] (default %(default)g)')
r.add_argument('--ramp', type=float, default=None,
               help='duration of the velocity ramp at the start and at reversals [s] (default: %g mm of travel at --rate)' % (scheme['rampTravel'] * 1e3))
r.add_argument('--compress-time', type=float, default=scheme['compressTime'], help='duration of the vertical-load ramp [s] (default %(default)g)')
r.add_argument('--damping', type=float, default=scheme['damping'], help="Cundall's non-viscous damping of the integrator, in [0, 1) (default %(default)g)")
r.add_argument('--inertia-scaling', choices=['on', 'off'], default='on' if scheme['inertiaScaling'] else 'off',
               help="the masonry blocks' moments of inertia scaled by rdem.quasi_static.rotationalInertiaScale, masses unchanged (default %(default)s)")
r.add_argument('--density-scaling', type=float, default=scheme['densityScaling'],
               help='partial density scaling for the push: the lightest and stiffest masonry blocks get the inertia that raises their own damped '
               'limit to this factor times the smallest one, their weight unchanged (rdem.walltest.scaleDensity; >= 1, 1: none; default %(default)g)')
r.add_argument('--gravity', type=float, default=wall_database.GRAVITY, help='gravity along -z [m/s2] (default %(default)g; 0: none)')
k = parser.add_argument_group('model')
k.add_argument('--formulation', choices=['consistent', 'paper', 'off'], default='consistent', help="Poisson effect: consistent (cells), paper, off (default consistent)")
k.add_argument('--failure-stress', choices=['total', 'spring'], default='total', help='springs break on the total stress of their face (default) or their own')
k.add_argument('--springs', type=int, default=2, help='springs per face edge (default 2)')
k.add_argument('--contact-samples', type=int, default=None, help="contact sample grid per face edge (default: --springs, the grid the walls of doc/validation.md were run with; 1: the vertices, rdem.engines' default)")
k.add_argument('--softening', choices=['off', 'on'], default='on', help='softening law of the springs (default on; off: brittle, the paper)')
k.add_argument('--crack-band', choices=['off', 'on'], default='on' if wall_database.rule('crackBand') else 'off',
               help="with softening: springs that would snap back get Bazant & Oh's lowered strength instead of an error (default %(default)s, the rule set's)")
k.add_argument('--head-joints', choices=['unbonded', 'bonded'], default=jnt['headJoints'],
               help='head joints without bond (compression and friction only, MannMuller1982) or bonded like the bed joints (default %(default)s, the rule set)')
k.add_argument('--verlet', type=float, default=0.003, help='sweep distance of the collider [m] once contacts can occur (default 0.003; 0: the collider runs every step)')
k.add_argument('--safety', type=float, default=0.8, help='time step over its stable estimate (default 0.8)')
o = parser.add_argument_group('output')
o.add_argument('--smooth', type=float, default=scheme['smoothDrift'] * 100,
               help='width of the centred moving average of the load for the smoothed peak and the stop criterion [%% drift] (default %(default)g)')
o.add_argument('--out', default='output/shear_wall', help='output folder (default output/shear_wall)')
o.add_argument('--setup-only', action='store_true', help='build the scene (every bond made and checked), write setup.json and stop (default: run the test)')
o.add_argument('--save', default='', help='save the scene at the end of the run to this file (O.save; e.g. for scripts/shear_wall_cost.py; default none)')
o.add_argument('--vtk-every', type=float, default=0.05, help='ParaView output every this drift [%%] (default 0.05; 0 = none)')
cli = parser.parse_args(sys.argv[1:])
for name in ('rate', 'drift', 'max_drift', 'past_peak', 'beam', 'compress_time', 'brick_density', 'beam_density', 'shear_span', 'smooth'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name.replace('_', '-'), getattr(cli, name)))
if not (math.isfinite(cli.density_scaling) and cli.density_scaling >= 1):
	sys.exit('--density-scaling = %g: must be >= 1 (the gain on the time step; 1: none)' % cli.density_scaling)
if not 0 <= cli.stop_drop < 1:
	sys.exit('--stop-drop = %g: must be in [0, 1)' % cli.stop_drop)
ramp = cli.ramp if cli.ramp is not None else scheme['rampTravel'] / (cli.rate * 1e-3)
if ramp < 0:
	sys.exit('--ramp = %g: must be >= 0' % ramp)
try:
	amplitudes = rdem.masonry.numbers(cli.cycles) if cli.cycles else []
except argparse.ArgumentTypeError as e:
	sys.exit('--cycles: %s' % e)
from yade.rdem.build import mpiProcesses
if mpiProcesses() > 1:
	sys.exit('shear_wall: cannot run on YADE\'s MPI (yade.mpy) yet; this process is one of %d that mpiexec launched. The wall itself '
	         'could (its blocks over the workers, the fixed base beam with its Poisson cell on the master: doc/mpi.md); missing: '
	         '(1) the top beam moves under the wall\'s forces and the vertical load, and mpy integrates a body on its owner only and '
	         'sends the master\'s states to no worker, so it must be a worker\'s block (then that worker\'s subdomain spans the wall); '
	         '(2) rdem.walltest.ShearWallTest reads the top beam\'s force and position and the base beam\'s force on one process and '
	         'runs O.run in chunks: its measurements and its loop must become collective (the owner\'s values on every rank, '
	         'mpy.mpirun); (3) the crack snapshot, the ParaView files and the figures read every block on one process. '
	         'Run it serially: build/bin/yade -n scripts/shear_wall.py' % mpiProcesses())
validated = all(getattr(cli, a.dest) == a.default for a in parser._actions if a.dest not in ('help', 'out', 'save', 'setup_only', 'vtk_every', 'max_wall', 'wall', 'table'))

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, VTKRecorder, plot
from yade.wrapper import RdemMat, RdemJoint
from yade.rdem import walltest

measured = spec['measured']
sigma0 = cli.sigma0 * 1e6
boundary = 'fixed' if cli.shear_span == 0.5 else 'cantilever'
os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)

# 2. Scene ------------------------------------------------------------------------------------------------------------
O.reset()
setup0 = time.time()
try:
	cap = lambda fc: fc * 1e6 if fc > 0 else float('inf')
	brick = O.materials.append(
	        RdemMat(young=cli.brick_E * 1e9, poisson=cli.brick_nu, density=cli.brick_density, tensileStrength=cli.brick_ft * 1e6, cohesion=cli.brick_c * 1e6,
	                frictionAngle=math.atan(cli.brick_mu), fractureEnergy=cli.brick_GfI, shearFractureEnergy=cli.brick_GfII,
	                compressiveStrength=cap(cli.brick_fc), compressiveFractureEnergy=cli.bond_Gfc, label='brick'))
	beam = O.materials.append(
	        RdemMat(young=cli.beam_E * 1e9, poisson=cli.beam_nu, density=cli.beam_density, tensileStrength=float('inf'), cohesion=float('inf'),
	                frictionAngle=math.atan(cli.bond_mu), label='beam'))
	joint = RdemJoint(young=cli.mortar_E * 1e9, poisson=cli.mortar_nu, tensileStrength=cli.bond_ft * 1e6, cohesion=cli.bond_c * 1e6,
	                  frictionAngle=math.atan(cli.bond_mu), fractureEnergy=cli.bond_GfI, shearFractureEnergy=cli.bond_GfII, compressiveStrength=cap(cli.bond_fc),
	                  compressiveFractureEnergy=cli.bond_Gfc)
	total = cli.failure_stress == 'total' and cli.formulation == 'consistent'
	O.engines = rdem.engines(segmentsPerEdge=cli.springs,
	                         contactSamples=cli.contact_samples or cli.springs,
	                         formulation=None if cli.formulation == 'off' else cli.formulation,
	                         damping=cli.damping,
	                         gravity=(0, 0, -cli.gravity),
	                         safety=cli.safety,
	                         verletDist=cli.verlet,
	                         failureStress='total' if total else 'spring',
	                         softening=cli.softening == 'on',
	                         crackBand=cli.crack_band == 'on')  # before the wall: a bond's law is fixed when it is made
	w = rdem.masonry.wall(cli.length, cli.height, cli.thickness, brick=cli.brick, joint=cli.joint, bond=cli.bond, blocksPerBrick=cli.blocks,
	                      mortar=cli.mortar, openings=cli.openings, baseBeam=cli.beam, topBeam=cli.beam, beamBlocks=1, brickMaterial=brick,
	                      jointMaterial=joint, beamMaterial=beam)
	if cli.formulation != 'off':
		if total:
			rdem.poissonEngine().elements = 'cells'
		rdem.poissonEngine().build(w.ids)
	unbonded = walltest.unbondJoints(w, 'head') if cli.head_joints == 'unbonded' else set()
	test = walltest.ShearWallTest(w, sigma0, boundary=boundary, shearSpan=cli.shear_span)
	inertiaFactor = walltest.scaleRotationalInertia(w.masonry()) if cli.inertia_scaling == 'on' else 1.0
	targets = [a * 1e-2 * w.layout.height for a in walltest.cycleTargets(amplitudes, cli.repeat)] if amplitudes else [cli.max_drift * 1e-2 * w.layout.height]
except ValueError as e:
	sys.exit('shear_wall: %s' % e)
O.trackEnergy = True
O.dt = rdem.timeStepper().safety * rdem.timeStepper().estimate()
span = sum(abs(b - a) for a, b in zip([0.0] + targets[:-1], targets))
print('shear_wall: %s; sigma0 %.3g MPa (N = %.1f kN), %s; rotational inertia x %.3g at most; time step %.3g s, about %d steps of loading; set-up %.1f s' %
      (w, sigma0 * 1e-6, test.axialForce * 1e-3, 'H0/H = %g' % cli.shear_span, inertiaFactor, O.dt, span / (cli.rate * 1e-3) / O.dt, time.time() - setup0),
      flush=True)

def crackBandBonds():
	"""The bonds whose strengths the crack-band rule lowered (--crack-band): f_t, c or the cap f_c equal to none of the
	values of the wall's materials and joint, with the lowest f_t and f_c of such bonds [MPa]."""
	given = dict(ft=(cli.brick_ft * 1e6, cli.bond_ft * 1e6), c=(cli.brick_c * 1e6, cli.bond_c * 1e6), fc=(cap(cli.brick_fc), cap(cli.bond_fc)))
	low = lambda v, name: math.isfinite(v) and not any(abs(v - g) <= 1e-9 * g for g in given[name])
	n, ft, fc = 0, float('inf'), float('inf')
	for I in O.interactions:
		p = I.phys
		if I.isReal and getattr(p, 'softening', False):
			lowered = [low(p.tensileStrength, 'ft'), low(p.cohesion, 'c'), low(p.compressiveStrength, 'fc')]
			if any(lowered):
				n += 1
				ft = min(ft, p.tensileStrength) if lowered[0] else ft
				fc = min(fc, p.compressiveStrength) if lowered[2] else fc
	return dict(bonds=n, lowestTensileStrengthMPa=ft * 1e-6 if math.isfinite(ft) else None, lowestCapMPa=fc * 1e-6 if math.isfinite(fc) else None)


crackBand = crackBandBonds()
print('shear_wall: crack band (%s): %d bonds with lowered strengths%s' %
      (cli.crack_band, crackBand['bonds'], ', lowest f_t %s MPa, f_c %s MPa' % (crackBand['lowestTensileStrengthMPa'], crackBand['lowestCapMPa']) if crackBand['bonds'] else ''),
      flush=True)
if cli.setup_only:
	with open(os.path.join(cli.out, 'setup.json'), 'w') as f:
		json.dump(dict(wall=cli.wall, blocks=len(w.ids), bonds=w.nBonds, interactions=sum(1 for I in O.interactions if I.isReal), crackBand=crackBand), f, indent=1)
	sys.exit(0)

# 3. Recording -------------------------------------------------------------------------------------------------------
ENERGIES = ('rdemElastic', 'rdemPoisson', 'rdemBondBreak', 'rdemContactRelease', 'rdemDashpot', 'rdemFriction', 'rdemPoissonRelease', 'rdemFractureTension', 'rdemFractureShear',
            'rdemCrushing', 'nonviscDamp', 'kinetic', 'gravWork', 'rdemStepChange')
# yade.plot keeps the history (plot.data): live curves with plot.plot() in a YADE with a GUI, history.txt by saveDataTxt.
plot.reset()
plot.plots = {'drift': ('shear', 'baseShear'), 't': ('tension', 'shearBreaks')}
history = plot.data
state = dict(peak=None, peakCracks=None, first=None, report=time.time(), iter=O.iter, vtkNext=0.0, smoothPeak=0.0, smoothPeakDrift=0.0)
cracks = rdem.CrackExport(os.path.join(cli.out, 'vtk', ''))


def record(t):
	nt, ns = rdem.breakCounts()
	keys = O.energy.keys()
	ts = rdem.timeStepper()
	plot.addData(t=O.time,
	             dt=O.dt,
	             criticalDt=ts.criticalDt,
	             contactDt=ts.contactDt,
	             springCriticalDt=ts.springCriticalDt,
	             drift=t.drift(),
	             shear=t.shear(),
	             baseShear=t.baseShear(),
	             axial=t.axialLoad(),
	             rotation=t.topRotation(),
	             vertical=t.verticalDisplacement(),
	             tension=nt,
	             shearBreaks=ns,
	             workH=t.work['horizontal'],
	             workV=t.work['vertical'],
	             workM=t.work['moment'],
	             moment=t.topMoment(),
	             momentOfMasonry=t.topMomentOfMasonry(),
	             **{e: O.energy[e] if e in keys else 0.0 for e in ENERGIES})


def onStep(t):
	"""After every chunk of the loading: record, track the peak and the first crack, ParaView output, progress."""
	record(t)
	V, d = history['shear'][-1], history['drift'][-1]
	if state['first'] is None and history['tension'][-1] + history['shearBreaks'][-1] > state['breaks0']:
		state['first'] = dict(shearKN=V * 1e-3, driftPercent=d * 100, time=O.time)
	if state['peak'] is None or abs(V) > abs(state['peak']['shearKN']) * 1e3:
		ts = rdem.timeStepper()  # the step and its limits at the peak (the last estimate)
		state['peak'] = dict(shearKN=V * 1e-3, driftPercent=d * 100, index=len(history['t']) - 1, dt=O.dt, criticalDt=ts.criticalDt,
		                     springCriticalDt=ts.springCriticalDt, contactDt=ts.contactDt)
		state['peakCracks'] = None
	elif state['peakCracks'] is None and abs(V) < 0.99 * abs(state['peak']['shearKN']) * 1e3:
		state['peakCracks'] = rdem.brokenSegments(cracks.snapshot)  # the cracks just past the peak (1 % drop)
	if cli.vtk_every > 0 and abs(d) * 100 >= state['vtkNext']:
		VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'])()
		cracks.write()
		state['vtkNext'] += cli.vtk_every
	now = time.time()
	if now - state['report'] > 5:
		rate = (O.iter - state['iter']) / (now - state['report'])
		state.update(report=now, iter=O.iter)
		print('step %7d  drift %+.4f %%  V %+8.1f kN (base %+8.1f)  N %.1f kN  rotation %+.2e rad  broken springs: tension %d, shear %d  %.0f steps/s' %
		      (O.iter, d * 100, V * 1e-3, history['baseShear'][-1] * 1e-3, history['axial'][-1] * 1e-3, history['rotation'][-1], history['tension'][-1],
		       history['shearBreaks'][-1], rate),
		      flush=True)


def stop(t):
	"""Monotonic test: ends once the load, averaged over the last --smooth of drift (crack bursts make single samples
	spike), has dropped by --stop-drop of the largest such average (once past the first crack: before it, the peak is
	the residual of the vertical loading), or once the drift is past both --drift and --past-peak times the drift of
	that largest average (the peak is behind), or at --max-drift."""
	if cli.max_wall > 0 and time.time() - t1 > cli.max_wall:
		print('shear_wall: --max-wall %g s reached; results so far' % cli.max_wall, flush=True)
		return True
	if amplitudes:
		return False
	mean = abs(walltest.trailingMean(history['drift'], history['shear'], cli.smooth * 1e-2))
	d = abs(history['drift'][-1])
	if mean > state.get('smoothPeak', 0.0):
		state['smoothPeak'], state['smoothPeakDrift'] = mean, d
	dropped = cli.stop_drop > 0 and state['first'] is not None and abs(state['peak']['driftPercent']) > 0.01 and mean < (1 - cli.stop_drop) * state['smoothPeak']
	behind = d * 100 >= cli.drift and d >= cli.past_peak * state['smoothPeakDrift']
	return dropped or behind


# 4. Run ----------------------------------------------------------------------------------------------------------------
t0 = time.time()
compressTime = test.compress(cli.compress_time)
compressWall = time.time() - t0
compressSteps = O.iter
print('shear_wall: sigma0 applied in %.3f s (%d steps, %.1f s); settlement %.3f mm, top rotation %.1e rad' %
      (compressTime, compressSteps, compressWall, test.verticalDisplacement() * 1e3, test.topRotation()),
      flush=True)
density = walltest.scaleDensity(w.masonry(), cli.density_scaling)  # after sigma0: the head joints' dashpots act
if density['scaled']:
	print('shear_wall: density scaling x%g: %d blocks scaled (inertia x%.3g at most, +%.0f %% of their mass), their own limits raised to %.3g us' %
	      (cli.density_scaling, density['scaled'], density['largest'], 100 * density['addedMass'], density['target'] * 1e6),
	      flush=True)
# cracks counted from here (none expected under sigma0 alone), the head joints that start without bond left out
cracks.snapshot = [row for row in rdem.bondSnapshot() if (min(row[0], row[1]), max(row[0], row[1])) not in unbonded]
state['breaks0'] = sum(rdem.breakCounts())

onStep(test)
t1 = time.time()
pushSteps = test.push(targets, cli.rate * 1e-3, ramp, record=onStep, stop=stop)
pushWall = time.time() - t1
cracks.write()
cracks.close()
final = rdem.brokenSegments(cracks.snapshot)
if cli.save:
	O.save(cli.save)
if state['peakCracks'] is None:
	state['peakCracks'] = final

# 5. Results ----------------------------------------------------------------------------------------------------------
h = history
peak, first = state['peak'], state['first']
smoothV, smoothDrift = walltest.smoothedPeakOverDrift(h['drift'], h['shear'], cli.smooth * 1e-2)
smoothed = dict(shearKN=smoothV * 1e-3, driftPercent=smoothDrift * 100, widthPercent=cli.smooth)
at = min(range(len(h['drift'])), key=lambda k: abs(abs(h['drift'][k]) - abs(smoothDrift)))  # the step and its limits there
smoothed.update({k: h[k][at] for k in ('dt', 'criticalDt', 'springCriticalDt', 'contactDt')})
uFirst = first['driftPercent'] * 1e-2 * test.height if first else None
stiffness = first['shearKN'] * 1e3 / uFirst if first and uFirst else float('nan')
closedForm = (walltest.timoshenkoStiffness(cli.brick_E * 1e9, cli.brick_nu, w.layout.length, w.layout.thickness, w.layout.height, boundary)
              if (cli.brick_E, cli.brick_nu) == (cli.mortar_E, cli.mortar_nu) and cli.shear_span in (0.5, 1.0) else None)
e0 = {e: h[e][0] for e in ENERGIES}  # energies when the horizontal loading began
stored = {e: h[e][-1] for e in ENERGIES}
external = h['workH'][-1] + h['workV'][-1] + h['workM'][-1]
accounted = sum(stored.values())
crackCount = walltest.crackClasses(w, final)
peakCount = walltest.crackClasses(w, state['peakCracks'])
indicators = walltest.failureIndicators(w, final)
failure = dict(modelClass=wall_database.failureClass(*indicators), horizontalTensionArea=indicators[0], coreCourses=indicators[1],
               coreCoursesCracked=indicators[2], jointArea=indicators[3], measured=measured['failure'], measuredClass=measured['failureClass'])
cost = dict(compressSteps=compressSteps, compressSeconds=compressWall, pushSteps=pushSteps, pushSeconds=pushWall, threads=O.numThreads,
            microsecondsPerBlockStep=1e6 * pushWall / max(1, pushSteps * len(w.ids)))
mean = measured['mean']
comparison = dict(measuredPeakKN=[v * 1e-3 for v in measured['peak']], measuredMeanKN=mean * 1e-3, modelPeakKN=abs(peak['shearKN']),
                  peakError=abs(peak['shearKN']) * 1e3 / mean - 1, measuredDriftPercent=[d * 100 for d in measured['driftAtPeak']],
                  modelDriftPercent=abs(peak['driftPercent']), smoothedPeakKN=abs(smoothed['shearKN']), smoothedPeakError=abs(smoothV) / mean - 1,
                  smoothedDriftPercent=abs(smoothed['driftPercent']), measuredFailure=measured['failure'], failure=failure)
results = dict(input=vars(cli), validated=validated, wall=cli.wall, model=spec, sigma0=sigma0, shearSpan=cli.shear_span, axialForce=test.axialForce, blocks=len(w.ids),
               bonds=w.nBonds, bricks=len(w.bricks), courses=len(w.courses), joints={k: len(v) for k, v in w.joints.items()},
               cells=rdem.poissonEngine().nCells if cli.formulation != 'off' else 0, crackBand=crackBand, timeStep=O.dt, densityScaling=density, rules={k: v[1] for k, v in wall_database.RULES.items()},
               peak=peak, smoothedPeak=smoothed, firstCrack=first, initialStiffnessKNPerMm=stiffness * 1e-6,
               timoshenkoStiffnessKNPerMm=closedForm * 1e-6 if closedForm else None, cracksAtPeak=peakCount, cracksAtEnd=crackCount, failure=failure,
               brokenSprings=dict(tension=h['tension'][-1] - h['tension'][0], shear=h['shearBreaks'][-1] - h['shearBreaks'][0]),
               settlementMm=-h['vertical'][0] * 1e3, largestTopRotation=max(abs(r) for r in h['rotation']),
               largestShearImbalance=max(abs(a - b) for a, b in zip(h['shear'], h['baseShear'])) / max(1.0, max(abs(v) for v in h['shear'])),
               energy=dict(externalWork=external, stored=stored, balanceError=(external - accounted) / external if external else None, atPushStart=e0),
               cost=cost, comparison=comparison, history=h)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

# 6. Figures ----------------------------------------------------------------------------------------------------------
drift = [100 * d for d in h['drift']]
fig, axes = plt.subplots(3, 1, figsize=(7, 10), sharex=True)
ax = axes[0]
ax.plot(drift, [1e-3 * v for v in h['shear']], 'k-', label='model, force on the top beam')
ax.plot(drift, [1e-3 * v for v in h['baseShear']], '-', color='0.6', lw=0.8, label='model, base shear')
ax.plot([peak['driftPercent']], [peak['shearKN']], 'ko', label='model peak %.1f kN at %.3f %%' % (peak['shearKN'], peak['driftPercent']))
if first:
	ax.plot([first['driftPercent']], [first['shearKN']], 'o', color='tab:orange', label='first broken spring, %.1f kN' % first['shearKN'])
for sign, V, d in zip((1, -1), measured['peak'], measured['driftAtPeak']):
	ax.plot([sign * 100 * d], [sign * 1e-3 * V], 's', color='tab:green', label='measured peak %s%.1f kN at %.3f %%' % ('+' if sign > 0 else '-', 1e-3 * V, 100 * d))
if not amplitudes:  # a monotonic run against the envelope: the negative peak mirrored
	ax.plot([100 * measured['driftAtPeak'][1]], [1e-3 * measured['peak'][1]], 's', mfc='none', color='tab:green', label='measured peak -, mirrored')
ax.set_ylabel('horizontal load V [kN]')
ax.set_title('%s%s: sigma0 = %.2f MPa, H0/H = %g, %s' % (cli.wall, '' if validated else ' (options changed)', sigma0 * 1e-6, cli.shear_span,
                                                   'softening' if cli.softening == 'on' else 'brittle springs'))
ax.legend(fontsize=7)
ax = axes[1]
dissipated = [
        sum(h[e][k] for e in rdem.measure.DISSIPATED + ('nonviscDamp',))
        for k in range(len(drift))
]
ax.plot(drift, [a + b + c for a, b, c in zip(h['workH'], h['workV'], h['workM'])], 'k-', label='work of the actuator, the vertical load and the couple')
ax.plot(drift, [a + b for a, b in zip(h['rdemElastic'], h['rdemPoisson'])], label='elastic (springs and cells)')
ax.plot(drift, dissipated, label='dissipated (breaks, dropped contact springs, fracture, crushing, dashpots, friction, damping)')
ax.plot(drift, h['nonviscDamp'], ':', label="of which Cundall's damping")
ax.plot(drift, h['kinetic'], label='kinetic')
ax.set_ylabel('energy [J]')
ax.legend(fontsize=7)
ax = axes[2]
ax.plot(drift, [n - h['tension'][0] for n in h['tension']], 'r-', label='tension')
ax.plot(drift, [n - h['shearBreaks'][0] for n in h['shearBreaks']], 'b-', label='shear')
ax.set_ylabel('broken springs')
ax.set_xlabel('drift u/H [%]')
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'load_drift.png'), dpi=120)

COLOURS = {1: 'tab:red', 2: 'tab:blue', 3: '0.4'}


def drawCracks(ax, segs, title):
	"""The wall's front (the units on y = 0) and every broken spring whose face is seen from the front (bed and head
	joints, vertical and horizontal cracks in bricks; collar faces left out), all wythes projected onto it."""
	lay = w.layout
	for ids in w.units:
		lo = [min(O.bodies[i].state.refPos[d] - O.bodies[i].shape.extents[d] for i in ids) for d in range(3)]
		hi = [max(O.bodies[i].state.refPos[d] + O.bodies[i].shape.extents[d] for i in ids) for d in range(3)]
		if lo[1] < 1e-9:
			ax.add_patch(plt.Rectangle((lo[0], lo[2]), hi[0] - lo[0], hi[2] - lo[2], fc=tuple(O.bodies[ids[0]].shape.color), ec='k', lw=0.2, alpha=0.5))
	for sg in segs:
		if abs(sg['normal'][1]) > 0.9:
			continue
		p, t1, t2 = sg['point'], sg['t1'], sg['t2']
		half, t = (sg['halfSizes'][0], t1) if abs(t1[1]) < 0.9 else (sg['halfSizes'][1], t2)
		ax.plot([p[0] - half * t[0], p[0] + half * t[0]], [p[2] - half * t[2], p[2] + half * t[2]], '-', color=COLOURS[sg['state']], lw=1.2)
	ax.set_xlim(-0.02, lay.length + 0.02)
	ax.set_ylim(-cli.beam, lay.height + cli.beam)
	ax.set_aspect('equal')
	ax.set_title(title, fontsize=8)
	ax.set_xlabel('x [m]')


fig, axes = plt.subplots(1, 2, figsize=(10, 7))
drawCracks(axes[0], state['peakCracks'], 'just past the peak (%.1f kN, %.3f %%): %d broken springs' % (peak['shearKN'], peak['driftPercent'], len(state['peakCracks'])))
drawCracks(axes[1], final, 'end (%.3f %%): %d broken springs' % (drift[-1], len(final)))
axes[0].set_ylabel('z [m]')
for state_, name in ((1, 'tension'), (2, 'shear'), (3, 'broken, mode not recorded')):
	axes[1].plot([], [], '-', color=COLOURS[state_], label=name)
axes[1].legend(fontsize=7, loc='upper right')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'cracks.png'), dpi=120)

print('shear_wall: %s: smoothed peak (over %g %% drift) %.1f kN at %.3f %% drift (measured mean %.1f kN: %+.1f %%); failure mode %s (measured %s)' %
      (cli.wall, cli.smooth, smoothed['shearKN'], smoothed['driftPercent'], mean * 1e-3, 100 * comparison['smoothedPeakError'], failure['modelClass'],
       measured['failure']),
      flush=True)
print('shear_wall: peak %.1f kN at %.3f %% drift%s; first broken spring at %s; initial stiffness %.1f kN/mm%s; cracks at the end: joints %s, bricks %s; '
      'energy balance %s; %d + %d steps in %.1f + %.1f s (%.3f us per block-step, %d threads); results in %s' %
      (peak['shearKN'], peak['driftPercent'], (' (measured mean %.1f kN: %+.1f %%)' % (comparison['measuredMeanKN'], 100 * comparison['peakError'])) if comparison else '',
       '%.1f kN' % first['shearKN'] if first else 'none', stiffness * 1e-6, (' (Timoshenko %.1f)' % (closedForm * 1e-6)) if closedForm else '',
       crackCount['joint'], crackCount['brick'], '%.2e' % results['energy']['balanceError'] if external else '-', compressSteps, pushSteps, compressWall, pushWall,
       cost['microsecondsPerBlockStep'], O.numThreads, cli.out))
sys.exit(0)
