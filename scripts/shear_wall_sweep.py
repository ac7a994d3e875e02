# -*- coding: utf-8 -*-
"""What a shear-wall run costs and what its accuracy depends on: scripts/shear_wall.py for a list of settings.

Problem
    The Magenes & Calvi wall MI1 (or another wall of the table, --wall) of scripts/shear_wall.py is run once per setting, each in its own YADE
    process (one after the other, never two at once): a base setting (that of doc/validation.md: softening, bricks of
    two blocks along their length, 2x2 springs, Poisson cells, head joints without bond, but loaded at 40 mm/s), then
    one knob changed at a time: blocks per brick along its length (1, 4), springs per face edge (1, 3), the Poisson
    effect off, softening off, head joints bonded, the validation rate 20 mm/s (case rate), the base on two threads
    (case j2). Every run writes its own folder under --out.

Expected result
    A table (markdown on stdout and in --table) of the smoothed peak load (rdem.walltest.smoothedPeak), the drift at the
    peak, their change against the finest run (the most blocks: 4 per brick), the number of blocks, steps, wall-clock time, µs per block-step and threads; the cheapest setting within 5 % and
    10 % of the finest run's peak.

How to run (each MI1 run takes minutes: the whole sweep about an hour on this 2-core machine)
    build/bin/yade -n scripts/shear_wall_sweep.py --table output/sweep.md       the default cases
    build/bin/yade -n scripts/shear_wall_sweep.py --cases base,rate,j2
    build/bin/yade -n scripts/shear_wall_sweep.py --replot        the table again from the runs' results.json
"""
import argparse
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(sys.argv[0]))  # this script's folder (under YADE, __file__ names YADE's launcher)
LAUNCHER = os.path.join(os.path.dirname(HERE), 'build', 'bin', 'yade')
SCRIPT = os.path.join(HERE, 'shear_wall.py')
#: name -> (description, options of shear_wall.py beyond the common ones, threads). The base is the validation setting
#: of doc/validation.md (softening, bricks of two blocks along their length); each other case changes one knob.
CASES = {
        'base': ('base: 2 blocks per brick, 2x2 springs, Poisson cells, softening', [], 1),
        'blocks1': ('1 block per brick', ['--blocks', '1,1,1'], 1),
        'blocks4': ('4 blocks per brick along its length', ['--blocks', '4,1,1'], 1),
        'springs1': ('1x1 spring per face', ['--springs', '1'], 1),
        'springs3': ('3x3 springs per face', ['--springs', '3'], 1),
        'poissonOff': ('Poisson effect off', ['--formulation', 'off', '--failure-stress', 'spring'], 1),
        'brickCapOff': ('no compression cap in the bricks', ['--brick-fc', '0'], 1),
        'poissonOffBrickCapOff': ('Poisson effect off, no compression cap in the bricks (with the Poisson effect off the bricks\' cap is refused: '
                                  'its softening would snap back)', ['--formulation', 'off', '--failure-stress', 'spring', '--brick-fc', '0'], 1),
        'brittle': ('softening off (brittle springs, the paper)', ['--softening', 'off'], 1),
        'headBonded': ('head joints bonded like the bed joints', ['--head-joints', 'bonded'], 1),
        'rate': ('half the loading rate (20 mm/s; doc/validation.md validates 40 mm/s with rotational inertia scaling)', ['--rate', '20'], 1),
        'j2': ('base on two threads', [], 2),
}
#: Cases whose end state is saved (state.yade.gz in their folder): the per-step cost of softening against brittle springs.
SAVED = ('base', 'brittle')
#: Options of every run: the validation setting of doc/validation.md, loaded to --drift at 40 mm/s (twice its rate, to
#: keep the sweep within an hour on a shared machine; the case 'rate' is the validation rate).
COMMON = ['--softening', 'on', '--blocks', '2,1,1', '--rate', '40', '--compress-time', '0.02', '--vtk-every', '0']

