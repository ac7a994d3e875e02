"""Tests of rdem.limit_analysis (pure Python, no YADE): the tilt at which a dry-stacked wall collapses on a tilting base.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_limit_analysis`` (or through CTest)."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.limit_analysis import stackTilt  # noqa: E402


class StackTilt(unittest.TestCase):

	def testSingleBlockIsHousnersUplift(self):
		# one block 2b wide and 2h tall: tan(theta) = b/h, Housner's alpha (../shared benchmarks §2: b = 0.1, h = 0.5)
		c = stackTilt(0.2, 1.0, [0.0], 0.8)
		self.assertEqual(c.mechanism, 'overturning')
		self.assertAlmostEqual(c.angle, 0.19739555984988078, delta=1e-15)  # atan(0.2)
		self.assertAlmostEqual(c.multiplier, 0.2, delta=1e-15)

	def testWallOverturnsAtItsBase(self):
		# ten courses of 55 mm, 0.12 m thick: the base joint governs, t/H = 0.12/0.55; the joint below the top course
		# would need t/0.055 = 2.18
		zs = [0.055 * k for k in range(10)]
		c = stackTilt(0.12, 0.55, zs, 0.75)
		self.assertEqual((c.mechanism, c.joint), ('overturning', 0))
		self.assertAlmostEqual(c.multiplier, 0.12 / 0.55, delta=1e-15)
		self.assertAlmostEqual(c.overturning[-1], 0.12 / 0.055, delta=1e-12)
		self.assertAlmostEqual(math.degrees(c.angle), 12.3080, delta=1e-4)  # atan(0.21818...) = 0.214814 rad (series to x^7)

	def testJointsInAnyOrder(self):
		c = stackTilt(0.12, 0.55, [0.11, 0.0, 0.055], 0.75)
		self.assertEqual(c.joint, 1)  # the joint at z = 0
		self.assertAlmostEqual(c.multiplier, 0.12 / 0.55, delta=1e-15)

	def testSquatWallSlides(self):
		# t/H = 2 > mu = 0.6: it slides at tan(theta) = mu
		c = stackTilt(0.3, 0.15, [0.0, 0.05, 0.1], 0.6)
		self.assertEqual((c.mechanism, c.joint), ('sliding', 0))
		self.assertAlmostEqual(c.angle, math.atan(0.6), delta=1e-15)
		self.assertAlmostEqual(c.overturning[0], 2.0, delta=1e-15)

	def testBadArguments(self):
		with self.assertRaisesRegex(ValueError, r'thickness = 0: must be a finite number > 0'):
			stackTilt(0, 1, [0], 0.7)
		with self.assertRaisesRegex(ValueError, r'friction = nan'):
			stackTilt(0.1, 1, [0], float('nan'))
		with self.assertRaisesRegex(ValueError, r'joints = \[1.0\]: must be one or more heights in \[0, height = 1\)'):
			stackTilt(0.1, 1, [1.0], 0.7)
		with self.assertRaisesRegex(ValueError, r'joints = \[\]'):
			stackTilt(0.1, 1, [], 0.7)
		with self.assertRaisesRegex(ValueError, r"joints = 'ab': must be a sequence of heights"):
			stackTilt(0.1, 1, 'ab', 0.7)


if __name__ == '__main__':
	unittest.main()
