"""Issue #25: RdemTimeStepper takes its stiffness from the law and the Poisson engine (RdemStiffnessSource), and that
stiffness is the one of the forces they apply: for a small perturbation du of a bonded assembly at rest, K du (
RdemTimeStepper.stiffnessTimes) equals minus the change of the forces and torques the engines then apply.

Scenes: a 2x2x2 grid of 2 cm concrete cubes bonded face to face, with the paper's Poisson element, with the consistent
formulation's element (skin), and with Poisson cells; a 3x1x2 stack of unequal blocks (no Poisson engine); and two
running-bond courses of 4 cm blocks on a 12 cm beam, with cells: bonds with offset centroids, whose shear springs'
offset correction couples them to the cells' strains at a lever of up to 5 cm (rdem::offsetSlip). Every
block is held (blocked DOFs, at rest) so that a step only evaluates the forces; du: random translations of 1e-9 m and
rotations of 1e-7 rad (the linear range of the 2 cm blocks: second-order terms ~1e-7 of the first).

Tolerance: |F(du) - F(0) + K du| <= 1e-5 |K du|: the springs follow the blocks' rotations (their normals and arms turn
by du's rotations), a second-order term of relative size ~1e-7; round-off of positions ~1e-17 m against 1e-9 m
displacements, 1e-8. A term missing from K or from the forces (a spring, an element, a weight of the consistent
formulation) is of relative size >= 1e-2. Measured: 3.0e-8 (paper element), 5.8e-8 (consistent element), 6.3e-8
(cells), 3.4e-8 (springs only), 4.2e-8 (running bond on a beam; 3.8e-2 with
K left without the offset correction's coupling, as it was before it was added)."""
import random
import unittest
import harness
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat
import rdem
import stability_cases as sc

TOL = 1e-5


def heldGrid(formulation, elements='auto', counts=(2, 2, 2), sizes=(2 * sc.H, ) * 3):
	harness.freshScene()
	mat = O.materials.append(RdemMat(young=sc.E, poisson=0.2, tensileStrength=sc.INF, cohesion=sc.INF))
	O.engines = rdem.engines(formulation=formulation, recontact=False, dt=1e-12)
	ids = rdem.blockGrid(counts, sizes, mat)
	rdem.bond(ids)
	if formulation:
		rdem.poissonEngine().elements = elements
		rdem.poissonEngine().build(ids)
	for i in ids:
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	return ids


def forcesAndTorques():
	"""One step with every block held: the forces and torques of the current configuration, 6 per body [N, N m]."""
	O.step()
	out = []
	for b in O.bodies:
		out += list(O.forces.f(b.id)) + list(O.forces.t(b.id))
	return out


def perturbation(seed=1):
	rnd = random.Random(seed)
	x = []
	for _ in O.bodies:
		x += [rnd.uniform(-1e-9, 1e-9) for _ in range(3)] + [rnd.uniform(-1e-7, 1e-7) for _ in range(3)]
	return x


def displace(x):
	for b in O.bodies:
		u, theta = Vector3(*x[6 * b.id:6 * b.id + 3]), Vector3(*x[6 * b.id + 3:6 * b.id + 6])
		b.state.pos += u
		if theta.norm() > 0:
			b.state.ori = Quaternion(theta / theta.norm(), theta.norm()) * b.state.ori


def heldRunningBondOnABeam():
	"""A 12 x 2 x 2 cm beam and two courses of 4 x 2 x 2 cm blocks on it, the second offset by half a block."""
	harness.freshScene()
	mat = O.materials.append(RdemMat(young=sc.E, poisson=0.2, tensileStrength=sc.INF, cohesion=sc.INF))
	O.engines = rdem.engines(formulation='consistent', recontact=False, dt=1e-12)
	h = 0.01
	ids = [O.bodies.append(rdem.block((0, 0, 0), (6 * h, h, h), mat))]
	ids += [O.bodies.append(rdem.block((x * h, 0, 2 * h), (2 * h, h, h), mat)) for x in (-4, 0, 4)]
	ids += [O.bodies.append(rdem.block((x * h, 0, 4 * h), (2 * h, h, h), mat)) for x in (-2, 2)]
	rdem.bond(ids)
	rdem.poissonEngine().elements = 'cells'
	rdem.poissonEngine().build(ids)
	for i in ids:
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	return ids


class StiffnessSource(unittest.TestCase):

	def check(self, label):
		x = perturbation()
		Kx = rdem.timeStepper().stiffnessTimes(x)
		F0 = forcesAndTorques()
		displace(x)
		F1 = forcesAndTorques()
		norm = lambda v: sum(a * a for a in v)**0.5
		err = norm([f1 - f0 + k for f1, f0, k in zip(F1, F0, Kx)]) / norm(Kx)
		print('%s: |dF + K du| / |K du| = %.3g (|K du| = %.3g)' % (label, err, norm(Kx)))
		self.assertGreater(norm(Kx), 0)
		self.assertLess(err, TOL, label)

	def testSpringsOnly(self):
		heldGrid(None, counts=(3, 1, 2), sizes=(0.04, 0.02, 0.015))
		self.check('springs, unequal blocks')

	def testPaperElement(self):
		heldGrid('paper')
		self.assertEqual(rdem.poissonEngine().nElements, 1)
		self.check('paper element')

	def testConsistentElement(self):
		heldGrid('consistent')
		self.assertEqual(rdem.poissonEngine().nElements, 1)
		self.check('consistent element')

	def testConsistentCells(self):
		heldGrid('consistent', elements='cells')
		self.assertEqual(rdem.poissonEngine().nCells, 8)
		self.check('consistent cells')

	def testRunningBondOnABeam(self):
		heldRunningBondOnABeam()
		offsets = [I for I in O.interactions if I.isReal and I.phys.offsetCorrection]
		self.assertEqual(len(offsets), 6)  # 2 of the beam's 3 bonds (the middle block is centred) and the 4 between courses
		self.check('running bond on a beam')


if __name__ == '__main__':
	harness.run(StiffnessSource)
