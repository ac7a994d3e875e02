"""Tests of rdem.rocking (pure Python, no YADE): the rigid rocking block's equation of motion with Housner's impacts.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_rocking_equation`` (or through CTest)."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.rocking import RockingBlockEquation  # noqa: E402


class Rocking(unittest.TestCase):

	def testFreeRockingLinearised(self):
		# a slender block (alpha = 0.02 rad): the linearised equation's time to the first impact from theta0,
		# (1/p) arcosh(1/(1 - theta0/alpha)) (Housner 1963, eq. 9), to 1e-3; then the amplitude after the impact from
		# the energy kept, eta^2 (Housner's r)
		e = RockingBlockEquation(0.01, 0.5)
		th0 = e.alpha / 2
		r = e.response(lambda t: 0.0, 2.0, theta0=th0)
		tq = r['impacts'][0]
		self.assertAlmostEqual(tq * e.p / math.acosh(1 / (1 - th0 / e.alpha)), 1, delta=1e-3)
		after = [abs(th) for t, th in zip(r['time'], r['theta']) if r['impacts'][0] < t < r['impacts'][1]]
		th1 = max(after)
		kept = (math.cos(e.alpha - th1) - math.cos(e.alpha)) / (math.cos(e.alpha - th0) - math.cos(e.alpha))
		self.assertAlmostEqual(kept, e.eta**2, delta=2e-4)

	def testUpliftThreshold(self):
		e = RockingBlockEquation(0.06, 0.3)
		a0 = e.g * math.tan(e.alpha)
		r = e.response(lambda t: 0.99 * a0, 1.0)
		self.assertEqual(r['maxTheta'], 0.0)
		r = e.response(lambda t: 1.01 * a0, 1.0)
		self.assertLess(min(r['theta']), -1e-3)  # onto the -x corner, away from the acceleration

	def testMinimumOverturningAmplitude(self):
		# ground pulse T = 0.5 s on a 0.12 m x 0.6 m parapet (omega_p/p = 2.56): converged in the step to 1e-3, and
		# the amplitude is a real threshold: 1 % less does not overturn, the value found does
		e = RockingBlockEquation(0.06, 0.3)
		a = e.minimumOverturningAmplitude(0.5, step=0.05, dt=1 / (500 * e.p))
		b = e.minimumOverturningAmplitude(0.5, step=0.05, dt=1 / (1500 * e.p))
		self.assertAlmostEqual(a / b, 1, delta=1e-3)  # measured 1e-4
		pulse = lambda A: (lambda t: A * math.sin(2 * math.pi * t / 0.5) if t <= 0.5 else 0.0)
		self.assertTrue(e.overturns(pulse(b * 1.0005), 0.5, dt=1 / (1500 * e.p)))
		self.assertFalse(e.overturns(pulse(b * 0.99), 0.5, dt=1 / (1500 * e.p)))
		self.assertAlmostEqual(b, 2.5519, delta=2e-3)  # the figure of doc/out-of-plane.md §4 (step 0.02, default dt)
		self.assertGreater(b / (e.g * math.tan(e.alpha)), 1)

	def testBadArguments(self):
		with self.assertRaisesRegex(ValueError, r'b = 0: must be a finite number > 0'):
			RockingBlockEquation(0, 1)
		with self.assertRaisesRegex(ValueError, r'eta = 1.5'):
			RockingBlockEquation(0.1, 1, eta=1.5)
		with self.assertRaisesRegex(ValueError, r'period = -1'):
			RockingBlockEquation(0.1, 1).minimumOverturningAmplitude(-1)


if __name__ == '__main__':
	unittest.main()
