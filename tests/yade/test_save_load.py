"""Issue #7: nothing is lost on save and reload. A compression scene saved mid-run (springs partly broken, a sampled
contact, Poisson elements partly released) and reloaded continues bit for bit as the uninterrupted run
(one thread, as CTest runs it: OMP_NUM_THREADS=1)."""
import os
import tempfile
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemGeom, RdemPhys, NewtonIntegrator
import rdem
from rdem.scenes import CompressionTest

AFTER = 300  # steps run after the save, by both runs


def snapshot():
	"""Everything that must agree: body states, per-segment state, forces, energies, counters, Poisson scales."""
	bodies = [(tuple(b.state.pos), tuple(b.state.vel), tuple(b.state.angVel), tuple(b.state.angMom), tuple(b.state.ori[k] for k in range(4)))
	          for b in O.bodies]
	inter = sorted((I.id1, I.id2, tuple(I.phys.segState), tuple(tuple(v) for v in I.phys.segShear), tuple(I.phys.segSigma), tuple(I.phys.force))
	               for I in O.interactions if isinstance(I.phys, RdemPhys))
	energy = sorted(O.energy.items())
	return dict(bodies=bodies, inter=inter, energy=energy, breaks=rdem.breakCounts(), scales=tuple(rdem.poissonEngine().elementScales()),
	            iter=O.iter, time=O.time, dt=O.dt)


class SaveLoad(unittest.TestCase):

	def scene(self, formulation):
		harness.freshScene()
		# 4x4x4 cube at 0.1 m/s: the first cracks come after ~850 steps. Beside it, a loose block rests on a fixed one under
		# gravity: a sampled contact (collider, dashpot, friction history) that lasts through the save.
		test = CompressionTest(blocksPerEdge=4, rate=0.1, formulation=formulation, corotational=formulation == 'consistent')
		next(e for e in O.engines if isinstance(e, NewtonIntegrator)).gravity = Vector3(0, 0, -9.81)
		floor = O.bodies.append(rdem.block((0.4, 0.1, 0.01), (0.01, 0.01, 0.01), test.material, fixed=True))
		self.loose = O.bodies.append(rdem.block((0.4, 0.1, 0.03), (0.01, 0.01, 0.01), test.material))
		O.trackEnergy = True
		while O.iter < 5000 and not self.partlyBroken():
			rdem.run(50)
		rdem.run(137)  # an arbitrary step, not at a multiple of the time stepper's interval

	def partlyBroken(self):
		"""Bonds with some springs broken, some intact."""
		return sum(1 for I in O.interactions if isinstance(I.phys, RdemPhys) and 0 < I.phys.nIntact() < len(I.phys.segState))

	def sampledContacts(self):
		"""Contacts of blocks that are not bonded, with contact points this step (sampled, or a face-to-face patch)."""
		return sum(1 for I in O.interactions if isinstance(I.geom, RdemGeom) and not I.geom.segArea and (I.geom.sampleKey or I.geom.patchAreas))

	def roundTrip(self, formulation, ext):
		self.scene(formulation)
		# what the saved state holds: broken springs, broken segments in contact, released elements
		self.assertGreater(self.partlyBroken(), 0)
		self.assertGreater(self.sampledContacts(), 0)
		self.assertGreater(len(O.bodies[self.loose].intrs()), 0)
		self.assertLess(min(rdem.poissonEngine().elementScales()), 1)
		path = os.path.join(tempfile.mkdtemp(prefix='rdem-saveload-'), 'scene' + ext)
		O.save(path)
		rdem.run(AFTER)
		straight = snapshot()
		O.load(path)
		rdem.run(AFTER)
		reloaded = snapshot()
		for key in straight:
			if key == 'energy':
				continue
			self.assertEqual(straight[key], reloaded[key], '%s differs after %s reload (%s)' % (key, ext, formulation))  # ==, bit for bit
		# Cumulated energies (dashpot, friction) are sums over interactions in container order, which O.load changes
		# (doc of RdemForceAssembler): they may differ in the last bit of the sum, 1e-16 relative per step, nothing else.
		for (name, a), (name2, b) in zip(straight['energy'], reloaded['energy']):
			self.assertEqual(name, name2)
			self.assertAlmostEqual(a, b, delta=1e-12 * max(abs(a), 1e-30), msg=name)
		os.remove(path)

	def testPaperBinary(self):
		self.roundTrip('paper', '.yade.gz')

	def testConsistentCorotationalXml(self):
		self.roundTrip('consistent', '.xml.bz2')


if __name__ == '__main__':
	harness.run(SaveLoad)
