"""Tests of rdem.wall_layout (pure Python, no YADE): bond patterns counted by hand, exact tiling of the wall, touching
pairs and their kinds, blocks per brick, openings, beams, input validation and speed.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_wall_layout`` (or through CTest).
Bricks 250 x 120 x 55 mm, joints 10 mm: modules L = l + t = 0.26 m, W = w + t = 0.13 m, h + t = 0.065 m."""
import itertools
import os
import re
import sys
import time
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.wall_layout import wallLayout, PAIR_KINDS, UNIT_KINDS  # noqa: E402

l, w, h, t = 0.25, 0.12, 0.055, 0.01
L, W, C = l + t, w + t, h + t
LENGTH, HEIGHT = 2.85, 0.315  # 11 bricks (11*0.25 + 10*0.01), 5 courses (5*0.055 + 4*0.01)
ONE, TWO, THREE = 0.12, 0.25, 0.38  # one, two, three wythes; 0.25 = l (one brick), 0.38 = l + t + w (one and a half)


def volume(box):
	lo, hi = box
	return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])


def overlapping(blocks):
	"""Pairs of blocks whose intersection has a positive volume (sweep along x)."""
	order = sorted(range(len(blocks)), key=lambda i: blocks[i][0][0])
	bad = []
	for a, i in enumerate(order):
		lo, hi = blocks[i]
		for j in order[a + 1:]:
			lo2, hi2 = blocks[j]
			if lo2[0] >= hi[0]:
				break
			if all(min(hi[d], hi2[d]) - max(lo[d], lo2[d]) > 0 for d in range(3)):
				bad.append((i, j))
	return bad


def components(n, edges):
	"""Number of connected components of a graph of n nodes."""
	parent = list(range(n))

	def root(x):
		while parent[x] != x:
			parent[x] = parent[parent[x]]
			x = parent[x]
		return x

	for i, j in edges:
		parent[root(i)] = root(j)
	return len(set(root(i) for i in range(n)))


def axisOf(lay, i, j):
	"""The normal axis of the face blocks i and j share, and whether j lies on the positive side of i."""
	(lo, hi), (lo2, hi2) = lay.blocks[i], lay.blocks[j]
	for d in range(3):
		if hi[d] == lo2[d]:
			return d, True
		if hi2[d] == lo[d]:
			return d, False
	raise AssertionError('blocks %d and %d share no plane' % (i, j))


def bruteForcePairs(lay):
	"""All pairs of blocks sharing a face of positive area, by comparing every two blocks."""
	out = set()
	for i, j in itertools.combinations(range(len(lay.blocks)), 2):
		(lo, hi), (lo2, hi2) = lay.blocks[i], lay.blocks[j]
		ov = [min(hi[d], hi2[d]) - max(lo[d], lo2[d]) for d in range(3)]
		if sorted(ov)[0] == 0 and sorted(ov)[1] > 1e-12:
			out.add((i, j))
	return out


def neighbours(lay, unit, axis, positive, kinds=None):
	"""{other unit: shared area} over the face of ``unit`` of normal ``axis`` on the ``positive`` side."""
	mine = set(lay.units[unit].blocks)
	out = {}
	for i, j, kind, area in lay.pairs:
		if (i in mine) == (j in mine) or (kinds is not None and kind not in kinds):
			continue
		a, b = (i, j) if i in mine else (j, i)
		d, up = axisOf(lay, a, b)
		if d == axis and up == positive:
			other = lay.blockUnit[b]
			out[other] = out.get(other, 0.0) + area
	return out


def brickPieces(lay, course):
	"""{piece: number} of the bricks and bats of one course."""
	return dict(c for c in lay.pieceCounts(course).items() if c[0] not in ('bed', 'head', 'collar'))


