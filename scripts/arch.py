# -*- coding: utf-8 -*-
"""An arch (or barrel vault) of voussoirs under gravity, then a quasi-static tilt or a ground pulse.

Problem
    A semicircular, segmental or pointed arch of --voussoirs voussoirs (dry joints, contacts sampled at the vertices so
    that hinges form on the joints' edges; friction --friction), on fixed abutments or on piers (rdem.masonry.arch,
    doc/arches.md). Gravity is ramped up over 0.2 s and held (Cundall's damping 0.2). Then, with --load tilt, gravity is
    turned about the arch's depth axis at --tilt-rate (a static horizontal load λ = tan θ times the weight, the
    collapse multiplier of a seismic check) until the arch collapses; with --load pulse the supports move with a
    one-sine pulse of --amplitude g and --period s; with --load gravity nothing more.

Expected result
    A semicircular arch stands under its own weight if t/R exceeds the minimum of rdem.limit_analysis for its number of
    voussoirs (0.10086 for 8; 0.1075 for a continuous arch, Milankovitch 1907) and collapses by a five-hinge mechanism
    below it (tests/yade/test_arch.py). Tilted, it collapses by a four-hinge mechanism at a multiplier that grows with
    t/R.

How to run
    build/bin/yade -n scripts/arch.py                                  gravity, then tilt (about a minute)
    build/bin/yade -n scripts/arch.py --ratio 0.98 --load gravity      below the minimum thickness: it collapses
    build/bin/yade -n scripts/arch.py --load pulse --amplitude 0.5 --period 0.4
    build/bin/yade -n scripts/arch.py --help

Outputs (in --out, default output/arch): results.json, history.txt (yade.plot's saveDataTxt), arch.png (the arch at the
start and at the end, with the hinges; crown drop against time and load), frames/arch-NNN.png (the arch every 0.1 s: an
animation of the collapse), ParaView files in vtk/ (blocks.boxes.*.vtu, every 0.1 s).
"""
import argparse
import json
import math
import os
import sys
import time

parser = argparse.ArgumentParser(prog='yade scripts/arch.py', description=__doc__.split('\n\n')[0])
g = parser.add_argument_group('arch (lengths in m)')
g.add_argument('--shape', choices=['semicircular', 'segmental', 'pointed'], default='semicircular', help='default semicircular')
g.add_argument('--span', type=float, default=2.0, help='span between the centreline springings (default 2)')
g.add_argument('--ratio', type=float, default=1.5, help='thickness as a multiple of the minimum thickness of a semicircular arch of as many voussoirs '
               '(rdem.limit_analysis; default 1.5); ignored if --thickness is given')
g.add_argument('--thickness', type=float, default=None, help='ring thickness (default: from --ratio)')
g.add_argument('--voussoirs', type=int, default=8, help='voussoirs (default 8)')
g.add_argument('--rise', type=float, default=None, help='rise of a segmental arch (default span/4)')
g.add_argument('--pointedness', type=float, default=1.0, help='pointed arch: centres at +-pointedness*span/2 (default 1, equilateral)')
g.add_argument('--supports', choices=['abutments', 'piers'], default='abutments', help='default abutments')
g.add_argument('--pier-height', type=float, default=1.0, help='pier height (default 1)')
g.add_argument('--pier-width', type=float, default=None, help='pier width (default 3 thicknesses)')
g.add_argument('--depth', type=float, default=0.2, help='depth of the arch (default 0.2)')
g.add_argument('--length', type=float, default=None, help='length of a barrel vault (default: an arch)')
g.add_argument('--rings', type=int, default=4, help='rings of a vault, staggered (default 4)')
m = parser.add_argument_group('material')
m.add_argument('--young', type=float, default=1e9, help='Young modulus of the contacts [Pa] (default 1e9)')
m.add_argument('--density', type=float, default=2000, help='[kg/m3] (default 2000)')
m.add_argument('--friction', type=float, default=1.0, help='friction coefficient of the joints (default 1)')
ld = parser.add_argument_group('load')
ld.add_argument('--load', choices=['gravity', 'tilt', 'pulse'], default='tilt', help='after gravity (default tilt)')
ld.add_argument('--tilt-rate', type=float, default=0.1, help='rate of the horizontal load multiplier tan(theta) [1/s] (default 0.1)')
ld.add_argument('--amplitude', type=float, default=0.5, help='pulse amplitude [g] (default 0.5)')
ld.add_argument('--period', type=float, default=0.4, help='pulse period [s] (default 0.4)')
ld.add_argument('--duration', type=float, default=4.0, help='simulated time after gravity [s] (default 4)')
parser.add_argument('--out', default='output/arch', help='output folder (default output/arch)')
cli = parser.parse_args(sys.argv[1:])
for name in ('span', 'ratio', 'depth', 'young', 'density', 'friction', 'tilt_rate', 'period', 'duration'):
	if not getattr(cli, name) > 0:
		sys.exit('--%s = %g: must be > 0' % (name.replace('_', '-'), getattr(cli, name)))

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from yade import O, Vector3, VTKRecorder, plot
from yade.wrapper import RdemMat
import rdem
from rdem import ground_motion as gm
from rdem.limit_analysis import archMinimumThickness

