"""Tests of rdem.arch_layout (pure Python, no YADE): voussoirs as clumps of boxes whose outer faces are the exact joints.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_arch_layout`` (or through CTest)."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.arch_layout import archLayout, _sectionsOverlap  # noqa: E402


def faceOf(block, P, Q):
	"""Whether one of the block's two faces normal to its own x axis is the segment P-Q (in x-z), to 1e-12 m."""
	(ax, az), (bx, bz) = block.axes()
	a, c = block.half[0], block.half[2]
	for sx in (-1, 1):
		corners = sorted((block.centre[0] + sx * a * ax + j * c * bx, block.centre[2] + sx * a * az + j * c * bz) for j in (-1, 1))
		if all(math.hypot(p[0] - q[0], p[1] - q[1]) < 1e-12 for p, q in zip(corners, sorted((P, Q)))):
			return True
	return False


def sector(R, t, delta):
	"""Area, centroid radius and polar moment about the centroid of an annular sector of angle delta (exact)."""
	ri, re = R - t / 2, R + t / 2
	A = delta * (re * re - ri * ri) / 2
	rc = 2 * math.sin(delta / 2) * (re**3 - ri**3) / (3 * A)
	return A, rc, delta * (re**4 - ri**4) / 4 - A * rc * rc


class Semicircular(unittest.TestCase):

	def setUp(self):
		self.N, self.R, self.t, self.d = 9, 1.0, 0.1, 0.2
		self.lay = archLayout(2 * self.R, self.t, self.d, self.N)

	def testJointFacesAreExact(self):
		lay, N = self.lay, self.N
		faces = lay.jointFaces[0]
		self.assertEqual(len(faces), N + 1)
		for k, (P, Q) in enumerate(faces):  # radial, t long, at angle pi - k pi/N
			ang = math.pi - k * math.pi / N
			self.assertAlmostEqual(P[0], (self.R - self.t / 2) * math.cos(ang), delta=1e-14)
			self.assertAlmostEqual(Q[1], (self.R + self.t / 2) * math.sin(ang), delta=1e-14)
		vs = lay.voussoirs()
		for k, v in enumerate(vs):
			a, b, core = (lay.blocks[i] for i in v.blocks)
			self.assertTrue(faceOf(a, *faces[k]) and faceOf(b, *faces[k + 1]), 'voussoir %d' % k)
		joints = [p for p in lay.pairs if p[2] == 'voussoir']
		self.assertEqual(len(joints), N - 1)
		for i, j, _ in joints:  # both boxes of a joint have that joint as a face
			k = lay.blocks[j].unit
			self.assertTrue(faceOf(lay.blocks[i], *faces[k]) and faceOf(lay.blocks[j], *faces[k]))

	def testMassCentroidAndInertiaAreTheWedges(self):
		A, rc, J = sector(self.R, self.t, math.pi / self.N)
		for k, v in enumerate(self.lay.voussoirs()):
			self.assertAlmostEqual(v.area / A, 1, delta=1e-12)
			self.assertAlmostEqual(v.polar / J, 1, delta=1e-9)
			bs = [self.lay.blocks[i] for i in v.blocks]
			m = sum(b.mass for b in bs)
			self.assertAlmostEqual(m / (A * self.d), 1, delta=1e-12)
			cx, cz = (sum(b.mass * b.centre[d] for b in bs) / m for d in (0, 2))
			ang = math.pi - (k + 0.5) * math.pi / self.N
			self.assertAlmostEqual(cx, rc * math.cos(ang), delta=1e-12)
			self.assertAlmostEqual(cz, rc * math.sin(ang), delta=1e-12)
			self.assertTrue(all(b.mass > 0 and min(b.inertia) > 0 for b in bs))

	def testBoxesOfDifferentVoussoirsDoNotOverlap(self):
		lay = self.lay
		for i, p in enumerate(lay.blocks):
			for j in range(i + 1, len(lay.blocks)):
				q = lay.blocks[j]
				if p.unit != q.unit:
					self.assertFalse(_sectionsOverlap(p, q), 'blocks %d and %d' % (i, j))

	def testOutline(self):
		# the face boxes reach beyond the extrados by about R Delta^2/8 (their far corners, half a chord from the joint)
		delta = math.pi / self.N
		self.assertGreater(self.lay.protrusion, 0)
		self.assertLess(self.lay.protrusion, 1.2 * self.R * delta * delta / 8)

	def testAbutments(self):
		ab = [u for u in self.lay.units if u.kind == 'abutment']
		self.assertEqual([u.side for u in ab], ['left', 'right'])
		faces = self.lay.jointFaces[0]
		for u, face in zip(ab, (faces[0], faces[-1])):
			b = self.lay.blocks[u.blocks[0]]
			# its face on the springing joint's plane, centred on the joint, twice as wide
			(ax, az), (bx, bz) = b.axes()
			P, Q = face
			M = ((P[0] + Q[0]) / 2, (P[1] + Q[1]) / 2)
			self.assertAlmostEqual(b.half[2], self.t, delta=1e-14)
			self.assertAlmostEqual(abs((b.centre[0] - M[0]) * ax + (b.centre[2] - M[1]) * az), b.half[0], delta=1e-14)
			self.assertAlmostEqual((b.centre[0] - M[0]) * bx + (b.centre[2] - M[1]) * bz, 0, delta=1e-14)
			self.assertLess(b.centre[2], 0)  # below the springing
		self.assertEqual(sorted(self.lay.fixed()), sorted(u.blocks[0] for u in ab))
		self.assertEqual(len([p for p in self.lay.pairs if p[2] == 'springing']), 2)


