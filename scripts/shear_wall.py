# -*- coding: utf-8 -*-
"""In-plane shear test of a masonry wall: constant vertical stress, then a horizontal displacement of the top beam.

Problem
    A brick wall (rdem.masonry.wall: any geometry, bond, joints, blocks per brick) between a fixed base beam and a top
    beam of one rigid block. First the vertical stress σ0 is ramped up on the top beam and held until the wall is at rest;
    then the top beam moves along the wall (monotonic, or cycles of growing drift) with the boundary condition of the
    test: both ends fixed (--boundary fixed: the top beam stays horizontal, shear span H0 = H/2) or a cantilever
    (--boundary cantilever: the top beam may rotate in the wall's plane, H0 = H). Quasi-static loading: the velocity of
    the top beam is ramped up along a half cosine (--ramp) at the start and at every reversal, and Cundall's
    non-viscous damping (--damping) takes out the vibrations; rerun at half --rate to check the peak load (doc/validation.md).

    Defaults: the Magenes & Calvi (1992) walls (rdem.walltest.MAGENES_CALVI: one parameter set, every value with its
    source): 1.55 × 2.005 × 0.38 m English bond of 250×120×55 mm bricks, 10 mm interface joints, E = 2991 MPa and ν = 0.25
    for brick and mortar, bed and collar joints f_t = 0.15 MPa, c = 0.21 MPa, μ = 0.81, head joints without bond
    (compression and friction only, Mann & Müller 1982: --head-joints), bricks f_t = 1.28 MPa, c = 1.79 MPa; concrete
    beams; σ0 = 1.2 MPa (MI1; --wall MI2: 0.4 MPa), both ends fixed. Consistent Poisson formulation with cells, springs
    breaking on the total stress of their face (doc/theory.md §5.6); brittle springs (the paper's law).

Expected result
    Linear up to the first cracks in the joints at the wall's corners, then diagonal, stair-stepped cracking through the
    bed and head joints (and bricks with several blocks per brick); the load peaks and drops. Magenes & Calvi measured
    V_max = 269.6 / 259.6 kN (MI1) and 241.6 / 227.2 kN (MI2) in the two directions, at 0.20 / 0.18 % and 0.40 / 0.39 %
    drift, with diagonal shear cracking.

How to run
    build/bin/yade -n scripts/shear_wall.py                       MI1, monotonic to 0.6 % drift (a few minutes)
    build/bin/yade -n scripts/shear_wall.py --wall MI2 --out output/shear_wall_MI2
    build/bin/yade -n scripts/shear_wall.py --boundary cantilever --sigma0 0.5 --cycles 0.05,0.1,0.2
    build/bin/yade -n -j2 scripts/shear_wall.py --blocks 2,1,1    two threads, bricks of two blocks
    build/bin/yade -n scripts/shear_wall.py --help                every option

Outputs (in --out, default output/shear_wall): results.json (inputs, peak load and drift, initial stiffness, first
crack, cracks by joint/brick and mode, energy balance, cost), history.txt (yade.plot's saveDataTxt), load_drift.png (load against drift with the measured
peaks, energy, broken springs), cracks.png (the front of the wall with every broken spring, coloured by mode, at the
peak and at the end), ParaView files in vtk/ (blocks.*.vtu from YADE's VTKRecorder, cracks.pvd).
"""
import argparse
import json
import math
import os
import sys
import time
import rdem  # before the options: rdem.masonry.addWallArguments


# 1. Options (defaults: rdem.walltest.MAGENES_CALVI, repeated here so that --help shows them) -------------------------
parser = argparse.ArgumentParser(prog='yade scripts/shear_wall.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--wall', choices=['MI1', 'MI2', 'none'], default='MI1',
                    help='a Magenes & Calvi (1992) wall: its sigma0 (unless --sigma0 is given) and its measured peaks for comparison; '
                    'none: no measured values (default MI1)')
