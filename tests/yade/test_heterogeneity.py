"""Heterogeneity of the bonds (doc/theory.md §2.2, Ip2_RdemMat_RdemMat_RdemPhys.strengthCoV, .stiffnessCoV, .seed).

A 10×10×4 grid of 2 cm blocks (1020 bonds) bonded with strengthCoV = 0.3 and stiffnessCoV = 0.2: the bonds' strength
factors have mean 1 and CoV 0.3, the stiffness factors mean 1 and CoV 0.2, within four standard errors of a sample of
1020 (the bounds below); the two factors are uncorrelated; a bond's factor does not depend on which other bonds are made.
A bar of six blocks pulled apart with softening springs cracks through at one joint, the weakest the seed made: the same seed reproduces the
run bit for bit (every position equal), another seed does not. With strengthPerSegment, every segment has its own factor
(mean 1, CoV 0.3 over 4080 segments), and the weakest segment of a pulled pair breaks first. About 6 s."""
import math
import unittest
import harness
from yade import O, Vector3
from yade.wrapper import RdemMat
from yade import rdem

E, NU, FT, C = 30e9, 0.2, 3e6, 6e6
KN = E / (1 - NU**2) / 0.02  # eqs. 11-12: two 2 cm blocks (ℓ = 1 cm each) [N/m3]


def grid(counts, seed, strengthCoV=0.3, stiffnessCoV=0.2, softening=False, perSegment=False):
	harness.freshScene()
	mat = O.materials.append(RdemMat(young=E, poisson=NU, density=2300, tensileStrength=FT, cohesion=C))
	O.engines = rdem.engines(formulation=None, recontact=False, softening=softening, strengthCoV=strengthCoV, strengthPerSegment=perSegment,
	                         stiffnessCoV=stiffnessCoV, seed=seed)
	rdem.blockGrid(counts, (0.02, ) * 3, material=mat)


def factors():
	"""{(id1, id2): (strength factor, stiffness factor)} of every bond."""
	return {(i.id1, i.id2): (i.phys.tensileStrength / FT, i.phys.kn / KN) for i in O.interactions if i.isReal}


def meanCoV(x):
	m = sum(x) / len(x)
	return m, math.sqrt(sum((v - m)**2 for v in x) / (len(x) - 1)) / m


def fourSE(v, n):
	"""Four standard errors of the sample mean and of the sample CoV of n lognormal draws of CoV v (kurtosis κ)."""
	q = 1 + v * v
	kurt = q**4 + 2 * q**3 + 3 * q**2 - 3
	return 4 * v / math.sqrt(n), 4 * v * math.sqrt((kurt - 1) / (4 * n))


class Heterogeneity(unittest.TestCase):

	def testFactorsHaveTheRequestedMeanAndCoV(self):
		grid((10, 10, 4), seed=11)
		n = rdem.bond(range(len(O.bodies)))
		self.assertEqual(n, 1020)
		f = factors()
		for k, v in ((0, 0.3), (1, 0.2)):
			m, cov = meanCoV([x[k] for x in f.values()])
			dm, dc = fourSE(v, n)
			self.assertAlmostEqual(m, 1, delta=dm, msg='factor %d' % k)
			self.assertAlmostEqual(cov, v, delta=dc, msg='factor %d' % k)
		# Independent streams: correlation within 4/√n.
		a, b = zip(*f.values())
		ma, mb = sum(a) / n, sum(b) / n
		r = sum((x - ma) * (y - mb) for x, y in zip(a, b)) / math.sqrt(sum((x - ma)**2 for x in a) * sum((y - mb)**2 for y in b))
		self.assertLess(abs(r), 4 / math.sqrt(n))
		# Cohesion scaled by the same factor as f_t.
		for i in O.interactions:
			self.assertAlmostEqual(i.phys.cohesion / C, i.phys.tensileStrength / FT, delta=1e-15)
		# A bond's factors do not depend on the other bonds made: bond the first 20 blocks only, in another scene.
		grid((10, 10, 4), seed=11)
		rdem.bond(range(20))
		for key, x in factors().items():
			self.assertEqual(x, f[key])

	def testFactorsPerSegment(self):
		# strengthPerSegment: each of a bond's 2x2 segments has its own factor (RdemPhys.segStrengthFactor), of mean 1 and
		# CoV 0.3 over the 4080 segments within four standard errors; the bond's own strengths stay the material's.
		grid((10, 10, 4), seed=11, perSegment=True)
		n = rdem.bond(range(len(O.bodies)))
		seg = [f for i in O.interactions if i.isReal for f in i.phys.segStrengthFactor]
		self.assertEqual(len(seg), 4 * n)
		for i in O.interactions:
			self.assertEqual(i.phys.tensileStrength, FT)
			self.assertEqual(len(set(i.phys.segStrengthFactor)), 4)
		m, cov = meanCoV(seg)
		dm, dc = fourSE(0.3, len(seg))
		self.assertAlmostEqual(m, 1, delta=dm)
		self.assertAlmostEqual(cov, 0.3, delta=dc)

	def testWeakSegmentBreaksFirst(self):
		# Two blocks pulled apart slowly with per-segment strengths: the segment of the smallest factor breaks first, at
		# the smallest f_t (the law runs the factors, not only the set-up).
		grid((2, 1, 1), seed=5, stiffnessCoV=0.0, perSegment=True)
		rdem.bond([0, 1])
		O.bodies[0].state.blockedDOFs = O.bodies[1].state.blockedDOFs = 'xyzXYZ'
		O.bodies[1].state.vel = Vector3(1e-3, 0, 0)
		phys = O.interactions[0, 1].phys
		weakest = min(range(4), key=lambda k: phys.segStrengthFactor[k])
		while list(phys.segState).count(0) == 4:
			O.step()
		self.assertEqual([k for k in range(4) if phys.segState[k] != 0], [weakest])

	def pulledBar(self, seed):
		grid((6, 1, 1), seed=seed, stiffnessCoV=0.1, softening=True)
		rdem.bond(range(6))
		for i in (0, 5):
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
		O.bodies[5].state.vel = Vector3(0.05, 0, 0)
		O.run(1500, True)
		bonds = sorted((i.id1, i.id2) for i in O.interactions if i.isReal)
		return [tuple(b.state.pos) for b in O.bodies], bonds

	def testFixedSeedReproducesBitForBit(self):
		pos1, bonds1 = self.pulledBar(seed=3)
		self.assertEqual(rdem.breakCounts(), (4, 0))  # one joint has cracked through, its bond released
		self.assertEqual(len(bonds1), 4)
		pos2, bonds2 = self.pulledBar(seed=3)
		self.assertEqual(pos1, pos2)
		self.assertEqual(bonds1, bonds2)
		pos3, _ = self.pulledBar(seed=4)
		self.assertNotEqual(pos1, pos3)


if __name__ == '__main__':
	harness.run(Heterogeneity)
