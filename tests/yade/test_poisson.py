"""RdemPoissonEngine (paper §4.2, eqs. 18-21) against an independent dense reference, and its topology rules."""
import math
import os
import sys
import unittest
import numpy as np
import harness
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat
from yade import rdem

E, NU, H = 30e9, 0.2, 0.01
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))


def referenceKp(X):
	"""K_p = sum over 2x2x2 Gauss points of B^T D_p B det J, written out independently with numpy (node a = i + 2j + 4k)."""
	corners = np.array([[2 * (a & 1) - 1, ((a >> 1) & 1) * 2 - 1, ((a >> 2) & 1) * 2 - 1] for a in range(8)], float)
	Dp = np.zeros((6, 6))
	Dp[:3, :3] = LAM
	np.fill_diagonal(Dp[:3, :3], 0)
	K = np.zeros((24, 24))
	g = 1 / math.sqrt(3)
	for gp in corners * g:
		dN = np.array([[c[d] * np.prod([1 + c[e] * gp[e] for e in range(3) if e != d]) / 8 for c in corners] for d in range(3)])
		J = dN @ X
		dNdx = np.linalg.solve(J, dN)
		B = np.zeros((6, 24))
		for a in range(8):
			dx, dy, dz = dNdx[:, a]
			B[0, 3 * a], B[1, 3 * a + 1], B[2, 3 * a + 2] = dx, dy, dz
			B[3, 3 * a + 1], B[3, 3 * a + 2] = dz, dy
			B[4, 3 * a], B[4, 3 * a + 2] = dz, dx
			B[5, 3 * a], B[5, 3 * a + 1] = dy, dx
		K += B.T @ Dp @ B * np.linalg.det(J)
	return K


