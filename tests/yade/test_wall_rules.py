"""The rule set of rdem.wall_database admits every wall of the validation set at set-up (issue #28): each row's scene,
built by scripts/shear_wall.py with its defaults, makes all its bonds without a snap-back refusal. The crack-band rule
(Bazant & Oh 1983, doc/validation.md) lowers strengths only where a spring would snap back, and without it PUP1 is
refused. The script itself runs (its code executed with its command line in sys.argv, in a namespace of its own whose
__builtins__ is the module, where YADE puts the engines' labels), once per row in this one YADE, and stops before any
step (--setup-only)."""
import builtins
import contextlib
import io
import json
import os
import shutil
import sys
import tempfile
import unittest
import harness
from rdem import wall_database

ROOT = os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', '..')  # under YADE, __file__ names its launcher
SCRIPT = os.path.join(ROOT, 'scripts', 'shear_wall.py')


class Admissible(unittest.TestCase):
	"""scripts/shear_wall.py --setup-only builds each row's scene with its defaults (the rule set, softening springs, crack
	band on), which makes every bond and runs its snap-back check (Ip2_RdemMat_RdemMat_RdemPhys, rdem::checkSoftening):
	exit 0 for all 15. The crack band lowers strengths only where a spring would snap back: in the hollow clay units of
	PUP1-PUP6 (f_t = 2.275 MPa lowered to sqrt(2 rho k_n G_f^I) = 2.0865 MPa for the 155 mm unit blocks,
	tests/unit/test_crack_band.cpp), nowhere in CS01-CS08 and MI1, which therefore run as before the rule. Without the
	rule (--crack-band off) PUP1 is refused with the snap-back message."""

	def setupOnly(self, name, *extra):
		"""(exit code, message, setup.json) of scripts/shear_wall.py --wall name --setup-only."""
		out = tempfile.mkdtemp(prefix='rdem-setup-')
		argv = sys.argv
		sys.argv = [SCRIPT, '--wall', name, '--setup-only', '--vtk-every', '0', '--out', out] + list(extra)
		printed = io.StringIO()
		code, message = 0, ''
		try:
			with open(SCRIPT) as f:
				compiled = compile(f.read(), SCRIPT, 'exec')
			with contextlib.redirect_stdout(printed):
				exec(compiled, {'__name__': '__main__', '__file__': SCRIPT, '__builtins__': builtins})
		except SystemExit as e:
			code, message = (0, '') if e.code in (0, None) else (1, str(e.code))
		finally:
			sys.argv = argv
		path = os.path.join(out, 'setup.json')
		result = None
		if os.path.exists(path):
			with open(path) as f:
				result = json.load(f)
		shutil.rmtree(out)
		return code, message + printed.getvalue(), result

	def testEveryWall(self):
		for name in wall_database.readTable():
			code, text, r = self.setupOnly(name)
			self.assertEqual(code, 0, '%s: %s' % (name, text[-3000:]))
			self.assertEqual(r['interactions'], r['bonds'], name)  # every bond made (and checked) at set-up
			if name.startswith('PUP'):
				self.assertEqual(r['crackBand']['bonds'], 66, name)  # the bonds inside the 66 two-block units
				self.assertAlmostEqual(r['crackBand']['lowestTensileStrengthMPa'], 2.0865, delta=0.0005)  # the 155 mm unit blocks (the 152.5 mm ones at the ends: 2.1035)
			else:
				self.assertEqual(r['crackBand']['bonds'], 0, name)

	def testWithoutTheRule(self):
		code, text, r = self.setupOnly('PUP1', '--crack-band', 'off')
		self.assertNotEqual(code, 0)
		self.assertIn('snap back', text)
		self.assertIsNone(r)


if __name__ == '__main__':
	harness.run(Admissible)
