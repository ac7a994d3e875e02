"""Poisson cells are conservative and stable at RdemTimeStepper's step (doc/theory.md §5.4): a running-bond wall (two
wythes, one block per brick: every bed joint has the offset correction, whose reaction on the cells keeps the stiffness
symmetric) at ν = 0.45, the hardest case, all blocks free, set vibrating by a random velocity field, no damping.

The total energy (kinetic + springs + cells, all from O.energy) of a linear conservative model integrated by the
leapfrog oscillates about its initial value by O(ω Δt) of it and does not drift; a non-symmetric stiffness (an
offset correction without its reaction) or a step above the stability limit makes it grow. Over 20 000 steps at 0.8
of the estimated critical step the largest excursion stays within 5 % of the initial energy (measured: 2.8 %; at 2.6 times
the estimated step, still below the stability limit, 19 %), the
mean of the second half within 1 % of the first's."""
import random
import statistics
import unittest
import harness
import wall_cases as wc
from yade import O, Vector3
from yade import rdem


class CellsAreStable(unittest.TestCase):

	def testRunningBondWallVibrates(self):
		wall, plates = wc.homogeneousWall('running', 2, (1, 1, 1), 0.45, 2)
		for p in plates[0] + plates[1]:
			O.bodies[p].state.blockedDOFs = ''
		rdem.timeStepper().active = True
		rdem.timeStepper().method = 'gershgorin'  # the step the excursion bound was measured at (docstring)
		O.dt = -1
		rnd = random.Random(7)
		for b in O.bodies:
			b.state.vel = Vector3(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-1, 1)) * 1e-3
			b.state.angVel = Vector3(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-1, 1)) * 1e-2
		O.trackEnergy = True
		totals, shares = [], []
		for _ in range(200):
			for _ in range(100):
				O.step()
			totals.append(O.energy.total())
			shares.append(abs(O.energy['rdemPoisson']) / O.energy['rdemElastic'])
		self.assertGreater(rdem.poissonEngine().nCells, 0)
		# The cells' energy is their quadratic form 1/2 s e^T K e over the blocks (K = V(D - M I), RdemState.cellStiffness),
		# to round-off; it is negative here (D - M I is indefinite and the random field mostly shears) and averages
		# 17.6 % of the springs' energy in size (measured): the cells take part, 5 % is a floor well below that.
		cells = sum(0.5 * b.state.cellScale * b.state.strain.dot(b.state.cellStiffness * b.state.strain) for b in O.bodies)
		self.assertAlmostEqual(O.energy['rdemPoisson'] / cells, 1, delta=1e-9)
		self.assertGreater(statistics.mean(shares), 0.05)
		e0 = totals[0]
		self.assertLess(max(abs(e / e0 - 1) for e in totals), 0.05)
		first, second = statistics.mean(totals[:100]), statistics.mean(totals[100:])
		self.assertAlmostEqual(second / first, 1, delta=0.01)


if __name__ == '__main__':
	harness.run(CellsAreStable)
