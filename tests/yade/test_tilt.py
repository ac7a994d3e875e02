"""A dry-stacked brick wall on a tilting base (rdem.earthquake.DryWall: 3 bricks × 6 courses of 250×120×55 mm in
running bond, laid dry on a fixed base, contacts at the vertices) falls over at the tilt of rigid-block limit analysis
(rdem.limit_analysis.stackTilt: the base joint governs, tan θc = t/H = 0.12/0.33, θc = 19.98°; sliding would need
tan θ = μ = 0.75):

* at 0.97 θc, ramped over 0.2 s and held 0.2 s, it stands: its lean stays below 5e-3 rad (measured 1.05e-3 at most:
  the loose courses rock slightly on their contact springs as the ramp loads them) and its bottom course does not slide
  (below 1e-5 m);
* at 1.03 θc it lifts off its downhill edge and falls over (lean beyond 0.02 rad within
  0.8 s; the rigid wall's lean grows as Δθ (cosh pt - 1), R = 0.176 m, p = √(3g/4R) = 6.5 rad/s, Δθ = 0.03 θc:
  0.02 rad after 0.26 s)."""
import math
import unittest
import harness
from yade import O
from yade.rdem.earthquake import DryWall


def hold(wall, theta, duration, ramp=0.0):
	"""Tilt from the current tilt to ``theta`` [rad] over ``ramp`` seconds, then hold it until ``duration`` [s] has passed
	or the wall leans beyond 0.02 rad; returns the largest lean of the wall [rad]."""
	start, t0, largest = wall.theta, O.time, 0.0
	while O.time - t0 < duration and largest <= 0.02:
		wall.tilt(start + (theta - start) * (min(1.0, (O.time - t0) / ramp) if ramp > 0 else 1.0))
		for _ in range(50):
			O.step()
		largest = max(largest, wall.lean())
	return largest


class Tilt(unittest.TestCase):

	def testFallsAtTheLimitAnalysisTilt(self):
		harness.freshScene()
		wall = DryWall(height=0.33)
		self.assertEqual((len(wall.courses), len(wall.ids)), (6, 21))  # running bond: half bats at the ends of odd courses
		self.assertEqual((wall.limit.mechanism, wall.limit.joint), ('overturning', 0))
		self.assertAlmostEqual(math.tan(wall.limit.angle), 0.12 / 0.33, delta=1e-12)
		hold(wall, 0.0, 0.02)  # settle under gravity
		y0 = sum(O.bodies[i].state.pos[1] for i in wall.courses[0])
		stands = hold(wall, 0.97 * wall.limit.angle, 0.4, ramp=0.2)
		self.assertLess(stands, 5e-3)
		self.assertLess(wall.lean(), 5e-3)
		self.assertLess(abs(sum(O.bodies[i].state.pos[1] for i in wall.courses[0]) - y0) / len(wall.courses[0]), 1e-5)
		falls = hold(wall, 1.03 * wall.limit.angle, 0.8, ramp=0.02)
		self.assertGreater(falls, 0.02)


if __name__ == '__main__':
	harness.run(Tilt)
