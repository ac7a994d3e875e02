"""The rule set of rdem.wall_database admits every wall of the validation set at set-up (issue #28): each row's scene,
built by scripts/shear_wall.py with its defaults, makes all its bonds without a snap-back refusal. The crack-band rule
(Bazant & Oh 1983, doc/validation.md) lowers strengths only where a spring would snap back, and without it PUP1 is
refused. Each wall is built in its own YADE process and stopped before any step (--setup-only)."""
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

class Admissible(unittest.TestCase):
	"""The rule set admits every wall of the table at set-up: scripts/shear_wall.py --setup-only builds each row's scene
	with its defaults (the rule set, softening springs, crack band on), which makes every bond and runs its snap-back check
	(Ip2_RdemMat_RdemMat_RdemPhys, rdem::checkSoftening): exit 0 for all 15. The crack band lowers strengths only where a
	spring would snap back: in the hollow clay units of PUP1-PUP6 (f_t = 2.275 MPa lowered to sqrt(2 rho k_n G_f^I) =
	2.086 MPa for the 155 mm unit blocks, tests/unit/test_crack_band.cpp), nowhere in CS01-CS08 and MI1, which therefore run
	as before the rule. Without the rule (--crack-band off) PUP1 is refused with the snap-back message."""

	def setupOnly(self, name, *extra):
		out = tempfile.mkdtemp(prefix='rdem-setup-')
		launcher = os.environ.get('RDEM_LAUNCHER', os.path.join(ROOT, 'build', 'bin', 'yade'))
		cmd = [launcher, '-n', '-x', os.path.join(ROOT, 'scripts', 'shear_wall.py'), '--wall', name, '--setup-only', '--vtk-every', '0', '--out', out] + list(extra)
		proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
		path = os.path.join(out, 'setup.json')
		result = None
		if os.path.exists(path):
			with open(path) as f:
				result = json.load(f)
		shutil.rmtree(out)
		return proc, result

	def testEveryWall(self):
		for name in wall_database.readTable():
			proc, r = self.setupOnly(name)
			self.assertEqual(proc.returncode, 0, '%s: %s' % (name, proc.stdout[-3000:]))
			self.assertEqual(r['interactions'], r['bonds'], name)  # every bond made (and checked) at set-up
			if name.startswith('PUP'):
				self.assertGreater(r['crackBand']['bonds'], 0, name)
				self.assertAlmostEqual(r['crackBand']['lowestTensileStrengthMPa'], 2.0865, delta=0.0005)  # the 155 mm unit blocks (the 152.5 mm ones at the ends: 2.1035)
			else:
				self.assertEqual(r['crackBand']['bonds'], 0, name)

	def testWithoutTheRule(self):
		proc, r = self.setupOnly('PUP1', '--crack-band', 'off')
		self.assertNotEqual(proc.returncode, 0)
		self.assertIn('snap back', proc.stdout)


if __name__ == '__main__':
	harness.run(Admissible)
