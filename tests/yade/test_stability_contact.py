"""Stability of contacts between blocks that are not bonded (issue 7): a cracked column collapsing under gravity onto a
fixed floor, and a block thrown at 5 m/s and 30 degrees onto an assembly. Both with the time step of RdemTimeStepper,
critical damping (h = 1, eq. 13), Coulomb friction (eq. 17) and O.trackEnergy.

Checked throughout: positions and velocities finite; no energy created (harness.EnergyBalance: the total energy, with
the work of gravity as the potential energy 'gravWork', never rises above an earlier value by more than a tolerance);
no block through another (two cubes of half-size H that do not overlap have centroids at least 2H apart: their
inscribed spheres do not overlap) or through the floor."""
import math
import unittest
import harness
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat
from yade import rdem

H = 0.01  # half-size of the 2 cm cubes [m]
G = 9.81


def material(tensileStrength=float('inf'), cohesion=float('inf')):
	return O.materials.append(
	    RdemMat(young=30e9,
	            poisson=0.2,
	            density=2300,
	            frictionAngle=math.atan(0.624),
	            dampingNormal=1.0,
	            dampingShear=1.0,
	            tensileStrength=tensileStrength,
	            cohesion=cohesion))


def corners(b):
	"""The 8 corners of a block body."""
	s, h = b.state, b.shape.extents
	R = s.ori.toRotationMatrix()
	return [s.pos + R * Vector3(sx * h[0], sy * h[1], sz * h[2]) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]


class Watch:
	"""Worst figures of the free cubes over a run, checked every `every` steps."""

	def __init__(self, ids, floorTop):
		self.ids, self.floorTop = ids, floorTop
		self.closest = float('inf')  # smallest centroid distance of two cubes, over 2H
		self.deepest = 0.0  # deepest corner below the floor's top [m]
		self.finite = True

	def check(self):
		states = [O.bodies[i].state for i in self.ids]
		for s in states:
			self.finite = self.finite and all(math.isfinite(x) for x in list(s.pos) + list(s.vel) + list(s.angVel))
		for a in range(len(states)):
			for b in range(a + 1, len(states)):
				self.closest = min(self.closest, (states[a].pos - states[b].pos).norm() / (2 * H))
		self.deepest = max(self.deepest, max(self.floorTop - c[2] for i in self.ids for c in corners(O.bodies[i])))

	def kinetic(self):
		return sum(0.5 * O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm() + 0.5 * O.bodies[i].state.inertia[0] * O.bodies[i].state.angVel.squaredNorm()
		           for i in self.ids)  # cubes: isotropic inertia


