"""Issue #7: bad input is refused at set-up with ValueError naming the parameter and its allowed range."""
import math
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint, RdemPoissonEngine, Ig2_RdemBlock_RdemBlock_RdemGeom, Ip2_RdemMat_RdemMat_RdemPhys, RdemTimeStepper
from yade import rdem

NAN, INF = float('nan'), float('inf')


class InputValidation(unittest.TestCase):

	def refused(self, pattern, fn, *args, **kw):
		"""fn(*args, **kw) raises ValueError whose message matches pattern (the parameter name and its range)."""
		with self.assertRaisesRegex(ValueError, pattern):
			fn(*args, **kw)

	def testMaterialConstructor(self):
		for name, value, rng in (('young', 0, r'> 0'), ('young', -1e9, r'> 0'), ('young', NAN, r'> 0'), ('poisson', 0.5, r'\(-1, 0\.5\)'),
		                         ('poisson', 0.7, r'\(-1, 0\.5\)'), ('poisson', -1, r'\(-1, 0\.5\)'), ('density', 0, r'> 0'),
		                         ('tensileStrength', -1, r'>= 0'), ('cohesion', -1, r'>= 0'), ('frictionAngle', -0.1, r'\[0, pi/2\)'),
		                         ('frictionAngle', math.pi / 2, r'\[0, pi/2\)'), ('dampingNormal', -1, r'>= 0'), ('dampingShear', -1, r'>= 0')):
			self.refused(r'RdemMat\.%s = .*%s' % (name, rng), RdemMat, **{name: value})

	def testMaterialAttributeSetLater(self):
		m = RdemMat()
		for name, value in (('young', -1), ('poisson', 0.5), ('tensileStrength', -1), ('cohesion', -2)):
			with self.assertRaisesRegex(ValueError, r'RdemMat\.%s' % name):
				setattr(m, name, value)

	def testDensitySetAfterConstructionRefusedByBlock(self):
		# density belongs to YADE's Material (no hook when set later); the block, which needs it for its mass, refuses it
		m = RdemMat()
		m.density = -1
		self.refused(r'RdemMat\.density = -1.*> 0', rdem.block, (0, 0, 0), (0.01, 0.01, 0.01), m)

	def testFunctorAttributes(self):
		self.refused(r'segmentsPerEdge = 0.*>= 1', Ig2_RdemBlock_RdemBlock_RdemGeom, segmentsPerEdge=0)
		ig2 = Ig2_RdemBlock_RdemBlock_RdemGeom()
		with self.assertRaisesRegex(ValueError, r'segmentsPerEdge = -2.*>= 1'):
			ig2.segmentsPerEdge = -2  # set directly on the functor
		with self.assertRaisesRegex(ValueError, r'bondGapTolerance = -1.*>= 0'):
			Ig2_RdemBlock_RdemBlock_RdemGeom().bondGapTolerance = -1
		with self.assertRaisesRegex(ValueError, r'prefetchDistance = -2.*-1 \(automatic\), 0 \(off\) or > 0'):
			Ig2_RdemBlock_RdemBlock_RdemGeom().prefetchDistance = -2
		ip2 = Ip2_RdemMat_RdemMat_RdemPhys()
		with self.assertRaisesRegex(ValueError, r"formulation = 'concrete'.*'paper' or 'consistent'"):
			ip2.formulation = 'concrete'
		with self.assertRaisesRegex(ValueError, r"RdemPoissonEngine.elements = 'tet4'.*'auto', 'hex8' or 'cells'"):
			RdemPoissonEngine().elements = 'tet4'
		for name, bad, allowed in (('thickness', -0.01, '>= 0'), ('young', 0, '> 0'), ('poisson', 0.5, r'\(-1, 0.5\)'), ('tensileStrength', -1, '>= 0'),
		                           ('cohesion', NAN, '>= 0'), ('frictionAngle', 2, r'\[0, pi/2\)')):
			with self.assertRaisesRegex(ValueError, r'RdemJoint\.%s = .*must be .*%s' % (name, allowed)):
				setattr(RdemJoint(), name, bad)
		ts = RdemTimeStepper()
		for bad in (0, -0.5, 1.5, NAN):
			with self.assertRaisesRegex(ValueError, r'RdemTimeStepper\.safety = .*\(0, 1\]'):
				ts.safety = bad

	def testEnginesArguments(self):
		harness.freshScene()
		self.refused(r'segmentsPerEdge = 0.*>= 1', rdem.engines, segmentsPerEdge=0)
		self.refused(r"formulation = 'full'.*'consistent', 'off', 'paper'", rdem.engines, formulation='full')
		# the formulation's former keyword, poisson (Poisson's ratio everywhere else), is refused with the new name
		with self.assertRaisesRegex(TypeError, r"poisson='consistent'.*formulation=.*rdem.engines\(formulation='consistent'\)"):
			rdem.engines(poisson='consistent')
		self.refused(r'damping = 1.*\[0, 1\)', rdem.engines, damping=1)
		self.refused(r'dt = 0.*> 0', rdem.engines, dt=0)
		self.refused(r'dt = -1e-06.*> 0', rdem.engines, dt=-1e-6)
		self.refused(r'safety = 0.*\(0, 1\]', rdem.engines, safety=0)
		self.refused(r'verletDist = -0.1.*>= 0', rdem.engines, verletDist=-0.1)
		self.refused(r'gravity = .*finite', rdem.engines, gravity=(0, 0, NAN))

	def testCompressionSceneArguments(self):
		from yade.rdem.scenes import CompressionTest
		for kw, pattern in ((dict(blocksPerEdge=1), r'blocksPerEdge = 1.*>= 2'), (dict(rate=0), r'rate = 0.*> 0'),
		                    (dict(plateYoung=0.0), r'plateYoung = 0.0.*> 0'), (dict(plateYoung=NAN), r'plateYoung = nan.*finite'),
		                    (dict(platePoisson=0.5), r'platePoisson = 0.5.*\(-1, 0.5\)'), (dict(frictionCoefficient=-1), r'frictionCoefficient = -1.*>= 0')):
			harness.freshScene()
			self.refused(pattern, CompressionTest, **kw)
		harness.freshScene()
		self.refused(r"recontact = 'sometimes'", rdem.engines, recontact='sometimes')

	def testGeometryArguments(self):
		harness.freshScene()
		mat = O.materials.append(RdemMat())
		self.refused(r'halfExtents = .*> 0', rdem.block, (0, 0, 0), (0.01, 0, 0.01), mat)
		self.refused(r'counts = .*>= 1', rdem.blockGrid, (2, 0, 2), (0.02, 0.02, 0.02), mat)
		self.refused(r'sizes = .*> 0', rdem.blockGrid, (2, 2, 2), (0.02, -0.02, 0.02), mat)

	def testBondRefusesOverlappingAndNonAdjacent(self):
		harness.freshScene()
		mat = O.materials.append(RdemMat())
		O.engines = rdem.engines(formulation=None)
		a = O.bodies.append(rdem.block((0, 0, 0), (0.01, 0.01, 0.01), mat))
		b = O.bodies.append(rdem.block((0.015, 0, 0), (0.01, 0.01, 0.01), mat))  # overlaps a by 5 mm
		self.refused(r'bond: blocks %d and %d overlap by 0\.005 m' % (a, b), rdem.bond, [a, b])
		c = O.bodies.append(rdem.block((0.1, 0, 0), (0.01, 0.01, 0.01), mat))  # 8 cm away from everything
		d = O.bodies.append(rdem.block((-0.02, 0, 0), (0.01, 0.01, 0.01), mat))  # touches a face to face
		self.refused(r'bond: block %d shares no face' % c, rdem.bond, [a, d, c])
		self.assertEqual(len(O.interactions), 0)  # refused before any bond was made
		self.refused(r'tolerance = -1', rdem.bond, [a, d], tolerance=-1)
		self.assertEqual(rdem.bond([a, d]), 1)  # the adjacent pair is fine

	def testPoissonEngineRefusesNonGrid(self):
		harness.freshScene()
		mat = O.materials.append(RdemMat())
		O.engines = rdem.engines(formulation='paper')
		# running bond: the upper layer is shifted by half a block, so a lower block has two upper neighbours
		lower = rdem.blockGrid((4, 2, 1), (0.02, 0.02, 0.02), mat)
		upper = rdem.blockGrid((3, 2, 1), (0.02, 0.02, 0.02), mat, origin=(0.01, 0, 0.02))
		rdem.bond(lower + upper)
		self.refused(r'RdemPoissonEngine\.build: block \d+ has two bonded neighbours on one side', rdem.poissonEngine().build, lower + upper)
		# a row of blocks has no 2x2x2 group
		harness.freshScene()
		mat = O.materials.append(RdemMat())
		O.engines = rdem.engines(formulation='paper')
		row = rdem.blockGrid((4, 1, 1), (0.02, 0.02, 0.02), mat)
		rdem.bond(row)
		self.refused(r'no 2x2x2 group', rdem.poissonEngine().build, row)

	def twoBlocks(self):
		harness.freshScene()
		mat = O.materials.append(RdemMat())
		O.engines = rdem.engines(formulation=None, dt=1e-8)
		rdem.bond(rdem.blockGrid((2, 1, 1), (0.02, 0.02, 0.02), mat))

	def testTimeStepMustBePositive(self):
		for bad in (0.0, INF):
			self.twoBlocks()
			O.dt = bad
			# O.step() raises in this thread (ValueError); O.run(1, True) only reports it through wait()'s 40 ms poll, which
			# missed it now and then on a loaded machine
			with self.assertRaisesRegex(ValueError, r'O\.dt = .*finite and > 0'):
				O.step()
			self.assertEqual(O.iter, 0)  # refused before the first step did anything
		self.twoBlocks()
		O.dt = -1  # YADE's convention: let the time stepper choose
		O.run(1, True)
		self.assertAlmostEqual(O.dt / (0.8 * rdem.timeStepper().criticalDt), 1, delta=1e-12)

	def testTimeStepperInterval(self):
		self.twoBlocks()
		rdem.timeStepper().timeStepUpdateInterval = 0  # would divide by zero
		# O.step() in this thread: O.run(1, True) reports the error of YADE's simulation thread only if its wait() sees it,
		# which it missed now and then on a loaded machine
		with self.assertRaisesRegex((RuntimeError, ValueError), r'timeStepUpdateInterval = 0.*>= 1'):
			O.step()


if __name__ == '__main__':
	harness.run(InputValidation)
