# -*- coding: utf-8 -*-
"""Compression test of a concrete cube with the refined DEM and the Poisson effect (the paper's §5).

Problem
    A 20 cm concrete cube of 10×10×10 rigid blocks sits on a fixed plate and is pushed down by a loading plate (each plate
    10×10×1 blocks, 4 cm tall; 1200 blocks, 891 Poisson elements). Concrete: ρ = 2300 kg/m³, E = 30 GPa, ν = 0.2,
    f_t = 4.5 MPa, bond strength ∞ (tension failure only), friction coefficient 0.624, damping constant 1.0; 2×2 springs
    per face; loading plate at 1.0 mm/s; Δt = 2.0e-6 s.

Expected result (paper §5.3)
    The apparent Poisson's ratio stays ≈ 0.2 until the tensile failure at ≈ 0.14 s, when it starts to oscillate
    because a crack crosses the measured span, at a mean compressive stress of ≈ 21.2 MPa (f_t/σ ≈ 0.21); cracks are
    vertical, first near the corners. results.json gives both that moment (firstTensileFailure, the paper's criterion)
    and the first single broken spring (firstBrokenSpring), which comes earlier, near the platens. The model's own estimate for uniform
    uniaxial stress: the lateral springs reach f_t when σ = f_t (1-ν²)/ν = 21.6 MPa.

How to run
    build/bin/yade scripts/compression.py                 the paper's scene (see README for its wall time)
    build/bin/yade scripts/compression.py --help          all options
    build/bin/yade -j2 scripts/compression.py --blocks 6  smaller, on two threads
    build/bin/yade -n scripts/compression.py              without YADE's viewer (which opens, in a YADE built with GUI,
                                                          with the cracks coloured by failure mode; rdem.gui)

Outputs (in --out, default output/compression): results.json, history.txt (yade.plot's saveDataTxt), plots (PNG),
ParaView files (*.pvd: blocks from YADE's VTKRecorder, crack faces and Poisson elements from rdem.export).
"""
import argparse
import json
import os
import sys
import time

# 1. Options ---------------------------------------------------------------------------------------------------------
parser = argparse.ArgumentParser(prog='yade scripts/compression.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--blocks', type=int, default=10, help='blocks per edge of the cube (default 10, as in the paper)')
parser.add_argument('--springs', type=int, default=2, help='springs per face edge: n×n springs per face (default 2)')
parser.add_argument('--nu', type=float, default=0.2, help="Poisson's ratio (default 0.2)")
parser.add_argument('--formulation', choices=['paper', 'consistent', 'off'], default='paper', help='Poisson formulation (default paper)')
parser.add_argument('--corotational', action='store_true', help='corotational Poisson elements (default off, as in the paper)')
parser.add_argument('--plate-young', type=float, default=None, help="Young's modulus of the plates [GPa] (default: the concrete's, 30)")
parser.add_argument('--rate', type=float, default=1.0, help='loading rate [mm/s] (default 1.0)')
parser.add_argument('--end', type=float, default=0.25, help='end displacement of the loading plate [mm] (default 0.25)')
parser.add_argument('--dt', default='2e-6', help="time step [s] (default 2e-6, as in the paper), or 'auto': RdemTimeStepper's, 0.8 of the critical step (also below the Gershgorin bound once springs break)")
parser.add_argument('--out', default='output/compression', help='output folder (default output/compression)')
parser.add_argument('--vtk-every', type=float, default=0.05, help='ParaView output every this displacement [mm] (default 0.05; 0 = none)')
parser.add_argument('--threads', type=int, default=None, help='OpenMP threads; same as yade -jN (given here, it must match -j)')
cli = parser.parse_args(sys.argv[1:])
if cli.threads is not None and cli.threads != yade.runtime.ompThreads:  # noqa: F821 (yade is in the launcher's globals)
	sys.exit('--threads %d given but YADE runs %d threads: start it as  build/bin/yade -j%d scripts/compression.py' %
	         (cli.threads, yade.runtime.ompThreads, cli.threads))  # noqa: F821
try:
	dt = None if cli.dt == 'auto' else float(cli.dt)
except ValueError:
	sys.exit("--dt = %s: must be a number of seconds > 0 or 'auto'" % cli.dt)
for name, value in (('rate', cli.rate), ('end', cli.end), ('dt', 1 if dt is None else dt)):
	if not value > 0:
		sys.exit('--%s = %g: must be > 0' % (name, value))

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, PyRunner, VTKRecorder, plot
from yade import rdem
from yade.rdem import gui
from yade.rdem.scenes import CompressionTest

os.makedirs(cli.out, exist_ok=True)

