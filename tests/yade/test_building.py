"""rdem.earthquake.building: a one-storey box of four brick walls (rdem.masonry.wall, the side walls turned by 90° about
z with their bonds), butt-jointed at the corners, on a base slab and under a roof slab:

* every block where it belongs: front and back walls along x at y in [0, t] and [W - t, W], side walls along y between
  them at x in [0, t] and [L - t, L]; the blocks' bonds, which live in their own frames, survive the turn (a settled
  building under gravity sags by the elastic amount only, m g H / (E A), micrometres);
* one corner bond per course and corner (running bond: each end of a side wall meets one brick of the front or back
  wall in every course), one slab bond per bottom and per top block, every block connected to the base;
* arguments checked with messages naming them."""
import math
import unittest
import harness
from yade import O
from yade.wrapper import RdemMat, RdemJoint
import rdem

BRICK, T = (0.25, 0.12, 0.055), 0.01
L, W, H = 4 * 0.26 - T, 2 * 0.26 - T + 2 * 0.12, 6 * 0.065 - T  # front: 4 stretchers, sides: 2, six courses [m]


def make(**kw):
	brick = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick'))
	joint = RdemJoint(young=2e9, poisson=0.25, tensileStrength=0.2e6, cohesion=0.3e6, frictionAngle=math.atan(0.75))
	args = dict(length=L, width=W, height=H, brickMaterial=brick, jointMaterial=joint, brick=BRICK, joint=T)
	args.update(kw)
	return rdem.earthquake.building(**args)


class Building(unittest.TestCase):

	def setUp(self):
		harness.freshScene()
		O.engines = rdem.engines(poisson=None, recontact=False, gravity=(0, 0, -9.81))

	def testLayoutAndBonds(self):
		b = make(openings={'front': [(0.255, 0, 0.52, 4 * 0.065)]})
		t = 0.12
		for name, (xlo, xhi, ylo, yhi) in (('front', (0, L, 0, t)), ('back', (0, L, W - t, W)), ('left', (0, t, t, W - t)), ('right', (L - t, L, t, W - t))):
			for i in b.walls[name].ids:
				lo, hi = rdem.earthquake._box(i)
				self.assertTrue(xlo - 1e-12 <= lo[0] and hi[0] <= xhi + 1e-12 and ylo - 1e-12 <= lo[1] and hi[1] <= yhi + 1e-12, '%s: block %d' % (name, i))
		courses = len(b.walls['front'].courses)
		self.assertEqual(courses, 6)
		self.assertEqual(b.corners, 4 * courses)
		self.assertEqual(len(b.ids), sum(len(w.ids) for w in b.walls.values()) + 2)
		bottom = sum(len(w.courses[0]) for w in b.walls.values())
		top = sum(len(w.courses[-1]) for w in b.walls.values())
		self.assertEqual(len([i for i in O.interactions if b.base[0] in (i.id1, i.id2)]), bottom)
		self.assertEqual(len([i for i in O.interactions if b.slab[0] in (i.id1, i.id2)]), top)
		# the door, two stretchers wide and four courses tall: 2 stretchers out of each of courses 0 and 2, and in courses 1
		# and 3 one out and two cut to bats (the back wall: 4 stretchers in even courses, 3 and two half bats in odd ones)
		self.assertEqual((len(b.walls['back'].ids), len(b.walls['front'].ids)), (27, 27 - 2 * 2 - 2 * 1))
		reached, frontier = set(b.base), list(b.base)
		neighbours = {}
		for i in O.interactions:
			neighbours.setdefault(i.id1, []).append(i.id2)
			neighbours.setdefault(i.id2, []).append(i.id1)
		while frontier:
			for j in neighbours.get(frontier.pop(), []):
				if j not in reached:
					reached.add(j)
					frontier.append(j)
		self.assertEqual(reached, set(b.ids))

	def testBondsSurviveTheTurn(self):
		b = make()
		O.bodies[b.base[0]].state.blockedDOFs = 'xyzXYZ'
		rdem.newtonIntegrator().damping = 0.5
		rdem.run(3000)
		sag = max(O.bodies[i].state.refPos[2] - O.bodies[i].state.pos[2] for i in b.top)
		# the walls' weight over their cross-section, about 1800 kg/m3 * 9.81 * 0.38 m / 2 GPa ~ 3e-6 of the height through
		# the mortar and more through the slab's weight: micrometres; a bond broken by the turn would let a block fall
		self.assertLess(sag, 2e-5)
		self.assertGreater(sag, 0)
		self.assertEqual(sum(rdem.breakCounts()), 0)
		for name in ('left', 'right'):
			for i in b.walls[name].ids:
				self.assertLess((O.bodies[i].state.pos - O.bodies[i].state.refPos).norm(), 2e-5)

	def testArguments(self):
		with self.assertRaisesRegex(ValueError, r'width = 0.2: must exceed twice the thickness'):
			make(width=0.2)
		with self.assertRaisesRegex(ValueError, r"openings: unknown wall \['roof'\]"):
			make(openings={'roof': []})
		with self.assertRaisesRegex(ValueError, r'height = -1: must be finite and > 0'):
			make(height=-1)


if __name__ == '__main__':
	harness.run(Building)