# The patterns checked below: bond, thickness, length -> pieces of each even and odd course, counted by hand.
PATTERNS = [
        ('stack', ONE, LENGTH, {'stretcher': 11}, {'stretcher': 11}),
        ('stack', TWO, LENGTH, {'stretcher': 22}, {'stretcher': 22}),
        ('running', ONE, LENGTH, {'stretcher': 11}, {'stretcher': 10, 'half bat': 2}),
        ('running', TWO, LENGTH, {'stretcher': 22}, {'stretcher': 20, 'half bat': 4}),
        # 2.98 = 11.5 modules - t: a half bat at the end of even courses, at the start of odd ones
        ('running', ONE, 2.98, {'stretcher': 11, 'half bat': 1}, {'stretcher': 11, 'half bat': 1}),
        # one brick: stretchers front and back / header, queen closer, 17 headers, queen closer, header
        ('english', TWO, LENGTH, {'stretcher': 22}, {'header': 21, 'queen closer': 2}),
        # one and a half bricks: front stretchers + header run behind / header run + back stretchers
        ('english', THREE, LENGTH, {'stretcher': 11, 'header': 21, 'queen closer': 2}, {'header': 21, 'queen closer': 2, 'stretcher': 11}),
        # 3.045 = 11.75 modules - t: stretcher rows end with a three-quarter bat / header, queen closer, 22 headers
        ('english', TWO, 3.045, {'stretcher': 22, 'three-quarter bat': 2}, {'header': 23, 'queen closer': 1}),
        ('english', THREE, 3.045, {'stretcher': 11, 'three-quarter bat': 1, 'header': 23, 'queen closer': 1},
         {'header': 23, 'queen closer': 1, 'stretcher': 11, 'three-quarter bat': 1}),
        # 1.03 = 4 modules - t: HQ S H S QH (stretchers doubled front and back) / S H S H S
        ('flemish', TWO, 1.03, {'header': 3, 'queen closer': 2, 'stretcher': 4}, {'stretcher': 6, 'header': 2}),
        # 1.16 = 4.5 modules - t: HQ S H S H T (T doubled) / S H S H S H
        ('flemish', TWO, 1.16, {'header': 3, 'queen closer': 1, 'stretcher': 4, 'three-quarter bat': 2}, {'stretcher': 6, 'header': 3}),
        # one and a half bricks: behind HQ a T, behind S two H, behind H a B; behind the last T an H and a Q
        ('flemish', THREE, 1.03, {'header': 7, 'queen closer': 2, 'stretcher': 2, 'half bat': 1, 'three-quarter bat': 2}, {'header': 8, 'stretcher': 3, 'half bat': 2}),
        ('flemish', THREE, 1.16, {'header': 8, 'queen closer': 2, 'stretcher': 2, 'half bat': 2, 'three-quarter bat': 2}, {'header': 9, 'stretcher': 3, 'half bat': 3}),
]


class BondPatterns(unittest.TestCase):

	def testPiecesPerCourse(self):
		for bond, thickness, length, even, odd in PATTERNS:
			for mortar in ('interface', 'layer'):
				with self.subTest(bond=bond, thickness=thickness, length=length, mortar=mortar):
					lay = wallLayout(length, HEIGHT, thickness, bond=bond, mortar=mortar)
					self.assertEqual(lay.courseCount, 5)
					for k in range(5):
						self.assertEqual(brickPieces(lay, k), even if k % 2 == 0 else odd, 'course %d' % k)
					whole = sum(n for k in range(5) for p, n in brickPieces(lay, k).items() if p in ('stretcher', 'header'))
					self.assertEqual(lay.counts()['units:brick'], whole)
					self.assertEqual(lay.counts()['units:bat'], sum(n for k in range(5) for n in brickPieces(lay, k).values()) - whole)

	def testLapOnTheFaces(self):
		"""Head joints of consecutive courses on both faces are at least this far apart: 0 stack, L/2 running, L/4
		English and Flemish (no straight joint on a face)."""
		expected = {'stack': 0.0, 'running': L / 2, 'english': L / 4, 'flemish': L / 4}
		for bond, thickness, length, even, odd in PATTERNS:
			lay = wallLayout(length, HEIGHT, thickness, bond=bond)
			for face in (0.0, lay.thickness):
				with self.subTest(bond=bond, thickness=thickness, length=length, face=face):
					joints = [
					        set(round(u.nominalHi[0] + t / 2, 9) for u in lay.units if u.course == k and (u.lo[1] == face or u.hi[1] == face) and u.hi[0] < lay.length)
					        for k in range(5)
					]
					gap = min(abs(a - b) for k in range(4) for a in joints[k] for b in joints[k + 1])
					self.assertAlmostEqual(gap, expected[bond], delta=1e-9)

	def testFlemishHeadersCentredOnStretchersBelow(self):
		for thickness, length in ((TWO, 1.03), (TWO, 1.16), (THREE, 1.03), (THREE, 1.16)):
			lay = wallLayout(length, HEIGHT, thickness, bond='flemish')
			centre = lambda u: round((u.nominalLo[0] + u.nominalHi[0]) / 2, 9)
			for k in range(1, 5):
				headers = [u for u in lay.units if u.course == k and u.piece == 'header' and u.wythe == 0 and 0 < u.lo[0] and u.hi[0] < lay.length]
				stretchers = set(centre(u) for u in lay.units if u.course == k - 1 and u.piece == 'stretcher' and u.wythe == 0)
				self.assertGreater(len(headers), 0)
				for u in headers:
					self.assertIn(centre(u), stretchers, 'course %d, header at x = %.4f' % (k, u.lo[0]))

	def testHeadersRunThroughTheWall(self):
		lay = wallLayout(LENGTH, HEIGHT, TWO, bond='english')
		for u in lay.units:
			self.assertEqual(u.orientation, 'header' if u.piece in ('header', 'queen closer') else 'stretcher')
			if u.orientation == 'header':
				self.assertEqual((u.lo[1], u.hi[1]), (0.0, TWO))
				self.assertAlmostEqual(u.nominalHi[1] - u.nominalLo[1], l, delta=1e-12)
			if u.piece == 'queen closer':
				self.assertAlmostEqual(u.nominalHi[0] - u.nominalLo[0], (w - t) / 2, delta=1e-12)  # L/4 - t

	def testSketch(self):
		lay = wallLayout(0.77, 0.185, ONE, bond='running')
		self.assertEqual(lay.sketch(), '   2 |   S   |   S   |   S   |\n   1 | B |   S   |   S   | B |\n   0 |   S   |   S   |   S   |')
		plan = wallLayout(1.03, HEIGHT, TWO, bond='flemish').sketch('plan', courses=[0])
		self.assertEqual(plan, 'course 0 (plan, back face on top):\n  y1 | H |Q|   S   | H |   S   |Q| H |\n  y0 | H |Q|   S   | H |   S   |Q| H |')


