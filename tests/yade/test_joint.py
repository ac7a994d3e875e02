"""A two-brick couplet with an interface mortar joint (:yref:`RdemJoint`, doc/theory.md §1.1): stiffness and strengths.

Two 250×120×55 mm clay bricks stacked along z with a 10 mm joint (interface model: each block reaches the joint's
mid-plane, 65 mm tall), bonded with ``rdem.bond(..., joint=RdemJoint(...))``. Both blocks blocked and placed by hand, so
every step evaluates the law for exactly that configuration (zero velocities: dashpots exert nothing).

Checks: the joint's normal and shear stiffness equal the series formula brick–mortar–brick (eq. 12 extended by t/M_m) to
round-off, for both formulations; the joint breaks in tension at its bond strength (not the brick's), and in shear on its
own Mohr–Coulomb line τ = c - σ tan φ at two normal stresses."""
import math
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem

L, W, H, T = 0.25, 0.12, 0.055, 0.01  # brick and joint [m]
EB, NUB, EM, NUM = 16.7e9, 0.15, 2e9, 0.25  # brick and mortar [Pa], [-]
FT, C, PHI = 0.2e6, 0.35e6, math.atan(0.75)  # the joint's bond: tensile strength, cohesion, friction angle
AREA = L * W


def series(Eb, nub, Em, num, formulation):
	"""1/k_n and 1/k_s of the joint, written out: brick over H/2, mortar over T, brick over H/2 [m³/N]."""
	M = (lambda E, nu: E / (1 - nu * nu)) if formulation == 'paper' else (lambda E, nu: E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)))
	G = lambda E, nu: E / (2 * (1 + nu))
	return H / M(Eb, nub) + T / M(Em, num), H / G(Eb, nub) + T / G(Em, num)


class Couplet(unittest.TestCase):

	def build(self, formulation='paper'):
		harness.freshScene()
		brick = O.materials.append(RdemMat(young=EB, poisson=NUB, density=1800, tensileStrength=3e6, cohesion=6e6, frictionAngle=0.6, label='brick'))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None if formulation == 'paper' else 'consistent', recontact=False, dt=1e-9)
		if formulation == 'consistent':
			O.engines = [e for e in O.engines if type(e).__name__ != 'RdemPoissonEngine']  # springs alone: no cells here
		half = (L / 2, W / 2, (H + T) / 2)
		ids = O.bodies.append([rdem.block((0, 0, z * (H + T)), half, brick) for z in (0, 1)])
		self.joint = RdemJoint(thickness=T, young=EM, poisson=NUM, tensileStrength=FT, cohesion=C, frictionAngle=PHI, label='bed')
		self.assertEqual(rdem.bond(ids, joint=self.joint), 1)
		for i in ids:
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
		self.I = O.interactions[0, 1]

	def place(self, u):
		"""Displace the upper brick by u from its reference position, evaluate one step, return the force on it [N]."""
		O.bodies[1].state.pos = O.bodies[1].state.refPos + u
		O.step()
		return O.forces.f(1)

	def testStiffnessIsTheSeriesFormula(self):
		for formulation in ('paper', 'consistent'):
			self.build(formulation)
			cn, cs = series(EB, NUB, EM, NUM, formulation)
			p = self.I.phys
			# A few divisions and additions of O(1e-12) compliances: 1e-14 relative.
			self.assertAlmostEqual(p.kn * cn, 1, delta=1e-14, msg=formulation)
			self.assertAlmostEqual(p.ks * cs, 1, delta=1e-14, msg=formulation)
			self.assertIs(self.I.geom.joint, self.joint)
			# The law uses it: opening u gives -k_n A u on the upper brick; u is a difference of positions 0.065 m apart
			# (round-off 7e-18 m, 7e-11 of u): 1e-9 relative.
			u = 1e-7
			self.assertAlmostEqual(self.place(Vector3(0, 0, u))[2] / (-p.kn * AREA * u), 1, delta=1e-9)
			self.assertAlmostEqual(self.place(Vector3(u, 0, 0))[0] / (-p.ks * AREA * u), 1, delta=1e-9)

	def testMortarOfTheBrickMaterialIsTheHomogeneousBar(self):
		# A joint of the brick's own E and nu: brick, mortar and brick in series are one bar of length H + T (eq. 12 with
		# l = (H + T)/2 on each side): k_n = M/(H + T).
		self.build('paper')
		harness.freshScene()
		brick = O.materials.append(RdemMat(young=EB, poisson=NUB, density=1800))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=False, dt=1e-9)
		ids = O.bodies.append([rdem.block((0, 0, z * (H + T)), (L / 2, W / 2, (H + T) / 2), brick) for z in (0, 1)])
		rdem.bond(ids, joint=RdemJoint(thickness=T, young=EB, poisson=NUB))
		self.assertAlmostEqual(O.interactions[0, 1].phys.kn * (H + T) * (1 - NUB**2) / EB, 1, delta=1e-14)

	def testTensionBreaksAtTheBondStrength(self):
		self.build()
		uLimit = FT / self.I.phys.kn
		self.place(Vector3(0, 0, uLimit * (1 - 1e-9)))  # sigma = f_t (1 - 1e-9): intact (eq. 15)
		self.assertEqual(rdem.breakCounts(), (0, 0))
		self.place(Vector3(0, 0, uLimit * (1 + 1e-9)))  # just above the joint's f_t, far below the brick's 3 MPa
		self.assertEqual(rdem.breakCounts(), (4, 0))

	def testShearBreaksOnTheJointsMohrCoulombLine(self):
		# Normal stress sigma (compression < 0) and shear just below / above tau = c - sigma tan(phi) (eq. 16): two points
		# of the line, so that both c and phi are the joint's.
		for sigma in (-0.2e6, -1.0e6):
			self.build()
			p = self.I.phys
			un = sigma / p.kn
			tauLimit = C - sigma * math.tan(PHI)
			self.place(Vector3(tauLimit * (1 - 1e-9) / p.ks, 0, un))
			self.assertEqual(rdem.breakCounts(), (0, 0), 'sigma = %g' % sigma)
			self.place(Vector3(tauLimit * (1 + 1e-9) / p.ks, 0, un))
			self.assertEqual(rdem.breakCounts(), (0, 4), 'sigma = %g' % sigma)

	def testJointThickerThanTheBlocksIsRefused(self):
		harness.freshScene()
		brick = O.materials.append(RdemMat(young=EB, poisson=NUB, density=1800))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=False, dt=1e-9)
		ids = O.bodies.append([rdem.block((0, 0, z * (H + T)), (L / 2, W / 2, (H + T) / 2), brick) for z in (0, 1)])
		with self.assertRaisesRegex(ValueError, r'RdemJoint\.thickness = 0\.1.*less than twice the centroid-to-face distance'):
			rdem.bond(ids, joint=RdemJoint(thickness=0.1))
		self.assertIsNone(rdem.geomFunctor().joint)  # reset even after the error


if __name__ == '__main__':
	harness.run(Couplet)