parser = argparse.ArgumentParser(prog='yade scripts/shear_wall_sweep.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--cases', default='base,blocks1,springs1,poissonOff,brittle,headBonded,blocks4,springs3', help='comma-separated names among %s, or all (default: all but rate and j2)' % ', '.join(CASES))
parser.add_argument('--wall', default='MI1', help='a wall of data/walls/walls.csv (default MI1)')
parser.add_argument('--drift', default='0.4', help='end drift of every run [%%] (default 0.4: past the peak of MI1)')
parser.add_argument('--stop-drop', default='0.1', help='stop a run once its load has dropped by this fraction of its peak (default 0.15)')
parser.add_argument('--extra', default='', help='further options for every run of shear_wall.py, as one string (default none)')
parser.add_argument('--out', default='output/shear_wall_sweep', help='folder of the runs (default output/shear_wall_sweep)')
parser.add_argument('--table', default=None, help='also write the markdown table to this file')
parser.add_argument('--replot', action='store_true', help='do not run: make the table from the results.json already in --out')
cli = parser.parse_args(sys.argv[1:])
names = list(CASES) if cli.cases == 'all' else [c for c in cli.cases.split(',') if c]
unknown = [c for c in names if c not in CASES]
if unknown:
	sys.exit('--cases: unknown %s; choose among %s or all' % (', '.join(unknown), ', '.join(CASES)))


def folder(name):
	return os.path.join(cli.out, '%s_%s' % (cli.wall, name))


def run(name):
	desc, extra, threads = CASES[name]
	cmd = [LAUNCHER, '-j%d' % threads, '-n', '-x', SCRIPT, '--wall', cli.wall, '--out', folder(name), '--drift', cli.drift, '--stop-drop', cli.stop_drop
	       ] + COMMON + extra + cli.extra.split()
	if name in SAVED:  # the state at the end, for scripts/shear_wall_cost.py
		cmd += ['--save', os.path.join(folder(name), 'state.yade.gz')]
	print('sweep: %s (%s): %s' % (name, desc, ' '.join(cmd[1:])), flush=True)
	start = time.time()
	proc = subprocess.run(cmd, env=dict(os.environ, OMP_NUM_THREADS=str(threads)), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
	last = [l for l in proc.stdout.splitlines() if l.startswith('shear_wall:')]
	print('sweep: %s done in %.0f s, exit %d: %s' % (name, time.time() - start, proc.returncode, last[-1] if last else proc.stdout[-2000:]), flush=True)


if not cli.replot:
	for name in names:
		run(name)

rows = []
for name in names:
	path = os.path.join(folder(name), 'results.json')
	if not os.path.exists(path):
		print('sweep: no %s (the run failed or was not made)' % path)
		continue
	with open(path) as f:
		r = json.load(f)
	c = r['cost']
	rows.append(dict(name=name, desc=CASES[name][0], peak=abs(r['smoothedPeak']['shearKN']), drift=abs(r['smoothedPeak']['driftPercent']), blocks=r['blocks'],
	                 steps=c['compressSteps'] + c['pushSteps'], wall=c['compressSeconds'] + c['pushSeconds'], us=c['microsecondsPerBlockStep'],
	                 threads=c['threads'], error=(r['comparison'] or {}).get('smoothedPeakError')))
finest = max((x for x in rows if x['threads'] == 1), key=lambda x: (x['blocks'], x['steps']), default=None)
lines = ['| setting | blocks | smoothed peak [kN] | vs measured mean | drift at peak [%] | peak vs finest | steps | wall [s] | µs per block-step | threads |',
         '|---|---|---|---|---|---|---|---|---|---|']
for x in rows:
	change = x['peak'] / finest['peak'] - 1 if finest else float('nan')
	lines.append('| %s | %d | %.1f | %s | %.3f | %+.1f %% | %d | %.0f | %.3f | %d |' % (x['desc'], x['blocks'], x['peak'], '%+.1f %%' % (100 * x['error'])
	                                                                                    if x['error'] is not None else '-', x['drift'], 100 * change, x['steps'],
	                                                                                    x['wall'], x['us'], x['threads']))
if finest:
	for target in (0.05, 0.10):
		ok = [x for x in rows if x['threads'] == 1 and abs(x['peak'] / finest['peak'] - 1) <= target]
		best = min(ok, key=lambda x: x['wall']) if ok else None
		lines.append('')
		lines.append('Cheapest within %d %% of the finest run (%s): %s' % (100 * target, finest['desc'], '%s, %.0f s' % (best['desc'], best['wall']) if best else 'none'))
text = '\n'.join(lines)
print(text)
if cli.table:
	with open(cli.table, 'w') as f:
		f.write(text + '\n')
sys.exit(0)