class Checks(unittest.TestCase):
	"""Checks of a whole layout shared by the test classes (no tests of its own)."""

	def check(self, lay, beams=(0.0, 0.0), openings=()):
		T = lay.thickness
		expected = lay.length * T * (lay.height + beams[0] + beams[1]) - sum(o[2] * o[3] * T for o in openings)
		self.assertAlmostEqual(lay.volume() + sum(volume(b) for b in lay.dropped), expected, delta=1e-12 * expected)
		self.assertEqual(overlapping(lay.blocks), [])
		lo, hi = lay.bounds()
		self.assertEqual(lo, (0.0, 0.0, -beams[0]))
		self.assertEqual(hi, (lay.length, T, lay.height + beams[1]))
		self.assertEqual(components(len(lay.blocks), [(i, j) for i, j, k, a in lay.pairs]), 1)
		self.assertEqual(components(len(lay.units), [(lay.blockUnit[i], lay.blockUnit[j]) for i, j, k, a in lay.pairs]), 1)
		for i, j, kind, area in lay.pairs:
			self.assertLess(i, j)
			self.assertIn(kind, PAIR_KINDS)
			self.assertGreater(area, 0)
		for u in lay.units:
			self.assertIn(u.kind, UNIT_KINDS)

	def faceCoverage(self, lay):
		"""Every face of every block inside the wall is covered exactly by the faces of the blocks it touches."""
		covered = [[0.0] * 6 for _ in lay.blocks]
		for i, j, kind, area in lay.pairs:
			d, up = axisOf(lay, i, j)
			covered[i][2 * d + up] += area
			covered[j][2 * d + (not up)] += area
		lo, hi = lay.bounds()
		for b, (blo, bhi) in enumerate(lay.blocks):
			for d in range(3):
				e, f = [a for a in range(3) if a != d]
				face = (bhi[e] - blo[e]) * (bhi[f] - blo[f])
				for side, plane, outer in ((0, blo[d], lo[d]), (1, bhi[d], hi[d])):
					self.assertAlmostEqual(covered[b][2 * d + side], 0.0 if plane == outer else face, delta=1e-12, msg='block %d axis %d side %d' % (b, d, side))


