"""Shared set-up for the plugin's tests that run inside YADE (``build/bin/yade -n -x tests/yade/test_*.py``)."""
import sys
import unittest
from yade import O


def run(testCase):
	"""Run one TestCase class inside YADE and exit with 0 if it passed, 1 otherwise (CTest reads the status)."""
	suite = unittest.defaultTestLoader.loadTestsFromTestCase(testCase)
	result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout).run(suite)
	sys.exit(0 if result.wasSuccessful() else 1)


def freshScene():
	"""Empty scene with no leftover engines, bodies or energy tracking."""
	O.reset()
	O.trackEnergy = False
