"""Partial density scaling (RdemDensityScaling, rdem.walltest.scaleDensity, rdem.quasi_static.inertialScales).

* A light block between two heavy ones (a row of three bonded 2 cm concrete cubes, the middle one a tenth as dense)
  sets the critical step: its own row gives the smallest local limit, 2/omega_b (no dashpot acts in a bonded row), and
  scaleDensity(ids, 2) gives it, and it alone, mu = (2 * 2/omega_b)^2 omega_b^2 / 4 = 4 by hand (the heavy blocks' own
  limits are about sqrt(10) times larger). The stepper's Lanczos estimate then matches the exact limit 2/sqrt(lambda_max)
  of the scaled system, from K (RdemTimeStepper.stiffnessTimes) and the inertial masses m/s, I/s, to the Lanczos
  tolerance (1e-3, measured 0.02-0.05 % below the limit); the unscaled estimate matches the unscaled system's.
* The same row upright on a fixed base block under gravity, damped to rest with and without scaling: the base carries
  the true weight of the two free blocks (the weight is not scaled), and the positions at rest are those of the
  unscaled run (a static equilibrium does not depend on the inertia). Tolerances: the residual motion after the
  damped run (measured below 1e-9 relative) and the round-off of positions (about 1e-17 m against settlements of
  about 1e-10 m).
* The energy balance of a free bonded 3x3x3 grid (translations only: a linear system) with its stiffest blocks scaled,
  undamped at safety 0.8: O.energy.total() constant to round-off (bound 1e-9, the same argument and bound as
  test_energy_balance.py); with Cundall's damping and gravity too, the damping's work booked for the scaled inertia.
* A scaled scene saved and loaded continues bit for bit."""
import os
import tempfile
import unittest
import harness
from yade import O, Vector3
import numpy as np
import rdem
from yade.rdem import walltest
from yade.wrapper import RdemMat
import stability_cases as sc

LANCZOS = 2e-3  # the stepper's estimate against the exact limit: 2 x lanczosTolerance (it is 0.02-0.05 % below)


def row(upright=False, gravity=(0, 0, 0), damping=0.0):
	"""Three bonded 2 cm cubes (heavy, light, heavy) along x, or along z on a fixed base cube (upright). Returns the
	ids of the free blocks and the base's id (None)."""
	harness.freshScene()
	heavy = O.materials.append(RdemMat(young=sc.E, poisson=0.2, density=2400, tensileStrength=sc.INF, cohesion=sc.INF))
	light = O.materials.append(RdemMat(young=sc.E, poisson=0.2, density=240, tensileStrength=sc.INF, cohesion=sc.INF))
	O.engines = rdem.engines(formulation=None, recontact=False, damping=damping, gravity=gravity)
	d = 2 * sc.H
	axis = Vector3(0, 0, 1) if upright else Vector3(1, 0, 0)
	mats = ([heavy] if upright else []) + [heavy, light, heavy]
	ids = [O.bodies.append(rdem.block(axis * (d * k), (sc.H, ) * 3, m, fixed=upright and k == 0)) for k, m in enumerate(mats)]
	rdem.bond(ids)
	return (ids[1:], ids[0]) if upright else (ids, None)


def exactStep(ids):
	"""2/sqrt(lambda_max) of M^-1/2 K M^-1/2 over the free DOFs of the blocks ids, with their inertial masses and
	inertias (m/s, I/s for density scaling s; cubes: isotropic inertia) [s]."""
	n = 6 * len(O.bodies)
	K = np.array([rdem.timeStepper().stiffnessTimes([1.0 if j == k else 0.0 for j in range(n)]) for k in range(n)]).T
	dofs = [6 * i + k for i in ids for k in range(6)]
	scale = []
	for i in ids:
		s = O.bodies[i].state
		f = 1 / s.densityScaling if s.densityScaling > 0 else 1.0
		scale += [(s.mass * f)**-0.5] * 3 + [(s.inertia[k] * f)**-0.5 for k in range(3)]
	S = np.diag(scale)
	A = S @ K[np.ix_(dofs, dofs)] @ S
	return 2 / np.sqrt(np.linalg.eigvalsh((A + A.T) / 2).max())


