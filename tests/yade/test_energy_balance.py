"""Issue #25: the total of O.energy balances at the default time step (RdemLeapfrogEnergy, pkg/rdem/math/LeapfrogEnergy.hpp).

A free, bonded 3x3x3 grid of 2 cm concrete cubes (springs only: a linear system), set vibrating by random velocities
free of rigid motion, run at RdemTimeStepper's automatic step (safety 0.8, the default, and 0.5), nothing broken:

* translations only (rotations blocked), speeds ~1 m/s: exactly linear, so O.energy.total() is constant to round-off.
  The round-off is that of the positions: a spring's elongation u (amplitude ~v/omega = 2.5e-6 m here) is the
  difference of coordinates x ~ 0.06 m stored to eps x = 1.3e-17 m, so each evaluation of the energy carries a
  relative error ~2 eps x/u = 1e-11; bound 1e-9 (at 0.01 m/s, amplitudes 100 times smaller, the same run measures
  5.7e-10: position round-off, not the balance);
* rotations free, speeds ~0.01 m/s and 1 rad/s: the springs follow the blocks' finite rotations (~2.5e-6 rad here), a
  non-linearity of the order of the rotation; measured 1.9e-6, bound 1e-5 (test_stability's bound of the same
  shadow energy);
* Cundall's damping 0.1 of NewtonIntegrator with gravity: total including ``nonviscDamp`` and ``gravWork`` constant to
  round-off, and the damping did dissipate;
* without RdemLeapfrogEnergy (NewtonIntegrator's own ``kinetic``, ½mv² at the half step) the same run swings by tens
  of percent (the issue measured 44 % at 0.8, 16 % at 0.5): shown, so that the test proves the difference;
* harness.EnergyBalance, which pairs the kinetic energy in Python, agrees with O.energy.total() to round-off."""
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemLeapfrogEnergy
import rdem
import stability_cases as sc

STEPS = 2000
ROUND_OFF = 1e-9  # relative to the total, translations only (module docstring)
ROTATION_TOL = 1e-5  # relative to the total, free rotations (module docstring)


def grid(safety, rotations=True, damping=0.0, gravity=(0, 0, 0), leapfrogEnergy=True, speed=0.01):
	"""The vibrating grid at safety x the automatic step, with O.trackEnergy; random velocities ~speed [m/s] and
	angular velocities ~speed/H."""
	harness.freshScene()
	mat = O.materials.append(RdemMat(young=sc.E, poisson=0.2, tensileStrength=sc.INF, cohesion=sc.INF))
	O.engines = rdem.engines(formulation=None, recontact=False, safety=safety, damping=damping, gravity=gravity)
	if not leapfrogEnergy:
		O.engines = [e for e in O.engines if not isinstance(e, RdemLeapfrogEnergy)]
	ids = rdem.blockGrid((3, 3, 3), (2 * sc.H, ) * 3, mat)
	rdem.bond(ids)
	sc.perturb(ids, speed)
	if not rotations:
		for i in ids:
			O.bodies[i].state.blockedDOFs = 'XYZ'
			O.bodies[i].state.angVel = Vector3.Zero
	O.trackEnergy = True
	return ids


def worstDeviation(steps=STEPS):
	"""stability_cases.worstTotalDeviation over the steps."""
	return sc.worstTotalDeviation(steps)


