"""Breakage of restoring springs (paper eqs. 14-16) and the contact springs that replace them (eqs. 13, 17).

Two bonded 2 cm cubes, 2x2 springs on the shared face; both blocks blocked and placed by hand, so every step evaluates
the law for exactly the configuration set (zero velocities: dashpots exert nothing)."""
import os
import sys
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat
from yade import rdem

E, NU, H = 30e9, 0.2, 0.01
AREA = (2 * H)**2
KN = E / (1 - NU**2) / (2 * H)  # eqs. 11-12, two identical blocks, ell = H [N/m3]
KS = E / (2 * (1 + NU)) / (2 * H)


class Breakage(unittest.TestCase):

	def build(self, ft=4.5e6, c=float('inf'), phi=0.5):
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=E, poisson=NU, tensileStrength=ft, cohesion=c, frictionAngle=phi))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=False, dt=1e-9)
		rdem.blockGrid((2, 1, 1), (2 * H, ) * 3, material=mat)
		rdem.bond([0, 1])
		for i in (0, 1):
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'

	def place(self, u):
		"""Displace block 1 by u from its reference position, evaluate one step, return the force on block 1."""
		O.bodies[1].state.pos = O.bodies[1].state.refPos + u
		O.step()
		return O.forces.f(1)

	def testTensileBreakExactlyAtStrength(self):
		ft = 4.5e6
		self.build(ft=ft)
		uLimit = ft / KN
		self.place(Vector3(uLimit * (1 - 1e-9), 0, 0))  # sigma = f_t (1 - 1e-9): f_1 < 0 (eq. 15)
		self.assertEqual(rdem.breakCounts(), (0, 0))
		self.place(Vector3(uLimit * (1 + 1e-9), 0, 0))  # sigma = f_t (1 + 1e-9): all four springs break in tension
		self.assertEqual(rdem.breakCounts(), (4, 0))
		self.assertFalse(O.interactions[0, 1].isReal)  # fully broken and open: the bond is released

	def testReleasedBondIsRecorded(self):
		"""A bond broken through and open is released (its interaction reset) but stays a crack: the law records its face
		in body 1's frame and what broke each segment (RdemReleasedBond), and rdem.brokenSegments reads the mode there."""
		self.build(ft=1e6)
		snapshot = rdem.bondSnapshot()
		self.place(Vector3(2e6 / KN, 0, 0))  # sigma = 2 f_t: all four springs break in tension and the faces are apart
		self.assertFalse(O.interactions[0, 1].isReal)
		records = rdem.law().releasedBonds
		self.assertEqual(len(records), 1)
		r = records[0]
		self.assertEqual((r.id1, r.id2, r.iter, r.samplesPerEdge), (0, 1, O.iter - 1, 2))
		self.assertEqual(list(r.segState), [1, 1, 1, 1])
		self.assertLess((r.faceCentre1 - Vector3(H, 0, 0)).norm(), 1e-15 * H)  # block 0's +x face, in its frame (round-off of the grid)
		self.assertEqual(tuple(r.segNormal1), (1, 0, 0))
		self.assertAlmostEqual(r.segHalf1u.norm() * r.segHalf1v.norm() * 4, AREA / 4, delta=1e-15)  # a segment of 2x2
		segs = rdem.brokenSegments(snapshot)
		self.assertEqual([(s['state'], s['released']) for s in segs], [(1, True)] * 4)

	def testReleasedBondBooksItsElasticEnergy(self):
		"""A bond whose four springs break in one step and open is released in that step; the elastic energy they held,
		A w_n σ²/(2 k_n) at σ = k_n u (eq. 14), is booked as rdemBondBreak (it was lost with the interaction)."""
		self.build(ft=1e6)
		wn = O.interactions[0, 1].phys.weightNormal
		O.trackEnergy = True
		sigma = 2e6
		self.place(Vector3(sigma / KN, 0, 0))  # sigma = 2 f_t: all four springs break in tension and the faces are apart
		self.assertFalse(O.interactions[0, 1].isReal)
		# round-off: u = P2 - P1 (6.7e-5 m) from points 2 cm from the origin, 1e-16 relative to them: about 1e-12 in u²
		self.assertAlmostEqual(O.energy['rdemBondBreak'] / (AREA * wn * sigma**2 / (2 * KN)), 1, delta=1e-10)

	def testBrokenTransmitsCompressionOnly(self):
		self.build(ft=1e6)
		self.place(Vector3(2e6 / KN, 0, 0))  # break
		self.assertEqual(rdem.breakCounts(), (4, 0))
		f = self.place(Vector3(1e-6, 0, 0))  # opened: nothing
		self.assertEqual(f.norm(), 0)
		# closed: contact springs k_n A per segment, same constants (paper §3.2). A contact point counts from the depth at
		# which it began (Law2: a point cannot enter deep within one step except through a gap of the sampling), so
		# the block first touches, u0 = 1e-10 m in, then is pressed to u = 1e-7 m.
		u0, u = 1e-10, 1e-7
		self.place(Vector3(-u0, 0, 0))
		f = self.place(Vector3(-u, 0, 0))
		self.assertAlmostEqual(f[0] / (KN * AREA * (u - u0)), 1, delta=1e-9)  # round-off of u, a difference of 0.03 m positions

	def testShearBreakOnMohrCoulombLine(self):
		c, phi = 2e6, 0.5
		self.build(ft=float('inf'), c=c, phi=phi)
		import math
		sigma = -3e6  # compression
		tauLimit = c - sigma * math.tan(phi)  # eq. 16: |tau| + sigma tan(phi) = c
		un = sigma / KN
		self.place(Vector3(un, tauLimit / KS * (1 - 1e-9), 0))
		self.assertEqual(rdem.breakCounts(), (0, 0))
		self.place(Vector3(un, tauLimit / KS * (1 + 1e-9), 0))
		self.assertEqual(rdem.breakCounts(), (0, 4))
		self.assertEqual(list(O.interactions[0, 1].phys.segState), [2, 2, 2, 2])

	def testShearBreakUnderCompressionKeepsItsNormalEnergy(self):
		"""A spring that breaks in shear under compression stays in contact: its contact spring takes over the
		compression with the same constant (paper §3.2), so the normal spring's energy A w_n σ²/(2 k_n) stays elastic and
		only the shear spring's A w_s τ²/(2 k_s) is released (rdemBondBreak). Across the break, elastic + released is
		the energy held just before it."""
		import math
		c, phi = 2e6, 0.5
		self.build(ft=float('inf'), c=c, phi=phi)
		wn, ws = O.interactions[0, 1].phys.weightNormal, O.interactions[0, 1].phys.weightShear
		O.trackEnergy = True
		sigma = -3e6  # compression
		tauLimit = c - sigma * math.tan(phi)  # eq. 16
		un = sigma / KN
		self.place(Vector3(un, tauLimit / KS * (1 - 1e-9), 0))
		held = O.energy['rdemElastic']
		self.assertAlmostEqual(held / (AREA * (wn * sigma**2 / KN + ws * tauLimit**2 / KS) / 2), 1, delta=1e-8)
		self.place(Vector3(un, tauLimit / KS * (1 + 1e-9), 0))
		self.assertEqual(rdem.breakCounts(), (0, 4))
		# tau moved by 1e-9 of itself between the two placements: 2e-9 of the shear energy; round-off of u (see above) 1e-12
		self.assertAlmostEqual(O.energy['rdemBondBreak'] / (AREA * ws * tauLimit**2 / (2 * KS)), 1, delta=1e-8)
		self.assertAlmostEqual(O.energy['rdemElastic'] / (AREA * wn * sigma**2 / (2 * KN)), 1, delta=1e-8)
		self.assertAlmostEqual((O.energy['rdemElastic'] + O.energy['rdemBondBreak']) / held, 1, delta=1e-8)

	def testTensionCheckedFirst(self):
		self.build(ft=1e6, c=1e6, phi=0.5)
		self.place(Vector3(2e6 / KN, 2e6 / KS, 0))  # violates both criteria
		self.assertEqual(rdem.breakCounts(), (4, 0))


if __name__ == '__main__':
	harness.run(Breakage)
