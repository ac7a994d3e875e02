"""Issue #17: RdemTimeStepper's Lanczos estimate of the critical time step. It is checked against the exact linear limit
2/omega_max of the stability cases (eigenvalues of the finite-difference stiffness, stability_cases.exactCriticalDt),
runs are stable just below it and blow up just above it, and a fixed O.dt above it is refused before the first step.
Figures: doc/stability.md (scripts/stability_sweep.py)."""
import math
import re
import unittest
import harness
from yade import O
from yade import rdem
from yade.rdem.scenes import CompressionTest
import stability_cases as sc


class TimeStep(unittest.TestCase):

	def testEstimateAgainstExactLimit(self):
		# The estimate is theta + r of the largest Ritz value, r <= 1e-3 theta (lanczosTolerance): at most 0.1 % below the
		# exact limit in dt (sqrt of 2e-3 in omega^2), and never above it by more than the finite-difference error of the
		# exact stiffness (1e-9 m steps on 1e-2 m blocks: ~1e-6 relative). Gershgorin is 2.2-2.7 times below it.
		for label, build in (('no Poisson', lambda: sc.grid(0.2, None)), ('paper', lambda: sc.grid(0.2, 'paper')),
		                     ('consistent', lambda: sc.grid(0.2, 'consistent')), ('consistent nu 0.45', lambda: sc.grid(0.45, 'consistent')),
		                     ('brick/mortar 1:100', lambda: sc.brickMortar(100))):
			ids = build()
			lanczos, gershgorin = rdem.timeStepper().estimate('lanczos'), rdem.timeStepper().estimate('gershgorin')
			steps = rdem.timeStepper().lanczosSteps
			exact = sc.exactCriticalDt(ids)
			print('%s: Lanczos %.6g s = %.5f of the exact limit %.6g s (%d steps); Gershgorin %.4f of it' %
			      (label, lanczos, lanczos / exact, exact, steps, gershgorin / exact))
			self.assertLess(lanczos / exact, 1 + 1e-5, label)
			self.assertGreater(lanczos / exact, 0.999, label)
			self.assertLess(gershgorin / exact, 0.5, label)

	def testCellsAgainstExactLimit(self):
		# Poisson cells (a running-bond wall, nu 0.45) enter through RdemCellNetwork::addStiffness; their offset correction
		# of the shear springs is left out of K, which could move the limit: measured 0.99968, as the grids (the bounds
		# of testEstimateAgainstExactLimit, with 0.5 % of room below for the left-out term)
		import wall_cases
		wall, plates = wall_cases.homogeneousWall('running', 2, (1, 1, 1), 0.45, 2)
		ids = wall.ids + plates[0] + plates[1]
		for p in plates[0] + plates[1]:
			O.bodies[p].state.blockedDOFs = ''  # all free, as test_cells_stability
		lanczos = rdem.timeStepper().estimate('lanczos')
		exact = sc.exactCriticalDt(ids)
		print('running-bond wall with cells: Lanczos %.5f of the exact limit' % (lanczos / exact))
		self.assertLess(lanczos / exact, 1 + 1e-5)
		self.assertGreater(lanczos / exact, 0.995)

	def runAt(self, fraction):
		"""The consistent 3x3x3 grid, perturbed, at fraction x the Lanczos estimate: (worst shadow-energy error, finite)."""
		ids = sc.grid(0.2, 'consistent')
		sc.perturb(ids, 0.01)
		rdem.timeStepper().refuseUnstableDt = False
		O.dt = fraction * rdem.timeStepper().estimate()
		H0, hist = sc.energyRun(5000)
		return sc.worstEnergyError(H0, hist), sc.stateIsFinite()

	def testStableBelowUnstableAbove(self):
		# 0.98 of the estimate: the shadow energy stays within 1e-4. Its error, from finite rotations (1e-7-1e-6 well
		# below the limit, doc/stability.md), is amplified near the limit: leapfrog's modified energy of the highest mode
		# carries 1/(1 - (omega dt/2)^2) = 25 at 0.98; measured 2.2e-5. 1.02: beyond the limit the highest mode grows
		# from round-off by |z| = 1.49 per step (|z| + 1/|z| = 4 (1.02)^2 - 2), past 1e-3 within a hundred steps (or the
		# guard stops the run at a non-finite value)
		err, finite = self.runAt(0.98)
		print('at 0.98 of the estimate: worst energy error %.3g' % err)
		self.assertTrue(finite)
		self.assertLess(err, 1e-4)
		err, finite = self.runAt(1.02)
		print('at 1.02 of the estimate: worst energy error %.3g, finite %s' % (err, finite))
		self.assertTrue(err > 1e-3 or not finite)

	def testFixedDtAboveLimitRefused(self):
		# The paper's cube (issue #17) with a fixed O.dt 13 times the Gershgorin estimate (the run that exploded into
		# fragments at 160 m/s): refused before the first step, naming O.dt and the limit.
		harness.freshScene()
		test = CompressionTest(blocksPerEdge=10, rate=1e-3)
		limit = rdem.timeStepper().estimate()
		O.dt = 13 * rdem.timeStepper().estimate('gershgorin')
		pos = O.bodies[test.specimen[0]].state.pos
		with self.assertRaises(ValueError) as refused:  # the stepper refuses the step (O.run would turn it into RuntimeError)
			rdem.run(1)
		print(refused.exception)
		named = re.search(r'O\.dt = (\S+) s exceeds the critical time step (\S+) s', str(refused.exception))
		self.assertAlmostEqual(float(named.group(1)) / O.dt, 1, delta=1e-5)  # printed to 6 digits
		self.assertAlmostEqual(float(named.group(2)) / limit, 1, delta=1e-3)  # the same estimate within its tolerance
		self.assertEqual(O.iter, 0)
		self.assertEqual(O.bodies[test.specimen[0]].state.pos, pos)
		# just above the limit: refused; just below: runs (and the paper's 2 us is far below)
		O.dt = 1.01 * limit
		with self.assertRaisesRegex(ValueError, 'exceeds the critical time step'):
			rdem.run(1)
		O.dt = 0.99 * limit
		rdem.run(10)
		self.assertEqual(O.iter, 10)
		# changed during the run: checked again
		O.dt = 1.5 * limit
		with self.assertRaisesRegex(ValueError, 'exceeds the critical time step'):
			rdem.run(1)
		# the Gershgorin fallback only warns
		rdem.timeStepper().method = 'gershgorin'
		O.dt = 2e-6
		rdem.run(1)
		self.assertTrue(rdem.timeStepper().warned)

	def testGershgorinFallbackAndSettings(self):
		ids = sc.grid(0.2, 'paper')
		ts = rdem.timeStepper()
		self.assertEqual(ts.method, 'lanczos')  # the default
		gershgorin = ts.estimate('gershgorin')
		ts.method = 'gershgorin'
		self.assertEqual(ts.estimate(), gershgorin)
		for attr, bad, good, text in (('method', 'power', 'lanczos', "method = 'power': must be 'lanczos' or 'gershgorin'"),
		                              ('lanczosTolerance', 0.0, 1e-3, r'lanczosTolerance = 0\.0+: must be in \(0, 0\.1\]'),
		                              ('lanczosMaxSteps', 1, 60, r'lanczosMaxSteps = 1: must be >= 2')):
			with self.assertRaisesRegex(ValueError, text):
				setattr(ts, attr, bad)
			setattr(ts, attr, good)
		with self.assertRaisesRegex(ValueError, "method = 'x'"):
			ts.estimate('x')

	def testWarmStartAndAutomaticStep(self):
		# The automatic step is safety x the estimate. While the springs are unchanged the stepper keeps its estimate
		# (reuseUnchanged); a new estimate starts from the last Ritz vector and converges in fewer Lanczos steps (measured:
		# see the print).
		ids = sc.grid(0.2, 'consistent', counts=(4, 4, 4))
		sc.perturb(ids, 0.01)
		O.dt = -1
		ts = rdem.timeStepper()
		ts.active = True
		O.step()
		cold, first = ts.lanczosSteps, ts.criticalDt
		self.assertAlmostEqual(O.dt / (0.8 * first), 1, delta=1e-12)
		rdem.run(200)
		self.assertEqual(ts.reused, 2)  # the updates at steps 100 and 200 kept it
		self.assertEqual(ts.criticalDt, first)
		again = ts.estimate()  # computes, from the Ritz vector of the first
		warm = ts.lanczosSteps
		print('Lanczos steps: %d cold, %d warm (384 DOFs); estimate moved by %.2g' % (cold, warm, again / first - 1))
		self.assertLess(warm, cold)
		self.assertLess(ts.lanczosResidual, 1e-3)
		self.assertAlmostEqual(again / first, 1, delta=1e-3)  # the same springs: the same limit within the tolerance
		# a broken bond changes the springs: the next update estimates anew
		I = O.interactions[ids[0], ids[1]]
		O.interactions.erase(I.id1, I.id2)
		rdem.run(100)
		self.assertEqual(ts.reused, 0)


	def testBreakUpdateAgainstFreshEstimate(self):
		# An update for a break alone keeps lambda_K and its Ritz vector (a broken segment keeps its spring as a contact
		# spring; the Poisson cells only scale down) and redoes the dashpots: lambda_C and the damped limit, the root of
		# lambda_max(dt^2 K + 2 dt C) = 4 with K as it is now. On a cracking 4x4x4 cube, at the state of each of 20 such
		# updates, its step ('dashpots') against a fresh estimate: both are the lower end of a bracket of 2 lanczosTolerance
		# (2e-3) around the same root, so they agree within 2e-3, unless the root is the springs' limit 2/omega_max (no
		# dashpot on the stiffest mode), where the kept lambda_K enters: within 2e-3 plus its drift since the last estimate
		# (printed; up to 9 % either way while the cube crumbles). lambda_C of both within 2e-3 (each within 1e-3 of the
		# largest eigenvalue of the same C). Measured: at most 1.1e-3 and 3.9e-4.
		harness.freshScene()
		CompressionTest(blocksPerEdge=4, rate=0.1, dt=None)
		ts = rdem.timeStepper()
		# without the contact limit: the damped limit is then found in full (with it, only up to contactDt, which here,
		# 0.41 of the springs' limit, is below every damped limit: the step would not depend on the dashpots at all)
		ts.contactLimit = False
		rows, damped = 0, 0
		while O.iter < 3000 and rows < 20:
			before = sum(rdem.breakCounts())
			O.step()
			if sum(rdem.breakCounts()) == before or O.iter % ts.timeStepUpdateInterval == 0:
				continue
			kept = ts.springCriticalDt
			update, updateC = ts.estimate('dashpots'), ts.dashpotRate
			self.assertEqual(ts.springCriticalDt, kept)  # lambda_K kept
			fresh, freshC = ts.estimate(), ts.dashpotRate
			drift = abs(kept / ts.springCriticalDt - 1)
			atSprings = abs(fresh / ts.springCriticalDt - 1) < 2e-3
			print('iter %d: dashpots only %.8g s, fresh %.8g s (%.1e); lambda_C %.6g, %.6g; springs kept %.8g s, fresh %.8g s (%.1e)' %
			      (O.iter, update, fresh, update / fresh - 1, updateC, freshC, kept, ts.springCriticalDt, kept / ts.springCriticalDt - 1))
			self.assertAlmostEqual(update / fresh, 1, delta=2e-3 + (drift if atSprings else 0))
			if freshC > 0:
				damped += 1
				self.assertAlmostEqual(updateC / freshC, 1, delta=2e-3)
			rows += 1
		self.assertEqual(rows, 20)
		self.assertGreater(damped, 10)  # most of them with dashpots acting

	def testBreaksWaitWhileContactLimited(self):
		# While the automatic step is held by contactLimit (contactDt = (sqrt(2) - 1) 2/omega_max, which allows for a
		# critically damped contact on the stiffest mode), a spring that breaks, which brings such a contact, waits for
		# the regular update as a contact that forms between two updates does; while the damped limit is below contactDt,
		# and without the contact limit, a step with a break triggers an update. The cracking 4x4x4 cube of
		# testBreakUpdateAgainstFreshEstimate, 3000 steps: the steps with breaks between two regular updates, by whether
		# the last update was held by the contact limit, and whether they triggered an update.
		for limit in (True, False):
			harness.freshScene()
			CompressionTest(blocksPerEdge=4, rate=0.1, dt=None)
			ts = rdem.timeStepper()
			ts.contactLimit = limit
			O.timingEnabled = True
			waited, updated = [0, 0], [0, 0]  # by contactLimited before the step
			while O.iter < 3000:
				before, calls, held = sum(rdem.breakCounts()), ts.execCount, ts.contactLimited
				O.step()
				if (O.iter - 1) % ts.timeStepUpdateInterval == 0 or sum(rdem.breakCounts()) == before:
					continue
				(updated if ts.execCount > calls else waited)[held] += 1
			print('contactLimit %s: breaks between regular updates, held by the contact limit: %d waited, %d updated; '
			      'not held: %d waited, %d updated' % (limit, waited[1], updated[1], waited[0], updated[0]))
			self.assertEqual(updated[1], 0)
			self.assertEqual(waited[0], 0)
			self.assertGreater(waited[1] if limit else updated[0], 10)

if __name__ == '__main__':
	harness.run(TimeStep)
