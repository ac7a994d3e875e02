"""Issue #25: the plugin's engines share one RdemSharedState (the crack state and what else they share), handed by
rdem.engines() or taken from the law at the first step; the engine list is checked then (and whenever it changes),
with an error naming the engine that is out of place or holds another state."""
import os
import tempfile
import unittest
import harness
from yade import O
from yade.wrapper import (RdemSharedState, RdemContactGate, RdemTimeStepper, RdemForceAssembler, InsertionSortCollider, InteractionLoop,
                          ForceResetter, NewtonIntegrator)
import rdem
from rdem.scenes import CompressionTest


def crackedCube():
	harness.freshScene()
	test = CompressionTest(blocksPerEdge=4, rate=0.4, dt=2e-7)
	return test


def engine(cls):
	return next(e for e in O.engines if isinstance(e, cls))


class SharedState(unittest.TestCase):

	def testOneStateCountsTheCracks(self):
		crackedCube()
		shared = engine(RdemContactGate).shared
		self.assertIsInstance(shared, RdemSharedState)
		rdem.run(2400)  # the first springs break at step 2100-2200 (test_deferred_forces)
		self.assertGreater(shared.tensionBreaks, 0)
		# every engine sees the law's count: the gate opened on it, the law reports it
		self.assertEqual(rdem.breakCounts(), (shared.tensionBreaks, shared.shearBreaks))
		self.assertEqual(engine(RdemContactGate).reason, 'a restoring spring broke')
		path = os.path.join(tempfile.mkdtemp(prefix='rdem-shared-'), 'scene.yade.gz')
		O.save(path)
		O.load(path)
		self.assertEqual(rdem.breakCounts(), (engine(RdemTimeStepper).shared.tensionBreaks, engine(RdemTimeStepper).shared.shearBreaks))
		rdem.run(10)
		self.assertEqual(rdem.breakCounts(), (engine(RdemForceAssembler).shared.tensionBreaks, engine(RdemForceAssembler).shared.shearBreaks))
		os.remove(path)

	def testHandBuiltListTakesTheLawsState(self):
		crackedCube()
		for e in O.engines:
			if isinstance(e, (RdemContactGate, RdemTimeStepper, RdemForceAssembler)):
				e.shared = None
		rdem.run(1)
		for cls in (RdemContactGate, RdemTimeStepper, RdemForceAssembler):
			self.assertIsNotNone(engine(cls).shared, cls.__name__)
		rdem.run(2400)
		self.assertEqual(rdem.breakCounts(), (engine(RdemTimeStepper).shared.tensionBreaks, engine(RdemTimeStepper).shared.shearBreaks))
		self.assertGreater(sum(rdem.breakCounts()), 0)

	def testAnotherStateRefused(self):
		crackedCube()
		engine(RdemTimeStepper).shared = RdemSharedState()
		with self.assertRaisesRegex(RuntimeError, r'RdemTimeStepper \(in O.engines\[\d+\]\) holds another RdemSharedState'):
			O.step()
		self.assertEqual(O.iter, 0)

	def testGateAfterColliderRefused(self):
		crackedCube()
		gate, collider = engine(RdemContactGate), engine(InsertionSortCollider)
		O.engines = [e for e in O.engines if e is not gate and e is not collider][:1] + [collider, gate] + \
		            [e for e in O.engines if e is not gate and e is not collider][1:]
		with self.assertRaisesRegex(RuntimeError, r'RdemContactGate \(O.engines\[2\]\) must come before the collider \(O.engines\[1\]\)'):
			O.step()

	def testCheckedAgainWhenTheListChanges(self):
		crackedCube()
		rdem.run(5)
		O.engines = [e for e in O.engines if not isinstance(e, RdemForceAssembler)]
		with self.assertRaisesRegex(RuntimeError, 'no RdemForceAssembler follows the InteractionLoop'):
			O.step()


if __name__ == '__main__':
	harness.run(SharedState)
