"""Poisson cells keep the critical time step of the springs (doc/sphinx/rdemTheory.rst §5.4, *Slivers* and *Stability*).

The scene: a one-storey English-bond house (rdem.masonry.building, 24 × 16 quarter modules, four courses, an inner wall
ending on the front and back walls in T-junctions, an RC roof slab in pieces cut at the wall faces), the bricks, mortar
and slab of scripts/building.py. At the T-junctions the top bricks reach 5 mm into the joint, so four slab pieces over
the rooms touch the masonry only at a 5 × 5 mm corner: a bond of 0.25 cm² along z, the slab piece's only one. Before the
cells condensed such an axis (rdem::cellMinBondedFraction), the piece's free faces were extrapolated from that sliver and
weighted onto its spring (w_n = 1.9·10⁴ in the two-storey house), and the critical step of scripts/building.py --big
was 4.39 µs against 26.6 µs for its springs alone (24.1 µs now).

What is asserted (K the linear stiffness of RdemTimeStepper, Δt_crit = 2/√λ_max of the mass-normalised K):
1. the slivers exist in the layout, and the slab's side of each is not part of its cell (cellCoef 0, the slab piece's
   z axis condensed: plane stress);
2. every normal weight w_n = lateral + extra₁ + extra₂ stays below the bound of the threshold, extra ≤ 7ℓ/|s| < 7 from
   each block (w_n ≤ 15);
3. cells against the same springs and weights without cells: the cells' energy ½Σ V εᵀ(D - M I)ε is at most
   4κν/(1-ν) times the springs' (per cell and axis V M ε_d² ≤ κ Σ_q k_q u_n,q² by Cauchy–Schwarz over its bonds, with the
   free faces' weights; each bond in two cells; D - M I has no eigenvalue above 2λ = 2Mν/(1-ν)), κ = max over the bonds
   and their sides of max(M_b C/|s|, M_b C_b/ℓ_b) (C = C₁ + C₂ the bond's compliance per area, eq. 12 with the joint;
   κ = 1 for a joint of the brick's own material, 1.98 for the 10 mm joints of 2 GPa mortar, which make the springs
   softer than the brick the cells are made of). So λ_max(cells) ≤ (1 + 4κν/(1-ν)) λ_max(weighted springs);
4. weighted against plain springs: w_n K_n + w_s K_s ≤ max(w) K per bond, so λ_max(weighted) ≤ w_max λ_max(plain).
The critical step with cells is therefore at least Δt_springs/√(w_max (1 + 4κν/(1-ν))) (0.395 here); measured: springs
26.25 µs, weighted springs 23.77 µs, with cells 23.76 µs, 0.905 of the springs' (w_max 2.62). Before the threshold the
slivers weighed w_n = 8026 and the step with cells was 6.53 µs, 0.249 of the springs'."""
import math
import unittest
import harness
from yade import O
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem
from yade.rdem import scenes

Q, C, T = 0.065, 0.065, 0.01  # quarter module, course and joint of the 250x120x55 mm brick [m]


def house(cells):
	"""The house of the module's docstring; Poisson cells over every bonded block if ``cells``."""
	harness.freshScene()
	brick = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=3e6, label='brick'))
	joint = RdemJoint(young=2e9, poisson=0.25, tensileStrength=0.2e6, cohesion=0.3e6, frictionAngle=math.atan(0.75))
	O.engines = rdem.engines(formulation='consistent', failureStress='total', contactSamples=1, gravity=(0, 0, -9.81))
	W = 16 * Q - T
	plan = rdem.building_layout.rectangle(24 * Q - T, W, 0.25, 'english') + [
	        dict(name='inner', start=(12 * Q + 0.125, 0.125), end=(12 * Q + 0.125, W - 0.125), thickness=0.25, bond='english')
	]
	b = rdem.masonry.building(plan=plan, storeys=[4 * C - T], brickMaterial=brick, jointMaterial=joint, floors='slab')
	b.fixBase()
	if cells:
		rdem.poissonEngine().elements = 'cells'
		rdem.poissonEngine().build(b.bonded())
	return b


def springDt():
	"""2/ω_max of the current scene's springs (and cells) by Lanczos [s]."""
	st = rdem.timeStepper()
	st.estimate('lanczos')
	return st.springCriticalDt


def modulus(m):
	"""The springs' normal modulus M = λ + 2μ of the consistent formulation [Pa]."""
	return m.young * (1 - m.poisson) / ((1 + m.poisson) * (1 - 2 * m.poisson))


def sideCompliance(M, ell, joint):
	"""rdem::bondSideCompliance: centroid to the joint's mid-plane, block over ℓ - t/2, mortar over t/2 [m³/N]."""
	t = joint.thickness if joint else 0.0
	return (ell - t / 2) / M + (t / 2 / modulus(joint) if t > 0 else 0.0)


