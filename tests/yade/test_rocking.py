"""Housner's rocking block (Housner 1963; ../shared figures: b = 0.1 m, h = 0.5 m, α = 0.1974 rad, quarter cycle from
α/2 0.3471 s, η = 0.9423) with rdem.engines' default contacts (sampled at the vertices, contactSamples=1) and the paper's
critical dashpots (h = 1):

* free rocking from θ0 = α/2: the time to the first impact is within 3 % of the exact equation's (integrated here by
  Runge–Kutta, rdem.scenes.RockingBlock.quarterCycle; measured: 0.003 % off);
* the energy kept through the first impact, from the amplitude θ1 of the next half cycle, within 5 % of Housner's
  r = η² for three slenderness ratios (h/b = 2.5, 5, 10; measured +3.4 %, +0.3 %, -0.03 %). With samples inside the
  base face (contactSamples=2, the paper's 2×2 springs' grid) the block keeps 6 % more than η² at h/b = 5:
  the interior samples store impact energy and give it back as the block rolls onto the new corner (doc/theory.md §4.2);
* uplift under a horizontal ground acceleration a (gravity tilted, the inertial load of a ground motion), ramped slowly
  and held, starts within 2 % of g tan α: at 0.98 g tan α the block stays down (its rotation is the contacts' elastic
  one, below 1e-5 rad: 96 N·m over the corner springs' 2.2e7 N·m/rad is 4e-6), at 1.02 g tan α it lifts off (beyond
  1e-3 rad within 1 s)."""
import math
import unittest
import harness
from yade import O, Vector3
from yade import rdem
from yade.rdem.scenes import RockingBlock


def advance(n):
	for _ in range(n):
		O.step()


def firstImpactAndNextAmplitude(rock, theta0, every=25):
	"""Run from the release to the end of the half cycle after the first impact; returns (time of the first crossing of
	θ = 0, interpolated between samples every ``every`` steps; the amplitude θ1 of the next half cycle)."""
	prev, tPrev = rock.angle(), O.time
	while True:
		advance(every)
		th = rock.angle()
		if th <= 0 < prev:
			tCross = tPrev + (O.time - tPrev) * prev / (prev - th)
			break
		prev, tPrev = th, O.time
	lowest = th
	while th <= 0:  # the half cycle on the other corner: θ < 0 until it comes back
		advance(every)
		th = rock.angle()
		lowest = min(lowest, th)
		if O.time > 10 * tCross:
			break
	return tCross, -lowest


class Rocking(unittest.TestCase):

	def testFreeRockingFromHalfAlpha(self):
		for h in (0.5, 0.25, 1.0):
			O.reset()
			rock = RockingBlock(b=0.1, h=h, theta0=0)
			theta0 = rock.alpha / 2
			O.reset()
			rock = RockingBlock(b=0.1, h=h, theta0=theta0)
			tq, theta1 = firstImpactAndNextAmplitude(rock, theta0)
			exact = rock.quarterCycle(theta0)
			if h == 0.5:
				self.assertAlmostEqual(exact, 0.3471, delta=5e-5)  # the reference figure of the benchmarks file
			self.assertAlmostEqual(tq / exact, 1, delta=0.03, msg='h = %g' % h)
			r = rock.energyRatio(theta0, theta1)
			self.assertAlmostEqual(r / rock.eta()**2, 1, delta=0.05, msg='h = %g: r = %.4f, eta^2 = %.4f' % (h, r, rock.eta()**2))

	def testInteriorSamplesKeepTooMuch(self):
		O.reset()
		rock = RockingBlock(b=0.1, h=0.5, theta0=0.0987, contactSamples=2)
		# the sampled contact (a persistent face-to-face patch with the same 3x3 points keeps 1.03 eta^2: its points are
		# material points of both blocks, not samples of each block's own face tested against the other's volume)
		rdem.geomFunctor().persistentContacts = False
		tq, theta1 = firstImpactAndNextAmplitude(rock, 0.0987)
		self.assertGreater(rock.energyRatio(0.0987, theta1) / rock.eta()**2, 1.05)

	def testUpliftThreshold(self):
		for factor, lifts in ((0.98, False), (1.02, True)):
			O.reset()
			rock = RockingBlock(b=0.1, h=0.5)
			newton = rdem.newtonIntegrator()
			largest = 0
			while O.time < 1.0 and largest < 1e-3:
				# the ground accelerates towards -x: ramped over 0.5 s (the block rocks on its contact springs at about
				# 8 ms: quasi-static), then held; a step load would overshoot past the static threshold
				a = factor * rock.upliftAcceleration() * min(1.0, O.time / 0.5)
				newton.gravity = Vector3(a, 0, -rock.g)
				advance(250)
				largest = max(largest, abs(rock.angle()))
			if lifts:
				self.assertGreater(largest, 1e-3, 'factor %g' % factor)
			else:
				self.assertLess(largest, 1e-5, 'factor %g' % factor)


if __name__ == '__main__':
	harness.run(Rocking)
