"""rdem.masonry.building: a building of rdem.building_layout as a scene (the layout's own tests: tests/python/test_building_layout.py).

* the blocks are where the layout puts them, every touching pair of a bonded kind is bonded (corners and T-junctions
  included), joists without ties are not, loads add their mass;
* a one-room, one-storey house (four one-wythe walls bonded at the corners, a door and a window with lintels, an RC slab
  roof with a load) stands under gravity: the base beam carries the weight (the vertical reactions sum to the weight to
  1e-3, the residual of the damped settling) and no spring breaks;
* a house with timber joists resting on their seats by friction (no ties) stands: the reaction equals the weight to
  3e-3 and the joists stay on their seats (micrometres);
* arguments checked with messages naming them."""
import math
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem

Q, C, T = 0.065, 0.065, 0.01  # quarter module (l + t)/4, course h + t and joint of 250x120x55 mm bricks [m]


def materials():
	brick = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick'))
	joint = RdemJoint(young=2e9, poisson=0.25, tensileStrength=0.2e6, cohesion=0.3e6, frictionAngle=math.atan(0.75))
	return brick, joint


def house(**kw):
	"""1.55 x 1.03 m outside, 12 courses (0.77 m), a door in the front wall and a window in the back wall."""
	brick, joint = materials()
	args = dict(plan=(24 * Q - T, 16 * Q - T), storeys=[12 * C - T], brickMaterial=brick, jointMaterial=joint,
	            openings=[('front', 0, 8 * Q - T / 2, 0.0, 8 * Q, 8 * C - T / 2), ('back', 0, 8 * Q - T / 2, 4 * C - T / 2, 8 * Q, 4 * C)], floors='slab',
	            roofLoad=150.0, baseHeight=0.1)
	args.update(kw)
	return rdem.masonry.building(**args)


def settle(b, steps, damping=0.5):
	"""Fix the base and run ``steps`` steps with Cundall's damping; returns the vertical reaction of the base beam on the
	house [N] (the opposite of the forces the house puts on it, upward positive)."""
	b.fixBase()
	rdem.newtonIntegrator().damping = damping
	O.dt = -1
	rdem.run(steps)
	return -sum(O.forces.f(i)[2] for i in b.base)


class Building(unittest.TestCase):

	def setUp(self):
		harness.freshScene()
		O.engines = rdem.engines(formulation=None, recontact=True, contactSamples=1, gravity=(0, 0, -9.81))

	def testBlocksAndBonds(self):
		b = house()
		lay = b.layout
		self.assertEqual(len(b.ids), len(lay.blocks))
		for k in (0, len(lay.blocks) // 2, len(lay.blocks) - 1):
			lo, hi = lay.blocks[k]
			self.assertLess((O.bodies[b.ids[k]].state.pos - Vector3(*((lo[d] + hi[d]) / 2 for d in range(3)))).norm(), 1e-12)
		bonded = [p for p in lay.pairs if p[2] not in ('base', 'joist')]
		self.assertEqual(b.nBonds, len(bonded))
		self.assertEqual(len([i for i in O.interactions if i.isReal]), len(bonded))
		corner = [p for p in lay.pairs if p[2] in ('bed', 'head') and len(set(lay.pairWalls(p))) == 2]
		self.assertEqual(sum(1 for p in corner if p[2] == 'head'), 4 * 12)  # per corner and course, the butting brick's end
		self.assertGreaterEqual(sum(1 for p in corner if p[2] == 'bed'), 4 * 11)  # bed joints across every corner
		roof = sum(O.bodies[i].state.mass for i in b.slabs[0])
		slabVolume = sum(O.bodies[i].shape.extents[0] * O.bodies[i].shape.extents[1] * O.bodies[i].shape.extents[2] * 8 for i in b.slabs[0])
		self.assertAlmostEqual(roof, 2500 * slabVolume + 150.0 * (24 * Q - T) * (16 * Q - T), delta=1e-9 * roof)

	def testStandsUnderGravity(self):
		b = house()
		weight = b.weight()
		reaction = settle(b, 4000)
		self.assertAlmostEqual(reaction / weight, 1.0, delta=1e-3)
		self.assertEqual(sum(rdem.breakCounts()), 0)
		top = max(O.bodies[i].state.refPos[2] - O.bodies[i].state.pos[2] for i in b.slabs[0])
		self.assertLess(top, 1e-4)  # the roof settles by the joints' elastic strain only (tens of micrometres)

	def testJoistsRestOnTheirSeats(self):
		b = house(storeys=[9 * C - T, 6 * C - T], floors=['joists', 'slab'], openings=[], floorLoad=100.0, joistSection=(0.1, 3 * C))
		self.assertGreater(len(b.joists[0]), 0)
		self.assertNotIn('joist', b.jointOf)
		reaction = settle(b, 8000)
		# the joists rattle on their contact springs as the floor settles: the reaction swings by 2 % of the weight after
		# 4000 steps and by less than 0.2 % after 7000 (damped); 3e-3 leaves room for that residual
		self.assertAlmostEqual(reaction / b.weight(), 1.0, delta=3e-3)
		for i in b.joists[0]:
			self.assertLess((O.bodies[i].state.pos - O.bodies[i].state.refPos).norm(), 1e-4)

	def testArguments(self):
		brick, joint = materials()
		with self.assertRaisesRegex(ValueError, r'jointMaterial = None: must be an RdemJoint'):
			rdem.masonry.building((1.55, 1.03), [0.77], brick, None)
		with self.assertRaisesRegex(ValueError, r'brickMaterial = None: must be an RdemMat'):
			rdem.masonry.building((1.55, 1.03), [0.77], None, joint)
		with self.assertRaisesRegex(ValueError, r'ties = 1: must be True or False'):
			house(ties=1)
		with self.assertRaisesRegex(ValueError, r'origin = .*3 finite numbers'):
			house(origin=(0, 0))
		with self.assertRaisesRegex(ValueError, r'storeys\[0\] = 0.8: must be'):
			house(storeys=[0.8])


if __name__ == '__main__':
	harness.run(Building)
