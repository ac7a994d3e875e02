"""Deferred forces (Law2_RdemGeom_RdemPhys_FaceSprings.deferForces, summed per body by RdemForceAssembler in a fixed
order) against forces added directly to YADE's ForceContainer: the same cracking scene gives the same results to
round-off; and a law that defers its forces with no assembler to apply them is refused with a message."""
import unittest
import harness
from yade import O
from yade.wrapper import RdemForceAssembler
import rdem
from rdem.scenes import CompressionTest

STEPS = 3000  # the 4x4x4 cube at 0.4 m/s: the first springs break at about step 2000 (asserted below)


def compressedCube(defer):
	harness.freshScene()
	test = CompressionTest(blocksPerEdge=4, rate=0.4, dt=2e-7)
	rdem.law().deferForces = defer
	if not defer:
		O.engines = [e for e in O.engines if not isinstance(e, RdemForceAssembler)]
	return test


class DeferredForces(unittest.TestCase):

	def testSameCrackingRun(self):
		runs = []
		for defer in (True, False):
			test = compressedCube(defer)
			O.run(STEPS, True)
			runs.append((test.stress(), sum(rdem.breakCounts()), [O.bodies[i].state.pos for i in test.ids]))
		(s1, b1, x1), (s2, b2, x2) = runs
		self.assertGreater(b1, 0, 'the run must crack to test the cracked phase')
		self.assertEqual(b1, b2)
		# Summation order differs (per body by id vs interaction order): round-off, 1e-16 relative per sum, grows through
		# the steps and the breaks by a few orders of magnitude: 1e-9 of the stress, 1e-12 m of positions (blocks 5 cm).
		self.assertAlmostEqual(s1 / s2, 1, delta=1e-9)
		self.assertLess(max((a - b).norm() for a, b in zip(x1, x2)), 1e-12)

	def testRefusedWithoutAssembler(self):
		compressedCube(True)
		O.engines = [e for e in O.engines if not isinstance(e, RdemForceAssembler)]
		with self.assertRaises(Exception) as cm:
			O.step()
		self.assertIn('RdemForceAssembler', str(cm.exception))
		self.assertIn('deferForces', str(cm.exception))


if __name__ == '__main__':
	harness.run(DeferredForces)
