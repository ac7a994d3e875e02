"""Poisson cells (doc/theory.md §5.4): a uniform uniaxial-stress state is an exact equilibrium of springs plus cells on
masonry layouts that are not grids of 2×2×2 groups, so the apparent E and ν equal the input.

How the apparent values are measured: every block (platens included) is placed on the uniform field of a uniaxial
compression of strain ε = -1e-5 along the load axis and +νε… across it (-ν times the axial strain), all DOFs blocked, and
one step evaluates the forces. If every free DOF of every block (the platens' translation along the load axis is the
prescribed one) carries no force, that field is the static solution of the compression test between frictionless
platens; its lateral strain over its axial strain is then exactly -ν (apparent ν = input), and the reaction on the
loaded platen over the cross-section and the strain gives the apparent E. Free-DOF forces are compared with one bed
face's spring force, the scale of the terms that cancel: round-off of sums of O(1e3) N terms gives 1e-12 … 1e-10.
Torques carry in addition the second-order term of forces applied at displaced points (see TOL_TORQUE).

Walls (joints of the brick's own E and ν, interface joints 10 mm, 250×120×55 mm bricks, 3 stretchers × 4 courses):
(a) running bond, one block per brick, two wythes (and one wythe: plane stress through the thickness, x and z only);
(b) a one-brick-thick English bond wall (two wythes of stretchers, headers through the wall), one block per brick along
x and z, headers cut in two through the thickness (2×1×1 blocks per brick) for all three axes; (c) running bond with
bricks of 2×1×1 and 3×1×1 blocks, two wythes. ν ∈ {0.15, 0.3, 0.45}."""
import unittest
import harness
import wall_cases as wc
from yade import O
from yade import rdem

NUS = (0.15, 0.3, 0.45)
EPS = -1e-5  # uniaxial compression
TOL = 1e-9  # of a bed face's spring force (round-off 1e-12 ... 1e-10, see above)
# Torques, over a bed face's spring force times a brick length: the forces act at the displaced points, a second-order
# term ε·F·L, of relative size O(ε) (1.6e-7 at ε = 1e-5, ten times less at 1e-6: it scales with ε, so it is not a
# linear residual); 0.1|ε| bounds it.
TOL_TORQUE = 0.1 * abs(EPS)


class CellsAreExact(unittest.TestCase):

	def check(self, bond, wythes, blocksPerBrick, axes, elements='auto'):
		for nu in NUS:
			for load in axes:
				wall, plates = wc.homogeneousWall(bond, wythes, blocksPerBrick, nu, load, elements=elements)
				msg = '%s, %d wythes, blocks %s, nu = %g, load along %s, elements %s' % (bond, wythes, blocksPerBrick, nu, 'xyz'[load], elements)
				self.assertGreater(rdem.poissonEngine().nCells, 0, msg)
				self.assertEqual(rdem.poissonEngine().nElements, 0, msg)
				force, torque, eRatio = wc.uniformResidual(wall, plates, nu, load, eps=EPS)
				self.assertLess(force, TOL, msg)
				self.assertLess(torque, TOL_TORQUE, msg)
				self.assertAlmostEqual(eRatio, 1, delta=TOL, msg=msg)

	def testRunningBondOneBlockPerBrick(self):
		self.check('running', 2, (1, 1, 1), (0, 1, 2))
		self.check('running', 1, (1, 1, 1), (0, 2))

	def testEnglishBond(self):
		self.check('english', 2, (1, 1, 1), (0, 2))
		self.check('english', 2, (2, 1, 1), (0, 1, 2))

	def testRunningBondBricksOfSeveralBlocks(self):
		# 2×1×1 blocks per brick line up across the bed joints (half a brick is one block): a grid, which 'auto' gives the
		# paper's hexahedra; the cells are asked for here. 3×1×1 blocks do not line up.
		self.check('running', 2, (2, 1, 1), (0, 1, 2), elements='cells')
		self.check('running', 2, (3, 1, 1), (0, 1, 2))

	def testWithoutTheOffsetCorrectionItIsNot(self):
		# The same running-bond wall with the shear springs' offset correction switched off:
		# the bed joints' shear springs resist the lateral expansion, and the uniform state is far from equilibrium.
		wall, plates = wc.homogeneousWall('running', 2, (1, 1, 1), 0.3, 2)
		for I in O.interactions:
			I.phys.offsetCorrection = False
		force, torque, eRatio = wc.uniformResidual(wall, plates, 0.3, 2, eps=EPS)
		self.assertGreater(force, 1e-2)


if __name__ == '__main__':
	harness.run(CellsAreExact)
