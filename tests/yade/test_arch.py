"""A semicircular arch of dry voussoirs under its own weight (issue 26, must-show 1; doc/arches.md §3).

Eight voussoirs (R = 1 m centreline radius, depth 0.2 m), friction 1.0 (the arch needs 0.39 to fail by hinging alone,
doc/arches.md §2), contacts sampled at the vertices (contactSamples=1: hinges on the joints' edges). The limit analysis
(rdem.limit_analysis.archMinimumThickness, tests/python/test_limit_analysis.py) gives t_min/R = 0.10086 for N = 8, with
hinges at the springings' extrados (joints 0 and 8), the haunches' intrados (joints 2 and 6) and the crown's extrados
(joint 4). Gravity is ramped up over 0.2 s, with Cundall's damping 0.2 (it slows a mechanism, it cannot stop one), then
held to 2 s:

* at t = 1.02 t_min the arch stands: the crown drops by its elastic settlement only (below 1e-3 R);
* at t = 0.98 t_min it collapses: the crown drops by more than 0.1 R within 2 s, and when it has dropped 0.02 R the joints
  that open are those of the five-hinge mechanism, on the sides the limit analysis gives.

Tilted (gravity turned about the depth axis: a horizontal load lambda times the weight, ramped over 1 s, then held to
3 s), an arch at 1.5 t_min collapses by a four-hinge mechanism at lambda_c = 0.1636
(rdem.limit_analysis.archTiltMultiplier, hinges at joints 0 and 4 on the extrados, 2 and 7 on the intrados). The model
stands at 0.90 lambda_c and collapses at 1.02 lambda_c through those four hinges. Near the limit its threshold is less
sharp than under gravity alone (doc/arches.md §3): with E = 1 GPa it stands at 0.85, 0.90, 0.95 and collapses at 0.96,
0.97, 0.98 lambda_c; with E = 10 GPa it stands at 0.95, 0.96, 0.98 but collapses at 0.97 and 0.99 lambda_c."""
import math
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat
import rdem
from rdem.limit_analysis import archMinimumThickness, archTiltMultiplier

N, R, DEPTH, G = 8, 1.0, 0.2, 9.81


def arch(factor, young=1e9):
	"""A fresh scene with the arch at factor * t_min; returns (arch, thickness)."""
	harness.freshScene()
	stone = O.materials.append(
	        RdemMat(young=young, poisson=0.2, density=2000, tensileStrength=float('inf'), cohesion=float('inf'), frictionAngle=math.atan(1.0),
	                dampingNormal=1.0, dampingShear=1.0, label='stone'))
	O.engines = rdem.engines(formulation=None, recontact='always', contactSamples=1, damping=0.2)
	t = factor * archMinimumThickness(N).ratio * R
	a = rdem.masonry.arch(2 * R, t, DEPTH, N, material=stone)
	O.dt = -1
	return a, t


def run(a, gravity, until, stopDrop, watchDrop):
	"""Step with ``gravity(t)`` [m/s2] up to ``until`` s or a crown drop of ``stopDrop``. Returns (largest crown drop, hinges
	when the drop first passed ``watchDrop`` or None)."""
	newton = rdem.newtonIntegrator()
	largest, hinges = 0.0, None
	while O.time < until:
		newton.gravity = gravity(O.time)
		rdem.run(50)
		drop = a.crownDrop()
		largest = max(largest, drop)
		if hinges is None and drop > watchDrop:
			hinges = a.hinges(opening=0.005 * a.layout.params['thickness'])
		if drop > stopDrop:
			break
	return largest, hinges


def load(a, until=2.0, ramp=0.2, stopDrop=0.1 * R, watchDrop=0.02 * R):
	"""Ramp gravity up over ``ramp`` s, then hold it (run)."""
	return run(a, lambda t: Vector3(0, 0, -G * min(1.0, t / ramp)), until, stopDrop, watchDrop)


def tilt(a, multiplier, ramp=1.0, until=3.0, stopDrop=0.1 * R, watchDrop=0.02 * R):
	"""Gravity turned so that the horizontal load (towards -x) is ``multiplier`` times the vertical, ramped over ``ramp`` s
	and held (run)."""

	def gravity(t):
		th = math.atan(multiplier * min(1.0, t / ramp))
		return Vector3(-G * math.sin(th), 0, -G * math.cos(th))

	return run(a, gravity, until, stopDrop, watchDrop)


class ArchUnderItsWeight(unittest.TestCase):

	def testLimitAnalysis(self):
		limit = archMinimumThickness(N)
		self.assertAlmostEqual(limit.ratio, 0.10086, delta=1e-5)
		self.assertEqual(limit.hinges, [(0, 'extrados'), (2, 'intrados'), (4, 'extrados'), (6, 'intrados'), (8, 'extrados')])

	def testStandsAbove(self):
		a, t = arch(1.02)
		drop, hinges = load(a)
		self.assertLess(drop, 1e-3 * R, 'the arch at 1.02 t_min should stand: crown drop %.3g m' % drop)
		self.assertIsNone(hinges)

	def testCollapsesBelowWithFiveHinges(self):
		a, t = arch(0.98)
		drop, hinges = load(a)
		self.assertGreater(drop, 0.1 * R, 'the arch at 0.98 t_min should collapse: crown drop %.3g m' % drop)
		self.assertEqual(hinges, archMinimumThickness(N).hinges)


	def testTilt(self):
		lam, hinges = archTiltMultiplier(N, 1.5 * archMinimumThickness(N).ratio)
		self.assertAlmostEqual(lam, 0.1636, delta=1e-4)
		a, t = arch(1.5)
		drop, opened = tilt(a, 0.90 * lam)
		self.assertLess(drop, 1e-3 * R, 'at 0.90 lambda_c the arch should stand: crown drop %.3g m' % drop)
		a, t = arch(1.5)
		drop, opened = tilt(a, 1.02 * lam)
		self.assertGreater(drop, 0.1 * R, 'at 1.02 lambda_c the arch should collapse: crown drop %.3g m' % drop)
		self.assertEqual(opened, hinges)


if __name__ == '__main__':
	harness.run(ArchUnderItsWeight)
