"""Tests of rdem.building_layout (pure Python, no YADE): the bond across corners and T-junctions, no overlaps and nothing
missing, the joint kinds, openings and lintels, floors bearing on the walls, the base, loads, block counts and input
validation.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_building_layout`` (or through CTest).
Lengths in m; tolerances: coordinates are sums of a few multiples of the module, exact to ~1e-15 m; 1e-9 m (TOL) is
far above round-off and far below any brick size."""
import itertools
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.building_layout import buildingLayout, rectangle, PAIR_KINDS  # noqa: E402

TOL = 1e-9
Q, T, H, C = 0.065, 0.01, 0.055, 0.065  # quarter module (l + t)/4, joint, brick height, course [m] for 250x120x55 bricks


def box(lo, hi):
	return tuple(lo), tuple(hi)


def overlap(a, b):
	return [min(a[1][d], b[1][d]) - max(a[0][d], b[0][d]) for d in range(3)]


def volume(b):
	return (b[1][0] - b[0][0]) * (b[1][1] - b[0][1]) * (b[1][2] - b[0][2])


def overlapping(boxes):
	"""Pairs of boxes whose interiors intersect (spatial hash of 0.1 m cells)."""
	grid = {}
	for i, (lo, hi) in enumerate(boxes):
		for c in itertools.product(*(range(int(lo[d] // 0.1), int(hi[d] // 0.1) + 1) for d in range(3))):
			grid.setdefault(c, []).append(i)
	bad = set()
	for ids in grid.values():
		for a, b in itertools.combinations(ids, 2):
			if min(overlap(boxes[a], boxes[b])) > TOL:
				bad.add((a, b))
	return bad


def house(**kw):
	"""One room, one storey, 2.59 x 2.07 m, 21 courses (1.355 m), one-wythe running bond, a door and a window."""
	args = dict(plan=(40 * Q - T, 32 * Q - T), storeys=[21 * C - T], thickness=0.12,
	            openings=[('front', 0, 14 * Q - T / 2, 0.0, 12 * Q, 15 * C - T / 2), ('back', 0, 14 * Q - T / 2, 6 * C - T / 2, 12 * Q, 8 * C)])
	args.update(kw)
	return buildingLayout(**args)


def tHouse(**kw):
	"""Two rooms: a rectangle 2.59 x 1.81 m with a wall across it ending on the front and back walls (two T-junctions)."""
	walls = rectangle(40 * Q - T, 28 * Q - T, 0.12) + [dict(name='inner', start=(20 * Q + 0.06, 0.06), end=(20 * Q + 0.06, 28 * Q - T - 0.06))]
	args = dict(plan=walls, storeys=[12 * C - T])
	args.update(kw)
	return buildingLayout(**args)


def masonryIn(lay, course, rect):
	"""Units (indices) of bricks and bats of ``course`` whose plan covers the rectangle ``rect`` = (x0, x1, y0, y1)
	entirely, and those that cover part of it."""
	whole, part = [], []
	x0, x1, y0, y1 = rect
	for i in lay.unitsOf('masonry'):
		u = lay.units[i]
		if u.course != course:
			continue
		ox, oy = min(u.hi[0], x1) - max(u.lo[0], x0), min(u.hi[1], y1) - max(u.lo[1], y0)
		if ox > TOL and oy > TOL:
			(whole if u.lo[0] <= x0 + TOL and u.hi[0] >= x1 - TOL and u.lo[1] <= y0 + TOL and u.hi[1] >= y1 - TOL else part).append(i)
	return whole, part


def junctionSquare(lay, i, j):
	"""The plan rectangle where walls i and j overlap (their footprints, junction squares included)."""
	a, b = lay.walls[i].footprint(), lay.walls[j].footprint()
	return (max(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), min(a[3], b[3]))


def coreOf(rect, margin):
	"""The rectangle shrunk by ``margin`` on each side (the part of a junction square clear of its joints)."""
	return (rect[0] + margin, rect[1] - margin, rect[2] + margin, rect[3] - margin)


def courseCount(lay):
	return sum(s.courses for s in lay.storeys)


class Interlocking(unittest.TestCase):
	"""Every course is bonded across every corner and T-junction, the wall that runs through alternating."""

	def checkCorners(self, lay):
		corners = [(i, j) for kind, i, j, _ in lay.junctions if kind == 'L']
		self.assertEqual(len(corners), 4)
		for i, j in corners:
			square = junctionSquare(lay, i, j)
			for k in range(courseCount(lay)):
				# the wall that runs through: the one along x in even courses, along y in odd ones
				own, other = (i, j) if (lay.walls[i].axis == 'x') == (k % 2 == 0) else (j, i)
				w, o = lay.walls[own], lay.walls[other]
				# its outer row (on the face away from the other wall) covers the corner square from face to face: the
				# strip one brick width w wide along the outer face, clear of the joints, lies in its bricks only
				c = 1 - w.along
				outerLow = (o.footprint()[2 * c] + o.footprint()[2 * c + 1]) / 2 > (w.v0 + w.thickness / 2)
				strip = list(coreOf(square, T))
				if outerLow:
					strip[2 * c + 1] = w.v0 + 0.12 - T
				else:
					strip[2 * c] = w.v0 + w.thickness - 0.12 + T
				whole, part = masonryIn(lay, k, tuple(strip))
				self.assertEqual({lay.unitWall[u] for u in whole + part}, {own}, 'corner %s/%s, course %d' % (w.name, o.name, k))
				# from the corner's outer face at least to the other wall's inner face
				outer = whole + part
				reach = max(lay.units[u].hi[w.along] - lay.units[u].lo[w.along] for u in outer)
				self.assertGreater(reach, o.thickness - TOL)
				# it is bonded (bed pairs) to bricks of both walls in the course below
				if k > 0:
					below = set()
					for p in lay.pairsOfKind('bed'):
						a, b = lay.blockUnit[p[0]], lay.blockUnit[p[1]]
						for x, y in ((a, b), (b, a)):
							if x in outer and lay.units[y].course == k - 1:
								below.add(lay.unitWall[y])
					self.assertEqual(below, {i, j}, 'corner %s/%s, course %d: bed pairs with walls %s' % (w.name, o.name, k, below))

	def testRunningBondCorners(self):
		self.checkCorners(house())

	def testEnglishBondCorners(self):
		self.checkCorners(house(thickness=0.25, bond='english', openings=[]))

	def testEnglishQuoin(self):
		"""English bond as a mason lays it: on the face of the wall in its header course, the quoin (the end of the other
		wall's stretcher), then a queen closer, then headers."""
		lay = house(thickness=0.25, bond='english', openings=[])
		front = lay.wallIndex('front')
		for k in (1, 3):  # header courses of the walls along x
			face = sorted((lay.units[i] for i in lay.unitsOf('masonry', wall=front) if lay.units[i].course == k and lay.units[i].lo[1] < TOL),
			              key=lambda u: u.lo[0])
			self.assertEqual([u.piece for u in face[:3]], ['queen closer', 'header', 'header'])
			self.assertAlmostEqual(face[0].nominalLo[0], 2 * Q, delta=TOL)  # behind the quoin, one module W from the corner

	def testTJunctions(self):
		lay = tHouse()
		ts = [(i, j) for kind, i, j, _ in lay.junctions if kind == 'T']
		self.assertEqual(sorted((lay.walls[i].name, lay.walls[j].name) for i, j in ts), [('inner', 'back'), ('inner', 'front')])
		for stem, bar in ts:
			square = junctionSquare(lay, stem, bar)
			for k in range(courseCount(lay)):
				whole, part = masonryIn(lay, k, coreOf(square, T))
				owners = {lay.unitWall[u] for u in whole + part}
				expected = stem if (lay.walls[stem].axis == 'x') == (k % 2 == 0) else bar
				self.assertEqual(owners, {expected}, 'T %s on %s, course %d' % (lay.walls[stem].name, lay.walls[bar].name, k))
				if expected == stem:  # the stem runs through the bar to its far face
					self.assertTrue(any(lay.units[u].lo[1] <= square[2] + TOL and lay.units[u].hi[1] >= square[3] - TOL for u in whole))

	def testLaps(self):
		"""Head joints of consecutive courses on each face of each wall lie at least a quarter module apart (half a brick
		in running bond, a quarter in English bond and next to a T-junction), corners and T-junctions included; less t/2
		where a joint's face is a brick's surface rather than the joint's mid-plane (a brick's end against the side of a
		brick of another wall)."""
		for lay, minimum in ((house(openings=[]), 2 * Q), (tHouse(), Q), (house(thickness=0.25, bond='english', openings=[]), Q)):
			for w in lay.walls:
				fp = w.footprint()
				for face in (w.v0, w.v0 + w.thickness):
					joints = {}
					for i in lay.unitsOf('masonry'):
						u = lay.units[i]
						c = 1 - w.along
						inWall = fp[0] - TOL <= u.lo[0] and u.hi[0] <= fp[1] + TOL and fp[2] - TOL <= u.lo[1] and u.hi[1] <= fp[3] + TOL
						if inWall and (abs(u.lo[c] - face) < TOL or abs(u.hi[c] - face) < TOL):
							joints.setdefault(u.course, set()).update((u.lo[w.along], u.hi[w.along]))
					ends = (w.u0, w.u0 + w.length)
					for k in range(1, courseCount(lay)):
						for a in joints.get(k, ()):
							for b in joints.get(k - 1, ()):
								if min(abs(a - e) for e in ends) > w.thickness + T and min(abs(b - e) for e in ends) > w.thickness + T:
									self.assertGreater(abs(a - b), minimum - T / 2 - TOL, 'wall %s, face %g, courses %d-%d: joints at %g and %g' % (w.name, face, k - 1, k, a, b))


class Geometry(unittest.TestCase):
	"""No overlaps, nothing missing, the right joint kinds."""

	def testNoOverlapsAndWhole(self):
		for lay in (house(), tHouse(), house(thickness=0.25, bond='english'), house(floors='joists'), tHouse(storeys=[12 * C - T] * 2, floors=['joists', 'slab'])):
			self.assertEqual(overlapping(lay.blocks), set())
			# masonry + what openings, lintels and joist pockets took + slivers = the walls' plan area x the storeys' height
			walls = sum(w.length * w.thickness for w in lay.walls)
			plan = walls - sum((lambda r: (r[1] - r[0]) * (r[3] - r[2]))(junctionSquare(lay, i, j)) for _, i, j, _ in lay.junctions)
			height = sum(s.height for s in lay.storeys) + sum(T for s in lay.storeys[:-1] if s.floor != 'slab')
			cut = 0.0
			for (wi, st, u0, z0, ow, oh) in lay.openings:
				w = lay.walls[wi]
				cut += w.thickness * (ow * oh + (ow + 2 * lay.lintelBearing) * lay.lintelHeight)
			joistInWalls = 0.0
			for i in lay.unitsOf('joist'):
				jb = lay.blocks[lay.units[i].blocks[0]]
				for w in lay.walls:
					fp = w.footprint()
					ov = [min(jb[1][0], fp[1]) - max(jb[0][0], fp[0]), min(jb[1][1], fp[3]) - max(jb[0][1], fp[2]), jb[1][2] - jb[0][2]]
					if min(ov) > 0:
						joistInWalls += ov[0] * ov[1] * ov[2]
			self.assertAlmostEqual(lay.volume('masonry') + sum(volume(b) for b in lay.dropped) + cut + joistInWalls, plan * height, delta=1e-9)

	def testJointKinds(self):
		lay = house()
		kinds = {p[2] for p in lay.pairs}
		self.assertTrue(kinds <= set(PAIR_KINDS))
		self.assertNotIn('collar', kinds)  # one wythe: no collar joints
		self.assertIn('collar', {p[2] for p in house(thickness=0.25, bond='english').pairs})
		n = courseCount(lay)
		cross = [p for p in lay.pairs if p[2] in ('bed', 'head', 'collar') and len(set(lay.pairWalls(p))) == 2]
		vertical = [p for p in cross if p[2] != 'bed']
		self.assertEqual({p[2] for p in vertical}, {'head'})
		self.assertEqual(len(vertical), 4 * n)  # each corner, each course: the butting brick's end against the through brick
		for p in vertical:  # a corner's head joint: the wall's thickness by a course (the bottom and top courses: h + t/2)
			self.assertIn(round(p[3] / 0.12, 12), (round(C, 12), round(H + T / 2, 12)))

	def testBlockCounts(self):
		lay = house(blocksPerBrick=(2, 1, 1))
		self.assertEqual(lay.counts()['units:brick'] * 2 + sum(len(lay.units[i].blocks) for i in lay.unitsOf('bat')), len(lay.blocksOf('masonry')))
		big = buildingLayout(**bigHouse())
		self.assertGreaterEqual(len(big.blocks), 10000)


def bigHouse():
	"""The two-storey house of scripts/building.py --big: 7.79 x 5.71 m, English bond one brick thick, a wall across,
	two storeys of 2.59 m, doors and windows, timber floor and RC slab roof."""
	L, W = 120 * Q - T, 88 * Q - T
	walls = rectangle(L, W, 0.25, 'english') + [dict(name='inner', start=(60 * Q + 0.125, 0.125), end=(60 * Q + 0.125, W - 0.125), thickness=0.25, bond='english')]
	door, window = (12 * Q, 33 * C - T / 2), (12 * Q, 20 * C)
	ops = [('front', 0, 20 * Q - T / 2, 0.0, *door), ('front', 0, 80 * Q - T / 2, 10 * C - T / 2, *window), ('back', 0, 40 * Q - T / 2, 10 * C - T / 2, *window),
	       ('front', 1, 20 * Q - T / 2, 10 * C - T / 2, *window), ('front', 1, 80 * Q - T / 2, 10 * C - T / 2, *window),
	       ('back', 1, 40 * Q - T / 2, 10 * C - T / 2, *window), ('left', 0, 36 * Q - T / 2, 10 * C - T / 2, *window),
	       ('right', 1, 36 * Q - T / 2, 10 * C - T / 2, *window)]
	return dict(plan=walls, storeys=[40 * C - T] * 2, openings=ops, floors=['joists', 'slab'])


class OpeningsAndFloors(unittest.TestCase):

	def testOpeningsEmptyAndLintelsBearing(self):
		lay = house()
		self.assertEqual(len(lay.lintels), 2)
		for (wi, st, u0, z0, ow, oh), li in zip(lay.openings, lay.lintels):
			w = lay.walls[wi]
			hole = w.toGlobal((u0, 0, z0), (u0 + ow, w.thickness, z0 + oh))
			for b in lay.blocks:
				self.assertLessEqual(min(overlap(b, hole)), TOL)
			lintel = lay.units[li]
			self.assertAlmostEqual(lintel.hi[w.along] - lintel.lo[w.along], ow + 2 * lay.lintelBearing, delta=TOL)
			self.assertAlmostEqual(lintel.lo[2], z0 + oh, delta=TOL)
			# the lintel rests on both jambs over its bearing, through the wall's thickness
			under = [p for p in lay.pairsOfKind('lintel') if li in (lay.blockUnit[p[0]], lay.blockUnit[p[1]])
			         and lay.blocks[p[0] if lay.blockUnit[p[1]] == li else p[1]][1][2] <= lintel.lo[2] + TOL]
			self.assertAlmostEqual(sum(p[3] for p in under), 2 * lay.lintelBearing * w.thickness, delta=1e-12)
			self.assertTrue(any(lay.units[lay.blockUnit[p[0] if lay.blockUnit[p[1]] == li else p[1]]].lo[2] >= lintel.hi[2] - TOL
			                    for p in lay.pairsOfKind('lintel') if li in (lay.blockUnit[p[0]], lay.blockUnit[p[1]])))  # masonry above it

	def testSlabBearsOnEveryWall(self):
		lay = tHouse(storeys=[12 * C - T] * 2, floors='slab', floorLoad=200.0, roofLoad=100.0)
		walls = sum(w.length * w.thickness for w in lay.walls) - sum((lambda r: (r[1] - r[0]) * (r[3] - r[2]))(junctionSquare(lay, i, j))
		                                                              for _, i, j, _ in lay.junctions)
		for st in lay.storeys:
			below = [p for p in lay.pairsOfKind('floor') if abs(lay.blocks[p[0]][1][2] - st.top) < TOL or abs(lay.blocks[p[1]][1][2] - st.top) < TOL]
			self.assertAlmostEqual(sum(p[3] for p in below), walls, delta=1e-9)  # on the top of every wall of the storey
		above = [p for p in lay.pairsOfKind('floor') if abs(min(lay.blocks[p[0]][0][2], lay.blocks[p[1]][0][2]) - lay.storeys[0].top) < TOL and
		         abs(max(lay.blocks[p[0]][0][2], lay.blocks[p[1]][0][2]) - lay.storeys[1].z0) < TOL]
		self.assertAlmostEqual(sum(p[3] for p in above), walls, delta=1e-9)  # the upper storey stands on the slab
		(x0, y0, _), (x1, y1, _) = lay.bounds()
		self.assertAlmostEqual(sum(lay.unitMass), (200.0 + 100.0) * (x1 - x0) * (y1 - y0), delta=1e-9)
		self.assertAlmostEqual(sum(p[3] for p in lay.pairsOfKind('beam')), walls, delta=1e-9)  # every wall on the base beam

	def testJoistsBearInPockets(self):
		lay = tHouse(storeys=[12 * C - T] * 2, floors=['joists', 'slab'], floorLoad=150.0, joistBearing=0.06)
		joists = lay.unitsOf('joist')
		self.assertEqual(len(joists), 4)  # two bays 1.17 m wide at 0.6 m: two joists each
		for i in joists:
			lo, hi = lay.units[i].lo, lay.units[i].hi
			self.assertAlmostEqual(hi[2], lay.storeys[0].top + T / 2, delta=TOL)
			seats = [p for p in lay.pairsOfKind('joist') if i in (lay.blockUnit[p[0]], lay.blockUnit[p[1]]) and
			         abs(lay.blocks[p[0] if lay.blockUnit[p[1]] == i else p[1]][1][2] - lo[2]) < TOL]
			self.assertAlmostEqual(sum(p[3] for p in seats), 2 * 0.06 * (hi[0] - lo[0]), delta=1e-12)  # both ends, bearing x width
		clear = (28 * Q - T - 0.24) * ((40 * Q - T) - 3 * 0.12)  # clear floor area of the two rooms
		self.assertAlmostEqual(sum(lay.unitMass[i] for i in joists), 150.0 * clear, delta=1e-9)


class Validation(unittest.TestCase):
	"""Every argument out of range: a ValueError naming it."""

	def bad(self, pattern, **kw):
		with self.assertRaisesRegex(ValueError, pattern):
			house(**kw)

	def testArguments(self):
		self.bad(r'plan = .*must be \(length, width\)', plan=[])
		self.bad(r'plan\[0\]\.start = .*2 finite numbers', plan=[dict(start=(0, float('nan')), end=(1, 0))])
		self.bad(r'plan\[0\]: start .* must differ along x or along y only', plan=[((0, 0), (1, 1))])
		self.bad(r'plan: wall front is 2.6 m long .*nearest: 2.59 or 2.655 m', plan=(2.6, 32 * Q - T))
		self.bad(r'plan = \(0.2, .*exceed twice the thickness', plan=(0.2, 2.07))
		self.bad(r'plan\[1\]\.name = .front.: must be .* unique', plan=[dict(name='front', start=(0, 0), end=(1, 0)), dict(name='front', start=(0, 2), end=(1, 2))])
		self.bad(r'plan: walls a and b cross', plan=[dict(name='a', start=(0.06, 1.0), end=(2.53, 1.0)), dict(name='b', start=(1.0, 0.06), end=(1.0, 2.01))])
		self.bad(r'storeys = \[\]: must be a list', storeys=[])
		self.bad(r'storeys\[0\] = 1.3: must be N\*h \+ \(N-1\)\*t .*nearest', storeys=[1.3])
		self.bad(r'thickness = 0.2: with bond=.running. must be', thickness=0.2)
		self.bad(r"bond = 'flemish': must be one of 'running', 'english'", bond='flemish')
		self.bad(r'brick = .*l = 2\*w \+ t', brick=(0.24, 0.12, 0.055))
		self.bad(r'joint = 0: must be > 0', joint=0)
		self.bad(r'blocksPerBrick = .*3 integers >= 1', blocksPerBrick=(1, 0, 1))
		self.bad(r"floors = .*one per storey", floors=['slab', 'slab'])
		self.bad(r"floors\[0\] = 'concrete': must be one of", floors='concrete')
		self.bad(r'slabThickness = -0.1: must be a finite number > 0', slabThickness=-0.1)
		self.bad(r'slabBlock = 0: must be a finite number > 0', slabBlock=0)
		self.bad(r'baseHeight = nan', baseHeight=float('nan'))
		self.bad(r'lintelHeight = 0: must be', lintelHeight=0)
		self.bad(r'lintelBearing = -1: must be', lintelBearing=-1)
		self.bad(r'floorLoad = -1: must be a finite number >= 0', floorLoad=-1)
		self.bad(r'roofLoad = inf', roofLoad=float('inf'))
		self.bad(r'joistSection = .*\(width, depth\)', joistSection=(0.1, ))
		self.bad(r'joistSpacing = 0: must be', joistSpacing=0)
		self.bad(r"joistDirection = 'z': must be", joistDirection='z')
		self.bad(r'joistBearing = 0: must be', joistBearing=0)

	def testOpenings(self):
		self.bad(r'openings\[0\] = .*: wall must be one of front, right, back, left', openings=[('roof', 0, 1, 0, 0.5, 0.5)])
		self.bad(r'openings\[0\] = .*: storey must be an index from 0 to 0', openings=[('front', 1, 1, 0, 0.5, 0.5)])
		self.bad(r'openings\[0\] = .*: u0, z0 must be finite and width, height > 0', openings=[('front', 0, 1, 0, -0.5, 0.5)])
		self.bad(r'openings\[0\] = .*must lie within u = 0.125 to 2.465 m of wall front', openings=[('front', 0, 0.1, 0, 0.5, 0.5)])
		self.bad(r'openings\[0\] = .*z0 \+ height \+ lintel height', openings=[('front', 0, 1, 0, 0.5, 1.3)])
		self.bad(r'openings\[1\] = .* overlaps openings\[0\]', openings=[('front', 0, 0.5, 0, 0.5, 0.5), ('front', 0, 0.9, 0.2, 0.5, 0.5)])
		self.bad(r'openings = 3: must be a list', openings=3)
		with self.assertRaisesRegex(ValueError, r'openings\[0\] = .*overlaps the junction with wall inner'):
			tHouse(openings=[('front', 0, 18 * Q, 0, 0.3, 0.3)])


if __name__ == '__main__':
	unittest.main()