class Tiling(Checks):
	"""Every pattern, both mortar models, with and without beams: the blocks fill the wall exactly."""

	def testPatterns(self):
		for (bond, thickness, length, even, odd), mortar in itertools.product(PATTERNS, ('interface', 'layer')):
			with self.subTest(bond=bond, thickness=thickness, length=length, mortar=mortar):
				lay = wallLayout(length, HEIGHT, thickness, bond=bond, mortar=mortar)
				self.assertEqual((lay.length, lay.height, lay.thickness), (length, HEIGHT, thickness))
				self.check(lay)
				self.faceCoverage(lay)
				self.assertEqual(lay.dropped, [])

	def testPatternsWithBeamsAndBlocks(self):
		for (bond, thickness, length, even, odd), mortar in itertools.product(PATTERNS, ('interface', 'layer')):
			with self.subTest(bond=bond, thickness=thickness, length=length, mortar=mortar):
				lay = wallLayout(length, HEIGHT, thickness, bond=bond, mortar=mortar, blocksPerBrick=(3, 2, 2), baseBeam=0.2, topBeam=0.1, beamBlocks=3)
				self.check(lay, beams=(0.2, 0.1))
				self.faceCoverage(lay)

	def testZeroJoint(self):
		"""joint = 0 (interface only): bricks 240 x 120 x 60 mm touch on their own faces."""
		for bond, thickness, length in (('running', 0.12, 2.4), ('english', 0.24, 2.4), ('flemish', 0.24, 0.6), ('flemish', 0.36, 0.72)):
			with self.subTest(bond=bond, thickness=thickness):
				lay = wallLayout(length, 0.3, thickness, brick=(0.24, 0.12, 0.06), joint=0, bond=bond, blocksPerBrick=(2, 1, 1))
				self.check(lay)
				self.faceCoverage(lay)
				for u in lay.units:
					self.assertEqual((u.lo, u.hi), (u.nominalLo, u.nominalHi))

	def testPairsAreAllTouchingPairs(self):
		"""The spatial hashing finds exactly the pairs a comparison of every two blocks finds."""
		for bond, thickness, length, mortar, per in (('running', TWO, LENGTH, 'layer', (2, 1, 1)), ('english', THREE, 1.03, 'interface', (3, 2, 2)),
		                                             ('flemish', THREE, 1.16, 'layer', (2, 2, 1))):
			with self.subTest(bond=bond, mortar=mortar):
				lay = wallLayout(length, HEIGHT, thickness, bond=bond, mortar=mortar, blocksPerBrick=per, baseBeam=0.1, openings=[(0.3, 0.1, 0.4, 0.13)])
				self.assertEqual(set((i, j) for i, j, k, a in lay.pairs), bruteForcePairs(lay))
				self.assertEqual(len(set((i, j) for i, j, k, a in lay.pairs)), len(lay.pairs))


