# -*- coding: utf-8 -*-
"""Apparent Poisson's ratio and Young's modulus of both Poisson formulations against the input, ν = 0 … 0.49.

Problem
    The compression scene of the paper (rdem.scenes.CompressionTest: a cube of N³ blocks between frictionless platens)
    loaded at 10 mm/s without breakage; the apparent ν (lateral over axial centroid strain, paper §5.3.1) and E (mean
    stress over axial centroid strain) are averaged over the second half of the run, once the start-up transient has
    passed, for the *paper* formulation (springs E/(1-ν²) plus D_p on the centroid hull) and the *consistent* one
    (doc/theory.md §5.2).

Expected result
    Consistent: both equal the input within 1 % for every ν. Paper: biased (doc/theory.md §5.1), refused above
    ν = 0.382 where it is not positive definite.

How to run (about a minute per block count on one core)
    build/bin/yade -n scripts/poisson_formulations.py [--blocks 6] [--out doc/poisson-formulations.md]
"""
import argparse
import sys
import time
from yade import O
from yade import rdem
from yade.rdem.scenes import CompressionTest

parser = argparse.ArgumentParser(prog='yade scripts/poisson_formulations.py', description=__doc__.split('\n\n')[0])
parser.add_argument('--blocks', type=int, default=6, help='blocks per edge of the cube (default 6)')
parser.add_argument('--steps', type=int, default=6000, help='steps per run (default 6000)')
parser.add_argument('--out', default='doc/poisson-formulations.md', help='markdown table to write')
cli = parser.parse_args(sys.argv[1:])

E = 30e9
NUS = (0.0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.49)
rows = []
wall0 = time.time()
for form in ('paper', 'consistent'):
	for nu in NUS:
		O.reset()
		try:
			test = CompressionTest(blocksPerEdge=cli.blocks, young=E, poisson=nu, formulation=form, tensileStrength=float('inf'), rate=10e-3, dt=1e-6)
		except ValueError as err:
			rows.append((form, nu, None, None, str(err).split(';')[0]))
			print(form, nu, 'refused:', err, flush=True)
			continue
		nuSum = eSum = 0.0
		n = 0
		for k in range(20):
			rdem.run(cli.steps // 20)
			if k >= 10:  # second half: past the start-up transient
				nuSum += test.apparentPoisson()
				eSum += test.apparentYoung()
				n += 1
		nuApp, eApp = nuSum / n, eSum / n
		rows.append((form, nu, nuApp, eApp, ''))
		print('%-10s nu=%.2f  apparent nu=%.4f  apparent E/E=%.4f' % (form, nu, nuApp, eApp / E), flush=True)

with open(cli.out, 'w') as f:
	f.write('# Apparent elastic constants of the two Poisson formulations\n\n')
	f.write('Made by `build/bin/yade -n scripts/poisson_formulations.py --blocks %d --steps %d` (%.0f s on one core, %s). '
	        'Cube of %d³ blocks between frictionless platens (plates 4 cm), 10 mm/s, no breakage; values averaged over the '
	        'second half of each run. Errors relative to the input.\n\n' % (cli.blocks, cli.steps, time.time() - wall0, time.strftime('%Y-%m-%d'), cli.blocks))
	f.write('| formulation | input ν | apparent ν | error ν | apparent E / E | error E |\n|---|---|---|---|---|---|\n')
	for form, nu, nuApp, eApp, note in rows:
		if nuApp is None:
			f.write('| %s | %.2f | refused: %s | | | |\n' % (form, nu, note))
			continue
		errNu = (nuApp / nu - 1) * 100 if nu > 0 else float('nan')
		f.write('| %s | %.2f | %.4f | %s | %.4f | %+.2f %% |\n' % (form, nu, nuApp, '%+.2f %%' % errNu if nu > 0 else '(%.1e)' % nuApp, eApp / E,
		                                                             (eApp / E - 1) * 100))
print('written', cli.out)
sys.exit(0)
