"""scripts/wall_database.py end to end on a tiny wall of one row (the runner's code path: the table, the rule set,
scripts/shear_wall.py in its own YADE, the table and the figure), checked against statics and the row it was given.

The row: two calcium-silicate units of 248 mm per course (0.498 m with a 2 mm thin-layer joint), three courses
(0.748 m), 0.175 m thick, unfilled head joints, sigma0 = 1 MPa, both ends fixed; E_m = 5000 MPa given. Pushed to 0.1 %
drift (0.75 mm), it must rock or crack: as an elastic wall (Timoshenko, both ends fixed, K = 1.1e8 N/m) it would carry
about 80 kN there, more than statics allows, so its largest load is bounded by the rocking bound (2N + W) L / (2H) of
the model's own geometry (rdem.wall_database.rockingBound): N = 87.15 kN, W = 1.15 kN, 58.4 kN. Tolerance 2 %: the
smoothed load may overshoot a static value by the inertia of the push.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
import harness
from rdem import wall_database

ROOT = os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', '..')  # under YADE, __file__ names its launcher
TOL_BOUND = 0.02


class Runner(unittest.TestCase):

	def testTinyWall(self):
		with open(wall_database.TABLE) as f:
			header = f.readline()
		names = header.strip().split(',')
		cells = dict.fromkeys(names, '')
		cells.update({
		        'N': '1', 'Reference': 'test', 'Specimen name': 'TINY', 'Unit type': 'CS', 'N courses': '3', 'H [m]': '0.75', 'L [m]': '0.5', 't [m]': '0.175',
		        'Bed Joints': 'TL', 'Head Joints': 'U', 'Void Ratio [%]': 'solid', 'lb [mm]': '248', 'wb [mm]': '175', 'hb [mm]': '248', 'fb_perp [MPa]': '26.5',
		        'fm_c [MPa]': '19.4', 'Em [MPa]': '5000', 'fv0 [MPa]': '0.5', 'mu [-]': 'NaN', 'H0/H [-]': '0.5', 'sigma0 [MPa]': '1', 'Failure mode': 'S',
		        'dVmax+ [%]': '0.2', 'dVmax- [%]': '0.2', 'Vmax+ [kN]': '20', 'Vmax- [kN]': '22'
		})
		out = tempfile.mkdtemp(prefix='rdem-walls-')
		table = os.path.join(out, 'tiny.csv')
		with open(table, 'w') as f:
			f.write(header + ','.join(cells[n] for n in names) + '\n')
		launcher = os.environ.get('RDEM_LAUNCHER', os.path.join(ROOT, 'build', 'bin', 'yade'))
		cmd = [launcher, '-n', '-x', os.path.join(ROOT, 'scripts', 'wall_database.py'), '--table', table, '--out', out, '--nice', '0', '--extra', '--drift 0.1 --max-drift 0.1']
		proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
		self.assertEqual(proc.returncode, 0, proc.stdout[-3000:])
		with open(os.path.join(out, 'walls.json')) as f:
			walls = json.load(f)
		self.assertTrue(os.path.getsize(os.path.join(out, 'walls.png')) > 0)
		(w, ) = walls['walls']
		self.assertEqual(w['wall'], 'TINY')
		self.assertEqual(w['measuredMeanKN'], 21.0)
		self.assertFalse(w['validated'])  # --drift changed
		self.assertIn(w['modelFailure'], ('S', 'F', 'H', '-'))
		with open(os.path.join(out, 'TINY', 'results.json')) as f:
			r = json.load(f)
		g = r['model']['geometry']
		self.assertAlmostEqual(g['length'], 0.498, delta=1e-12)
		self.assertAlmostEqual(g['height'], 0.748, delta=1e-12)
		self.assertAlmostEqual(r['axialForce'], 1e6 * 0.498 * 0.175, delta=1e-6)
		W = 1800 * 9.81 * 0.498 * 0.748 * 0.175
		bound = wall_database.rockingBound(r['axialForce'], W, 0.498, 0.748, 0.5)
		self.assertAlmostEqual(bound, 58.4e3, delta=0.1e3)
		self.assertGreater(w['modelPeakKN'], 0.0)
		self.assertLess(w['modelPeakKN'] * 1e3, (1 + TOL_BOUND) * bound, 'model %.2f kN, rocking bound %.2f kN' % (w['modelPeakKN'], bound * 1e-3))
		shutil.rmtree(out)


if __name__ == '__main__':
	harness.run(Runner)