class JointKinds(unittest.TestCase):

	def testRunningInterfaceOneWythe(self):
		lay = wallLayout(LENGTH, HEIGHT, ONE, bond='running')
		for k in (1, 2, 3):  # interior courses
			bricks = [i for i in lay.courses()[k] if lay.units[i].piece == 'stretcher']
			for b in bricks[1:-1]:  # not next to a bat or a wall end
				u = lay.units[b]
				self.assertAlmostEqual(u.hi[0] - u.lo[0], L, delta=1e-12)
				self.assertAlmostEqual(u.hi[2] - u.lo[2], C, delta=1e-12)
				for up in (True, False):
					beds = neighbours(lay, b, 2, up)
					self.assertEqual(len(beds), 2)
					for other, area in beds.items():
						self.assertEqual(lay.units[other].course, k + (1 if up else -1))
						self.assertAlmostEqual(area, L / 2 * w, delta=1e-15)  # 0.13 x 0.12: half of the bed face L x w
				for side in (True, False):
					heads = neighbours(lay, b, 0, side)
					self.assertEqual(len(heads), 1)
					self.assertAlmostEqual(list(heads.values())[0], w * C, delta=1e-15)  # 0.12 x 0.065
		# a brick at the wall end of an even course: box L - t/2 long, on a half bat and a brick
		end = lay.courses()[2][0]
		self.assertAlmostEqual(sorted(neighbours(lay, end, 2, True).values())[0], (L / 2 - t / 2) * w, delta=1e-15)
		kinds = lay.counts()
		# bed: 4 course interfaces x 22 overlaps; head: 10 joints in each of 3 even courses, 11 in each of 2 odd ones
		self.assertEqual((kinds['pairs:bed'], kinds['pairs:head'], kinds['pairs:collar'], kinds['pairs:internal']), (88, 52, 0, 0))

	def testRunningInterfaceTwoWythes(self):
		lay = wallLayout(LENGTH, HEIGHT, TWO, bond='running')
		b = [i for i in lay.courses()[2] if lay.units[i].piece == 'stretcher' and lay.units[i].wythe == 0][5]
		beds = neighbours(lay, b, 2, True)
		self.assertEqual(len(beds), 2)
		for area in beds.values():
			self.assertAlmostEqual(area, L / 2 * (w + t / 2), delta=1e-15)  # 0.13 x 0.125
		collar = neighbours(lay, b, 1, True)
		self.assertEqual(len(collar), 1)
		self.assertAlmostEqual(list(collar.values())[0], L * C, delta=1e-15)
		# collar pairs: 11 + 12 per even + odd course, both wythes alike
		self.assertEqual(len(lay.pairsOfKind('collar')), 3 * 11 + 2 * 12)

	def testEnglishAndFlemishCollars(self):
		# collars only between the front and back stretchers of a one-brick wall (3 stretcher courses of 11)
		self.assertEqual(len(wallLayout(LENGTH, HEIGHT, TWO, bond='english').pairsOfKind('collar')), 33)
		# Flemish 1.03: 2 stretcher pairs in even courses, 3 in odd ones
		self.assertEqual(len(wallLayout(1.03, HEIGHT, TWO, bond='flemish').pairsOfKind('collar')), 3 * 2 + 2 * 3)

	def testLayerMode(self):
		lay = wallLayout(LENGTH, HEIGHT, ONE, bond='running', mortar='layer')
		mortar = [i for i, u in enumerate(lay.units) if u.kind == 'mortar']
		beds = [i for i in mortar if lay.units[i].piece == 'bed']
		heads = [i for i in mortar if lay.units[i].piece == 'head']
		# head joints: 10 per even course, 11 per odd; bed pieces: 4 interfaces x (20 + 22 head-joint edges + 1)
		self.assertEqual((len(heads), len(beds), len(mortar)), (3 * 10 + 2 * 11, 4 * 43, 52 + 172))
		for m in beds:
			u = lay.units[m]
			self.assertAlmostEqual(u.hi[2] - u.lo[2], t, delta=1e-15)
			for up in (True, False):
				touching = neighbours(lay, m, 2, up)
				self.assertEqual(len(touching), 1)  # one unit above and one below: a brick, a bat or a head joint
				self.assertLessEqual(sum(1 for o in touching if lay.units[o].kind in ('brick', 'bat')), 1)
		for i, u in enumerate(lay.units):
			if u.kind == 'brick' and 0 < u.course < 4 and 0 < u.lo[0] and u.hi[0] < lay.length:
				for up in (True, False):
					self.assertAlmostEqual(sum(neighbours(lay, i, 2, up, kinds=('bed', )).values()), l * w, delta=1e-15)
					self.assertAlmostEqual(sum(neighbours(lay, i, 0, up, kinds=('head', )).values()), w * h, delta=1e-15)
		for i, j, kind, area in lay.pairs:
			a, b = lay.units[lay.blockUnit[i]], lay.units[lay.blockUnit[j]]
			self.assertTrue(a.kind == 'mortar' or b.kind == 'mortar', 'bricks touch each other in layer mode')
			self.assertEqual(kind, 'mortar' if a.kind == b.kind == 'mortar' else (a if a.kind == 'mortar' else b).piece)
		# mortar-mortar: bed pieces under or over the 21 head joints of the two courses, and next to each other (42 per layer)
		self.assertEqual(len(lay.pairsOfKind('mortar')), 4 * 21 + 4 * 42)

	def testLayerModeCollars(self):
		"""English one brick, layer mode: a collar slab between the wythes of stretcher courses, cut at every brick
		and head-joint edge; the collar pieces touch the bricks on both sides over l x h."""
		lay = wallLayout(LENGTH, HEIGHT, TWO, bond='english', mortar='layer')
		collars = [u for u in lay.units if u.piece == 'collar']
		self.assertEqual(len(collars), 3 * 21)  # 11 under bricks + 10 between head joints, 3 stretcher courses
		self.assertEqual(sorted(set(round(u.hi[0] - u.lo[0], 12) for u in collars)), [t, l])
		for u in collars:
			self.assertAlmostEqual(u.lo[1], w, delta=1e-15)
			self.assertAlmostEqual(u.hi[1], w + t, delta=1e-15)
		brickCollar = [p for p in lay.pairsOfKind('collar')]
		self.assertEqual(len(brickCollar), 3 * 22)
		for i, j, kind, area in brickCollar:
			self.assertAlmostEqual(area, l * h, delta=1e-15)