class DensityScaling(unittest.TestCase):

	def testLightBlockStep(self):
		ids, _ = row()
		rows0 = rdem.timeStepper().blockRows()
		dt0 = rdem.timeStepper().estimate()
		exact0 = exactStep(ids)
		info = walltest.scaleDensity(ids, 2.0)
		mu = [1 / O.bodies[i].state.densityScaling if O.bodies[i].state.densityScaling > 0 else 1.0 for i in ids]
		print('unscaled: estimate %.5g s, exact %.5g s; scaled %s, mu %s' % (dt0, exact0, info, mu))
		self.assertEqual(info['scaled'], 1)
		self.assertAlmostEqual(mu[1], 4.0, delta=1e-12)  # by hand (module docstring)
		self.assertEqual((mu[0], mu[2]), (1.0, 1.0))
		self.assertAlmostEqual(info['target'], 2 * 2 / rows0[ids[1]][0]**0.5, delta=1e-12 * info['target'])
		rows1 = rdem.timeStepper().blockRows()  # the rows with the inertial mass: a quarter of the light block's
		self.assertAlmostEqual(rows1[ids[1]][0], rows0[ids[1]][0] / 4, delta=1e-12 * rows0[ids[1]][0])
		dt1 = rdem.timeStepper().estimate()
		exact1 = exactStep(ids)
		print('scaled: estimate %.5g s, exact %.5g s (x%.3f)' % (dt1, exact1, exact1 / exact0))
		for est, exact in ((dt0, exact0), (dt1, exact1)):
			self.assertLessEqual(est, exact * (1 + 1e-9))
			self.assertGreater(est, exact * (1 - LANCZOS))
		self.assertGreater(exact1, 1.5 * exact0)  # the light block set the step

	def testStaticEquilibriumUnchanged(self):
		rest = {}
		for factor in (1.0, 3.0):
			ids, base = row(upright=True, gravity=(0, 0, -9.81), damping=0.3)
			info = walltest.scaleDensity(ids, factor)
			rdem.run(20000)
			weight = sum(O.bodies[i].state.mass for i in ids) * 9.81
			reaction = O.forces.f(base)[2]
			z = [O.bodies[i].state.pos[2] - O.bodies[i].state.refPos[2] for i in ids]
			print('factor %g (%d scaled, dt %.4g s): base reaction %.12g N, true weight %.12g N; settlements %s m' %
			      (factor, info['scaled'], O.dt, reaction, weight, z))
			self.assertAlmostEqual(-reaction / weight, 1, delta=1e-6)
			rest[factor] = z
		self.assertGreater(info['scaled'], 0)
		for a, b in zip(rest[1.0], rest[3.0]):
			self.assertAlmostEqual(b / a, 1, delta=1e-5)

	def grid(self, damping=0.0, gravity=(0, 0, 0)):
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=sc.E, poisson=0.2, tensileStrength=sc.INF, cohesion=sc.INF))
		O.engines = rdem.engines(formulation=None, recontact=False, safety=0.8, damping=damping, gravity=gravity)
		ids = rdem.blockGrid((3, 3, 3), (2 * sc.H, ) * 3, mat)
		rdem.bond(ids)
		info = walltest.scaleDensity(ids, 1.5)
		sc.perturb(ids, 1.0)
		for i in ids:
			O.bodies[i].state.blockedDOFs = 'XYZ'
			O.bodies[i].state.angVel = Vector3.Zero
		O.trackEnergy = True
		return info

	def worstDeviation(self, steps=2000):
		return sc.worstTotalDeviation(steps)

	def testEnergyBalance(self):
		info = self.grid()
		err = self.worstDeviation()
		print('undamped, safety 0.8, %d blocks scaled (mu up to %.3g): worst |E - E0|/E0 = %.3g' % (info['scaled'], info['largest'], err))
		self.assertGreater(info['scaled'], 0)
		self.assertLess(err, 1e-9)
		info = self.grid(damping=0.1, gravity=(0, 0, -9.81))
		err = self.worstDeviation()
		print('damping 0.1 + gravity: worst |E - E0|/E0 = %.3g, dissipated %.3g J' % (err, O.energy['nonviscDamp']))
		self.assertLess(err, 1e-9)
		self.assertGreater(O.energy['nonviscDamp'], 0)

	def testSaveLoadContinues(self):
		"""A scaled scene saved and loaded continues bit for bit (State.densityScaling and the engine are saved)."""
		ids, _ = row()
		walltest.scaleDensity(ids, 2.0)
		sc.perturb(ids, 0.01)
		rdem.run(50)
		path = os.path.join(tempfile.mkdtemp(), 'scaled.yade.gz')
		O.save(path)
		rdem.run(50)
		want = [tuple(O.bodies[i].state.pos) + tuple(O.bodies[i].state.vel) for i in ids]
		O.load(path)
		self.assertEqual(sum(1 for e in O.engines if e.label == walltest.DENSITY_SCALING), 1)
		self.assertEqual(O.bodies[ids[1]].state.densityScaling, 0.25)
		rdem.run(50)
		got = [tuple(O.bodies[i].state.pos) + tuple(O.bodies[i].state.vel) for i in ids]
		self.assertEqual(got, want)

	def testErrors(self):
		ids, _ = row()
		with self.assertRaisesRegex(ValueError, '^factor'):
			walltest.scaleDensity(ids, 0.5)
		walltest.scaleDensity(ids, 2.0)
		engines = O.engines
		k = next(k for k, e in enumerate(engines) if e.label == walltest.DENSITY_SCALING)
		O.engines = engines[:k] + engines[k + 1:] + [engines[k]]  # last, after the integrator
		with self.assertRaisesRegex(RuntimeError, 'right before the NewtonIntegrator'):
			O.step()


if __name__ == '__main__':
	harness.run(DensityScaling)