G = 9.81
os.makedirs(os.path.join(cli.out, 'vtk'), exist_ok=True)
limit = archMinimumThickness(cli.voussoirs) if cli.voussoirs >= 2 else None
R = cli.span / 2
t = cli.thickness if cli.thickness is not None else cli.ratio * limit.ratio * R
stone = O.materials.append(
        RdemMat(young=cli.young, poisson=0.2, density=cli.density, tensileStrength=float('inf'), cohesion=float('inf'), frictionAngle=math.atan(cli.friction),
                dampingNormal=1.0, dampingShear=1.0, label='stone'))
O.engines = rdem.engines(formulation=None, recontact='always', contactSamples=1, damping=0.2)
try:
	a = rdem.masonry.arch(cli.span, t, cli.depth, cli.voussoirs, shape=cli.shape, rise=(cli.rise or cli.span / 4) if cli.shape == 'segmental' else None,
	                      pointedness=cli.pointedness, supports=cli.supports, pierHeight=cli.pier_height if cli.supports == 'piers' else None,
	                      pierWidth=(cli.pier_width or 3 * t) if cli.supports == 'piers' else None, length=cli.length,
	                      rings=cli.rings if cli.length else 1, material=stone)
except ValueError as e:
	sys.exit('arch.py: %s' % e)
O.dt = -1
newton = rdem.newtonIntegrator()
print('arch.py: %s, t = %.4g m (t/R = %.4f; minimum of a semicircular arch of %d voussoirs %.5f), %d blocks' %
      (a, t, t / R, cli.voussoirs, limit.ratio, len(a.ids)), flush=True)

plot.reset()
plot.plots = {'t': ('crownDrop', ), 'lam': ('crownDrop ', )}
history = plot.data
state = {'lam': 0.0, 'phase': 'gravity'}
outline0 = [[tuple(c) for c in b.corners()] for b in a.layout.blocks]


def record():
	plot.addData(t=O.time, lam=state['lam'], crownDrop=a.crownDrop(), **{'crownDrop ': a.crownDrop()})


def outline():
	"""The blocks' sections now, in x-z."""
	out = []
	for k, blk in enumerate(a.layout.blocks):
		b = O.bodies[a.blocks[k]]
		R_ = b.state.ori
		h = b.shape.extents
		out.append([(p[0], p[2]) for p in (b.state.pos + R_ * Vector3(i * h[0], 0, j * h[2]) for i, j in ((-1, -1), (1, -1), (1, 1), (-1, 1)))])
	return out


os.makedirs(os.path.join(cli.out, 'frames'), exist_ok=True)
for old in os.listdir(os.path.join(cli.out, 'frames')):
	os.remove(os.path.join(cli.out, 'frames', old))
limits = None


def frame(k):
	"""The blocks' sections now as frames/arch-k.png (same axes for every frame)."""
	global limits
	f, ax = plt.subplots(figsize=(6, 4))
	for poly in outline():
		xs, zs = zip(*(poly + poly[:1]))
		ax.fill(xs, zs, color='0.8', ec='C3', lw=0.6)
	if limits is None:
		limits = (ax.get_xlim(), (ax.get_ylim()[0] - 0.3 * R, ax.get_ylim()[1]))
	ax.set_xlim(*limits[0])
	ax.set_ylim(*limits[1])
	ax.set_aspect('equal')
	ax.set_title('t = %.2f s, crown drop %.3f m%s' % (O.time, a.crownDrop(), (', load multiplier %.3f' % state['lam']) if cli.load == 'tilt' else ''))
	f.tight_layout()
	f.savefig(os.path.join(cli.out, 'frames', 'arch-%03d.png' % k), dpi=80)
	plt.close(f)