class BlocksPerBrick(unittest.TestCase):

	def testTwoBlocksLineUp(self):
		"""(2, 1, 1), running bond: the half-brick blocks of adjacent courses line up, each block on exactly one."""
		for mortar in ('interface', 'layer'):
			lay = wallLayout(LENGTH, HEIGHT, ONE, bond='running', blocksPerBrick=(2, 1, 1), mortar=mortar)
			bricks, bats = lay.counts()['units:brick'], lay.counts()['units:bat']
			self.assertEqual((bricks, bats), (53, 4))
			self.assertEqual(len(lay.blocks) - lay.counts()['units:mortar'], 2 * 53 + 4)  # half bats: round(2 x 0.48) = 1 block
			self.assertEqual(len(lay.pairsOfKind('internal')), 53)
			if mortar == 'interface':
				xs = lambda k: sorted(set(b for u in lay.units if u.course == k for i in u.blocks for b in (lay.blocks[i][0][0], lay.blocks[i][1][0])))
				for k in range(4):
					self.assertEqual(xs(k), xs(k + 1))
				above = {}
				for i, j, kind, area in lay.pairsOfKind('bed'):
					d, up = axisOf(lay, i, j)
					above.setdefault(i if up else j, []).append(area)
				for b, (lo, hi) in enumerate(lay.blocks):  # every block under the top course carries exactly one block
					if hi[2] < lay.height:
						self.assertEqual(len(above[b]), 1)
						self.assertAlmostEqual(above[b][0], (hi[0] - lo[0]) * (hi[1] - lo[1]), delta=1e-15)
				self.assertEqual(len(lay.pairsOfKind('bed')), 4 * 22)  # 22 block columns, one bed pair per column and interface

	def testThreeByTwo(self):
		"""(3, 1, 2): bricks of 3 x 2 blocks (7 internal faces), half bats 1 x 2 (1 internal face); block edges of
		adjacent courses do not line up: 3n - 1 + 3n - 2 edges inside the wall give 6n - 2 bed pairs per interface."""
		lay = wallLayout(LENGTH, HEIGHT, ONE, bond='running', blocksPerBrick=(3, 1, 2))
		self.assertEqual(len(lay.blocks), 53 * 6 + 4 * 2)
		self.assertEqual(len(lay.pairsOfKind('internal')), 53 * 7 + 4 * 1)
		self.assertEqual(len(lay.pairsOfKind('bed')), 4 * (6 * 11 - 2))
		self.assertEqual(len(lay.pairsOfKind('head')), 2 * (3 * 10 + 2 * 11))  # two block layers per course
		self.assertEqual(len(lay.pairs), 375 + 256 + 104)
		u = lay.units[lay.courses()[2][5]]
		self.assertEqual([round(lay.blocks[i][1][0] - lay.blocks[i][0][0], 12) for i in u.blocks[:3]], [round(l / 3 + t / 2, 12), round(l / 3, 12), round(l / 3 + t / 2, 12)])

	def testHeadersSplitAlongTheirOwnLength(self):
		lay = wallLayout(LENGTH, HEIGHT, TWO, bond='english', blocksPerBrick=(2, 1, 1))
		for u in lay.units:
			if u.orientation == 'header':
				self.assertEqual(len(u.blocks), 2)  # headers and queen closers (l long): two blocks along y
				(lo0, hi0), (lo1, hi1) = (lay.blocks[i] for i in u.blocks)
				self.assertEqual((lo0[0], hi0[0], hi0[1]), (lo1[0], hi1[0], lo1[1]))
		internal = lay.pairsOfKind('internal')
		self.assertEqual(len(internal), 3 * 22 + 2 * 23)
		for i, j, kind, area in internal:
			d, up = axisOf(lay, i, j)
			self.assertEqual(d, 0 if lay.units[lay.blockUnit[i]].orientation == 'stretcher' else 1)