class Shapes(unittest.TestCase):

	def testSegmentalSkewbacks(self):
		s, f, t = 4.0, 1.0, 0.2
		lay = archLayout(s, t, 0.5, 8, shape='segmental', rise=f)
		R = (s * s / 4 + f * f) / (2 * f)
		self.assertAlmostEqual(lay.radius, R, delta=1e-14)
		P, Q = lay.jointFaces[0][0]
		# the springing joint is radial: inclined by the half-angle asin(s/2R) from the vertical
		self.assertAlmostEqual(math.atan2(Q[1] - P[1], P[0] - Q[0]), math.pi / 2 - math.asin(s / 2 / R), delta=1e-12)
		self.assertAlmostEqual((P[0] + Q[0]) / 2, -s / 2, delta=1e-12)
		self.assertAlmostEqual((P[1] + Q[1]) / 2, 0, delta=1e-12)
		crown = lay.jointFaces[0][4]
		self.assertAlmostEqual((crown[0][1] + crown[1][1]) / 2, f, delta=1e-12)
		for u in lay.units:
			if u.kind == 'abutment':  # on the springing joint's plane
				b = lay.blocks[u.blocks[0]]
				P, Q = lay.jointFaces[0][0 if u.side == 'left' else -1]
				(ax, az), _ = b.axes()
				self.assertAlmostEqual(abs((b.centre[0] - P[0]) * ax + (b.centre[2] - P[1]) * az), b.half[0], delta=1e-12)
				self.assertAlmostEqual(abs((b.centre[0] - Q[0]) * ax + (b.centre[2] - Q[1]) * az), b.half[0], delta=1e-12)

	def testPointedCrownJointIsVertical(self):
		s, t = 2.0, 0.1
		lay = archLayout(s, t, 0.2, 8, shape='pointed')  # equilateral: centres at the springings, radius = span
		self.assertAlmostEqual(lay.radius, s, delta=1e-14)
		P, Q = lay.jointFaces[0][4]
		self.assertEqual((P[0], Q[0]), (0.0, 0.0))
		self.assertAlmostEqual(P[1], math.sqrt((s - t / 2)**2 - 1), delta=1e-14)  # intrados of radius s - t/2 centred at (+-1, 0)
		vs = lay.voussoirs()
		for a, b in zip(vs, reversed(vs)):  # mirror symmetric
			self.assertAlmostEqual(a.area, b.area, delta=1e-12)
			self.assertAlmostEqual(a.centroid[0], -b.centroid[0], delta=1e-12)
			self.assertAlmostEqual(a.centroid[2], b.centroid[2], delta=1e-12)
		# the crown voussoirs: mass centre as the section's
		for v in vs:
			bs = [lay.blocks[i] for i in v.blocks]
			m = sum(b.mass for b in bs)
			self.assertAlmostEqual(sum(b.mass * b.centre[2] for b in bs) / m, v.centroid[2], delta=1e-12)
		# total area: the equilateral arch's centreline length 2 R pi/3 times t (each arc's offsets are symmetric)
		self.assertAlmostEqual(sum(v.area for v in vs), t * 2 * s * math.pi / 3, delta=1e-3 * t)

	def testPiers(self):
		lay = archLayout(2.0, 0.12, 0.3, 10, supports='piers', pierHeight=1.5, pierWidth=0.4, pierCourses=3)
		piers = [u for u in lay.units if u.kind == 'pier']
		self.assertEqual(len(piers), 6)
		P, Q = lay.jointFaces[0][0]
		self.assertAlmostEqual(P[1], 1.5, delta=1e-14)  # springing on the pier tops
		left = [lay.blocks[u.blocks[0]] for u in piers if u.side == 'left']
		self.assertAlmostEqual(left[-1].centre[2] + left[-1].half[2], 1.5, delta=1e-14)
		self.assertAlmostEqual(left[-1].centre[0] + left[-1].half[0], -1 + 0.06, delta=1e-14)  # flush with the intrados
		kinds = sorted(k for _, _, k in lay.pairs)
		self.assertEqual(kinds.count('pier'), 4)
		self.assertEqual(kinds.count('foundation'), 2)
		self.assertEqual(kinds.count('springing'), 2)
		self.assertEqual(len(lay.fixed()), 2)