# 2. Scene ------------------------------------------------------------------------------------------------------------
O.reset()
wall0 = time.time()
test = CompressionTest(blocksPerEdge=cli.blocks,
                       segmentsPerEdge=cli.springs,
                       poisson=cli.nu,
                       formulation=cli.formulation,
                       corotational=cli.corotational,
                       plateYoung=cli.plate_young * 1e9 if cli.plate_young is not None else None,
                       rate=cli.rate * 1e-3,
                       dt=dt)
tEnd = cli.end / cli.rate  # [s]
critical = rdem.timeStepper().estimate()
dtRun = dt if dt is not None else rdem.timeStepper().safety * critical  # the automatic step is updated every 100 steps
nSteps = int(round(tEnd / dtRun))  # exact for a fixed step; about, for the automatic one
print('compression: %d blocks, %d bonds, %d Poisson elements, %d steps of %.3g s (critical step %.3g s), set-up %.1f s' %
      (len(test.ids), test.nBonds, test.nElements, nSteps, dtRun, critical, time.time() - wall0))

# 3. Recording -------------------------------------------------------------------------------------------------------
# yade.plot keeps the history (plot.data): live curves with plot.plot() in a YADE with a GUI, history.txt by saveDataTxt.
plot.reset()
plot.plots = {'disp': ('stress', ), 't': ('nu', )}
history = plot.data
first = {}
vtkEvery = int(round(cli.vtk_every * 1e-3 / (cli.rate * 1e-3) / dtRun)) if cli.vtk_every > 0 else 0
cracks = rdem.CrackExport(os.path.join(cli.out, 'vtk', ''))


def record():
	nT, nS = rdem.breakCounts()
	plot.addData(t=O.time, disp=test.displacement(), stress=test.stress(), nu=test.apparentPoisson(), tension=nT, shear=nS)
	if nT + nS > 0 and not first:
		first.update(time=O.time, iter=O.iter, stress=history['stress'][-1], disp=history['disp'][-1], segments=rdem.brokenSegments(cracks.snapshot))


progress = dict(wall=time.time(), iter=0)


def report():
	now = time.time()
	rate = (O.iter - progress['iter']) / max(now - progress['wall'], 1e-9)
	progress.update(wall=now, iter=O.iter)
	left = (nSteps - O.iter) / rate if rate > 0 else float('nan')
	nT, nS = rdem.breakCounts()
	print('step %7d/%d  t=%.4f s  disp=%.4f mm  stress=%6.2f MPa  nu=%.4f  breaks=%d+%d  %.0f steps/s  %.0f s left' %
	      (O.iter, nSteps, O.time, 1e3 * test.displacement(), 1e-6 * test.stress(), test.apparentPoisson(), nT, nS, rate, left),
	      flush=True)