class Openings(Checks):
	# running bond, 2.85 x 1.225 m (19 courses); window edges on joint mid-planes: x from 3L - t/2 to 7L - t/2, z from
	# 3(h + t) - t/2 to 11(h + t) - t/2
	WINDOW = (3 * L - t / 2, 3 * C - t / 2, 4 * L, 8 * C)

	def inside(self, lay, o):
		x0, z0, ow, oh = o
		return [b for b in lay.blocks if min(b[1][0], x0 + ow) - max(b[0][0], x0) > 0 and min(b[1][2], z0 + oh) - max(b[0][2], z0) > 0]

	def testWindowOnJointPlanes(self):
		for mortar, o in (('interface', self.WINDOW), ('layer', (3 * L, 3 * C, 4 * L - t, 8 * C - t))):
			with self.subTest(mortar=mortar):
				lay = wallLayout(LENGTH, 1.225, TWO, bond='running', mortar=mortar, blocksPerBrick=(2, 1, 1), openings=[o])
				self.check(lay, openings=[o])
				self.assertEqual(lay.dropped, [])
				self.assertEqual(self.inside(lay, o), [])
				x0, z0, ow, oh = o
				# flush: the faces of the blocks around the opening cover its four sides exactly
				T = lay.thickness
				side = lambda x: sum((hi[1] - lo[1]) * (hi[2] - lo[2]) for lo, hi in lay.blocks if x(lo, hi) and lo[2] < z0 + oh and hi[2] > z0)
				sill = lambda z: sum((hi[0] - lo[0]) * (hi[1] - lo[1]) for lo, hi in lay.blocks if z(lo, hi) and lo[0] < x0 + ow and hi[0] > x0)
				self.assertAlmostEqual(side(lambda lo, hi: hi[0] == x0), oh * T, delta=1e-12)
				self.assertAlmostEqual(side(lambda lo, hi: lo[0] == x0 + ow), oh * T, delta=1e-12)
				self.assertAlmostEqual(sill(lambda lo, hi: hi[2] == z0), ow * T, delta=1e-12)
				self.assertAlmostEqual(sill(lambda lo, hi: lo[2] == z0 + oh), ow * T, delta=1e-12)
				cut = [u for u in lay.units if u.cut]
				self.assertGreater(len(cut), 0)
				for u in cut:
					self.assertTrue(u.hi[0] == x0 or u.lo[0] == x0 + ow or u.hi[2] == z0 or u.lo[2] == z0 + oh, u)
				if mortar == 'interface':
					# odd courses 3, 5, 7, 9 lose half of a brick on each side: 4 courses x 2 wythes x 2 sides half-brick bats
					self.assertEqual(sum(1 for u in cut if u.kind == 'bat'), 16)

	def testOpeningOffTheJoints(self):
		"""Edges anywhere: no block in the opening; slivers (< l/4 along x, < h/4 along z) dropped and accounted for."""
		o = (0.8, 0.2, 0.9, 0.5)
		x1, z1 = 0.8 + 0.9, 0.2 + 0.5
		for mortar in ('interface', 'layer'):
			with self.subTest(mortar=mortar):
				lay = wallLayout(LENGTH, 1.225, ONE, bond='running', mortar=mortar, openings=[o], topBeam=0.1)
				self.check(lay, beams=(0.0, 0.1), openings=[o])
				self.assertEqual(self.inside(lay, o), [])
				self.assertGreater(len(lay.dropped), 0)
				for lo, hi in lay.dropped:
					self.assertTrue(hi[0] - lo[0] < l / 4 or hi[2] - lo[2] < h / 4)
				for u in lay.units:
					if u.cut:
						self.assertTrue(u.hi[0] == 0.8 or u.lo[0] == x1 or u.hi[2] == 0.2 or u.lo[2] == z1, u)
						if u.hi[0] == 0.8 or u.lo[0] == x1:  # cut along x: at least l/4 long
							self.assertGreaterEqual(u.hi[0] - u.lo[0], l / 4)
						if u.hi[2] == 0.2 or u.lo[2] == z1:  # cut along z: at least h/4 tall
							self.assertGreaterEqual(u.hi[2] - u.lo[2], h / 4)

	def testDoorAndWindow(self):
		openings = [(2 * L - t / 2, 0.0, 2 * L, 14 * C - t / 2), (6 * L - t / 2, 5 * C - t / 2, 3 * L, 6 * C)]
		for mortar in ('interface', 'layer'):
			lay = wallLayout(LENGTH, 1.225, ONE, bond='running', mortar=mortar, openings=openings, baseBeam=0.2)
			self.check(lay, beams=(0.2, 0.0), openings=openings)
			for o in openings:
				self.assertEqual(self.inside(lay, o), [])


class Accessors(unittest.TestCase):

	def testCoursesBeamsCounts(self):
		lay = wallLayout(LENGTH, HEIGHT, ONE, bond='running', baseBeam=0.3, topBeam=0.2, beamBlocks=4)
		courses = lay.courses()
		self.assertEqual([len(c) for c in courses], [11, 12, 11, 12, 11])
		self.assertEqual([lay.units[i].piece for i in lay.beams()], ['base', 'top'])
		self.assertEqual([lay.units[i].course for i in lay.beams()], [-1, 5])
		c = lay.counts()
		self.assertEqual((c['units'], c['blocks'], c['units:brick'], c['units:bat'], c['units:beam'], c['units:mortar']), (59, 65, 53, 4, 2, 0))
		self.assertEqual(c['pairs:internal'], 2 * 3)
		# beam pairs: the base beam's 4 blocks under the 11 bricks of course 0 (edges 3 x 0.7125 m fall inside bricks)
		self.assertEqual(c['pairs:beam'], (11 + 3) + (11 + 3))
		self.assertEqual(sum(c['pairs:' + k] for k in PAIR_KINDS), c['pairs'])
		self.assertEqual(len(lay.pairsOfKind('beam')), c['pairs:beam'])
		for i in lay.beams():
			u = lay.units[i]
			self.assertEqual(len(u.blocks), 4)
			self.assertEqual(set(round(lay.blocks[b][1][0] - lay.blocks[b][0][0], 12) for b in u.blocks), {round(LENGTH / 4, 12)})
		self.assertEqual(sum(a for i, j, k, a in lay.pairsOfKind('beam')), 2 * LENGTH * ONE)
		with self.assertRaisesRegex(ValueError, 'kind'):
			lay.pairsOfKind('glue')


