"""A sampled contact's area and the time step it sets with Ig2_RdemBlock_RdemBlock_RdemGeom.clipSampleAreas (rdem::tributaryCover).

A face sample acts over the part of its tributary rectangle across which the other block lies (paper §3.1 and eq. 13:
springs and dashpots per unit contact area). The case is that of the two-storey house of scripts/building.py --big
(doc/building.md "Runs"): a roof-slab piece whose corner rests on the edge of a top brick, their faces overlapping by a
strip d = 1 mm wide. Before, the slab's corner sample took a quarter of the slab's face, halved (0.0409 m², more than the
brick's whole top face), with its eq. 13 dashpot on the 3.5 kg brick, and the house's cracked step fell to 0.96 µs."""
import math
import unittest
import harness
from yade import O
from yade.wrapper import RdemMat
from yade import rdem

SLAB = (0.2825, 0.2894, 0.075)  # half-extents [m], as the house's slab pieces over the rooms
BRICK = (0.0625, 0.13, 0.03)  # a top brick of the house's inner wall
D = 1e-3  # width of the overlap along x [m]; below a hundredth of the brick's face, so not a persistent patch
DEPTH = 1e-6  # overlap along z [m]


class ContactArea(unittest.TestCase):

	def scene(self, clip=True):
		harness.freshScene()
		mat = O.materials.append(RdemMat(young=16.7e9, poisson=0.15, density=1800, dampingNormal=1, dampingShear=1))
		O.engines = rdem.engines(segmentsPerEdge=2, formulation=None, recontact=True, contactSamples=1, dt=1e-10)
		rdem.geomFunctor().clipSampleAreas = clip
		slab = O.bodies.append(rdem.block((0, 0, 0), SLAB, mat, fixed=True))
		brick = O.bodies.append(
		        rdem.block((-SLAB[0] - BRICK[0] + D, -SLAB[1], -SLAB[2] - BRICK[2] + DEPTH), BRICK, mat))
		O.bodies[brick].state.blockedDOFs = 'XYZ'  # translations only: the mass-normalised stiffness is diagonal
		rdem.run(1)  # the collider and the geometry make the contact (the brick moves by ~1e-20 m)
		return slab, brick

	def testCornerOnAnEdgeCarriesTheOverlap(self):
		# Two samples in contact, the slab's corner in the brick and the brick's corner in the slab, each with the strip
		# d × 0.13 m halved: together the overlap of the two faces.
		slab, brick = self.scene()
		I = O.interactions[slab, brick]
		self.assertEqual(len(I.geom.sampleArea), 2)
		self.assertEqual(len(I.geom.patch), 0)
		for a in I.geom.sampleArea:
			self.assertAlmostEqual(a / (D * BRICK[1] / 2), 1, delta=1e-9)

	def testWithoutClipTheSlabCornerTakesAnEighthOfItsFace(self):
		# the default (the validated walls and the paper's cube): the slab's corner sample takes a quarter of the slab's
		# face, halved; the brick's corner a quarter of its top face, halved, whatever the overlap
		slab, brick = self.scene(clip=False)
		areas = sorted(O.interactions[slab, brick].geom.sampleArea)
		self.assertEqual(len(areas), 2)
		self.assertAlmostEqual(areas[0] / (4 * BRICK[0] * BRICK[1] / 8), 1, delta=1e-9)
		self.assertAlmostEqual(areas[1] / (4 * SLAB[0] * SLAB[1] / 8), 1, delta=1e-9)

	def testStepOfTheOverlap(self):
		# The brick moves along x, y, z only, each axis a spring-dashpot oscillator of the whole contact area
		# A = d × 0.13 m: k = k̄A, c = c̄A (eq. 13, h = 1; the caps m/Δt do not bind at Δt = 1e-10 s). Springs alone:
		# 2/ω, ω² = k̄_n A/m (k̄_n > k̄_s); with the dashpots, per axis the root of Δt²k/m + 2Δt c/m = 4 (leapfrog with a
		# mid-step dashpot, Belytschko2000), the smallest over the axes. Lanczos to 1e-3 in λ: 1e-3 in Δt.
		slab, brick = self.scene()
		I = O.interactions[slab, brick]
		m = O.bodies[brick].state.mass
		A = D * BRICK[1]
		wn, ws = I.phys.weightNormal, I.phys.weightShear
		ts = rdem.timeStepper()
		ts.contactBound = False  # the contact that exists, not those the free brick could still make on its other faces
		dt = ts.estimate('lanczos')
		springs = 2 / math.sqrt(wn * I.phys.kn * A / m)
		damped = min(4 / (c + math.sqrt(c * c + 4 * k)) for k, c in ((wn * I.phys.kn * A / m, wn * I.phys.cn * A / m),
		                                                            (ws * I.phys.ks * A / m, ws * I.phys.cs * A / m)))
		print('springs %.6g s (analytic %.6g s), damped %.6g s (analytic %.6g s)' % (ts.springCriticalDt, springs, dt, damped))
		self.assertAlmostEqual(ts.springCriticalDt / springs, 1, delta=1e-3)
		self.assertAlmostEqual(dt / damped, 1, delta=1e-3)


if __name__ == '__main__':
	harness.run(ContactArea)
