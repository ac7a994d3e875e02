"""Issue #7: hard cases stay numerically stable. Every case asserts a finite state, a bounded shadow energy (no growth
without external work; stability_cases.shadowEnergy) and no block passing through another. Figures of each case and
the time-step sweep: doc/stability.md (scripts/stability_sweep.py); the wall time of each case:
scripts/stability_timing.py (not asserted here: it depends on the machine and its load)."""
import math
import os
import sys
import unittest
import harness
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat, PyRunner
from yade import rdem
from yade.rdem.scenes import CompressionTest
import stability_cases as sc

# Energy bound of the elastic cases. Measured worst |H - H0|/H0 over 20 000 steps: 2e-8 to 1.5e-6 (doc/stability.md),
# from the geometric non-linearity of finite block rotations; an unstable mode grows by e per few steps and passes
# 1e-5 within a few hundred steps, so 1e-5 separates the two by a factor > 6.
ENERGY_TOL = 1e-5
# Penetration bound: vibration amplitudes are ~1e-8 m against 1 cm half-sizes; a block passing through another
# reaches O(1). Measured: < 2e-4 (the thin mortar blocks of the contrast case).
PENETRATION_TOL = 1e-3

PLATEN = dict(work=0.0, top=[], rate=0.0)


def platenWork():
	"""PyRunner of testFastCompression: work of the agent that drives the top platen down at `rate` in this step [J]
	(it holds the platen against the specimen's push f_z > 0 while moving it by rate*dt)."""
	PLATEN['work'] += sum(O.forces.f(i)[2] for i in PLATEN['top']) * PLATEN['rate'] * O.dt