rdem.masonry.addWallArguments(parser, length=1.55, height=2.005, thickness=0.38, bond='english', blocks=(1, 1, 1), beam=0.2)
m = parser.add_argument_group('materials (stresses in MPa, moduli in GPa, densities in kg/m3)')
m.add_argument('--brick-E', type=float, default=2.991, help="brick Young's modulus (default 2.991)")
m.add_argument('--brick-nu', type=float, default=0.25, help="brick Poisson's ratio (default 0.25)")
m.add_argument('--brick-ft', type=float, default=1.28, help='brick tensile strength (default 1.28)')
m.add_argument('--brick-c', type=float, default=1.79, help='brick cohesion (default 1.79)')
m.add_argument('--brick-mu', type=float, default=0.81, help='brick friction coefficient (default 0.81)')
m.add_argument('--density', type=float, default=1800, help='brick (masonry) density (default 1800)')
m.add_argument('--mortar-E', type=float, default=2.991, help="mortar Young's modulus (default 2.991)")
m.add_argument('--mortar-nu', type=float, default=0.25, help="mortar Poisson's ratio (default 0.25)")
m.add_argument('--bond-ft', type=float, default=0.15, help='tensile bond strength of the joints (default 0.15)')
m.add_argument('--bond-c', type=float, default=0.21, help='cohesion of the joints (default 0.21)')
m.add_argument('--bond-mu', type=float, default=0.81, help='friction coefficient of the joints (default 0.81)')
m.add_argument('--bond-GfI', type=float, default=18.0, help='mode-I fracture energy of the joints [J/m2] (softening; default 18, LourencoRots1997)')
m.add_argument('--bond-GfII', type=float, default=125.0, help='mode-II fracture energy of the joints [J/m2] (softening; default 125, LourencoRots1997)')
m.add_argument('--bond-fc', type=float, default=7.92,
               help='compressive strength of the joints\' cap (softening; default 7.92, the masonry strength f_m of the database; 0: no cap)')
m.add_argument('--bond-Gfc', type=float, default=5000.0, help='compressive fracture energy of the cap [J/m2] (softening; default 5000, LourencoRots1997)')
m.add_argument('--brick-GfI', type=float, default=80.0, help='mode-I fracture energy of the bricks [J/m2] (softening; default 80, LourencoRots1997)')
m.add_argument('--brick-GfII', type=float, default=800.0, help='mode-II fracture energy of the bricks [J/m2] (softening; default 800 = 10 G_f^I)')
m.add_argument('--brick-fc', type=float, default=19.72,
               help='compressive strength of the bricks\' cap (softening; default 19.72, f_b of the database; 0: no cap)')
m.add_argument('--beam-E', type=float, default=30.0, help="beams' Young's modulus (default 30, concrete)")
m.add_argument('--beam-nu', type=float, default=0.2, help="beams' Poisson's ratio (default 0.2)")
m.add_argument('--beam-density', type=float, default=2400, help="beams' density (default 2400)")
r = parser.add_argument_group('test')
r.add_argument('--sigma0', type=float, default=None, help='vertical stress on the masonry [MPa] (default: that of --wall, 1.2 for MI1)')
r.add_argument('--boundary', choices=['fixed', 'cantilever'], default='fixed', help='top beam kept horizontal (fixed) or free to rotate (default fixed)')
r.add_argument('--drift', type=float, default=0.6, help='monotonic test: end drift [%%] (default 0.6)')
r.add_argument('--cycles', type=str, default='', help='cyclic test instead: drift amplitudes [%%] separated by commas, e.g. 0.05,0.1,0.2 (default none)')
r.add_argument('--repeat', type=int, default=1, help='cycles per amplitude (default 1)')
r.add_argument('--stop-drop', type=float, default=0.3, help='monotonic test: stop once the load (averaged over --smooth samples) has dropped by this fraction of its peak (default 0.3; 0 = never)')
r.add_argument('--max-wall', type=float, default=0, help='end the loading after this wall-clock time [s] and write the results so far (default 0: no limit)')
r.add_argument('--rate', type=float, default=10.0, help='speed of the top beam [mm/s] (default 10)')
r.add_argument('--ramp', type=float, default=0.05, help='duration of the velocity ramp at the start and at reversals [s] (default 0.05)')
r.add_argument('--compress-time', type=float, default=0.05, help='duration of the vertical-load ramp [s] (default 0.05)')
r.add_argument('--damping', type=float, default=0.2, help="Cundall's non-viscous damping of the integrator, in [0, 1) (default 0.2)")
r.add_argument('--gravity', type=float, default=9.81, help='gravity along -z [m/s2] (default 9.81; 0: none)')
k = parser.add_argument_group('model')
k.add_argument('--formulation', choices=['consistent', 'paper', 'off'], default='consistent', help="Poisson effect: consistent (cells), paper, off (default consistent)")
k.add_argument('--failure-stress', choices=['total', 'spring'], default='total', help='springs break on the total stress of their face (default) or their own')
k.add_argument('--springs', type=int, default=2, help='springs per face edge (default 2)')
k.add_argument('--softening', choices=['off', 'on'], default='off', help='softening law of the springs (issue #18; default off: brittle, the paper)')
k.add_argument('--head-joints', choices=['unbonded', 'bonded'], default='unbonded',
               help='head joints without bond (compression and friction only, MannMuller1982; default) or bonded like the bed joints')
