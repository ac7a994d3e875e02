# -*- coding: utf-8 -*-
"""Figures of shear-wall runs from their progress output and ParaView files, for runs stopped before they wrote results.json.

Problem
    scripts/shear_wall.py writes its figures at the end of a run. A run stopped earlier (out of time) leaves its
    progress lines (step, drift, V, base shear, broken springs every 5 s of wall-clock) and its ParaView crack files
    (vtk/cracks.<step>.vtu every --vtk-every of drift). This plain-Python script (numpy, matplotlib; no YADE) plots the
    load-drift curves of several runs against the measured peaks of the Magenes & Calvi walls and the last crack
    pattern of each run, cracks coloured by mode (tension red, shear blue, released bond grey), seen from the front
    (faces whose normal is along y, collar joints, left out).

How to run
    /usr/bin/python3 scripts/shear_wall_replot.py --runs MI1:run1.log:output/sw/MI1,MI2:run2.log:output/sw/MI2 --out doc/figures/shear_walls.png
"""
import argparse
import glob
import os
import re
import xml.etree.ElementTree as ET
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

#: Measured peaks (kN) and drifts at the peaks (%), + and -, of Magenes & Calvi (1992) (data/walls/walls.csv and statics-failures.csv, read by rdem.wall_database).
MEASURED = {'MI1': ((269.55, 259.63), (0.1995, 0.1795)), 'MI2': ((241.62, 227.21), (0.4005, 0.3866))}
LINE = re.compile(r'step\s+(\d+)\s+drift\s+([-+\d.]+) %\s+V\s+([-+\d.]+) kN \(base\s+([-+\d.]+)\).*tension (\d+), shear (\d+)')
COLOURS = {1: 'tab:red', 2: 'tab:blue', 3: '0.4'}


def readLog(path):
	"""(step, drift %, V kN, base kN, tension breaks, shear breaks) of every progress line of a shear_wall.py run."""
	rows = []
	with open(path) as f:
		for line in f:
			m = LINE.search(line)
			if m:
				rows.append(tuple(float(g) for g in m.groups()))
	return rows


def readCracks(path):
	"""The quads of a cracks.<step>.vtu (rdem.CrackExport): list of (4 points, state)."""
	root = ET.parse(path).getroot()
	arrays = {a.get('Name'): a.text.split() for a in root.iter('DataArray')}
	pts = [float(v) for v in root.find('.//Points/DataArray').text.split()]
	pts = [pts[3 * k:3 * k + 3] for k in range(len(pts) // 3)]
	conn = [int(v) for v in arrays['connectivity']]
	state = [int(float(v)) for v in arrays['state']]
	return [([pts[i] for i in conn[4 * k:4 * k + 4]], state[k]) for k in range(len(state))]


def drawCracks(ax, quads, title):
	for corners, state in quads:
		ys = [p[1] for p in corners]
		if max(ys) - min(ys) < 1e-9:
			continue  # the quad lies in a plane y = const: a collar joint, not seen from the front
		xs, zs = [p[0] for p in corners], [p[2] for p in corners]
		if max(zs) - min(zs) < 1e-9:  # bed face: a horizontal line
			ax.plot([min(xs), max(xs)], [zs[0]] * 2, '-', color=COLOURS[state], lw=1.0)
		else:  # head face or a vertical crack in a brick
			ax.plot([xs[0]] * 2, [min(zs), max(zs)], '-', color=COLOURS[state], lw=1.0)
	ax.set_aspect('equal')
	ax.set_title(title, fontsize=8)
	ax.set_xlabel('x [m]')
	ax.set_ylabel('z [m]')


parser = argparse.ArgumentParser(prog='python3 scripts/shear_wall_replot.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--runs', required=True, help='name:log:folder,... (name MI1 or MI2 adds the measured peaks)')
parser.add_argument('--out', default='shear_walls.png', help='figure to write (default shear_walls.png)')
cli = parser.parse_args()
runs = [r.split(':') for r in cli.runs.split(',')]
fig, axes = plt.subplots(1, 1 + len(runs), figsize=(5 + 3.2 * len(runs), 5.5), gridspec_kw=dict(width_ratios=[1.6] + [1] * len(runs)))
for k, (name, log, folder) in enumerate(runs):
	rows = readLog(log)
	colour = 'C%d' % k
	axes[0].plot([r[1] for r in rows], [r[2] for r in rows], '-', color=colour, label='%s model (brittle), force on the top beam' % name)
	if name in MEASURED:
		(vp, vn), (dp, dn) = MEASURED[name]
		axes[0].plot([dp, dn], [vp, vn], 's', color=colour, mfc='none', label='%s measured peaks, + and - (mirrored)' % name)
	files = sorted(glob.glob(os.path.join(folder, 'vtk', 'cracks.*.vtu')), key=lambda p: int(p.split('.')[-2]))
	if files:
		step = int(files[-1].split('.')[-2])
		drift = min(rows, key=lambda r: abs(r[0] - step))[1] if rows else float('nan')
		quads = readCracks(files[-1])
		drawCracks(axes[1 + k], quads, '%s at %.2f %% drift: %d broken springs' % (name, drift, len(quads)))
for state, label in ((1, 'tension'), (2, 'shear'), (3, 'released bond')):
	axes[-1].plot([], [], '-', color=COLOURS[state], label=label)
axes[-1].legend(fontsize=7, loc='upper right')
axes[0].set_xlabel('drift u/H [%]')
axes[0].set_ylabel('horizontal load V [kN]')
axes[0].legend(fontsize=7)
fig.tight_layout()
fig.savefig(cli.out, dpi=120)
print('shear_wall_replot: %s' % cli.out)
