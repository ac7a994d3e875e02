"""Contacts between blocks that are not bonded: friction limit (eq. 17), impact damping (eq. 13), oblique drop.

Sampled contacts (Ig2_RdemBlock_RdemBlock_RdemGeom): every face of each block is sampled on a trapezoid grid and a
sample that entered the other block pushes back with k_n per area times its weight (half per side)."""
import math
import os
import sys
import unittest
import harness
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat
import rdem

H = 0.01  # half-size of the 2 cm cubes [m]
RHO = 2300


class Contact(unittest.TestCase):

	def scene(self, h=1.0, phi=math.atan(0.624), gravity=(0, 0, 0), dt=2e-8):
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=30e9, poisson=0.2, density=RHO, frictionAngle=phi, dampingNormal=h, dampingShear=h))
		O.engines = rdem.engines(segmentsPerEdge=2, poisson=None, recontact=True, gravity=gravity, dt=dt)
		base = O.bodies.append(rdem.block((0, 0, 0), (H, H, H), mat, fixed=True))
		return mat, base

	def testImpactCriticalDamping(self):
		# A cube hits a fixed cube face-on at v0. With h = 1 the contact is critically damped for the cube's own mass
		# (m_ave = rho*l_A + rho*l_B = the cube's mass per face area, eq. 13), and a linear spring-dashpot that
		# separates when the force vanishes returns v0*exp(-2): it keeps exp(-4) = 1.83 % of its kinetic energy.
		mat, base = self.scene(h=1.0)
		v0 = 0.1
		b = O.bodies.append(rdem.block((0, 0, 2 * H), (H, H, H), mat))
		O.bodies[b].state.vel = Vector3(0, 0, -v0)
		O.run(3000, True)  # the contact lasts about 2/omega = 11 us = 550 steps
		vz = O.bodies[b].state.vel[2]
		# discretisation of the contact (omega*dt = 0.004) and the step at which the force vanishes: 2 % of the rebound
		self.assertAlmostEqual(vz / (v0 * math.exp(-2)), 1, delta=0.02)
		self.assertLess(abs(O.bodies[b].state.vel[0]) + abs(O.bodies[b].state.vel[1]), 1e-9)

	def testImpactUndampedIsElastic(self):
		mat, base = self.scene(h=0.0)
		b = O.bodies.append(rdem.block((0, 0, 2 * H), (H, H, H), mat))
		O.bodies[b].state.vel = Vector3(0, 0, -0.1)
		O.run(3000, True)
		self.assertAlmostEqual(O.bodies[b].state.vel[2] / 0.1, 1, delta=1e-3)  # leapfrog: energy error O((omega dt)^2)

	def testFrictionLimit(self):
		# A cube resting on a fixed cube under gravity, pushed sideways by F = 2*mu*m*g: it slides with a = (F - mu m g)/m = mu g.
		mu = 0.624
		g = 9.81
		mat, base = self.scene(h=1.0, phi=math.atan(mu), gravity=(0, 0, -g), dt=1e-7)
		b = O.bodies.append(rdem.block((0, 0, 2 * H), (H, H, H), mat))
		m = O.bodies[b].state.mass
		O.bodies[b].state.blockedDOFs = 'XYZ'  # no tipping: the test is about the friction limit
		O.run(2000, True)  # settle: critically damped, period 34 us = 340 steps
		F = 2 * mu * m * g
		O.forces.setPermF(b, Vector3(F, 0, 0))
		O.run(500, True)  # transient of the shear spring
		v1, t1 = O.bodies[b].state.vel[0], O.time
		O.run(5000, True)
		a = (O.bodies[b].state.vel[0] - v1) / (O.time - t1)
		self.assertAlmostEqual(a / (mu * g), 1, delta=0.01)  # 1 %: residual normal oscillation after settling
		# below the limit it sticks
		O.forces.setPermF(b, Vector3(0.5 * mu * m * g, 0, 0))
		O.bodies[b].state.vel = Vector3(0, 0, 0)
		O.run(2000, True)
		self.assertLess(abs(O.bodies[b].state.vel[0]), 1e-4)  # only the elastic shear spring moves (um/s)

	@unittest.skip('open defect (issue 3 note): a tumbling block can be driven unstable by edge and corner contacts; '
	               'the blocks stay apart in the first 0.2 s but the run does not always come to rest')
	def testObliqueDropComesToRest(self):
		# A cube tilted 30 degrees about two axes falls corner first on a 5x5 layer of fixed cubes (a fractured floor:
		# cubes touching, not bonded, so it lands across their joints); it must bounce, tumble and come to rest on top
		# without sinking in: face, edge, corner and edge-to-edge contacts all take part.
		mat, base = self.scene(h=1.0, gravity=(0, 0, -9.81), dt=2e-6)
		layer = rdem.blockGrid((5, 5, 1), (2 * H, ) * 3, mat, origin=(-5 * H, -5 * H, 2 * H))
		for i in layer:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
		q = Quaternion(Vector3(1, 0, 0), math.radians(30)) * Quaternion(Vector3(0, 1, 0), math.radians(30))
		b = O.bodies.append(rdem.block((0.3 * H, 0.2 * H, 4 * H + 2 * H * math.sqrt(3)), (H, H, H), mat, orientation=q))
		O.bodies[b].state.vel = Vector3(0, 0, -0.5)
		top = 4 * H  # top face of the layer
		lowest = []
		for _ in range(200):  # 0.4 s at most
			O.run(1000, True)
			s = O.bodies[b].state
			R = s.ori.toRotationMatrix()
			corners = [s.pos + R * Vector3(sx * H, sy * H, sz * H) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
			lowest.append(min(c[2] for c in corners))
			if s.vel.norm() < 1e-3 and s.angVel.norm() < 0.05:
				break
		s = O.bodies[b].state
		self.assertLess(s.vel.norm(), 1e-3)  # at rest [m/s]
		self.assertLess(s.angVel.norm(), 0.05)  # [rad/s]
		# never sank in: deepest corner below the layer's top by less than 1 % of the block size at any sampled time
		self.assertGreater(min(lowest), top - 0.02 * H)
		# it rests flat on a face: its lowest corners on the layer (within the static overlap m g / k, nanometres)
		self.assertAlmostEqual(lowest[-1], top, delta=0.01 * H)


if __name__ == '__main__':
	harness.run(Contact)