O.engines += [PyRunner(command='record()', iterPeriod=max(1, nSteps // 2000)), PyRunner(command='report()', realPeriod=5)]
if vtkEvery:
	O.engines += [
	        VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'], iterPeriod=vtkEvery),
	        PyRunner(command='cracks.write()', iterPeriod=vtkEvery)
	]

# 4. Run --------------------------------------------------------------------------------------------------------------
# With YADE's viewer (a YADE built with GUI, started without -n) a 3D view shows the blocks and the broken springs beside
# the controller YADE opens; gui.run keeps both drawing while the script waits. Headless, gui.run is rdem.run(n).
if gui.available():
	gui.view()
wallRun = time.time()
while O.time < tEnd - 0.5 * O.dt:  # to the end displacement, whatever the step
	gui.run(max(1, min(nSteps, int((tEnd - O.time) / O.dt))))
wall = time.time() - wallRun
record()
cracks.close()

# 5. Results ----------------------------------------------------------------------------------------------------------
nuHist = [(t, nu) for t, nu in zip(history['t'], history['nu']) if t > 0]
tCrack = first.get('time', float('inf'))
preCrack = [nu for t, nu in nuHist if 0.25 * min(tCrack, O.time) <= t < tCrack]  # after the start-up transient
nuBefore = sorted(preCrack)[len(preCrack) // 2] if preCrack else float('nan')
firstSegs = first.get('segments', [])
# The paper's tensile failure (§5.3.1-5.3.2): the moment the apparent Poisson's ratio stops following the input because a
# crack crosses the measured span, i.e. the first record after the first broken spring where it departs from its value
# before cracking by more than NU_DEPARTURE; its stress is that of the last record before (the quasi-static reaction).
NU_DEPARTURE = 0.01  # the ratio's scatter from isolated broken springs before the macro-crack stays below 0.3 % (doc/validation.md)
failure = None
for k in range(1, len(history['t'])):
	if history['t'][k] >= tCrack and abs(history['nu'][k] / nuBefore - 1) > NU_DEPARTURE:
		failure = dict(time=history['t'][k - 1], stress=history['stress'][k - 1], disp=history['disp'][k - 1], breaks=history['tension'][k - 1] + history['shear'][k - 1])
		break
results = dict(
        input=vars(cli),
        blocks=len(test.ids),
        specimen=dict(blocksPerEdge=test.n, size=test.size, x0=0.0, y0=0.0),
        tensileStrength=test.material.tensileStrength,
        bonds=test.nBonds,
        poissonElements=test.nElements,
        apparentPoissonBeforeCracking=nuBefore,
        firstTensileFailure=dict(criterion="apparent Poisson's ratio departs by more than %g %% from its value before cracking (paper 5.3.1)" %
                                 (100 * NU_DEPARTURE),
                                 time=failure['time'] if failure else None,
                                 stressMPa=failure['stress'] * 1e-6 if failure else None,
                                 displacementMm=failure['disp'] * 1e3 if failure else None,
                                 ftOverStress=test.material.tensileStrength / failure['stress'] if failure else None,
                                 brokenSpringsBefore=failure['breaks'] if failure else None),
        firstBrokenSpring=dict(time=first.get('time'),
                               stressMPa=first['stress'] * 1e-6 if first else None,
                               displacementMm=first['disp'] * 1e3 if first else None,
                               ftOverStress=test.material.tensileStrength / first['stress'] if first else None,
                               segments=[dict(point=list(s['point']), normal=list(s['normal']), state=s['state']) for s in firstSegs]),
        breaks=dict(zip(('tension', 'shear'), rdem.breakCounts())),
        steps=O.iter,
        dt=O.dt,
        criticalDt=rdem.timeStepper().criticalDt,
        wallSeconds=wall,
        stepsPerSecond=O.iter / wall,
        microsecondsPerBlockStep=1e6 * wall / (O.iter * len(test.ids)),
        history=history)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

# Figures: apparent Poisson's ratio vs time (paper Fig. 9b), stress vs displacement, crack pattern (paper Fig. 10).
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot([t for t, _ in nuHist], [nu for _, nu in nuHist], label='apparent ν')
ax.axhline(cli.nu, color='k', ls=':', label='input ν = %g' % cli.nu)
if first:
	ax.axvline(first['time'], color='orange', ls=':', label='first broken spring')
if failure:
	ax.axvline(failure['time'], color='r', ls='--', label='tensile failure (ν departs)')
ax.set_xlabel('time [s]')
ax.set_ylabel("apparent Poisson's ratio")
ax.set_ylim(0, max(0.5, 2 * cli.nu))
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'apparent_poisson.png'), dpi=120)

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot([1e3 * d for d in history['disp']], [1e-6 * s for s in history['stress']])
if first:
	ax.plot([1e3 * first['disp']], [1e-6 * first['stress']], 'o', color='orange', label='first broken spring, %.1f MPa' % (1e-6 * first['stress']))
if failure:
	ax.plot([1e3 * failure['disp']], [1e-6 * failure['stress']], 'ro', label='tensile failure (ν departs), %.1f MPa' % (1e-6 * failure['stress']))
if first or failure:
	ax.legend()
ax.set_xlabel('displacement of the loading plate [mm]')
ax.set_ylabel('mean compressive stress [MPa]')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'stress_displacement.png'), dpi=120)

segs = rdem.brokenSegments(cracks.snapshot)
fig, axes = plt.subplots(1, 2, figsize=(10, 5))
for ax, (u, v, name) in zip(axes, ((0, 2, 'front view (x-z)'), (0, 1, 'top view (x-y)'))):
	ax.scatter([s['point'][u] for s in segs], [s['point'][v] for s in segs], s=4, c=['b' if s['state'] == 2 else 'r' for s in segs])
	ax.set_title('%s: %d broken springs (red tension, blue shear)' % (name, len(segs)))
	ax.set_aspect('equal')
	ax.set_xlabel('xyz'[u] + ' [m]')
	ax.set_ylabel('xyz'[v] + ' [m]')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'crack_pattern.png'), dpi=120)

fmt = lambda x, f: f % x if x is not None else 'none'
print('compression: apparent nu before cracking %.4f; first broken spring at t = %s s, %s MPa; tensile failure (nu departs) at t = %s s, '
      '%s MPa (f_t/sigma = %s); breaks %s; %d steps in %.1f s (%.0f steps/s, %.3f us per block-step); results in %s' %
      (nuBefore, fmt(first.get('time'), '%.4f'), fmt(first.get('stress', None) and first['stress'] * 1e-6, '%.2f'), fmt(failure and failure['time'], '%.4f'),
       fmt(failure and failure['stress'] * 1e-6, '%.2f'), fmt(results['firstTensileFailure']['ftOverStress'], '%.3f'), results['breaks'], O.iter, wall,
       results['stepsPerSecond'], results['microsecondsPerBlockStep'], cli.out))
if not gui.available():  # with the viewer, YADE's shell stays, and the view with it
	sys.exit(0)