class Stability(unittest.TestCase):

	def assertStable(self, ids, steps, tol=ENERGY_TOL, label=''):
		H0, hist = sc.energyRun(steps)
		err = sc.worstEnergyError(H0, hist)
		self.assertTrue(sc.stateIsFinite(), label)
		self.assertLess(err, tol, label)
		self.assertLess(sc.deepestPenetration(ids), PENETRATION_TOL, label)
		print('%s: worst energy error %.3g, deepest penetration %.3g' % (label, err, sc.deepestPenetration(ids)))
		return err

	def testNearlyIncompressibleConsistent(self):
		for nu in (0.45, 0.49):
			ids = sc.grid(nu, 'consistent')
			sc.perturb(ids, 0.01)
			sc.setDtFraction(0.8)
			self.assertStable(ids, 20000, label='nu = %g' % nu)

	def testNearlyIncompressiblePaperRefused(self):
		# doc/theory.md §5.3: springs E/(1-nu^2) plus D_p are indefinite above (3 - sqrt 5)/2 = 0.382
		for nu in (0.39, 0.45, 0.49):
			with self.assertRaisesRegex(ValueError, r'poisson = 0\.(39|45|49).*above 0\.382.*consistent'):
				sc.grid(nu, 'paper')
		sc.grid(0.38, 'paper')  # just below the bound: accepted

	def testTimeStepFractions(self):
		# below the Gershgorin estimate (and at it) the run is stable for every formulation; the true limit is 2.2-2.7
		# times that estimate (doc/stability.md), so 1.0 is stable with margin (the Lanczos estimate: test_time_step)
		for formulation in (None, 'paper', 'consistent'):
			for fraction in (0.5, 0.9, 1.0):
				ids = sc.grid(0.2, formulation)
				sc.perturb(ids, 0.01)
				rdem.timeStepper().method = 'gershgorin'
				sc.setDtFraction(fraction, 'gershgorin')
				self.assertStable(ids, 20000, label='%s at %g' % (formulation, fraction))
				# below the estimate no warning; at 1.0 the stepper's in-run estimate (current normals) may differ
				# from the set-up one by round-off and warn
				if fraction < 1:
					self.assertFalse(rdem.timeStepper().warned)
				# the estimate follows the current arms and normals: vibration rotations of ~1e-6 rad move it by < 1e-5
				self.assertAlmostEqual(rdem.timeStepper().criticalDt * fraction / O.dt, 1, delta=1e-5)

	def testWarningAboveEstimate(self):
		ids = sc.grid(0.2, 'consistent')
		rdem.timeStepper().method = 'gershgorin'  # above this bound but below the limit: a warning (the Lanczos estimate refuses)
		est = sc.setDtFraction(1.5, 'gershgorin')
		err = os.path.join(os.environ.get('TMPDIR', '/tmp'), 'rdem-stability-warn-%d.txt' % os.getpid())
		saved = os.dup(2)
		with open(err, 'w') as f:
			os.dup2(f.fileno(), 2)  # RdemTimeStepper's LOG_WARN goes to the C++ stderr
			try:
				rdem.run(10)
			finally:
				os.dup2(saved, 2)
				os.close(saved)
		text = open(err).read()
		os.remove(err)
		self.assertTrue(rdem.timeStepper().warned)
		self.assertIn('exceeds the critical time step', text)
		self.assertEqual(text.count('exceeds the critical'), 1)  # once, not every check
		self.assertAlmostEqual(rdem.timeStepper().criticalDt / est, 1, delta=1e-3)  # the same estimate

	def testStiffnessContrastAndAspectRatio(self):
		# 3 brick layers (aspect 2:1) and 2 mortar layers (aspect 10:1), mortar 100 and 1000 times softer
		for contrast in (100, 1000):
			ids = sc.brickMortar(contrast)
			sc.perturb(ids, 0.01)
			sc.setDtFraction(0.9, 'gershgorin')  # the step of doc/stability.md's figures (0.9 of Lanczos: 1.3e-5 at 1:100)
			self.assertStable(ids, 20000, label='contrast %d' % contrast)

	def rigidMotion(self, corotational):
		"""A bonded 3x3x3 concrete cube (finite strengths) translating at 100 m/s and spinning at 300 rad/s for 2 rad.
		Returns (largest spring stress [Pa], largest |rdemPoisson| [J], breaks, rho*Omega^2*a^2 [Pa], ids)."""
		ids = sc.grid(0.2, 'consistent', corotational=corotational, tensileStrength=4.5e6, cohesion=9e6)
		V, W = Vector3(1, 2, 3).normalized() * 100, Vector3(1, -1, 2).normalized() * 300
		c = sum((O.bodies[i].state.pos for i in ids), Vector3.Zero) / len(ids)
		for i in ids:
			s = O.bodies[i].state
			s.vel, s.angVel = V + W.cross(s.pos - c), W
		sc.setDtFraction(0.8)
		steps = int(2.0 / (W.norm() * O.dt))
		sigma, poisson = 0, 0
		for k in range(20):
			try:
				rdem.run(steps // 20)
			except RuntimeError:
				break  # the guard stopped a blow-up (control case)
			for I in O.interactions:
				sigma = max([sigma] + [abs(x) for x in I.phys.segSigma] + list(I.phys.segTau))
			poisson = max(poisson, abs(dict(O.energy.items()).get('rdemPoisson', 0)))
		a = 3 * sc.H  # half-width of the cube
		rho = O.bodies[ids[0]].material.density
		return sigma, poisson, sum(rdem.breakCounts()), rho * W.norm()**2 * a**2, ids

	def testRigidMotionCorotational(self):
		sigma, poisson, breaks, centrifugal, ids = self.rigidMotion(True)
		print('rigid motion: largest spring stress %.4g Pa (bound %.4g), |rdemPoisson| %.3g J' % (sigma, centrifugal, poisson))
		self.assertTrue(sc.stateIsFinite())
		self.assertEqual(breaks, 0)
		# Only the centripetal load stresses the springs. A rod of half-length a spinning about its middle carries
		# rho Omega^2 a^2 / 2 at the middle (the largest); the cube's material beside the axis only shares it. The
		# motion starts unstressed, so the stress overshoots up to twice the static one: bound rho Omega^2 a^2 =
		# 0.19 MPa for a = 3 cm. Measured 0.052 MPa; without the corotational frame 0.87 MPa and 62 broken springs.
		self.assertLess(sigma, centrifugal)
		self.assertLess(sc.deepestPenetration(ids), PENETRATION_TOL)
		# the elements see no rotation: their energy is that of the centripetal strain, sigma^2/E per volume
		self.assertLess(poisson, centrifugal**2 / sc.E * (6 * sc.H)**3)
		# the control: without the corotational frame the same motion is torn apart (the test can fail)
		sigmaNo, poissonNo, breaksNo, _, _ = self.rigidMotion(False)
		print('rigid motion without corotational frame: stress %.4g Pa, %d breaks, finite %s' % (sigmaNo, breaksNo, sc.stateIsFinite()))
		self.assertTrue(breaksNo > 0 or not sc.stateIsFinite() or sigmaNo > 10 * centrifugal)

	def testLongUndampedVibration(self):
		# 2x2x2 blocks, one consistent element, 10^6 steps at 0.8 of the estimate. Drift: mean shadow energy of the
		# first and the last quarter of the run (20 samples); a secular error of the integrator would show there.
		ids = sc.grid(0.3, 'consistent', counts=(2, 2, 2))
		sc.perturb(ids, 0.01)
		sc.setDtFraction(0.8)
		H0, hist = sc.energyRun(10**6, samples=20)
		self.assertEqual(len(hist), 20)
		self.assertTrue(sc.stateIsFinite())
		early, late = sum(hist[:5]) / 5, sum(hist[-5:]) / 5
		drift = abs(late - early) / H0
		# measured drift and worst error: doc/stability.md; 1e-6 is ~ the error of 20 000 steps, round-off of 1e6
		# steps of 1e-16 relative would stay below 1e-10
		self.assertLess(drift, 1e-6)
		self.assertLess(sc.worstEnergyError(H0, hist), ENERGY_TOL)
		self.assertLess(sc.deepestPenetration(ids), PENETRATION_TOL)
		print('long vibration: drift %.3g, worst %.3g' % (drift, sc.worstEnergyError(H0, hist)))

	def testFastCompression(self):
		# The paper's compression test on 4x4x4 blocks, loaded at 0.1 m/s (100 x the paper's 1 mm/s) to 0.3 mm, past
		# the first cracks. External work W of the platen: sum of f_z(top) * rate * dt (PyRunner every step).
		harness.freshScene()
		rate = 0.1
		test = CompressionTest(blocksPerEdge=4, rate=rate, formulation='paper')
		O.trackEnergy = True
		PLATEN.update(work=0.0, top=test.top, rate=rate)
		O.engines = O.engines + [PyRunner(iterPeriod=1, command='platenWork()')]
		self.assertFalse(O.dt > rdem.timeStepper().estimate())  # the paper's 2e-6 s is below the estimate
		O.step()
		kin0 = O.energy['kinetic']  # the moving platen's own, constant
		worst = 0
		while test.displacement() < 0.3e-3:
			rdem.run(100)
			self.assertTrue(sc.stateIsFinite())
			balance = O.energy['kinetic'] - kin0 + sc.elasticEnergy() + sc.dissipatedEnergy() - PLATEN['work']
			worst = max(worst, abs(balance))
		worst /= PLATEN['work']
		self.assertGreater(sum(rdem.breakCounts()), 0)  # it did crack
		# energy balance, kinetic + elastic + dissipated (dashpots, friction, broken springs, Poisson elements
		# released by cracks) - W, largest over the run relative to the final W: measured 0.094 %, from the half-step
		# kinetic energy and the rectangle rule of W. Without the rdemPoissonRelease term it was 4.9 %, with released
		# elements revived by re-contact 0.8 %: bound 0.5 %
		self.assertLess(worst, 0.005)
		self.assertLess(sc.deepestPenetration(test.ids), 0.01)  # cracks open, blocks do not pass through
		print('fast compression: energy balance worst %.3g, %d steps' % (worst, O.iter))


if __name__ == '__main__':
	harness.run(Stability)