class Vault(unittest.TestCase):

	def testStaggeredRings(self):
		N = 8
		lay = archLayout(3.0, 0.15, None, N, length=1.2, rings=4)
		self.assertEqual(lay.rings, 4)
		for r in range(4):
			vs = lay.voussoirs(r)
			self.assertEqual(len(vs), N if r % 2 == 0 else N + 1)
			for v in vs:
				for i in v.blocks:
					b = lay.blocks[i]
					self.assertAlmostEqual(b.half[1], 0.15 - 0.5e-3 * 0.3, delta=1e-14)  # the ring gap, 1e-3 of the ring depth
					self.assertAlmostEqual(b.centre[1], 0.3 * r + 0.15, delta=1e-14)
		us = [v.joints for v in lay.voussoirs(1)]
		self.assertEqual(us[0], (0.0, 0.5 / N))  # half voussoirs at the springings
		self.assertEqual(us[1], (0.5 / N, 1.5 / N))
		# every voussoir touches two of the next ring (staggered); springings of all rings on the abutments
		ring = [p for p in lay.pairs if p[2] == 'ring']
		for v in lay.voussoirs(0):
			touched = set(lay.blocks[j].unit for i, j, _ in ring if lay.blocks[i].unit == lay.units.index(v))
			self.assertEqual(len(touched), 2)
		self.assertEqual(len([p for p in lay.pairs if p[2] == 'springing']), 8)

	def testUnstaggered(self):
		lay = archLayout(3.0, 0.15, None, 8, length=1.2, rings=3, stagger=False)
		self.assertEqual([len(lay.voussoirs(r)) for r in range(3)], [8, 8, 8])


class BadArguments(unittest.TestCase):

	def testMessages(self):
		cases = [
		        (dict(span=0), r'span = 0: must be a finite number > 0'),
		        (dict(thickness=1.5), r'thickness = 1.5: must be < the centreline radius 1'),
		        (dict(voussoirs=2), r'voussoirs = 2: must be an integer >= 3'),
		        (dict(voussoirs=7.0), r'voussoirs = 7.0: must be an integer'),
		        (dict(shape='gothic'), r"shape = 'gothic': must be one of 'semicircular', 'segmental', 'pointed'"),
		        (dict(shape='pointed', voussoirs=7), r'voussoirs = 7: a pointed arch needs an even number'),
		        (dict(shape='segmental'), r'rise = None: a segmental arch needs its rise'),
		        (dict(shape='segmental', rise=1.0), r'rise = 1.0: must be < span/2 = 1'),
		        (dict(rise=0.5), r"rise = 0.5: only for shape='segmental'"),
		        (dict(supports='piers'), r'pierHeight = nan'),
		        (dict(supports='piers', pierHeight=1, pierWidth=0.05), r'pierWidth = 0.05: must be >= thickness'),
		        (dict(shape='segmental', rise=0.5, supports='piers', pierHeight=1, pierWidth=0.3), r"supports = 'piers': only for semicircular and pointed"),
		        (dict(rings=2), r'rings = 2: an arch \(length=None\) has one ring'),
		        (dict(depth=-1), r'depth = -1'),
		        (dict(pointedness=0), r'pointedness = 0'),
		]
		for kw, msg in cases:
			args = dict(span=2.0, thickness=0.1, depth=0.2, voussoirs=8)
			args.update(kw)
			with self.assertRaisesRegex(ValueError, msg, msg=str(kw)):
				archLayout(**args)


if __name__ == '__main__':
	unittest.main()
