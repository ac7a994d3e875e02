"""The plugin is loaded by the launcher: its classes are registered in yade.wrapper and a two-block scene steps."""
import unittest
import harness
import yade
from yade import O
from yade import rdem

CLASSES = ('RdemMat', 'RdemBlock', 'RdemGeom', 'RdemPhys', 'Ig2_RdemBlock_RdemBlock_RdemGeom', 'Ip2_RdemMat_RdemMat_RdemPhys',
           'Law2_RdemGeom_RdemPhys_FaceSprings', 'RdemPoissonEngine', 'RdemTimeStepper', 'RdemForceAssembler', 'RdemFiniteGuard')


class Smoke(unittest.TestCase):

	def testClassesRegistered(self):
		for name in CLASSES:
			self.assertTrue(hasattr(yade.wrapper, name), name)
		self.assertTrue(set(CLASSES) <= set(O.plugins()))

	def testTwoBlocksStep(self):
		harness.freshScene()
		mat = O.materials.append(yade.wrapper.RdemMat())
		O.engines = rdem.engines()
		ids = rdem.blockGrid((2, 1, 1), (0.02, 0.02, 0.02), mat)
		self.assertEqual(rdem.bond(ids), 1)
		O.bodies[ids[1]].state.vel = yade.Vector3(1e-3, 0, 0)
		rdem.run(10)
		self.assertEqual(O.iter, 10)
		self.assertLess(O.bodies[ids[1]].state.vel[0], 1e-3)  # the bond pulls it back (decelerates)
		self.assertEqual(len(O.interactions[ids[0], ids[1]].phys.segState), 4)  # 2x2 springs on the shared face

	def testInvalidInputRefused(self):
		with self.assertRaisesRegex(ValueError, 'young'):
			yade.wrapper.RdemMat(young=-1)
		with self.assertRaisesRegex(ValueError, 'poisson'):
			yade.wrapper.RdemMat(poisson=0.5)
		with self.assertRaisesRegex(ValueError, 'segmentsPerEdge'):
			yade.wrapper.Ig2_RdemBlock_RdemBlock_RdemGeom(segmentsPerEdge=0)
		with self.assertRaisesRegex(ValueError, 'segmentsPerEdge'):
			rdem.engines(segmentsPerEdge=0)


if __name__ == '__main__':
	harness.run(Smoke)
