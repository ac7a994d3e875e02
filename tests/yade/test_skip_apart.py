"""Pairs of blocks found apart are not tested again while their RdemGap certificate holds, and a sampled contact tests
only the samples of its sample certificate (Ig2_RdemBlock_RdemBlock_RdemGeom.skipApart, with the travel recorded by
RdemContactGate; pkg/rdem/math/SeparationBound.hpp): the same bits with and without certificates, and the certificates
are made and used."""
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat
from yade import rdem
from yade import rdem

E, NU, H = 30e9, 0.2, 0.01


class SkipApart(unittest.TestCase):

	def crackingRun(self, skip, samples=1):
		# The compression run of test_assembly.testPrefetchChangesNoResult (it cracks, makes sampled contacts, loses a
		# block half-way: the travel record restarts), with a save and a load in the middle (certificates are not saved:
		# every pair is tested again).
		from yade.rdem.scenes import CompressionTest
		harness.freshScene()
		CompressionTest(blocksPerEdge=4, tensileStrength=2e6, rate=0.5, dt=2e-6)
		rdem.build.geomFunctor().skipApart = skip
		rdem.build.geomFunctor().contactSamplesPerEdge = samples
		rdem.run(40)
		O.bodies.erase(40)
		rdem.run(20)
		O.saveTmp('skipApart')
		O.loadTmp('skipApart')
		rdem.build.geomFunctor().skipApart = skip
		rdem.run(40)
		law, ig2 = rdem.build.law(), rdem.build.geomFunctor()
		contacts = sum(1 for I in O.interactions if I.isReal and not I.geom.bonded)
		gaps = sum(1 for I in O.interactions.all() if not I.isReal and type(I.geom).__name__ == 'RdemGap')
		state = ([tuple(b.state.pos) + tuple(b.state.ori) + tuple(b.state.vel) for b in O.bodies if b], law.tensionBreaks + law.shearBreaks, contacts)
		return state, ig2.skippedTests, gaps

	def testSameBitsWithAndWithout(self):
		on, skippedOn, gapsOn = self.crackingRun(True)
		off, skippedOff, gapsOff = self.crackingRun(False)
		self.assertGreater(on[1], 0)  # springs broke
		self.assertGreater(on[2], 0)  # sampled contacts
		self.assertEqual(on, off)
		self.assertEqual((skippedOff, gapsOff), (0, 0))
		# Tests were saved (the counter restarts with the load: the 40 steps after it).
		self.assertGreater(skippedOn, 1000)
		self.assertGreater(gapsOn, 100)

	def testSameBitsWithAndWithoutOnTheWallsSampleGrid(self):
		# The sample grid of the walls of doc/validation.md (contactSamplesPerEdge = 0: that of the 2×2 segments, 3×3
		# samples per face), whose sample certificates skip most of a face's samples.
		on, skippedOn, gapsOn = self.crackingRun(True, samples=0)
		off, skippedOff, gapsOff = self.crackingRun(False, samples=0)
		self.assertGreater(on[2], 0)  # sampled contacts
		self.assertEqual(on, off)

	def pair(self, gap, speed):
		# Two loose cubes of side 2H side by side along x, a gap apart [m], the second moving towards the first [m/s].
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=E, poisson=NU))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, dt=1e-6, verletDist=0.1 * H)
		a = O.bodies.append(rdem.block((0, 0, 0), (H, H, H), mat))
		b = O.bodies.append(rdem.block((2 * H + gap, 0, 0), (H, H, H), mat))
		O.bodies[b].state.vel = Vector3(-speed, 0, 0)
		return a, b

	def testCertificateOfAGapAndContactOnTime(self):
		# Apart by g = 1e-5 m, closing at 1 m/s with Δt = 1e-6 s: the first step certifies the gap with the slack
		# g + tol - margin (tol = 1e-9 H, margin = 1e-6 (|h_A| + |h_B|) = 2√3e-6 H), reach = slack at zero travel; the
		# pair is then skipped until the second block has travelled about that far (about 10 steps), and touches in the
		# same step as without certificates.
		g, margin = 1e-5, 2 * 3**0.5 * 1e-6 * H
		onset, skipped = {}, {}
		for skip in (True, False):
			a, b = self.pair(g, 1.0)
			rdem.build.geomFunctor().skipApart = skip
			O.step()
			I = O.interactions[a, b]
			self.assertFalse(I.isReal)
			if skip:
				self.assertEqual(type(I.geom).__name__, 'RdemGap')
				self.assertAlmostEqual(I.geom.reach, g + 1e-9 * H - margin, delta=1e-15)
			else:
				self.assertIsNone(I.geom)
			for step in range(40):
				O.step()
				if O.interactions[a, b].isReal:
					break
			onset[skip], skipped[skip] = O.iter, rdem.build.geomFunctor().skippedTests
		self.assertEqual(onset[True], onset[False])
		self.assertGreater(onset[True], 10)  # the contact came after the gap had closed, not at once
		# Skipped while the second block travelled less than the slack: (g - margin)/(1 m/s · 1e-6 s) - 1 ≈ 9 steps.
		self.assertGreaterEqual(skipped[True], 8)
		self.assertLessEqual(skipped[True], 10)
		self.assertEqual(skipped[False], 0)


	def dryStackRun(self, skip):
		# A dry-stacked cube of 4³ loose 2 cm blocks on a fixed floor under gravity tilted by 45° (scripts/benchmark.py's
		# collapse, small): its edge and corner neighbours touch (overlap 0 along a face axis, no certificate), 86 % of the
		# collider's pairs.
		import math
		harness.freshScene()
		h = 0.02
		mat = O.materials.append(RdemMat(young=30e9, poisson=0.2, density=2300, frictionAngle=math.atan(0.6)))
		O.engines = rdem.engines(formulation=None, gravity=(9.81 * math.sin(math.pi / 4), 0, -9.81 * math.cos(math.pi / 4)), verletDist=0.05 * h,
		                         contactSamples=1)
		O.bodies.append(rdem.block((6 * h, 2 * h, -h / 2), (6 * h, 2 * h + h, h / 2), mat, fixed=True))
		rdem.build.blockGrid((4, 4, 4), (h, h, h), mat)
		rdem.build.geomFunctor().skipApart = skip
		rdem.run(150)
		ig2 = rdem.build.geomFunctor()
		touching = sum(1 for I in O.interactions.all() if not I.isReal and type(I.geom).__name__ == 'RdemGap' and I.geom.witness >= 0)
		state = [tuple(b.state.pos) + tuple(b.state.ori) + tuple(b.state.vel) + tuple(b.state.angVel) for b in O.bodies] + [O.dt]
		return state, ig2.witnessTests, touching, len(O.interactions.all()), sum(1 for I in O.interactions if I.isReal)

	def testTouchingPairsAreDecidedByTheirWitnessAxis(self):
		# The pairs that only touch are found apart by their witness axis alone (RdemGap.witness), with the same bits as
		# when every pair is tested in full at every step.
		on, witnessOn, touchingOn, pairs, real = self.dryStackRun(True)
		off, witnessOff, touchingOff, _, _ = self.dryStackRun(False)
		self.assertEqual(on, off)
		self.assertEqual((witnessOff, touchingOff), (0, 0))
		self.assertGreater(real, 60)  # the stack's contacts: 4·4·3 vertical ones, 16 on the floor, some sideways
		# Measured: 484 pairs, 76 real, all 408 others touching with a witness; 59 949 of their 408 × 150 tests decided by it.
		self.assertGreater(touchingOn, 0.9 * (pairs - real))
		self.assertGreater(witnessOn, 0.9 * 150 * touchingOn)


if __name__ == '__main__':
	harness.run(SkipApart)
