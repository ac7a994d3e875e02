"""The Poisson cells' run-time network (RdemCellNetwork, doc/theory.md §5.4) is made from the scene's bonds, and made again
only when they or the bodies change (RdemPoissonEngine.cellRebuilds counts it), not when contacts come and go; after a
change it gives the forces of a network made afresh.

Scene: a running-bond wall with Poisson cells between its platens (tests/yade/wall_cases.py, nu = 0.3), the collider
running at every step, every block displaced from its reference position by a random field of 1e-7 m (so that every cell
and bond carries a force) and held there (all DOFs blocked: the forces of a step are those of these positions). A loose
block, blocked as well, is moved at every step between a place beside the wall, where the collider pairs it with a wall
block, and one away from it: the interaction container changes at every step, the bonds do not.

A fresh network is the one a scene saved and loaded makes (the network is not saved: the loaded engine builds it at its
first step from the loaded bonds, with the cell coefficients of the build): the forces of one step of the running scene
and of its saved copy, at the same positions, agree to round-off (1e-12 of the largest force; they are sums of the same
terms, in the order of the bodies' and bonds' ids in both)."""
import random
import unittest
import harness
import wall_cases as wc
from yade import O, Vector3
from yade import rdem

TOL = 1e-12  # of the largest force (see above)


def wallScene():
	wall, plates = wc.homogeneousWall('running', 2, (1, 1, 1), 0.3, 2)
	ids = wall.ids + plates[0] + plates[1]
	O.engines = rdem.engines(formulation='consistent', recontact='always', dt=1e-9)
	rdem.poissonEngine().elements = 'cells'
	rdem.poissonEngine().build(ids)
	rnd = random.Random(3)
	for i in ids:
		s = O.bodies[i].state
		s.pos = s.refPos + Vector3(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-1, 1)) * 1e-7
		s.vel = s.angVel = Vector3.Zero
		s.blockedDOFs = 'xyzXYZ'
	return ids


def forces():
	return [(O.forces.f(b.id), O.forces.t(b.id)) for b in O.bodies if b]


def liftApart(blocks):
	"""Weakens every bond of `blocks` (f_t = c = 1 kPa: their springs break in tension at the move) and lifts each block
	2 + 0.1 id m above its place, apart from the wall and from each other. Returns the lifts by id."""
	lift = {i: Vector3(0, 0, 2.0 + 0.1 * i) for i in blocks}
	for i in blocks:
		for I in O.interactions.withBody(i):
			if I.isReal and I.geom.bonded:
				I.phys.tensileStrength, I.phys.cohesion = 1e3, 1e3  # [Pa]
		O.bodies[i].state.pos += lift[i]
	return lift


def largestDifference(a, b):
	scale = max(max(f.norm(), t.norm()) for f, t in a)
	return max(max((fa - fb).norm(), (ta - tb).norm()) for (fa, ta), (fb, tb) in zip(a, b)) / scale


