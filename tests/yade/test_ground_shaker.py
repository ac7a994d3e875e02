"""RdemGroundShaker (rdem.earthquake.shaker) plays a ground motion (rdem.ground_motion):

* prescribed: the base block sits on the integrated ground displacement at every step (to round-off of the positions),
  with the velocity of the step, and stops at the last displacement after the record;
* inertial: NewtonIntegrator.gravity is gravity minus the ground acceleration at the current time;
* with O.trackEnergy, groundWork books the work of the motion (on the scene and on the base's own kinetic energy), so
  that the total energy of a block carried by the moving base (bonded to it) stays within 1e-3 of the largest energy the
  motion put in;
* bad arguments are refused with messages naming them."""
import math
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemGroundShaker
from yade import rdem
from yade.rdem import ground_motion as gm


def scene():
	harness.freshScene()
	mat = O.materials.append(RdemMat(young=30e9, poisson=0.2, density=2500, tensileStrength=float('inf'), cohesion=float('inf')))
	O.engines = rdem.engines(formulation=None, recontact=False, gravity=(0, 0, -9.81))
	base = O.bodies.append(rdem.block((0, 0, -0.05), (0.3, 0.3, 0.05), mat))
	top = O.bodies.append(rdem.block((0, 0, 0.1), (0.1, 0.1, 0.1), mat))
	rdem.bond([base, top])
	return base, top


class GroundShaker(unittest.TestCase):

	def testPrescribedBaseFollowsTheGround(self):
		base, top = scene()
		motion = gm.GroundMotion(x=gm.sinePulse(3.0, 0.2, dt=1e-3, before=0.01), y=gm.sinePulse(1.0, 0.1, dt=1e-3, before=0.02))
		sh = rdem.earthquake.shaker(motion, ids=[base])
		self.assertEqual(O.bodies[base].state.blockedDOFs, 'xyzXYZ')
		O.dt = 1e-5
		x0 = Vector3(O.bodies[base].state.pos)
		worst = 0
		for k in range(30000):
			O.step()
			u = O.bodies[base].state.pos - x0
			expected = sh.displacementAt(O.time)
			worst = max(worst, (u - expected).norm())
		# positions of 0.05 m moved by steps of 1e-5 s: round-off of 3e4 additions of ~1e-8 m to 0.05 m, below 1e-12 m
		self.assertLess(worst, 1e-12)
		self.assertGreater(O.time, motion.end)
		self.assertAlmostEqual((O.bodies[base].state.pos - x0)[0], motion.displacements()[-1][0], delta=1e-12)
		self.assertEqual(O.bodies[base].state.vel.norm(), 0)  # at rest after the record

	def testInertialModeTiltsGravity(self):
		base, top = scene()
		motion = gm.GroundMotion(x=gm.constant(2.0, 0.1, 1e-3))
		sh = rdem.earthquake.shaker(motion, mode='inertial')
		O.dt = 1e-5
		rdem.run(1000)
		newton = rdem.newtonIntegrator()
		self.assertAlmostEqual(newton.gravity[0], -2.0, delta=1e-12)
		self.assertAlmostEqual(newton.gravity[2], -9.81, delta=1e-12)

	def testEnergyOfACarriedBlock(self):
		base, top = scene()
		motion = gm.GroundMotion(x=gm.sinePulse(5.0, 0.05, dt=2e-4, before=0.01))
		rdem.earthquake.shaker(motion, ids=[base])
		O.trackEnergy = True
		rdem.timeStepper().active = False  # a fixed step: the drift below grows with it
		O.dt = 2e-6
		O.step()
		total0 = O.energy.total()
		flow = drift = 0  # the largest energy the motion has put into the scene so far, the largest change of the total [J]
		for _ in range(400):
			for _ in range(100):
				O.step()
			flow = max(flow, abs(O.energy['groundWork']))
			drift = max(drift, abs(O.energy.total() - total0))
		self.assertGreater(flow, 0.1)  # the pulse did work
		# YADE's kinetic energy (½mv² at the mid-step velocity), which the booking of the base's own kinetic energy
		# matches; the bond's elastic energy belongs to the positions: their sum oscillates by O(F·vΔt), 6.3e-6 of the flow
		# at this step (0.023 of the critical 87 µs; 2.7e-3 at the automatic 0.8 of it, 7e-4 at the Gershgorin step)
		self.assertLess(drift / flow, 1e-3)

	def testArgumentsAreChecked(self):
		base, top = scene()
		motion = gm.GroundMotion(x=gm.constant(1.0, 0.1, 1e-3))
		with self.assertRaisesRegex(ValueError, r"mode = 'shake'"):
			rdem.earthquake.shaker(motion, ids=[base], mode='shake')
		with self.assertRaisesRegex(ValueError, r"ids = \[\]: mode='prescribed' needs the base blocks"):
			rdem.earthquake.shaker(motion)
		with self.assertRaisesRegex(ValueError, r'motion = .*GroundMotion or Record'):
			rdem.earthquake.shaker([1, 2, 3], ids=[base])
		with self.assertRaisesRegex(ValueError, r"RdemGroundShaker.mode = 'x': must be 'prescribed' or 'inertial'"):
			RdemGroundShaker().mode = 'x'
		with self.assertRaisesRegex(ValueError, r'RdemGroundShaker.times: must increase'):
			RdemGroundShaker().times = [0, 1, 1]


if __name__ == '__main__':
	harness.run(GroundShaker)
