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


if __name__ == '__main__':
	unittest.main()
