"""Restoring springs of two bonded blocks against closed forms (paper eqs. 11, 12, 14).

Block A (id 0) is fixed; block B (id 1) is placed by hand and all its DOFs are blocked, so one O.step() computes the
spring forces of that exact configuration without moving anything. Face springs of 2x2 segments (paper §5)."""
import math
import os
import sys
import unittest
import harness
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat
from yade import rdem

E, NU, A_HALF = 30e9, 0.2, 0.01  # concrete (paper Table 1), cubes of 2 cm
AREA = (2 * A_HALF)**2
KN = 1 / (2 * A_HALF * (1 - NU**2) / E)  # eq. 11 for each block (ell = A_HALF), eq. 12 in series [N/m3]
KS = 1 / (2 * A_HALF * 2 * (1 + NU) / E)


class TwoBlocks(unittest.TestCase):

	def setUp(self):
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=E, poisson=NU, density=2300, tensileStrength=float('inf')))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=False, dt=1e-9)
		self.ids = rdem.blockGrid((2, 1, 1), (2 * A_HALF, ) * 3, material=mat)
		self.assertEqual(rdem.bond(self.ids), 1)
		for i in self.ids:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'

	def forceOnB(self, pos=None, ori=None):
		b = O.bodies[1].state
		if pos is not None:
			b.pos = pos
		if ori is not None:
			b.ori = ori
		O.step()
		return O.forces.f(1), O.forces.t(1), O.forces.f(0), O.forces.t(0)

	def testTension(self):
		u = 1e-7  # [m]: sigma = KN*u = 7.8 MPa
		f, t, f0, t0 = self.forceOnB(pos=O.bodies[1].state.pos + Vector3(u, 0, 0))
		# Exact up to round-off: u is a difference of positions of 0.03 m (3e-18 m round-off, 3e-11 of u); 1e-9 relative.
		self.assertAlmostEqual(f[0] / (-KN * AREA * u), 1, delta=1e-9)
		self.assertLess(abs(f[1]) + abs(f[2]), 1e-9 * abs(f[0]))
		self.assertLess((f + f0).norm(), 1e-12 * f.norm())  # action = reaction

	def testShear(self):
		for axis in (1, 2):
			u = Vector3(0, 0, 0)
			u[axis] = 1e-7
			f, t, f0, t0 = self.forceOnB(pos=O.bodies[1].state.refPos + u)
			# shear spring isotropic in the face plane, exact up to the round-off of u (as in testTension)
			self.assertAlmostEqual(f[axis] / (-KS * AREA * u[axis]), 1, delta=1e-9)
			self.assertLess((f + f0).norm(), 1e-12 * f.norm())

	def testBending(self):
		theta = 1e-7  # [rad] about y through the face centre: pure normal springs, u_n = theta*z at each segment
		c = Vector3(2 * A_HALF, A_HALF, A_HALF)  # face centre
		q = Quaternion(Vector3(0, 1, 0), theta)
		f, t, f0, t0 = self.forceOnB(pos=c + q * (O.bodies[1].state.pos - c), ori=q)
		# closed form: M_y = -KN*theta*sum(A_i z_i^2); 2x2 segments at z = +-a/2 with A_i = AREA/4 -> sum = AREA*a^2/4
		expected = -KN * theta * AREA * A_HALF**2 / 4
		# second-order terms in theta (1e-7) and the moment arm of the mid-point (u/2): 1e-6 relative
		self.assertAlmostEqual(t[1] / expected, 1, delta=1e-6)

	def testTwisting(self):
		theta = 1e-7  # about x, the axis through both centroids: pure shear springs
		c = O.bodies[1].state.pos
		q = Quaternion(Vector3(1, 0, 0), theta)
		f, t, f0, t0 = self.forceOnB(ori=q)
		# closed form: M_x = -KS*theta*sum(A_i r_i^2), r_i^2 = a^2/2 for the 4 segments -> AREA*a^2/2
		expected = -KS * theta * AREA * A_HALF**2 / 2
		self.assertAlmostEqual(t[0] / expected, 1, delta=1e-6)  # second order in theta
		self.assertLess((t + t0).norm() / abs(expected), 1e-6)  # twisting moments balance (arms differ by u/2)

	def testRigidMotionIsForceFree(self):
		# 45 degrees about an arbitrary axis plus a translation: the material points stay together, no force at all.
		q = Quaternion(Vector3(1, 2, 3).normalized(), math.pi / 4)
		for i in self.ids:
			s = O.bodies[i].state
			s.pos = Vector3(0.3, -0.2, 0.1) + q * s.refPos
			s.ori = q
		O.step()
		# round-off of positions of magnitude 0.3 m: 1e-16 relative -> |d| ~ 1e-17 m, force ~ KN*AREA*1e-17 ~ 1e-8 N
		self.assertLess(O.forces.f(1).norm(), KN * AREA * 1e-15)

	def testSegmentGeometry(self):
		# The 2x2 segments of the shared face x = 2 A_HALF: centres at (2a, a ± a/2, a ± a/2) with a = A_HALF, the same
		# material points seen from both blocks, areas summing to the face; then the relative displacement of each
		# segment's points after moving B by u and turning it by theta about x through its centroid (rigid-body
		# kinematics by hand). Round-off of coordinates of 0.03 m: 1e-17 m; 1e-15 m is 100 times that.
		O.step()
		g = O.interactions[0, 1].geom
		a = A_HALF
		self.assertTrue(g.bonded)
		self.assertEqual(len(g.segPoint1), 4)
		self.assertAlmostEqual(sum(g.segArea) / AREA, 1, delta=1e-14)
		s1, s2 = O.bodies[0].state, O.bodies[1].state
		expected = sorted((round(2 * a, 9), round(a + dy, 9), round(a + dz, 9)) for dy in (-a / 2, a / 2) for dz in (-a / 2, a / 2))
		found = sorted(tuple(round(x, 9) for x in s1.pos + s1.ori * p) for p in g.segPoint1)
		self.assertEqual(found, expected)
		for p1, p2 in zip(g.segPoint1, g.segPoint2):
			self.assertLess((s1.pos + s1.ori * p1 - (s2.pos + s2.ori * p2)).norm(), 1e-15)
		u, theta = Vector3(1e-7, -2e-7, 3e-7), 1e-4
		s2.pos = s2.refPos + u
		s2.ori = Quaternion(Vector3(1, 0, 0), theta)
		for p1, p2, d in zip(g.segPoint1, g.segPoint2, g.segDisp(s1, s2)):
			arm = s1.pos + s1.ori * p1 - s2.refPos  # the point relative to B's centroid before the motion
			moved = s2.refPos + u + Quaternion(Vector3(1, 0, 0), theta) * arm
			self.assertLess((d - (moved - (s1.pos + s1.ori * p1))).norm(), 1e-15)
			self.assertGreater(d.norm(), 1e-7)  # the test sees the motion


if __name__ == '__main__':
	harness.run(TwoBlocks)