class Poisson(unittest.TestCase):

	def grid(self, counts, corotational=False):
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=E, poisson=NU, tensileStrength=float('inf')))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation='paper', corotational=corotational, recontact=False, dt=1e-9)
		ids = rdem.blockGrid(counts, (2 * H, ) * 3, material=mat)
		rdem.bond(ids)
		rdem.poissonEngine().build(ids)
		for i in ids:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
		return ids

	def poissonForces(self, ids):
		"""Forces of the Poisson engine alone: the step with the engine minus the step without it."""
		eng = rdem.poissonEngine()
		O.step()
		withP = [Vector3(O.forces.f(i)) for i in ids]
		eng.dead = True
		O.step()
		eng.dead = False
		return [w - Vector3(O.forces.f(i)) for w, i in zip(withP, ids)]

	def testElementCount(self):
		self.grid((4, 3, 5))
		self.assertEqual(rdem.poissonEngine().nElements, 3 * 2 * 4)

	def testMatchesDenseReference(self):
		ids = self.grid((2, 2, 2))
		X = np.array([list(O.bodies[i].state.refPos) for i in ids])
		rng = np.random.default_rng(1)
		u = rng.uniform(-1e-6, 1e-6, (8, 3))
		for i, d in zip(ids, u):
			O.bodies[i].state.pos = O.bodies[i].state.refPos + Vector3(*d)
		F = np.array([list(f) for f in self.poissonForces(ids)]).ravel()
		Fref = -referenceKp(X) @ u.ravel()
		# same arithmetic in another order: 1e-10 of the largest force (differences of O(1e3 N) spring forces included)
		self.assertLess(np.abs(F - Fref).max(), 1e-9 * np.abs(Fref).max())

	def testCompressionPushesOutward(self):
		ids = self.grid((2, 2, 2))
		for i in ids:
			s = O.bodies[i].state
			s.pos = s.refPos - Vector3(0, 0, 1e-3 * (s.refPos[2] - 2 * H))  # 0.1 % shortening along z about the centre
		F = self.poissonForces(ids)
		for i, f in zip(ids, F):
			r = O.bodies[i].state.refPos - Vector3(2 * H, 2 * H, 2 * H)
			self.assertGreater(f[0] * r[0], 0)  # outward in x
			self.assertGreater(f[1] * r[1], 0)  # outward in y
			self.assertLess(abs(f[2]), 1e-9 * abs(f[0]))  # D_p has no zz-zz term: uniaxial strain gives no z force
		# magnitude: a box element under uniform strain e_zz gets nodal x-forces -lambda*e_zz * (face area)/4 each
		self.assertAlmostEqual(F[1][0] / (LAM * 1e-3 * (2 * H)**2 / 4), 1, delta=1e-9)

	def rotatedForces(self, corotational, angle, strain=0.0):
		ids = self.grid((3, 3, 3), corotational=corotational)
		q = Quaternion(Vector3(1, 1, 0).normalized(), angle)
		c = Vector3(3 * H, 3 * H, 3 * H)
		for i in ids:
			s = O.bodies[i].state
			local = s.refPos - c
			local[2] *= (1 - strain)
			s.pos = c + q * local
			s.ori = q
		return max(f.norm() for f in self.poissonForces(ids))

	def testCorotationalRigidRotation(self):
		ref = self.rotatedForces(True, 0.0, strain=1e-3)  # a 0.1 % strain, unrotated
		rot = self.rotatedForces(True, math.pi / 4)
		self.assertLess(rot, 1e-9 * ref)  # the bound; round-off is about 1e-13 of ref
		small = self.rotatedForces(False, math.pi / 4)
		# without corotation a 45 degree rigid rotation produces spurious forces far above the 0.1 % strain ones
		self.assertGreater(small, 10 * ref)
		print('Poisson forces of a 45 deg rigid rotation: small strain %.3g x, corotational %.3g x those of a 0.1 %% strain' %
		      (small / ref, rot / ref))

	def testCrackReleasesElement(self):
		ids = self.grid((2, 2, 2))
		eng = rdem.poissonEngine()
		self.assertEqual(eng.elementScales(), [1.0])
		phys = O.interactions[ids[0], ids[1]].phys
		phys.segState = [1, 1, 0, 0]  # half of one bond broken
		self.assertEqual(eng.elementScales(), [0.5])
		phys.segState = [1, 1, 1, 1]
		self.assertEqual(eng.elementScales(), [0.0])
		for i in ids:
			O.bodies[i].state.pos = O.bodies[i].state.refPos + Vector3(0, 0, 1e-6 * O.bodies[i].state.refPos[2])
		self.assertEqual(max(f.norm() for f in self.poissonForces(ids)), 0)

	def testErasedBlockReleasesItsElements(self):
		# Erasing a block (O.bodies.erase also erases its bonds) releases the elements it is a node of, and only those:
		# in a 3×3×3 grid the corner block (0,0,0) is a node of 1 of the 8 elements, the centre block of all 8. Steps go
		# on without touching the erased block (before the fix, the engine read its position and crashed).
		ids = self.grid((3, 3, 3))
		eng = rdem.poissonEngine()
		self.assertEqual(eng.elementScales(), [1.0] * 8)
		O.bodies.erase(ids[0])
		self.assertEqual(sorted(eng.elementScales()), [0.0] + [1.0] * 7)
		O.bodies.erase(ids[13])
		self.assertEqual(eng.elementScales(), [0.0] * 8)
		for i in ids:
			if O.bodies[i]:
				O.bodies[i].state.blockedDOFs = ''
				O.bodies[i].state.vel = Vector3(0, 0, 1e-3 * (O.bodies[i].state.pos[2] - H))
		rdem.run(20)
		self.assertEqual(O.iter, 20)
		self.assertTrue(all(O.bodies[i].state.pos.norm() < 1 for i in ids if O.bodies[i]))

	def testRefusesRunningBond(self):
		harness.freshScene()
		mat = O.materials.append(RdemMat())
		O.engines = rdem.engines(formulation='paper', recontact=False, dt=1e-9)
		lower = rdem.blockGrid((2, 2, 1), (2 * H, ) * 3, mat)
		upper = rdem.blockGrid((2, 2, 1), (2 * H, ) * 3, mat, origin=(H, 0, 2 * H))  # shifted by half a block
		rdem.bond(lower + upper)
		with self.assertRaisesRegex(ValueError, 'two bonded neighbours on one side'):
			rdem.poissonEngine().build(lower + upper)

	def testRefusesNoGroup(self):
		harness.freshScene()
		mat = O.materials.append(RdemMat())
		O.engines = rdem.engines(formulation='paper', recontact=False, dt=1e-9)
		ids = rdem.blockGrid((3, 3, 1), (2 * H, ) * 3, mat)  # one layer: no 2x2x2 group
		rdem.bond(ids)
		with self.assertRaisesRegex(ValueError, 'no 2x2x2 group'):
			rdem.poissonEngine().build(ids)


if __name__ == '__main__':
	harness.run(Poisson)
