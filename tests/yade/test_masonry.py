"""rdem.masonry.wall: a wall laid out by rdem.wall_layout becomes bodies and bonds in YADE (the layout itself is tested
without YADE in tests/python/test_wall_layout.py).

Per bond pattern (stack, running, English, Flemish; one and two wythes; interface and layer mortar; beams; an opening):
one body per layout block with the layout's box, one bond per touching pair, every brick bonded, each bond made with
the joint of its kind (bed, head, collar, beam: RdemJoint; inside a brick: none), partial faces bonded over exactly the
shared area (running bond: a brick's bed face is covered by two bonds of half its area each, so its bonds' areas add up
to the face), and every argument of wall() checked with a message naming it."""
import math
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem

BRICK, T = (0.25, 0.12, 0.055), 0.01
L3 = 3 * 0.25 + 2 * T  # three stretchers [m]
H4 = 4 * 0.055 + 3 * T  # four courses [m]


def materials():
	brick = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick'))
	joint = RdemJoint(young=2e9, poisson=0.25, tensileStrength=0.2e6, cohesion=0.3e6, frictionAngle=math.atan(0.75))
	return brick, joint


class Masonry(unittest.TestCase):

	def setUp(self):
		harness.freshScene()
		O.engines = rdem.engines(formulation='consistent', recontact=False, dt=1e-9)

	def build(self, **kw):
		brick, joint = materials()
		args = dict(brick=BRICK, joint=T, brickMaterial=brick, jointMaterial=joint)
		args.update(kw)
		return rdem.masonry.wall(**args)

	def checkWall(self, w, msg):
		lay = w.layout
		self.assertEqual(len(w.ids), len(lay.blocks), msg)
		self.assertEqual(len(O.bodies), len(lay.blocks), msg)
		# Every block where the layout put it, with its half-sizes (exact: both come from the same floats).
		for k, (lo, hi) in enumerate(lay.blocks):
			b = O.bodies[w.ids[k]]
			for d in range(3):
				self.assertAlmostEqual(b.state.pos[d], (lo[d] + hi[d]) / 2, delta=1e-15, msg=msg)
				self.assertAlmostEqual(b.shape.extents[d], (hi[d] - lo[d]) / 2, delta=1e-15, msg=msg)
		# One bond per touching pair, with the joint of its kind, over exactly the layout's shared area.
		self.assertEqual(w.nBonds, len(lay.pairs), msg)
		self.assertEqual(len(O.interactions), len(lay.pairs), msg)
		for i, j, kind, area in lay.pairs:
			I = O.interactions[w.ids[i], w.ids[j]]
			self.assertTrue(I.isReal, msg)
			joint = I.geom.joint
			if kind in ('internal', 'mortar'):
				self.assertIsNone(joint, msg)
			else:
				self.assertEqual(joint.label, kind, msg)
				self.assertEqual(joint.thickness, T if (lay.mortar == 'interface' and kind != 'beam') else 0.0, msg)
			bonded = I.geom.segArea[0] * len(I.geom.segArea)
			self.assertAlmostEqual(bonded / area, 1, delta=1e-12, msg='%s: pair %d-%d (%s)' % (msg, i, j, kind))
		# Every brick is bonded to something outside itself.
		for ids in w.bricks:
			inside = set(ids)
			self.assertTrue(any((I.id1 in inside) != (I.id2 in inside) for i in ids for I in O.bodies[i].intrs()), msg)

	def testEveryBondPattern(self):
		cases = [('stack', 0.12, 'interface', (1, 1, 1)), ('running', 0.12, 'interface', (1, 1, 1)), ('running', 0.25, 'interface', (2, 1, 2)),
		         ('running', 0.12, 'layer', (1, 1, 1)), ('english', 0.25, 'interface', (1, 1, 1)), ('english', 0.38, 'interface', (1, 1, 1)),
		         ('flemish', 0.25, 'layer', (1, 1, 1))]
		for bond, thickness, mortar, blocks in cases:
			self.setUp()
			length = L3 if bond != 'flemish' else 2.5 * (0.25 + T) - T
			w = self.build(length=length, height=H4, thickness=thickness, bond=bond, mortar=mortar, blocksPerBrick=blocks, baseBeam=0.1, topBeam=0.1)
			self.checkWall(w, '%s %g %s %s' % (bond, thickness, mortar, blocks))
			self.assertEqual(len(w.beams['base']), 1)
			self.assertEqual(len(w.courses), 4)

	def testRunningBondBedFacesAreCoveredByTwoBricks(self):
		# An interior brick of a one-wythe running-bond wall: two bonds above, two below, each half its bed face.
		w = self.build(length=L3, height=H4, thickness=0.12, bond='running')
		l, b = BRICK[0] + T, BRICK[1]
		interior = [u for u in w.bricks if len(u) == 1 and O.bodies[u[0]].shape.extents[0] > 0.12 and 0.1 < O.bodies[u[0]].state.pos[2] < 0.2 and
		            0.3 < O.bodies[u[0]].state.pos[0] < 0.5][0][0]
		beds = [I for I in O.bodies[interior].intrs() if abs((O.bodies[I.id1].state.ori * I.geom.segNormal1)[2]) > 0.99]
		self.assertEqual(len(beds), 4)
		for I in beds:
			self.assertAlmostEqual(I.geom.segArea[0] * 4 / (l / 2 * b), 1, delta=1e-12)

	def testLayerMortarHasItsOwnBlocks(self):
		w = self.build(length=L3, height=H4, thickness=0.12, bond='running', mortar='layer')
		self.assertGreater(len(w.mortar), 0)
		self.assertEqual(O.bodies[w.mortar[0]].material.label, 'mortar')
		self.assertAlmostEqual(O.bodies[w.mortar[0]].material.young, 2e9)
		self.assertTrue(all(2 * O.bodies[i].shape.extents[2] <= T + 1e-12 or 2 * O.bodies[i].shape.extents[0] <= T + 1e-12 for i in w.mortar
		                    if O.bodies[i].state.pos[1] > 0))

	def testPoissonCellsOnTheWall(self):
		w = self.build(length=L3, height=H4, thickness=0.12, bond='running', topBeam=0.1, baseBeam=0.1)
		rdem.poissonEngine().build(w.ids)
		self.assertEqual(rdem.poissonEngine().nCells, len(w.ids))

	def testArgumentsAreChecked(self):
		brick, joint = materials()
		good = dict(length=L3, height=H4, thickness=0.12, brick=BRICK, joint=T, brickMaterial=brick, jointMaterial=joint)
		bad = [('brickMaterial', None, r'brickMaterial = None: must be an RdemMat'), ('brickMaterial', joint, r'brickMaterial = .*must be an RdemMat'),
		       ('jointMaterial', None, r'jointMaterial = None: must be an RdemJoint'), ('origin', (0, 0), r'origin = .*3 finite numbers'),
		       ('mortarMaterial', brick, r"mortarMaterial is for mortar='layer'"), ('length', 1.0, r'length'), ('bond', 'herringbone', r'bond'),
		       ('blocksPerBrick', (0, 1, 1), r'blocksPerBrick'), ('openings', [(5, 0, 1, 1)], r'openings\[0\]')]
		for name, value, pattern in bad:
			args = dict(good)
			args[name] = value
			with self.assertRaisesRegex(ValueError, pattern, msg=name):
				rdem.masonry.wall(**args)
			self.assertEqual(len(O.bodies), 0, name)  # nothing appended before the arguments are checked

	def testPaperFormulationRefusesRunningBond(self):
		O.engines = rdem.engines(formulation='paper', recontact=False, dt=1e-9)
		w = self.build(length=L3, height=H4, thickness=0.25, bond='running')
		with self.assertRaisesRegex(ValueError, r"two bonded neighbours on one side.*Poisson cells.*formulation = 'consistent'"):
			rdem.poissonEngine().build(w.ids)


if __name__ == '__main__':
	harness.run(Masonry)
