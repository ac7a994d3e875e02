"""RdemInteractionLoop does not visit the pairs of blocks known apart (RdemGap) while their certificate holds or their
witness axis still separates them: runs
with RdemInteractionLoop.sleepApart on and off (off: YADE's own InteractionLoop::action) from the same saved state give
the same bits (positions, orientations, velocities, forces, torques, the time step, every energy, the functor's counters
of pairs found apart by certificate and by witness axis), also when bodies and interactions are erased, a block is moved far (the collider erases its pairs:
positions in the container change) and bodies are added while pairs sleep; and the sleepers do skip most pairs. The
same for RdemInteractionLoop.bondLane (bonds visited without YADE's dispatch) on and off."""
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemInteractionLoop, RdemSharedState
from yade import rdem


def loop():
	return next(e for e in O.engines if isinstance(e, RdemInteractionLoop))


def snapshot():
	"""Every number a step leaves (for == comparisons), and the counters of pairs found apart by certificate and witness."""
	bodies = [(tuple(b.state.pos), tuple(b.state.ori), tuple(b.state.vel), tuple(b.state.angVel), tuple(O.forces.f(b.id)), tuple(O.forces.t(b.id)))
	          for b in O.bodies if b]
	real = sorted((I.id1, I.id2) for I in O.interactions if I.isReal)
	return dict(bodies=bodies, dt=O.dt, energy=sorted(O.energy.items()), real=real, breaks=rdem.breakCounts(), iter=O.iter,
	            skipped=rdem.build.geomFunctor().skippedTests, witnessed=rdem.build.geomFunctor().witnessTests)


def cracked(name):
	"""The cracking compression of tests/yade/test_skip_apart.py (4³ blocks, weak in tension, loaded fast) with the
	automatic time step, run 100 steps (240 springs broken, most of its 752 pairs certified apart) and saved as name;
	energy tracked."""
	from yade.rdem.scenes import CompressionTest
	harness.freshScene()
	CompressionTest(blocksPerEdge=4, tensileStrength=2e6, rate=0.5, dt=None)
	O.trackEnergy = True
	rdem.run(100)
	O.saveTmp(name)


def collapse(name, n=4, h=0.02):
	"""scripts/benchmark.py's collapse of n³ loose blocks (gravity tilted by 45°, automatic time step), run 600 steps
	(gaps open between blocks that touched) and saved as name."""
	import math
	from yade.wrapper import RdemMat
	harness.freshScene()
	mat = O.materials.append(RdemMat(young=30e9, poisson=0.2, density=2300, frictionAngle=math.atan(0.6)))
	tilt = math.radians(45)
	O.engines = rdem.engines(formulation=None, gravity=(9.81 * math.sin(tilt), 0, -9.81 * math.cos(tilt)), verletDist=0.05 * h, contactSamples=1)
	O.bodies.append(rdem.block((1.5 * n * h, n * h / 2, -h / 2), (1.5 * n * h, n * h / 2 + h, h / 2), mat, fixed=True))
	rdem.build.blockGrid((n, n, n), (h, h, h), mat)
	O.trackEnergy = True
	rdem.run(600)
	O.saveTmp(name)


