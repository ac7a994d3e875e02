"""Tests of rdem.partition (pure Python, no YADE): recursive coordinate bisection of block centroids into the
subdomains of YADE's MPI (yade.mpy), counted by hand on grids and a running-bond wall.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_partition`` (or through CTest)."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.partition import bisect, counts, neighbourhood, ranks, refusals  # noqa: E402


def grid(nx, ny, nz, h=0.02):
	"""Centroids of an nx × ny × nz grid of cubes of side h, x fastest (as rdem.blockGrid)."""
	return [((i + .5) * h, (j + .5) * h, (k + .5) * h) for k in range(nz) for j in range(ny) for i in range(nx)]


def runningBond(bricks=8, courses=6, l=0.25, h=0.065):
	"""Centroids of a one-wythe running-bond wall: every other course shifted by half a brick (half bricks at its ends)."""
	out = []
	for k in range(courses):
		z = (k + .5) * h
		if k % 2 == 0:
			out += [((i + .5) * l, 0.06, z) for i in range(bricks)]
		else:
			out += [(l / 4, 0.06, z)] + [((i + 1) * l, 0.06, z) for i in range(bricks - 1)] + [(bricks * l - l / 4, 0.06, z)]
	return out


class Bisect(unittest.TestCase):

	def test_paper_cube_two_workers_cut_between_layers(self):
		# 10 x 10 x 12 blocks (the specimen and its two platens): z is longest, 6 layers of 100 each side
		c = grid(10, 10, 12)
		parts = bisect(c, 2)
		self.assertEqual(counts(parts, 2), [600, 600])
		for p, (_, _, z) in zip(parts, c):
			self.assertEqual(p, 0 if z < 0.12 else 1)

	def test_three_parts_balanced_to_a_layer(self):
		# 1200 / 3 = 400 = 4 layers: the first cut leaves 4 layers, the second cuts the other 8 in halves
		parts = bisect(grid(10, 10, 12), 3)
		self.assertEqual(counts(parts, 3), [400, 400, 400])

	def test_slabs_are_contiguous(self):
		# every subdomain of a 4-part split of a long wall is an interval of x with no other subdomain inside it
		c = grid(40, 1, 10)
		parts = bisect(c, 4)
		self.assertEqual(counts(parts, 4), [100] * 4)
		spans = [(min(x for (x, _, _), q in zip(c, parts) if q == p), max(x for (x, _, _), q in zip(c, parts) if q == p)) for p in range(4)]
		for a in range(3):
			self.assertLess(spans[a][1], spans[a + 1][0])

	def test_never_through_a_layer(self):
		# 5 layers of 9 into 2: the balanced count 22.5 falls inside a layer; the cut goes to the nearest gap (18 or 27)
		parts = bisect(grid(3, 3, 5), 2)
		self.assertIn(counts(parts, 2), ([18, 27], [27, 18]))

	def test_running_bond_wall_cut_between_bricks(self):
		# 8 bricks x 6 courses, odd courses with two half bricks: 51 blocks; x is longest, cut near 25.5
		c = runningBond()
		parts = bisect(c, 2)
		n = counts(parts, 2)
		self.assertEqual(sum(n), 51)
		self.assertLessEqual(abs(n[0] - n[1]), 3)  # within the blocks that share one x (3 courses of one column)
		xLow = max(x for (x, _, _), p in zip(c, parts) if p == 0)
		xHigh = min(x for (x, _, _), p in zip(c, parts) if p == 1)
		self.assertLess(xLow, xHigh)

	def test_rounding_noise_is_one_layer(self):
		# centroids of one layer that differ by 1e-15 m are not cut apart
		c = [(0.01 + (1e-15 if i % 2 else 0), 0.001 * i, 0.0) for i in range(10)] + [(0.05, 0.001 * i, 0.0) for i in range(10)]
		parts = bisect(c, 2)
		self.assertEqual(len({parts[i] for i in range(10)}), 1)

	def test_one_part(self):
		self.assertEqual(bisect(grid(2, 2, 2), 1), [0] * 8)

	def test_refusals(self):
		with self.assertRaisesRegex(ValueError, 'parts = 0: must be an integer >= 1'):
			bisect(grid(2, 2, 2), 0)
		with self.assertRaisesRegex(ValueError, 'more subdomains than blocks'):
			bisect(grid(2, 1, 1), 3)
		with self.assertRaisesRegex(ValueError, 'coincide'):
			bisect([(0, 0, 0)] * 4, 2)
		with self.assertRaisesRegex(ValueError, 'use fewer subdomains'):
			bisect(grid(1, 1, 2) + [(0.01, 0.01, 0.01)], 3)  # two layers (2 and 1 blocks) cannot make 3 subdomains
		with self.assertRaisesRegex(ValueError, '3 coordinates'):
			bisect([(0, 0)], 1)


class Ranks(unittest.TestCase):

	def test_master_blocks_stay_and_the_others_are_bisected(self):
		# a 4 x 1 x 2 grid whose bottom row (a fixed beam, indices 0-3) stays on the master; the top row (4-7) goes to two
		# workers, cut across x (its longest side): ranks 1, 1, 2, 2, as bisect of the top row alone gives them
		c = grid(4, 1, 2)
		rank, perWorker = ranks(c, {0, 1, 2, 3}, 2)
		self.assertEqual(rank, [0, 0, 0, 0, 1, 1, 2, 2])
		self.assertEqual(perWorker, [2, 2])
		self.assertEqual(rank[4:], [p + 1 for p in bisect(c[4:], 2)])

	def test_no_master(self):
		rank, perWorker = ranks(grid(10, 10, 12), set(), 2)
		self.assertEqual(perWorker, [600, 600])
		self.assertNotIn(0, rank)


class Neighbourhood(unittest.TestCase):

	def chain(self, n):
		"""n blocks in a row, each bonded to the next."""
		return [(i, i + 1) for i in range(n - 1)]

	def test_layers_of_a_row(self):
		# blocks 0-4 on subdomain 1, 5-9 on 2: one layer out of 1 is block 5, two layers blocks 5 and 6
		parts = [1] * 5 + [2] * 5
		self.assertEqual(neighbourhood(parts, self.chain(10), 1, 0), [0, 1, 2, 3, 4])
		self.assertEqual(neighbourhood(parts, self.chain(10), 1, 1), [0, 1, 2, 3, 4, 5])
		self.assertEqual(neighbourhood(parts, self.chain(10), 1), [0, 1, 2, 3, 4, 5, 6])
		self.assertEqual(neighbourhood(parts, self.chain(10), 2), [3, 4, 5, 6, 7, 8, 9])

	def test_a_beam_brings_what_it_is_bonded_to(self):
		# a beam (block 0, the master's) under a course of 6 (1-6; 1-3 on subdomain 1): two layers out of subdomain 1 reach
		# the beam and, through it, the whole course, so that the beam's cell sees all its bonds
		parts = [0, 1, 1, 1, 2, 2, 2]
		pairs = [(0, k) for k in range(1, 7)] + [(k, k + 1) for k in range(1, 6)]
		self.assertEqual(neighbourhood(parts, pairs, 1), [0, 1, 2, 3, 4, 5, 6])
		self.assertEqual(neighbourhood(parts, pairs, 1, 1), [0, 1, 2, 3, 4])
		self.assertEqual(neighbourhood(parts, pairs, 0, 1), [0, 1, 2, 3, 4, 5, 6])

	def test_every_bond_of_a_block_and_its_neighbours_is_there(self):
		# a running-bond wall cut by bisection: for each subdomain, every block within one bond of it has all its bonds in the
		# neighbourhood (what the Poisson cells of the rank's blocks and ghosts are built from)
		c = runningBond(bricks=8, courses=6)
		l, h = 0.25, 0.065
		pairs = [(i, j) for i in range(len(c)) for j in range(i + 1, len(c))
		         if (abs(c[i][2] - c[j][2]) < 1e-9 and abs(abs(c[i][0] - c[j][0]) - l) < 0.126 and abs(c[i][0] - c[j][0]) < l + 1e-9)
		         or (abs(abs(c[i][2] - c[j][2]) - h) < 1e-9 and abs(c[i][0] - c[j][0]) < l / 2 + l / 4 - 1e-9)]
		parts = [p + 1 for p in bisect(c, 2)]
		near = {}
		for i, j in pairs:
			near.setdefault(i, set()).add(j)
			near.setdefault(j, set()).add(i)
		for part in (1, 2):
			made = set(neighbourhood(parts, pairs, part))
			ghosts = set(j for i in range(len(c)) if parts[i] == part for j in near[i]) - set(i for i in range(len(c)) if parts[i] == part)
			self.assertTrue(ghosts)
			for b in ghosts | set(i for i in range(len(c)) if parts[i] == part):
				self.assertLessEqual(near[b], made, b)
			self.assertLess(len(made), len(c))  # not the whole wall

	def test_refusals(self):
		with self.assertRaisesRegex(ValueError, 'layers = -1: must be an integer >= 0'):
			neighbourhood([1, 1], [(0, 1)], 1, -1)
		with self.assertRaisesRegex(ValueError, 'outside the 2 of parts'):
			neighbourhood([1, 1], [(0, 2)], 1)


class Refusals(unittest.TestCase):

	def test_springs_and_cells_with_exchange_run(self):
		self.assertEqual(refusals({}), [])
		self.assertEqual(refusals(dict(cells=1200, exchange=True, breakable=True, offsets=400)), [])  # running bond: both exchanges
		self.assertEqual(refusals(dict(trackEnergy=True)), [])  # energies: rdem.distributed.energies sums them over ranks
		# a beam's cell on the master, completed from every rank's part of its bonds (RdemGhostExchange.masterCells)
		self.assertEqual(refusals(dict(masterCells=[0], cells=10, exchange=True, masterCellsReduced=True)), [])

	def test_each_refusal_names_what(self):
		for f, what in ((dict(others=[7]), 'not RdemBlock'), (dict(masterMoving=[3]), 'only fixed'), (dict(cells=10), 'RdemGhostExchange'),
		                (dict(masterCells=[0], cells=10, exchange=True), 'with a Poisson cell'),
		                (dict(hex8=5), 'hexahedral')):
			r = refusals(f)
			self.assertEqual(len(r), 1, f)
			self.assertIn(what, r[0])


if __name__ == '__main__':
	unittest.main()