k.add_argument('--verlet', type=float, default=0.003,
               help='sweep distance of the collider [m] once contacts can occur (default 0.003, about 5 %% of a course; 0: the collider runs every step)')
k.add_argument('--safety', type=float, default=0.8, help='time step over its stable estimate (default 0.8)')
o = parser.add_argument_group('output')
o.add_argument('--smooth', type=int, default=21,
               help='samples (of 100 steps) of the moving average for the smoothed peak, odd (default 21: about one first period of MI1)')
o.add_argument('--out', default='output/shear_wall', help='output folder (default output/shear_wall)')
o.add_argument('--save', default='', help='save the scene at the end of the run to this file (O.save; e.g. for scripts/shear_wall_cost.py; default none)')
o.add_argument('--vtk-every', type=float, default=0.05, help='ParaView output every this drift [%%] (default 0.05; 0 = none)')
cli = parser.parse_args(sys.argv[1:])
for name in ('rate', 'drift', 'beam', 'compress_time', 'density', 'beam_density'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name.replace('_', '-'), getattr(cli, name)))
if not (cli.smooth >= 1 and cli.smooth % 2 == 1):
	sys.exit('--smooth = %d: must be an odd integer >= 1' % cli.smooth)
if not 0 <= cli.stop_drop < 1:
	sys.exit('--stop-drop = %g: must be in [0, 1)' % cli.stop_drop)
if cli.ramp < 0:
	sys.exit('--ramp = %g: must be >= 0' % cli.ramp)
try:
	amplitudes = rdem.masonry.numbers(cli.cycles) if cli.cycles else []
except argparse.ArgumentTypeError as e:
	sys.exit('--cycles: %s' % e)

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, VTKRecorder, plot
from yade.wrapper import RdemMat, RdemJoint
from rdem import walltest

measured = walltest.MAGENES_CALVI_WALLS.get(cli.wall)
sigma0 = cli.sigma0 * 1e6 if cli.sigma0 is not None else (measured['sigma0'] if measured else 0.0)
os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)