class SleepingPairs(unittest.TestCase):

	def continued(self, name, sleep, steps, disturb=None, lane=None):
		"""The state saved as name, run steps steps with sleepApart = sleep and bondLane = lane (None: as sleep, so that
		off is YADE's own loop; disturb(step) called before each step)."""
		O.loadTmp(name)
		loop().sleepApart = sleep
		loop().bondLane = sleep if lane is None else lane
		visits = 0
		for k in range(steps):
			if disturb:
				disturb(k)
			visits += len(O.interactions.all())
			O.step()
		return snapshot(), loop().sleptPairs, visits

	def assertSameBits(self, a, b):
		self.assertEqual(a['iter'], b['iter'])
		self.assertEqual(a['dt'], b['dt'])
		self.assertEqual(a['real'], b['real'])
		self.assertEqual(a['breaks'], b['breaks'])
		self.assertEqual(a['energy'], b['energy'])
		self.assertEqual(len(a['bodies']), len(b['bodies']))
		for k, (x, y) in enumerate(zip(a['bodies'], b['bodies'])):
			self.assertEqual(x, y, 'body %d: position, orientation, velocity, angular velocity, force or torque differ' % k)
		# every pair found apart is counted once, whether the functor or the loop found its certificate holds or its
		# witness axis separates the blocks
		self.assertEqual(a['skipped'], b['skipped'])
		self.assertEqual(a['witnessed'], b['witnessed'])

	def testCrackedCubeSameBits(self):
		cracked('cube')
		on, slept, visits = self.continued('cube', True, 100)
		off, sleptOff, _ = self.continued('cube', False, 100)
		self.assertGreater(sum(on['breaks']), 0)  # springs broke (rdem.breakCounts)
		self.assertGreater(len(on['energy']), 3)
		self.assertSameBits(on, off)
		self.assertEqual(sleptOff, 0)  # YADE's loop
		# The certificates are not saved: the first step after the load tests every pair, the next ones skip the pairs
		# certified apart without a visit. Measured: 10.7 % of the 75 200 pair-visits, all of the pairs found apart by
		# certificate.
		self.assertGreater(slept, 0.08 * visits)
		# every certified pair after the first step is skipped by the loop; the rest of its skips are pairs that only touch,
		# decided by their witness axis (counted in witnessTests, which also counts the functor's own witness tests)
		self.assertGreaterEqual(slept, on['skipped'])
		self.assertLessEqual(slept, on['skipped'] + on['witnessed'])

	def testCollapseSameBits(self):
		collapse('collapse')
		on, slept, visits = self.continued('collapse', True, 100)
		off, _, _ = self.continued('collapse', False, 100)
		self.assertSameBits(on, off)
		print('collapse: %d of %d pair-visits skipped; %d by certificate, %d found apart by witness' % (slept, visits, on['skipped'], on['witnessed']))
		# Loose blocks touching along edges and corners have no certificate but a witness axis (RdemGap.witness), those
		# that parted have a certificate; both sleep.
		self.assertGreater(slept, 0.02 * visits)

	def testBondLaneSameBits(self):
		"""The bonds visited without YADE's dispatch (bondLane) against through it, the sleepers off in both: the cracking
		cube (paper's springs and hexahedra, springs breaking, contacts) and a running-bond wall with Poisson cells (the
		offset correction of bonds between blocks of different lengths) vibrating from random velocities."""
		cracked('cube')
		lane, _, _ = self.continued('cube', False, 100, lane=True)
		dispatch, _, _ = self.continued('cube', False, 100, lane=False)
		self.assertGreater(sum(lane['breaks']), 0)
		self.assertSameBits(lane, dispatch)
		import random
		import wall_cases as wc
		wall, plates = wc.homogeneousWall('running', 2, (1, 1, 1), 0.3, 2)
		rdem.poissonEngine().elements = 'cells'
		rdem.poissonEngine().build(wall.ids + plates[0] + plates[1])
		rnd = random.Random(5)
		for b in O.bodies:
			b.state.vel = Vector3(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-1, 1)) * 0.01
		O.trackEnergy = True
		rdem.run(20)
		self.assertTrue(any(I.phys.offsetCorrection for I in O.interactions if I.isReal and I.geom.bonded))
		O.saveTmp('cells')
		lane, _, _ = self.continued('cells', False, 100, lane=True)
		dispatch, _, _ = self.continued('cells', False, 100, lane=False)
		self.assertSameBits(lane, dispatch)

	def testContainerChangesWhileSleeping(self):
		# A body erased (its interactions erased: the container moves its last interaction into the place of each), a block
		# moved far (the collider erases its pairs), a body added (the bodies' record restarts): the same bits, the same
		# pairs found apart by certificate.
		cracked('changes')
		marks = []

		def disturb(k):
			if k == 10:
				O.bodies.erase(21)
			elif k == 30:
				O.bodies[50].state.pos += Vector3(1, 0, 0)
			elif k == 50:
				O.bodies.append(rdem.block((2, 2, 2), (0.01, 0.01, 0.01), O.materials[0]))
			if k in (9, 29, 49):
				marks.append(loop().sleptPairs)

		on, slept, _ = self.continued('changes', True, 70, disturb)
		sleptMarks = marks + [slept]
		off, _, _ = self.continued('changes', False, 70, disturb)
		self.assertSameBits(on, off)
		self.assertEqual(len(on['bodies']), 64 + 2 * 16 - 1 + 1)  # the blocks, the two platens' blocks, -1 erased, +1 added
		# pairs slept between the changes and after the last one
		self.assertTrue(all(b > a for a, b in zip(sleptMarks, sleptMarks[1:])), sleptMarks)

	def testPairsResetInPlace(self):
		# O.interactions.erase from Python resets an interaction in place (InteractionContainer::requestErase): the loop,
		# which does not look at a sleeping pair, tests it again when its certificate runs out, not at once. The certificate
		# proves the blocks apart, so the bits are the same; the counts of pairs then certified or decided by their witness axis
		# differ (RdemInteractionLoop's docstring).
		cracked('reset')

		def disturb(k):
			if k == 10:  # a few bonds of a block released
				for I in [I for I in O.interactions if I.isReal and 37 in (I.id1, I.id2)][:3]:
					O.interactions.erase(I.id1, I.id2)
			elif k == 20:  # the pairs found apart of a block reset while they sleep
				for I in [I for I in O.interactions.all() if not I.isReal and 42 in (I.id1, I.id2)]:
					O.interactions.erase(I.id1, I.id2)

		on, slept, _ = self.continued('reset', True, 40, disturb)
		off, _, _ = self.continued('reset', False, 40, disturb)
		on['skipped'] = off['skipped'] = on['witnessed'] = off['witnessed'] = None
		self.assertSameBits(on, off)
		self.assertGreater(slept, 0)

	def testSkipApartTurnedOff(self):
		# Ig2_RdemBlock_RdemBlock_RdemGeom.skipApart turned off while pairs sleep: the functor then makes no witness test
		# (nor certificates), so the loop wakes its witness sleepers: the same bits and the same counts of pairs found
		# apart by certificate and by witness as YADE's loop.
		collapse('skipoff')

		def disturb(k):
			if k == 20:
				rdem.build.geomFunctor().skipApart = False

		on, _, _ = self.continued('skipoff', True, 40, disturb)
		off, _, _ = self.continued('skipoff', False, 40, disturb)
		self.assertGreater(on['witnessed'], 0)  # witness tests before the switch
		self.assertSameBits(on, off)

	def testSharedStateChecked(self):
		# The loop's RdemSharedState must be the geometry functor's (its travel decides the certificates): another one is
		# refused at the first step, as for the plugin's other engines.
		cracked('shared')
		O.loadTmp('shared')
		loop().shared = RdemSharedState()
		with self.assertRaisesRegex(RuntimeError, 'holds another RdemSharedState'):
			O.step()
		O.loadTmp('shared')
		loop().shared = None  # takes the law's: the one that counted the breaks (a new one counts none)
		rdem.run(5)
		self.assertGreater(loop().shared.tensionBreaks + loop().shared.shearBreaks, 0)
		self.assertEqual((loop().shared.tensionBreaks, loop().shared.shearBreaks), rdem.breakCounts())
		self.assertGreater(loop().sleptPairs, 0)


if __name__ == '__main__':
	harness.run(SleepingPairs)
