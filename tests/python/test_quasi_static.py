"""rdem.quasi_static: the rotational inertia factor against numbers worked by hand and against its defining bound on
random springs, and the step count of a push."""
import math
import os
import random
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem import quasi_static as qs  # noqa: E402


class RotationalInertia(unittest.TestCase):

	def testHand(self):
		# cube: 9 * 3 / 2 = 13.5; MI1's half brick 62.5 x 60 x 27.5 mm: 9 * (3906.25 + 3600 + 756.25) / (3600 + 756.25)
		self.assertAlmostEqual(qs.rotationalInertiaScale((1, 1, 1)), 13.5, delta=1e-12)
		self.assertAlmostEqual(qs.rotationalInertiaScale((0.0275, 0.0625, 0.06)), 9 * 8262.5 / 4356.25, delta=1e-12)
		self.assertAlmostEqual(qs.rotationalInertiaScale((0.0275, 0.0625, 0.06)), 17.07, delta=0.01)
		for bad in ((1, 1), (1, 0, 1), (1, -1, 1), (1, float('nan'), 1)):
			with self.assertRaisesRegex(ValueError, '^halfExtents'):
				qs.rotationalInertiaScale(bad)

	def testBound(self):
		"""The defining property, on random blocks and springs on their faces (the Gershgorin terms of RdemTimeStepper):
		sum k_r / (s I_min) <= sum k_t / m, with equality approached by a spring at a corner; I_min = m (b^2 + c^2)/3."""
		rng = random.Random(1)
		worst = 0.0
		for _ in range(2000):
			h = [rng.uniform(0.01, 0.2) for _ in range(3)]
			a, b, c = sorted(h, reverse=True)
			m = 1.0
			Imin = m * (b * b + c * c) / 3
			s = qs.rotationalInertiaScale(h)
			rot = trans = 0.0
			for _ in range(rng.randint(1, 24)):
				axis = rng.randrange(3)
				r = [rng.uniform(-x, x) for x in h]
				r[axis] = h[axis] * rng.choice((-1, 1))  # on a face
				n = [0.0, 0.0, 0.0]
				n[axis] = 1.0
				kn, ks, A = rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1)
				r2 = sum(x * x for x in r)
				rxn2 = r2 - r[axis]**2
				rot += A * (kn * rxn2 + ks * (r2 + r[axis]**2)) / (s * Imin)
				trans += max(kn, ks) * A / m
			worst = max(worst, rot / trans)
			self.assertLessEqual(rot, trans * (1 + 1e-12))
		self.assertGreater(worst, 0.3)  # the bound is not vacuous


class Steps(unittest.TestCase):

	def testPushSteps(self):
		self.assertEqual(qs.pushSteps(0.012, 0.02, 1e-5), 60000)
		self.assertEqual(qs.pushSteps(0.012, 0.08, 1.5e-5), 10000)
		with self.assertRaisesRegex(ValueError, '^rate'):
			qs.pushSteps(0.01, 0.0, 1e-5)



class DensityScaling(unittest.TestCase):
	"""The partial density scaling rule against cases worked by hand, and its defining property on random rows."""

	def testLocalStepHand(self):
		# undamped: 2/omega; omega^2 = 1e10 (omega 1e5): 20 us
		self.assertAlmostEqual(qs.localDampedStep(1e10, 0.0), 2e-5, delta=1e-18)
		# c = 5e4, omega^2 = 1e10: 4 / (5e4 + sqrt(2.5e9 + 4e10)) = 4 / (5e4 + 206155.28...) = 15.6155 us
		self.assertAlmostEqual(qs.localDampedStep(1e10, 5e4), 4 / (5e4 + math.sqrt(4.25e10)), delta=1e-18)
		self.assertAlmostEqual(qs.localDampedStep(1e10, 5e4), 15.6155e-6, delta=1e-10)
		# one oscillator: omega^2 = w^2, c = 2 zeta w (row of C/m = 2 zeta w): (2/w)(sqrt(1 + zeta^2) - zeta), Belytschko et al.
		w, zeta = 3e4, 0.7
		self.assertAlmostEqual(qs.localDampedStep(w * w, 2 * zeta * w) * w / 2, math.sqrt(1 + zeta**2) - zeta, delta=1e-14)
		self.assertEqual(qs.localDampedStep(0.0, 0.0), float('inf'))

	def testScalesHand(self):
		# T = 40 us: T^2 omega^2 / 4 = 1.6e-9 * 1e10 / 4 = 4; 2 T c / 4 = 2 * 4e-5 * 5e4 / 4 = 1; a soft block keeps 1
		mu = qs.inertialScales([1e10, 1e10, 1e8, 0.0], [0.0, 5e4, 0.0, 0.0], 40e-6)
		for got, want in zip(mu, (4.0, 5.0, 1.0, 1.0)):
			self.assertAlmostEqual(got, want, delta=1e-12)
		# a factor 2 on the smallest local limit (the second block, 15.6 us): target 31.2 us
		T = qs.densityScalingTarget([1e10, 1e10, 1e8], [0.0, 5e4, 0.0], 2)
		self.assertAlmostEqual(T, 2 * 4 / (5e4 + math.sqrt(4.25e10)), delta=1e-18)
		self.assertEqual(qs.densityScalingTarget([1e10], [0.0], 1), 2e-5)

	def testScalesReachTheTarget(self):
		"""Random rows: every scaled block's own limit is the target (the scale is the smallest), the others' above it."""
		rng = random.Random(2)
		for _ in range(500):
			n = rng.randint(1, 30)
			w2 = [10**rng.uniform(6, 12) for _ in range(n)]
			c = [rng.choice((0.0, 10**rng.uniform(2, 6))) for _ in range(n)]
			T = qs.densityScalingTarget(w2, c, rng.uniform(1, 4))
			for a, b, m in zip(w2, c, qs.inertialScales(w2, c, T)):
				step = qs.localDampedStep(a / m, b / m)
				if m > 1:
					self.assertAlmostEqual(step / T, 1, delta=1e-12)
				else:
					self.assertGreaterEqual(step, T * (1 - 1e-12))

	def testBadInput(self):
		with self.assertRaisesRegex(ValueError, '^target'):
			qs.inertialScales([1.0], [0.0], 0.0)
		with self.assertRaisesRegex(ValueError, '^target'):
			qs.inertialScales([1.0], [0.0], float('inf'))
		with self.assertRaisesRegex(ValueError, r'^omega2\[1\]'):
			qs.inertialScales([1.0, -1.0], [0.0, 0.0], 1e-5)
		with self.assertRaisesRegex(ValueError, r'^dashpotRate\[0\]'):
			qs.localDampedStep(1.0, float('nan'))
		with self.assertRaisesRegex(ValueError, '^omega2 and dashpotRate'):
			qs.inertialScales([1.0, 2.0], [0.0], 1e-5)
		with self.assertRaisesRegex(ValueError, '^factor'):
			qs.densityScalingTarget([1.0], [0.0], 0.5)

if __name__ == '__main__':
	unittest.main()