class EnergyBalance(unittest.TestCase):

	def testTranslationsBalanceToRoundOff(self):
		for safety in (0.8, 0.5):
			grid(safety, rotations=False, speed=1.0)
			err = worstDeviation()
			print('translations, safety %g (dt %.4g s): worst |E - E0|/E0 = %.3g' % (safety, O.dt, err))
			self.assertLess(err, ROUND_OFF, 'safety %g' % safety)

	def testRotationsBalance(self):
		for safety in (0.8, 0.5):
			grid(safety)
			err = worstDeviation()
			print('rotations free, safety %g: worst |E - E0|/E0 = %.3g' % (safety, err))
			self.assertLess(err, ROTATION_TOL, 'safety %g' % safety)

	def testDampingAndGravityBalance(self):
		for safety in (0.8, 0.5):
			grid(safety, rotations=False, damping=0.1, gravity=(0, 0, -9.81), speed=1.0)
			err = worstDeviation()
			damped = O.energy['nonviscDamp']
			print('damping 0.1 + gravity, safety %g: worst |E - E0|/E0 = %.3g, dissipated %.3g J of %.3g J' % (safety, err, damped, O.energy.total()))
			self.assertLess(err, ROUND_OFF, 'safety %g' % safety)
			self.assertGreater(damped, 0)

	def testHalfStepKineticEnergySwings(self):
		for safety in (0.8, 0.5):
			grid(safety, leapfrogEnergy=False)
			err = worstDeviation()
			print('without RdemLeapfrogEnergy, safety %g: worst |E - E0|/E0 = %.3g' % (safety, err))
			self.assertGreater(err, 0.05, 'safety %g' % safety)

	def testStepChangesBalance(self):
		"""The step changed every 50 steps (as the time stepper's updates change it), translations, gravity and Cundall's
		damping 0.1: the total, with the jump each change makes in the leapfrog's conserved energy booked as
		``rdemStepChange`` (rdem::stepChangeJump), stays constant to round-off; the jumps themselves are far above it."""
		grid(0.5, rotations=False, damping=0.1, gravity=(0, 0, -9.81), speed=1.0)
		rdem.run(2)
		E0, dt0, worst = O.energy.total(), O.dt, 0.0
		for k in range(1, 9):
			O.dt = dt0 * (0.9 if k % 2 else 1.05)
			for _ in range(50):
				O.step()
				worst = max(worst, abs(O.energy.total() - E0) / abs(E0))
		jumps = abs(O.energy['rdemStepChange'])
		print('step changed 8 times: worst |E - E0|/E0 = %.3g, |rdemStepChange| = %.3g of %.3g J' % (worst, jumps, E0))
		self.assertGreater(jumps, 1e3 * ROUND_OFF * abs(E0))
		self.assertLess(worst, ROUND_OFF)

	def testBreakBalancesToRoundOff(self):
		"""Two bonded blocks, one fixed, the other free along the bond's axis only (one linear degree of freedom), released
		from a compression of 2 MPa: it swings out and its four springs break together in tension at 1 MPa, half its
		reach, while still moving; then it flies away. The springs' energy released at the break
		(rdem::releasedSpringEnergy, ½ k u_{n-1}u_n) keeps the total constant to round-off at any stable step; booked as
		½ k u_n² (the code before) it rose at the break by the springs' force times half the last step's travel:
		measured 0.093 of E₀ at safety 0.1. (At 0.3 the last step crosses from compression to beyond f_t, so the
		released ½ k u_{n-1}u_n is negative: the balance, not the sign, is what holds.)"""
		for safety in (0.1, 0.3):
			harness.freshScene()
			mat = O.materials.append(RdemMat(young=sc.E, poisson=0.2, tensileStrength=1e6, cohesion=sc.INF))
			O.engines = rdem.engines(formulation=None, recontact=False, safety=safety)
			rdem.blockGrid((2, 1, 1), (2 * sc.H, ) * 3, mat)
			rdem.bond([0, 1])
			O.bodies[0].state.blockedDOFs = 'xyzXYZ'
			O.bodies[1].state.blockedDOFs = 'yzXYZ'
			kn = sc.E / (1 - 0.2**2) / (2 * sc.H)  # eqs. 11-12, two identical blocks [N/m3]
			O.bodies[1].state.pos = O.bodies[1].state.refPos - Vector3(2e6 / kn, 0, 0)  # sigma = -2 MPa
			O.trackEnergy = True
			err = worstDeviation(200)
			print('a break, safety %g (dt %.4g s): worst |E - E0|/E0 = %.3g, released %.3g of %.3g J' %
			      (safety, O.dt, err, O.energy['rdemBondBreak'], O.energy.total()))
			self.assertEqual(rdem.breakCounts(), (4, 0), 'safety %g' % safety)
			self.assertGreater(O.bodies[1].state.vel[0], 0, 'safety %g: flies away' % safety)
			self.assertLess(err, ROUND_OFF, 'safety %g' % safety)

	def testHarnessAgrees(self):
		grid(0.8)
		rdem.run(2)
		balance = harness.EnergyBalance()
		balance.run(200)
		self.assertAlmostEqual(balance.energies[-1], O.energy.total(), delta=1e-12 * abs(O.energy.total()))


if __name__ == '__main__':
	harness.run(EnergyBalance)
