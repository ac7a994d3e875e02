# -*- coding: utf-8 -*-
"""Where the instructions of a step go: callgrind's self and inclusive cost per function, per block-step, of a saved state.

Problem
    scripts/benchmark.py counts the instructions of a whole step (case wall-instructions); this script says where they
    go. It runs scripts/shear_wall_cost.py on a saved state (``--state``, e.g. one of scripts/shear_wall.py --save) under
    ``valgrind --tool=callgrind`` twice, ``--short`` and ``--long`` steps after loading, counting only inside
    ``Scene::moveToNextTimeStep`` (one thread), and reports the difference of the two profiles per function, over
    ``--long - --short`` steps and the number of bodies: the first steps after loading, which test every pair again
    (the separation certificates are not saved) and warm the time stepper, are not counted. Plain Python 3 (it
    starts YADE itself); needs valgrind.

Expected result
    The functions with the largest self cost and inclusive cost per block-step, summed to the step's total.

How to run
    build/bin/yade -n scripts/shear_wall.py --max-drift 0.02 --save /tmp/mi1.yade.gz --vtk-every 0 --out /tmp/mi1
    python3 scripts/profile_step.py --state /tmp/mi1.yade.gz [--short 10 --long 40] [--top 40] [--json /tmp/p.json]

Outputs: two tables on stdout (self, inclusive: instructions per block-step and share of the step); with ``--json`` the
same figures for every function in that file.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser(prog='python3 scripts/profile_step.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--state', required=True, help='a saved scene (O.save) whose engines run it')
parser.add_argument('--short', type=int, default=10, help='steps of the first run (default 10)')
parser.add_argument('--long', type=int, default=40, help='steps of the second run (default 40); the profile is the difference')
parser.add_argument('--top', type=int, default=40, help='functions per table (default 40)')
parser.add_argument('--yade', default=os.path.join(here, '..', 'build', 'bin', 'yade'), help='the YADE launcher (default build/bin/yade)')
parser.add_argument('--json', default='', help='also write every function\'s figures to this JSON file')
cli = parser.parse_args(sys.argv[1:])
if not 0 <= cli.short < cli.long:
	sys.exit('--short %d, --long %d: need 0 <= --short < --long' % (cli.short, cli.long))
if not os.path.exists(cli.state):
	sys.exit('--state %s: no such file' % cli.state)


def profile(steps):
	"""{function: instructions} of a run of `steps` steps after loading, self or inclusive cost; and the body count."""
	out = tempfile.mktemp(prefix='rdem-callgrind-')
	cmd = [
	    'valgrind', '--tool=callgrind', '--trace-children=yes', '--callgrind-out-file=' + out + '.%p', '--collect-atstart=no', '--toggle-collect=yade::Scene::moveToNextTimeStep()', cli.yade,
	    '-j1', '-n', '-x',
	    os.path.join(here, 'shear_wall_cost.py'), '--state', cli.state, '--steps',
	    str(steps), '--rounds', '1'
	]
	proc = subprocess.run(cmd, env=dict(os.environ, OMP_NUM_THREADS='1'), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
	bodies = re.findall(r'steps of (\d+) bodies', proc.stdout)
	files = [f for f in os.listdir(os.path.dirname(out)) if f.startswith(os.path.basename(out))]
	if proc.returncode != 0 or not bodies or not files:
		sys.exit('profile_step: the run failed:\n%s' % proc.stdout[-3000:])
	path = os.path.join(os.path.dirname(out), max(files, key=lambda f: os.path.getsize(os.path.join(os.path.dirname(out), f))))
	costs = {}
	for incl in (False, True):
		ann = subprocess.run(['callgrind_annotate', '--threshold=100', '--auto=no', '--show-percs=no', '--inclusive=' + ('yes' if incl else 'no'), path],
		                     stdout=subprocess.PIPE, universal_newlines=True).stdout
		table = {}
		for line in ann.splitlines():
			m = re.match(r'^\s*([\d,]+)\s+(?:\([^)]*\)\s+)?(\S.*)$', line)
			if m and ':' in m.group(2) and 'PROGRAM TOTALS' not in line:
				name = re.sub(r'\s+\[[^\]]*\]$', '', m.group(2))
				name = name.split(':', 1)[1] if not name.startswith('yade::') else name
				table[name] = table.get(name, 0) + int(m.group(1).replace(',', ''))
			m = re.match(r'^\s*([\d,]+)\s+(?:\([^)]*\)\s+)?PROGRAM TOTALS', line)
			if m:
				table['(total)'] = int(m.group(1).replace(',', ''))
		costs[incl] = table
	for f in files:
		os.remove(os.path.join(os.path.dirname(out), f))
	return costs, int(bodies[-1])


a, bodies = profile(cli.short)
b, _ = profile(cli.long)
steps = cli.long - cli.short
result = {}
for incl, label in ((False, 'self'), (True, 'inclusive')):
	diff = {k: (b[incl].get(k, 0) - a[incl].get(k, 0)) / steps / bodies for k in set(a[incl]) | set(b[incl])}
	result[label] = diff
	total = result['self'].get('(total)', 0) or 1
	print('\n%s cost, instructions per block-step (%d steps, %d bodies; the step: %.0f)' % (label, steps, bodies, total))
	for k, v in sorted(diff.items(), key=lambda kv: -kv[1])[:cli.top]:
		print('%10.0f %6.2f %%  %s' % (v, 100 * v / total, k[:160]))
if cli.json:
	with open(cli.json, 'w') as f:
		json.dump(dict(state=cli.state, steps=steps, bodies=bodies, **result), f, indent=1)