class CellsKeepTheStep(unittest.TestCase):

	def testEnglishBondHouseWithSlab(self):
		house(False)
		plain = springDt()
		b = house(True)
		slabs = set(i for s in b.slabs.values() for i in s)
		slivers = [I for I in O.interactions if I.isReal and (I.id1 in slabs) != (I.id2 in slabs) and sum(I.geom.segArea) < 1e-4]
		self.assertEqual(len(slivers), 4)  # the T-junctions' top bricks under the slab pieces over the rooms (docstring)
		for I in slivers:
			self.assertEqual(I.phys.cellCoef1 if I.id1 in slabs else I.phys.cellCoef2, 0.0)
		wMax, kappa, nuMax = 0.0, 0.0, 0.0
		for I in O.interactions:
			if not I.isReal or not I.geom.segArea:
				continue
			g, p = I.geom, I.phys
			wMax = max(wMax, p.weightNormal)
			m1, m2 = O.bodies[I.id1].material, O.bodies[I.id2].material
			c1, c2 = sideCompliance(modulus(m1), g.ell1, g.joint), sideCompliance(modulus(m2), g.ell2, g.joint)
			self.assertAlmostEqual(p.kn * (c1 + c2), 1, delta=1e-12)  # the compliances are the law's (no heterogeneity here)
			for m, cb, ell in ((m1, c1, g.ell1), (m2, c2, g.ell2)):
				k = max(modulus(m) * (c1 + c2) / (g.ell1 + g.ell2), modulus(m) * cb / ell)
				kappa = max(kappa, k * m.poisson / (1 - m.poisson))
		self.assertLess(wMax, 15)
		withCells = springDt()
		rdem.poissonEngine().dead = True
		weighted = springDt()
		factor = 1 + 4 * kappa
		print('critical step: springs %.4g us, weighted springs %.4g us, with cells %.4g us (%.3f of the springs\'); w_max %.3g, '
		      'bounds: cells/weighted >= %.3f, cells/springs >= %.3f' % (plain * 1e6, weighted * 1e6, withCells * 1e6, withCells / plain, wMax,
		                                                                   1 / math.sqrt(factor), 1 / math.sqrt(wMax * factor)))
		self.assertGreater(withCells, weighted / math.sqrt(factor))
		self.assertGreater(weighted, plain / math.sqrt(wMax))
		self.assertGreater(withCells, plain / math.sqrt(wMax * factor))


class OffsetCorrectionSetsTheStep(unittest.TestCase):
	"""A running-bond course bonded to a long beam (rdem.scenes.runningBondWall(1000): a 5.2 m wall of half-brick blocks on
	a 5.2 m base beam). Its 40 beam bonds are its only ones with offset centroids, and their shear springs' offset
	correction (rdem::offsetSlip) takes the beam's strain at the face centre, up to 2.6 m from the beam's centroid: a
	stiff coupling that RdemTimeStepper must count (rdem::BlockStiffness::addOffsetShear; that K is the forces' own is
	tests/yade/test_stiffness_source.py's). Measured: critical step 30.9 µs with the coupling, 43.9 µs without. At the
	automatic step the wall settles with no broken spring and a horizontal speed of 3.1·10⁻³ m/s after 32 steps; at
	0.8 × 43.9 µs (the step before the coupling was counted) its speed reached 0.058 m/s after 32 steps and 4 springs of
	the beam bonds broke by step 128. The criterion: the horizontal motion under gravity comes from the Poisson
	expansion of the settling wall, so it stays below the free-fall speed g·t (7.8·10⁻³ m/s after 32 steps)."""

	def wall(self):
		harness.freshScene()
		w = scenes.runningBondWall(1000)
		offsets = [I for I in O.interactions if I.isReal and I.phys.offsetCorrection]
		base = set(w['base'])
		self.assertEqual(len(offsets), 40)
		self.assertTrue(all(I.id1 in base or I.id2 in base for I in offsets))
		return w, offsets

	def testCouplingLowersTheStep(self):
		w, offsets = self.wall()
		st = rdem.timeStepper()
		withCoupling = st.estimate('lanczos')
		for I in offsets:
			I.phys.offsetCorrection = False
		without = st.estimate('lanczos')
		self.assertLess(withCoupling, 0.9 * without)

	def testAutomaticStepIsStable(self):
		w, offsets = self.wall()
		O.run(32, True)
		self.assertLess(max(abs(O.bodies[i].state.vel[0]) for i in w['ids']), 9.81 * O.time)
		self.assertEqual(rdem.breakCounts(), (0, 0))


if __name__ == '__main__':
	harness.run(CellsKeepTheStep, OffsetCorrectionSetsTheStep)