class StabilityContact(unittest.TestCase):

	def testCrackedColumnCollapses(self):
		# A column of 6 cubes standing on a fixed floor slab, tilted 10 degrees about x and bonded with springs of almost
		# no strength (f_t = c = 1 kPa, 1e-4 of concrete): its own weight opens the joints, it falls apart, the blocks
		# tumble, hit the floor and each other and must come to rest.
		harness.freshScene()
		mat = material(tensileStrength=1e3, cohesion=1e3)
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=True, gravity=(0, 0, -G))
		floor = O.bodies.append(rdem.block((0, 0, -H), (30 * H, 30 * H, H), mat, fixed=True))  # top at z = 0
		column = rdem.blockGrid((1, 1, 6), (2 * H, ) * 3, mat, origin=(-H, -H, 0.01 * H))
		bonds = rdem.bond(column)
		tilt = Quaternion(Vector3(1, 0, 0), math.radians(10))  # about the column's bottom edge: bonds follow rigid motions
		pivot = Vector3(0, -H, 0.01 * H)
		for i in column:
			s = O.bodies[i].state
			s.pos = pivot + tilt * (s.pos - pivot)
			s.ori = tilt * s.ori
		O.trackEnergy = True
		O.step()
		watch = Watch(column, 0.0)
		balance = harness.EnergyBalance()
		inflow = sum(O.bodies[i].state.mass * G * (O.bodies[i].state.pos[2] - H) for i in column)  # fall to resting on the floor
		restTime = None
		while O.time < 1.5:
			balance.run(20)
			watch.check()
			if watch.kinetic() < 1e-9 * inflow:
				restTime = restTime or O.time
				if O.time > restTime + 0.02:
					break
			else:
				restTime = None
		law = rdem.build.law()
		print('cracked column: %d bonds, %d tension and %d shear breaks, dt %.3g s, rest at %.3f s, energy growth %.3g J = %.3g of the inflow %.3g J, '
		      'closest centroids %.4f x 2H, deepest corner %.3g m below the floor' %
		      (bonds, law.tensionBreaks, law.shearBreaks, O.dt, restTime or float('nan'), balance.growth, balance.growth / inflow, inflow,
		       watch.closest, watch.deepest))
		self.assertTrue(watch.finite)
		self.assertEqual(bonds, 5)
		self.assertGreater(law.tensionBreaks + law.shearBreaks, 0)  # it did crack
		# it fell apart: the top block is no longer above the others
		self.assertLess(O.bodies[column[-1]].state.pos[2], 5 * H)
		# at rest within 1.5 s (measured 0.72 s): kinetic energy below 1e-9 of the inflow, for 20 ms (4000 periods of a
		# resting contact)
		self.assertIsNotNone(restTime)
		# no block through another or the floor: centroids at least 2H(1 - 1e-3) apart (a 10 um overlap; the contact
		# overlaps of these impacts are ~1 um) and no corner deeper than 1e-3 H below the floor
		self.assertGreater(watch.closest, 1 - 1e-3)
		self.assertLess(watch.deepest, 1e-3 * H)
		# no energy created beyond 0.1 % of the inflow (measured 0.016 %; see the oblique drop in test_contact)
		self.assertLess(balance.growth, 1e-3 * inflow)

	def testFastObliqueImpact(self):
		# A cube tilted 30 degrees hits, at 5 m/s and 30 degrees from the vertical, a 3x3 layer of loose cubes resting on
		# a fixed slab: the impact scatters the layer; nothing may pass through, blow up or create energy.
		harness.freshScene()
		mat = material()
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=True, gravity=(0, 0, -G))
		floor = O.bodies.append(rdem.block((0, 0, -H), (30 * H, 30 * H, H), mat, fixed=True))
		layer = rdem.blockGrid((3, 3, 1), (2 * H, ) * 3, mat, origin=(-3 * H, -3 * H, 1e-3 * H))
		q = Quaternion(Vector3(1, 1, 0).normalized(), math.radians(30))
		b = O.bodies.append(rdem.block((-2.5 * H, 0.4 * H, 2 * H + 2 * H * math.sqrt(3)), (H, H, H), mat, orientation=q))
		v0 = 5.0
		O.bodies[b].state.vel = Vector3(v0 * math.sin(math.radians(30)), 0, -v0 * math.cos(math.radians(30)))
		ids = layer + [b]
		O.trackEnergy = True
		O.step()
		watch = Watch(ids, 0.0)
		balance = harness.EnergyBalance()
		inflow = 0.5 * O.bodies[b].state.mass * v0**2 + O.bodies[b].state.mass * G * O.bodies[b].state.pos[2]
		while O.time < 0.05:
			balance.run(20)
			watch.check()
		print('fast oblique impact: dt %.3g s, energy growth %.3g J = %.3g of the inflow %.3g J, closest centroids %.4f x 2H, deepest corner %.3g m below the floor, '
		      'kinetic energy left %.3g of the inflow' %
		      (O.dt, balance.growth, balance.growth / inflow, inflow, watch.closest, watch.deepest, watch.kinetic() / inflow))
		self.assertTrue(watch.finite)
		# the impact was hard: overlap of the face contact at 5 m/s, v/omega with omega = sqrt(k A/m) ~ 1.8e5 rad/s,
		# about 30 um; nothing deeper than 1e-2 H = 100 um, centroids at least 2H(1 - 1e-2) apart
		self.assertGreater(watch.closest, 1 - 1e-2)
		self.assertLess(watch.deepest, 1e-2 * H)
		# no energy created beyond 0.2 % of the inflow (measured 0.076 %: ten blocks whose contact points come and go,
		# with the approximate pairing of rotational kinetic energies; a sample entering 110 um deep through a gap of
		# the sampling created 57 % of the inflow in one step before entry depths were taken as spring offsets)
		self.assertLess(balance.growth, 2e-3 * inflow)
		# the contacts dissipated: less than half of the inflow is left as kinetic energy after 50 ms
		self.assertLess(watch.kinetic(), 0.5 * inflow)


if __name__ == '__main__':
	harness.run(StabilityContact)