# 2. Scene ------------------------------------------------------------------------------------------------------------
O.reset()
setup0 = time.time()
try:
	cap = lambda fc: fc * 1e6 if fc > 0 else float('inf')
	brick = O.materials.append(
	        RdemMat(young=cli.brick_E * 1e9, poisson=cli.brick_nu, density=cli.density, tensileStrength=cli.brick_ft * 1e6, cohesion=cli.brick_c * 1e6,
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
	                         poisson=None if cli.formulation == 'off' else cli.formulation,
	                         damping=cli.damping,
	                         gravity=(0, 0, -cli.gravity),
	                         safety=cli.safety,
	                         verletDist=cli.verlet,
	                         failureStress='total' if total else 'spring',
	                         softening=cli.softening == 'on')  # before the wall: a bond's law is fixed when it is made
	w = rdem.masonry.wall(cli.length, cli.height, cli.thickness, brick=cli.brick, joint=cli.joint, bond=cli.bond, blocksPerBrick=cli.blocks,
	                      mortar=cli.mortar, openings=cli.openings, baseBeam=cli.beam, topBeam=cli.beam, beamBlocks=1, brickMaterial=brick,
	                      jointMaterial=joint, beamMaterial=beam)
	if cli.formulation != 'off':
		if total:
			rdem.poissonEngine().elements = 'cells'
		rdem.poissonEngine().build(w.ids)
	unbonded = walltest.unbondJoints(w, 'head') if cli.head_joints == 'unbonded' else set()
	test = walltest.ShearWallTest(w, sigma0, boundary=cli.boundary)
	targets = [a * 1e-2 * w.layout.height for a in walltest.cycleTargets(amplitudes, cli.repeat)] if amplitudes else [cli.drift * 1e-2 * w.layout.height]
except ValueError as e:
	sys.exit('shear_wall: %s' % e)
O.trackEnergy = True
O.dt = rdem.timeStepper().safety * rdem.timeStepper().estimate()
span = sum(abs(b - a) for a, b in zip([0.0] + targets[:-1], targets))
print('shear_wall: %s; sigma0 %.3g MPa (N = %.1f kN), %s ends; time step %.3g s, about %d steps of loading; set-up %.1f s' %
      (w, sigma0 * 1e-6, test.axialForce * 1e-3, cli.boundary, O.dt, span / (cli.rate * 1e-3) / O.dt, time.time() - setup0),
      flush=True)

# 3. Recording -------------------------------------------------------------------------------------------------------
ENERGIES = ('rdemElastic', 'rdemPoisson', 'rdemBondBreak', 'rdemDashpot', 'rdemFriction', 'rdemPoissonRelease', 'rdemFractureTension', 'rdemFractureShear',
            'rdemCrushing', 'nonviscDamp', 'kinetic', 'gravWork')
# yade.plot keeps the history (plot.data): live curves with plot.plot() in a YADE with a GUI, history.txt by saveDataTxt.
plot.reset()
plot.plots = {'drift': ('shear', 'baseShear'), 't': ('tension', 'shearBreaks')}
history = plot.data
state = dict(peak=None, peakCracks=None, first=None, report=time.time(), iter=O.iter, vtkNext=0.0)
cracks = rdem.CrackExport(os.path.join(cli.out, 'vtk', ''))


def record(t):
	nt, ns = rdem.breakCounts()
	keys = O.energy.keys()
	plot.addData(t=O.time,
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
	             **{e: O.energy[e] if e in keys else 0.0 for e in ENERGIES})


def onStep(t):
	"""After every chunk of the loading: record, track the peak and the first crack, ParaView output, progress."""
	record(t)
	V, d = history['shear'][-1], history['drift'][-1]
	if state['first'] is None and history['tension'][-1] + history['shearBreaks'][-1] > state['breaks0']:
		state['first'] = dict(shearKN=V * 1e-3, driftPercent=d * 100, time=O.time)
	if state['peak'] is None or abs(V) > abs(state['peak']['shearKN']) * 1e3:
		state['peak'] = dict(shearKN=V * 1e-3, driftPercent=d * 100, index=len(history['t']) - 1)
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
	"""Monotonic test: the load, averaged over the last --smooth samples (crack bursts make single samples spike), has
	dropped by --stop-drop of the largest such average, once past the first crack (before it, the peak is the residual
	of the vertical loading)."""
	if cli.max_wall > 0 and time.time() - t1 > cli.max_wall:
		print('shear_wall: --max-wall %g s reached; results so far' % cli.max_wall, flush=True)
		return True
	recent = history['shear'][-cli.smooth:]
	mean = abs(sum(recent) / len(recent))
	state['smoothPeak'] = max(state.get('smoothPeak', 0.0), mean)
	return (not amplitudes and cli.stop_drop > 0 and state['first'] is not None and abs(state['peak']['driftPercent']) > 0.01
	        and mean < (1 - cli.stop_drop) * state['smoothPeak'])


# 4. Run ----------------------------------------------------------------------------------------------------------------
t0 = time.time()
compressTime = test.compress(cli.compress_time)
compressWall = time.time() - t0
compressSteps = O.iter
print('shear_wall: sigma0 applied in %.3f s (%d steps, %.1f s); settlement %.3f mm, top rotation %.1e rad' %
      (compressTime, compressSteps, compressWall, test.verticalDisplacement() * 1e3, test.topRotation()),
      flush=True)
# cracks counted from here (none expected under sigma0 alone), the head joints that start without bond left out
cracks.snapshot = [row for row in rdem.bondSnapshot() if (min(row[0], row[1]), max(row[0], row[1])) not in unbonded]
state['breaks0'] = sum(rdem.breakCounts())
onStep(test)
t1 = time.time()
pushSteps = test.push(targets, cli.rate * 1e-3, cli.ramp, record=onStep, stop=stop)
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
smoothV, smoothDrift = walltest.smoothedPeak(h['drift'], h['shear'], cli.smooth)
smoothed = dict(shearKN=smoothV * 1e-3, driftPercent=smoothDrift * 100, window=cli.smooth)
uFirst = first['driftPercent'] * 1e-2 * test.height if first else None
stiffness = first['shearKN'] * 1e3 / uFirst if first and uFirst else float('nan')
closedForm = (walltest.timoshenkoStiffness(cli.brick_E * 1e9, cli.brick_nu, w.layout.length, w.layout.thickness, w.layout.height, cli.boundary)
              if (cli.brick_E, cli.brick_nu) == (cli.mortar_E, cli.mortar_nu) else None)
e0 = {e: h[e][0] for e in ENERGIES}  # energies when the horizontal loading began
stored = {e: h[e][-1] for e in ENERGIES}
external = h['workH'][-1] + h['workV'][-1]
accounted = sum(stored.values())
crackCount = walltest.crackClasses(w, final)
peakCount = walltest.crackClasses(w, state['peakCracks'])
cost = dict(compressSteps=compressSteps, compressSeconds=compressWall, pushSteps=pushSteps, pushSeconds=pushWall, threads=O.numThreads,
            microsecondsPerBlockStep=1e6 * pushWall / max(1, pushSteps * len(w.ids)))
comparison = None
if measured:
	mean = 0.5 * sum(measured['peak'])
	comparison = dict(measuredPeakKN=[v * 1e-3 for v in measured['peak']], measuredMeanKN=mean * 1e-3, modelPeakKN=abs(peak['shearKN']),
	                  peakError=abs(peak['shearKN']) * 1e3 / mean - 1, measuredDriftPercent=[d * 100 for d in measured['driftAtPeak']],
	                  modelDriftPercent=abs(peak['driftPercent']), smoothedPeakKN=abs(smoothed['shearKN']), smoothedPeakError=abs(smoothV) / mean - 1,
	                  smoothedDriftPercent=abs(smoothed['driftPercent']), measuredFailure=measured['failure'])
results = dict(input=vars(cli), sigma0=sigma0, axialForce=test.axialForce, blocks=len(w.ids), bonds=w.nBonds, bricks=len(w.bricks), courses=len(w.courses),
               joints={k: len(v) for k, v in w.joints.items()}, cells=rdem.poissonEngine().nCells if cli.formulation != 'off' else 0, timeStep=O.dt,
               sources=walltest.MAGENES_CALVI['sources'], peak=peak, smoothedPeak=smoothed, firstCrack=first, initialStiffnessKNPerMm=stiffness * 1e-6,
               timoshenkoStiffnessKNPerMm=closedForm * 1e-6 if closedForm else None, cracksAtPeak=peakCount, cracksAtEnd=crackCount,
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
if measured:
	for sign, V, d in zip((1, -1), measured['peak'], measured['driftAtPeak']):
		ax.plot([sign * 100 * d], [sign * 1e-3 * V], 's', color='tab:green', label='measured peak %s%.1f kN at %.3f %%' % ('+' if sign > 0 else '-', 1e-3 * V, 100 * d))
	if not amplitudes:  # a monotonic run against the envelope: the negative peak mirrored
		ax.plot([100 * measured['driftAtPeak'][1]], [1e-3 * measured['peak'][1]], 's', mfc='none', color='tab:green', label='measured peak -, mirrored')
ax.set_ylabel('horizontal load V [kN]')
ax.set_title('%s: sigma0 = %.2f MPa, %s ends, %s' % (cli.wall if measured else 'wall', sigma0 * 1e-6, cli.boundary,
                                                   'softening' if cli.softening == 'on' else 'brittle springs'))
ax.legend(fontsize=7)
ax = axes[1]
dissipated = [
        sum(h[e][k] for e in ('rdemBondBreak', 'rdemDashpot', 'rdemFriction', 'rdemPoissonRelease', 'rdemFractureTension', 'rdemFractureShear', 'rdemCrushing', 'nonviscDamp'))
        for k in range(len(drift))
]
ax.plot(drift, [a + b for a, b in zip(h['workH'], h['workV'])], 'k-', label='work of the actuator and the vertical load')
ax.plot(drift, [a + b for a, b in zip(h['rdemElastic'], h['rdemPoisson'])], label='elastic (springs and cells)')
ax.plot(drift, dissipated, label='dissipated (breaks, fracture, crushing, dashpots, friction, damping)')
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

print('shear_wall: smoothed peak (%d samples) %.1f kN at %.3f %% drift' % (cli.smooth, smoothed['shearKN'], smoothed['driftPercent']), flush=True)
print('shear_wall: peak %.1f kN at %.3f %% drift%s; first broken spring at %s; initial stiffness %.1f kN/mm%s; cracks at the end: joints %s, bricks %s; '
      'energy balance %s; %d + %d steps in %.1f + %.1f s (%.3f us per block-step, %d threads); results in %s' %
      (peak['shearKN'], peak['driftPercent'], (' (measured mean %.1f kN: %+.1f %%)' % (comparison['measuredMeanKN'], 100 * comparison['peakError'])) if comparison else '',
       '%.1f kN' % first['shearKN'] if first else 'none', stiffness * 1e-6, (' (Timoshenko %.1f)' % (closedForm * 1e-6)) if closedForm else '',
       crackCount['joint'], crackCount['brick'], '%.2e' % results['energy']['balanceError'] if external else '-', compressSteps, pushSteps, compressWall, pushWall,
       cost['microsecondsPerBlockStep'], O.numThreads, cli.out))
sys.exit(0)
