"""Contact detection on demand (RdemContactGate): the collider stays dead while new contacts are impossible, and runs
from the step after the first broken spring, or from the start when a free block or a second assembly exists."""
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemContactGate, InsertionSortCollider
from yade import rdem

E, NU, H = 30e9, 0.2, 0.01


class ContactGate(unittest.TestCase):

	def scene(self, ft=float('inf'), recontact=True):
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=E, poisson=NU, tensileStrength=ft))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=recontact, dt=1e-8)
		return mat

	def gate(self):
		return rdem.build.contactGate()

	def collider(self):
		return rdem.collider()

	def testClosedForOneIntactAssembly(self):
		mat = self.scene()
		rdem.bond(rdem.blockGrid((3, 3, 3), (2 * H, ) * 3, mat))
		nBonds = len(O.interactions)
		rdem.run(20)
		self.assertFalse(self.gate().open)
		self.assertTrue(self.collider().dead)
		self.assertEqual(len(O.interactions), nBonds)  # no potential interaction was ever made: the collider never ran

	def testOpensAtFirstBreak(self):
		# A bonded pair pulled apart: the spring breaks in some step; the gate opens in the next one and the collider runs.
		mat = self.scene(ft=1e6)
		ids = rdem.blockGrid((2, 1, 1), (2 * H, ) * 3, mat)
		rdem.bond(ids)
		O.bodies[ids[0]].state.blockedDOFs = 'xyzXYZ'
		O.bodies[ids[1]].state.vel = Vector3(1, 0, 0)  # kinetic energy 9 mJ, spring energy at f_t 0.13 mJ
		law = rdem.law()
		for step in range(2000):
			O.step()
			if law.tensionBreaks > 0:
				break
		self.assertGreater(law.tensionBreaks, 0)
		self.assertFalse(self.gate().open)  # the break happened after the gate of this step
		O.step()
		self.assertTrue(self.gate().open)
		self.assertEqual(self.gate().reason, 'a restoring spring broke')
		self.assertFalse(self.collider().dead)

	def testOpenForFreeBlock(self):
		mat = self.scene()
		rdem.bond(rdem.blockGrid((2, 2, 1), (2 * H, ) * 3, mat))
		O.bodies.append(rdem.block((0, 0, 0.1), (H, H, H), mat))
		O.step()
		self.assertTrue(self.gate().open)
		self.assertIn('has no bond', self.gate().reason)
		self.assertFalse(self.collider().dead)

	def testOpenForTwoAssemblies(self):
		mat = self.scene()
		rdem.bond(rdem.blockGrid((2, 1, 1), (2 * H, ) * 3, mat))
		rdem.bond(rdem.blockGrid((2, 1, 1), (2 * H, ) * 3, mat, origin=(0, 0, 0.1)))
		O.step()
		self.assertIn('two assemblies', self.gate().reason)

	def testOpensWhenBlockAddedMidRun(self):
		mat = self.scene()
		rdem.bond(rdem.blockGrid((2, 1, 1), (2 * H, ) * 3, mat))
		rdem.run(5)
		self.assertFalse(self.gate().open)
		O.bodies.append(rdem.block((0, 0, 0.1), (H, H, H), mat))
		O.step()
		self.assertTrue(self.gate().open)

	def testForcedOpen(self):
		mat = self.scene()
		rdem.bond(rdem.blockGrid((2, 1, 1), (2 * H, ) * 3, mat))
		self.gate().open = True
		O.step()
		self.assertFalse(self.collider().dead)
		self.assertEqual(self.gate().reason, 'opened by the user')

	def testAlwaysHasNoGate(self):
		self.scene(recontact='always')
		self.assertFalse(any(isinstance(e, RdemContactGate) for e in O.engines))
		self.assertFalse(self.collider().dead)
		with self.assertRaisesRegex(ValueError, 'recontact'):
			rdem.engines(recontact='sometimes')


if __name__ == '__main__':
	harness.run(ContactGate)
