"""The plugin is loaded by the launcher: its classes are registered in yade.wrapper and a two-block scene steps."""
import math
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
		v0 = 1e-3
		O.bodies[ids[1]].state.vel = yade.Vector3(v0, 0, 0)
		rdem.run(10)
		self.assertEqual(O.iter, 10)
		# Two free 2 cm cubes bonded face to face, the second pushed away at v0: the centre of mass moves at v0/2, the
		# opening oscillates at omega^2 = 2K/m, K = kbar_n A, kbar_n = M/(l_A + l_B), M = E/(1 - nu^2) (eqs. 11-12, the
		# paper's springs; RdemMat's defaults E = 30 GPa, nu = 0.2, rho = 2300). Leapfrog from a zero opening with the
		# velocity v0 at t = -dt/2 gives the relative velocity v0 cos((n + 1/2) W dt) / cos(W dt/2) after n + 1 steps,
		# sin(W dt/2) = omega dt/2: here n = 9. Exact up to round-off (no rotation: the push is along the bond's axis).
		mat = O.materials[mat]
		m = O.bodies[ids[1]].state.mass
		K = mat.young / (1 - mat.poisson**2) / 0.02 * 0.02**2
		W = 2 * math.asin(math.sqrt(2 * K / m) * O.dt / 2) / O.dt
		expected = v0 / 2 + v0 / 2 * math.cos(9.5 * W * O.dt) / math.cos(W * O.dt / 2)
		self.assertAlmostEqual(O.bodies[ids[1]].state.vel[0] / expected, 1, delta=1e-9)
		self.assertAlmostEqual(O.bodies[ids[0]].state.vel[0] + O.bodies[ids[1]].state.vel[0], v0, delta=1e-9 * v0)  # momentum is conserved
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