vtk = VTKRecorder(fileName=os.path.join(cli.out, 'vtk', 'blocks.'), recorders=['boxes'])
wall0, lastReport, vtkNext = time.time(), time.time(), 0.0
collapse, hingesAtCollapse = None, None
shaker = None
tGravity = 0.6
end = tGravity + cli.duration
while O.time < end:
	if O.time < tGravity:
		newton.gravity = Vector3(0, 0, -G * min(1.0, O.time / 0.2))
	elif cli.load == 'tilt':
		state['phase'] = 'tilt'
		state['lam'] = cli.tilt_rate * (O.time - tGravity)
		th = math.atan(state['lam'])
		newton.gravity = Vector3(-G * math.sin(th), 0, -G * math.cos(th))  # the load pushes towards -x: the arch sways left
	elif cli.load == 'pulse' and shaker is None:
		state['phase'] = 'pulse'
		record_ = gm.sinePulse(cli.amplitude * G, cli.period, dt=cli.period / 200, before=O.time + 0.01)
		shaker = rdem.earthquake.shaker(record_, ids=a.fixed, mode='prescribed')
	rdem.run(50)
	record()
	drop = a.crownDrop()
	if collapse is None and drop > 0.02 * R:
		collapse = dict(time=O.time, multiplier=state['lam'], phase=state['phase'])
		hingesAtCollapse = a.hinges()
	if O.time >= vtkNext:
		vtk()
		frame(len(os.listdir(os.path.join(cli.out, 'frames'))))
		vtkNext += 0.1
	if time.time() - lastReport > 5:
		lastReport = time.time()
		print('t = %.3f s of %.3g (%s), crown drop %.4g m, multiplier %.4f' % (O.time, end, state['phase'], drop, state['lam']), flush=True)
	if drop > 0.3 * R:
		break
wall = time.time() - wall0

results = dict(input=vars(cli), thickness=t, ratio=t / R, minimumRatio=limit.ratio, minimumHinges=limit.hinges, blocks=len(a.ids), protrusion=a.layout.protrusion,
               collapsed=collapse is not None, collapse=collapse, hingesAtCollapse=hingesAtCollapse, finalCrownDrop=a.crownDrop(), timeStep=O.dt, steps=O.iter,
               wallSeconds=wall, history=history)
with open(os.path.join(cli.out, 'results.json'), 'w') as f:
	json.dump(results, f, indent=1)
plot.saveDataTxt(os.path.join(cli.out, 'history.txt'))

fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
for poly in outline0:
	xs, zs = zip(*(poly[i] for i in (0, 1, 3, 2, 0)))
	axes[0].plot(xs, zs, color='0.75', lw=0.6)
for poly in outline():
	xs, zs = zip(*(poly + poly[:1]))
	axes[0].plot(xs, zs, color='C3', lw=0.8)
for k, side in (hingesAtCollapse or []):
	P, Q = a.layout.jointFaces[0][k]
	p = P if side == 'intrados' else Q
	axes[0].plot(p[0], p[1], 'ko', ms=6)
axes[0].set_aspect('equal')
axes[0].set_title('start (grey), end (red), hinges at collapse (dots)')
axes[1].plot(history['t'], history['crownDrop'])
axes[1].axvline(tGravity, color='0.5', lw=0.5)
axes[1].set_xlabel('time [s]')
axes[1].set_ylabel('crown drop [m]')
if cli.load == 'tilt':
	ax2 = axes[1].twinx()
	ax2.plot(history['t'], history['lam'], 'C1')
	ax2.set_ylabel('horizontal load multiplier', color='C1')
fig.tight_layout()
fig.savefig(os.path.join(cli.out, 'arch.png'), dpi=120)
print('arch.py: t/R = %.4f (minimum %.5f): %s; hinges %s; %d steps in %.1f s; results in %s' %
      (t / R, limit.ratio, ('collapsed at t = %.3f s, multiplier %.4f (%s)' % (collapse['time'], collapse['multiplier'], collapse['phase'])) if collapse else 'standing',
       hingesAtCollapse, O.iter, wall, cli.out))
sys.exit(0)