class Validation(unittest.TestCase):
	"""A bad value of every argument raises ValueError naming the argument."""
	GOOD = dict(length=LENGTH, height=HEIGHT, thickness=ONE)

	def refused(self, name, *values, message=None, **context):
		"""wallLayout(..., name=value) raises ValueError whose message starts with ``message`` (default: name)."""
		for v in values:
			with self.subTest(**{name: v}):
				with self.assertRaisesRegex(ValueError, '^' + re.escape(message or name)):
					wallLayout(**dict(self.GOOD, **dict(context, **{name: v})))

	def testLength(self):
		self.refused('length', 0, -1, float('nan'), float('inf'), '2.85', 2.86, 0.2)
		with self.assertRaisesRegex(ValueError, r'length = 2\.86: .* nearest valid values: 2\.85 and 2\.98'):
			wallLayout(2.86, HEIGHT, ONE)
		with self.assertRaisesRegex(ValueError, r'length = 1\.1: .* nearest valid values: 1\.03 and 1\.16'):
			wallLayout(1.1, HEIGHT, TWO, bond='flemish')
		self.refused('length', 0.25, bond='english', thickness=TWO)  # one stretcher: too short for the closers
		# English bond: whole stretchers, or whole stretchers and a three-quarter bat (not a half or a quarter)
		with self.assertRaisesRegex(ValueError, r'length = 1\.42: .* nearest valid values: 1\.29 and 1\.485'):
			wallLayout(1.42, HEIGHT, TWO, bond='english')

	def testHeight(self):
		self.refused('height', 0, -0.3, None, 0.3, 0.05)
		with self.assertRaisesRegex(ValueError, r'height = 0\.3: .* nearest valid values: 0\.25 and 0\.315'):
			wallLayout(LENGTH, 0.3, ONE)

	def testThickness(self):
		self.refused('thickness', 0, float('nan'), 0.2, 0.06)
		with self.assertRaisesRegex(ValueError, r'thickness = 0\.2: .* nearest valid values: 0\.12 and 0\.25'):
			wallLayout(LENGTH, HEIGHT, 0.2)
		for bond in ('english', 'flemish'):
			with self.assertRaisesRegex(ValueError, r'thickness = 0\.12: .* accepts thickness = l = 0\.25 .* or l \+ t \+ w = 0\.38'):
				wallLayout(1.03, HEIGHT, ONE, bond=bond)
			with self.assertRaisesRegex(ValueError, r'thickness = 0\.25: .* needs bricks with l = 2\*w \+ t'):
				wallLayout(1.03, HEIGHT, 0.25, bond=bond, brick=(0.24, 0.12, 0.055))

	def testBrick(self):
		self.refused('brick', (0.25, 0.12), (0.25, 0.12, 0), (0.25, -0.12, 0.055), 0.25, None, (0.25, 0.12, float('inf')))

	def testJoint(self):
		self.refused('joint', -0.01, float('nan'), 0.06, 'thin', None)
		self.refused('joint', 0, mortar='layer')

	def testBond(self):
		self.refused('bond', 'herringbone', 'English', None)

	def testBlocksPerBrick(self):
		self.refused('blocksPerBrick', (1, 1), (1, 0, 1), (1.5, 1, 1), (True, 1, 1), 2, None)

	def testMortar(self):
		self.refused('mortar', 'glue', None, 'Layer')

	def testOpenings(self):
		self.refused('openings', 5, None)
		self.refused('openings', [(0.5, 0.1, 0.5)], [(0.5, 0.1, 0.5, 0)], [(-0.1, 0.1, 0.5, 0.1)], [(2.5, 0.1, 0.5, 0.1)], [(0.5, 0.1, 0.5, 0.3)], [(0.5, 0.1, 'a', 0.1)],
		             [(0.5, float('nan'), 0.5, 0.1)], [None], message='openings[0]')
		self.refused('openings', [(0.5, 0.1, 0.5, 0.1), (0.9, 0.15, 0.5, 0.1)], message='openings[1]')
		wallLayout(LENGTH, HEIGHT, ONE, openings=[(0.5, 0.1, 0.5, 0.1), (1.0, 0.1, 0.5, 0.1)])  # touching is not overlapping

	def testBeams(self):
		self.refused('baseBeam', 0, -0.2, float('nan'), '0.2')
		self.refused('topBeam', 0, -0.2, float('inf'))
		self.refused('beamBlocks', 0, 1.5, None, True)


class Large(unittest.TestCase):

	def testHundredThousandBlocks(self):
		"""Running bond, 20.01 x 2.98 m (77 bricks, 46 courses), blocksPerBrick (4, 2, 4): 113 344 blocks. Its set-up time is
		measured by scripts/masonry_cost.py (doc/masonry-cost.md), not asserted here: a test does not assert wall-clock time."""
		start = time.perf_counter()
		lay = wallLayout(20.01, 2.98, ONE, bond='running', blocksPerBrick=(4, 2, 4))
		elapsed = time.perf_counter() - start
		print('\n    wallLayout: %d blocks, %d pairs in %.2f s' % (len(lay.blocks), len(lay.pairs), elapsed), file=sys.stderr)
		self.assertEqual(len(lay.blocks), 46 * 77 * 32)


if __name__ == '__main__':
	unittest.main()