class CellNetworkRefresh(unittest.TestCase):

	def setUp(self):
		self.ids = wallScene()
		self.engine = rdem.poissonEngine()
		self.assertGreater(self.engine.nCells, 0)
		O.step()
		self.assertEqual(self.engine.cellRebuilds, 1)

	def matchesFreshNetwork(self, msg):
		"""One step here and one of the saved and loaded scene give the same forces; the loaded one built its network."""
		O.step()
		mine = forces()
		O.saveTmp('cellRefresh')
		O.loadTmp('cellRefresh')
		O.step()
		self.assertEqual(rdem.poissonEngine().cellRebuilds, 1, msg)
		self.assertLess(largestDifference(mine, forces()), TOL, msg)

	def testContactsComeAndGo(self):
		top = max(O.bodies[i].state.pos[2] + O.bodies[i].shape.extents[2] for i in self.ids)
		near, far = Vector3(0.2, 0.06, top + 0.015), Vector3(0.2, 0.06, top + 1.0)
		loose = O.bodies.append(rdem.block(far, (0.02, 0.02, 0.02), O.materials['brick']))
		O.bodies[loose].state.blockedDOFs = 'xyzXYZ'
		O.step()
		self.assertEqual(self.engine.cellRebuilds, 2, 'a body added')
		counts = set()
		for k in range(20):
			O.bodies[loose].state.pos = near if k % 2 == 0 else far
			O.step()
			counts.add(len(O.interactions.withBody(loose)))
		self.assertGreater(len(counts), 1, 'the collider should pair the loose block with the wall and drop the pair')
		self.assertEqual(self.engine.cellRebuilds, 2, 'contacts that come and go leave the network')
		self.matchesFreshNetwork('contacts came and went')

	def testErasedBond(self):
		bonded = [I for I in O.interactions if I.isReal and I.geom.bonded and I.id1 in self.ids and I.id2 in self.ids]
		I = bonded[len(bonded) // 2]
		O.interactions.erase(I.id1, I.id2)
		O.step()
		self.assertEqual(self.engine.cellRebuilds, 2, 'a bond erased')
		self.matchesFreshNetwork('a bond erased')

	def testErasedBody(self):
		O.bodies.erase(self.ids[len(self.ids) // 2])
		O.step()
		self.assertEqual(self.engine.cellRebuilds, 2, 'a body erased')
		self.matchesFreshNetwork('a body erased')

	def testReleasedBond(self):
		"""Bonds the law releases at once (every spring broken in one step, the blocks apart) release the cells of both
		their blocks at the next step, as bonds whose springs broke one by one do, and stay in the network as zero
		terms instead of making it again: a cracking building releases bonds at nearly every step."""
		mover = self.ids[len(self.ids) // 2]
		mine = [I for I in O.interactions.withBody(mover) if I.isReal and I.geom.bonded]
		liftApart([mover])
		O.step()  # the law releases the bonds to the other wall blocks (not the one to the top platen: the lift pushes the block into it)
		released = [(I.id1, I.id2) for I in mine if not (I.isReal and I.geom.bonded)]
		self.assertGreaterEqual(len(released), 4)
		cells = {i for pair in released for i in pair}
		self.assertTrue(all(O.bodies[i].state.cellScale == 1 for i in cells), 'released in one step, from intact')
		O.step()  # the cells see the releases
		self.assertEqual([i for i in cells if O.bodies[i].state.cellScale != 0], [], 'the cells of the released bonds')
		self.assertEqual(self.engine.cellRebuilds, 1, 'a release makes no new network')
		self.matchesFreshNetwork('bonds released')

	def testManyReleasedBonds(self):
		"""Once the released bonds are a quarter of the network's and their cells have dropped, the network is made again
		without them at the next change of the container; the cells stay released (the crack scale never rises), and
		the forces are those of a fresh network."""
		bonds = [I for I in O.interactions if I.isReal and I.geom.bonded]
		movers = self.ids[:len(self.ids) // 2]
		lift = liftApart(movers)
		O.step()  # the law releases their bonds
		released = [(I.id1, I.id2) for I in bonds if not (I.isReal and I.geom.bonded)]
		self.assertGreater(4 * len(released), len(bonds), 'more than a quarter released')
		O.step()  # the collider erases them; the cells see the releases, and the network keeps them as zero terms
		cells = {i for pair in released for i in pair}
		self.assertEqual([i for i in cells if O.bodies[i].state.cellScale != 0], [], 'the cells of the released bonds')
		self.assertEqual(self.engine.cellRebuilds, 1, 'the releases unseen by the cells when the container changed')
		O.bodies[movers[0]].state.pos -= lift[movers[0]]  # back into its place: the collider pairs it with its neighbours
		O.step()
		self.assertEqual(self.engine.cellRebuilds, 2, 'a quarter released, seen by the cells')
		self.assertEqual([i for i in cells if O.bodies[i].state.cellScale != 0], [], 'the cells stay released')
		self.matchesFreshNetwork('a quarter released')

	def testNewBuild(self):
		self.engine.build(self.ids)
		O.step()
		self.assertEqual(self.engine.cellRebuilds, 2, 'a new build')
		self.matchesFreshNetwork('a new build')


if __name__ == '__main__':
	harness.run(CellNetworkRefresh)
