"""Shared set-up for the plugin's tests that run inside YADE (``build/bin/yade -n -x tests/yade/test_*.py``)."""
import sys
import unittest
from yade import O, Matrix3, Vector3
from yade import rdem


def run(*testCases):
	"""Run TestCase classes inside YADE and exit with 0 if all passed, 1 otherwise (CTest reads the status)."""
	suite = unittest.TestSuite(unittest.defaultTestLoader.loadTestsFromTestCase(t) for t in testCases)
	result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout).run(suite)
	sys.exit(0 if result.wasSuccessful() else 1)


def freshScene():
	"""Empty scene with no leftover engines, bodies or energy tracking."""
	O.reset()
	O.trackEnergy = False


class EnergyBalance:
	"""Total energy of the scene after every step, for runs with ``O.trackEnergy = True``.

	(``O.energy.total()`` is the same sum, but for the kinetic energy of fully blocked bodies (a moving base), which this class
	leaves out, since RdemLeapfrogEnergy books ``kinetic`` paired (issue #25; they agree to round-off on a free grid,
	tests/yade/test_energy_balance.py); this class stays as the independent Python check.) NewtonIntegrator's
	own ``kinetic`` is ½mv² at the mid-step velocity v_{n-1/2}, while ``rdemElastic`` and ``gravWork`` (the potential
	energy of gravity, the opposite of its work) belong to the positions x_n: their sum oscillates by O(F·vΔt) in every
	contact. The kinetic energy ½(m v_{n-1/2}·v_{n+1/2} + ω_{n-1/2}·I ω_{n+1/2}) pairs with x_n: for a linear spring
	under the leapfrog (v_{n+1/2} = v_{n-1/2} - (k/m)x_nΔt, x_{n+1} = x_n + v_{n+1/2}Δt), ½m v_{n-1/2}v_{n+1/2} + ½k x_n²
	is exactly conserved (substitute one step into the other), and the dashpot work is booked with the same mid-step
	velocities (Law2_RdemGeom_RdemPhys_FaceSprings). E_n = that + every other O.energy term (gravWork, rdemElastic,
	rdemDashpot, rdemFriction, rdemBondBreak) is therefore constant for a conservative model up to the non-linearity of
	contacts and rotations, and never grows in a dissipative one. [J]

	``run(n)`` steps one by one; ``growth`` is the largest rise of E above its lowest earlier value (energy created by
	the model), ``energies`` the values of E. ``run(n, every=k)`` evaluates E at every k-th step only (the steps between
	run in ``O.run``, at C++ speed) for long runs of many blocks."""

	def __init__(self):
		self.free = [b for b in O.bodies if b and not b.state.blockedDOFs == 'xyzXYZ']
		self.energies, self.growth, self.lowest = [], 0.0, float('inf')
		self._prev = None

	def _kinetic(self, prev):
		e = 0.0
		for b, (v, w) in zip(self.free, prev):
			s = b.state
			R = s.ori.toRotationMatrix()
			Iw = R * Matrix3(s.inertia[0], 0, 0, 0, s.inertia[1], 0, 0, 0, s.inertia[2]) * R.transpose()
			e += 0.5 * (s.mass * v.dot(s.vel) + w.dot(Iw * s.angVel))
		return e

	def run(self, n, every=1):
		for _ in range(n // every):
			if every > 1:
				rdem.run(every - 1)
			prev = [(Vector3(b.state.vel), Vector3(b.state.angVel)) for b in self.free]
			O.step()
			E = self._kinetic(prev) + sum(v for k, v in O.energy.items() if k != 'kinetic')
			self.energies.append(E)
			self.lowest = min(self.lowest, E)
			self.growth = max(self.growth, E - self.lowest)
