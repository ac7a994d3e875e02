"""Tests of rdem.limit_analysis (pure Python, no YADE): the tilt at which a dry-stacked wall collapses on a tilting base,
and the minimum thickness of a semicircular arch of voussoirs.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_limit_analysis`` (or through CTest)."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.limit_analysis import stackTilt, archMinimumThickness, archTiltMultiplier, OneWayWall  # noqa: E402


class StackTilt(unittest.TestCase):

	def testSingleBlockIsHousnersUplift(self):
		# one block 2b wide and 2h tall: tan(theta) = b/h, Housner's alpha (../shared benchmarks §2: b = 0.1, h = 0.5)
		c = stackTilt(0.2, 1.0, [0.0], 0.8)
		self.assertEqual(c.mechanism, 'overturning')
		self.assertAlmostEqual(c.angle, 0.19739555984988078, delta=1e-15)  # atan(0.2)
		self.assertAlmostEqual(c.multiplier, 0.2, delta=1e-15)

	def testWallOverturnsAtItsBase(self):
		# ten courses of 55 mm, 0.12 m thick: the base joint governs, t/H = 0.12/0.55; the joint below the top course
		# would need t/0.055 = 2.18
		zs = [0.055 * k for k in range(10)]
		c = stackTilt(0.12, 0.55, zs, 0.75)
		self.assertEqual((c.mechanism, c.joint), ('overturning', 0))
		self.assertAlmostEqual(c.multiplier, 0.12 / 0.55, delta=1e-15)
		self.assertAlmostEqual(c.overturning[-1], 0.12 / 0.055, delta=1e-12)
		self.assertAlmostEqual(math.degrees(c.angle), 12.3080, delta=1e-4)  # atan(0.21818...) = 0.214814 rad (series to x^7)

	def testJointsInAnyOrder(self):
		c = stackTilt(0.12, 0.55, [0.11, 0.0, 0.055], 0.75)
		self.assertEqual(c.joint, 1)  # the joint at z = 0
		self.assertAlmostEqual(c.multiplier, 0.12 / 0.55, delta=1e-15)

	def testSquatWallSlides(self):
		# t/H = 2 > mu = 0.6: it slides at tan(theta) = mu
		c = stackTilt(0.3, 0.15, [0.0, 0.05, 0.1], 0.6)
		self.assertEqual((c.mechanism, c.joint), ('sliding', 0))
		self.assertAlmostEqual(c.angle, math.atan(0.6), delta=1e-15)
		self.assertAlmostEqual(c.overturning[0], 2.0, delta=1e-15)

	def testBadArguments(self):
		with self.assertRaisesRegex(ValueError, r'thickness = 0: must be a finite number > 0'):
			stackTilt(0, 1, [0], 0.7)
		with self.assertRaisesRegex(ValueError, r'friction = nan'):
			stackTilt(0.1, 1, [0], float('nan'))
		with self.assertRaisesRegex(ValueError, r'joints = \[1.0\]: must be one or more heights in \[0, height = 1\)'):
			stackTilt(0.1, 1, [1.0], 0.7)
		with self.assertRaisesRegex(ValueError, r'joints = \[\]'):
			stackTilt(0.1, 1, [], 0.7)
		with self.assertRaisesRegex(ValueError, r"joints = 'ab': must be a sequence of heights"):
			stackTilt(0.1, 1, 'ab', 0.7)



def mechanismThickness(N, haunch):
	"""The thickness t/R at which the symmetric five-hinge mechanism of a semicircular arch of N voussoirs (N even; hinges
	at the springings' extrados, the intrados of joints haunch and N - haunch, the crown's extrados) does no work under a
	virtual motion: the kinematic (upper bound) theorem, independent of the thrust-line search. Right half, R = 1, the
	lower piece (joints haunch..N) turning about the springing's extrados A, the upper piece (joints N/2..haunch) about the
	intersection I of line AB with the horizontal through the crown's hinge C (which moves vertically by symmetry)."""
	delta = math.pi / N

	def work(t):
		ri, re = 1 - t / 2, 1 + t / 2
		rbar = (2.0 / 3.0) * (re**3 - ri**3) / (re * re - ri * ri) * math.sin(delta / 2) / (delta / 2)
		A = (re, 0.0)
		th = math.pi - haunch * delta
		B = (ri * math.cos(th), ri * math.sin(th))
		C = (0.0, re)
		s = (C[1] - A[1]) / (B[1] - A[1])  # I = A + s (B - A) at the height of C
		I = (A[0] + s * (B[0] - A[0]), C[1])
		w2 = (B[0] - A[0]) / (B[0] - I[0])  # the rate of the upper piece for a unit rate of the lower one (same velocity at B)
		total = 0.0
		for m in range(N // 2, N):  # voussoirs of the right half, between joints m and m + 1
			a = math.pi - (m + 0.5) * delta
			G = (rbar * math.cos(a), rbar * math.sin(a))
			vz = (G[0] - A[0]) if m >= haunch else w2 * (G[0] - I[0])  # vertical velocity of the centroid
			total -= vz  # power of gravity (equal weights)
		return total

	lo, hi = 0.01, 0.5
	flo = work(lo)
	for _ in range(100):
		mid = (lo + hi) / 2
		if (work(mid) > 0) == (flo > 0):
			lo = mid
		else:
			hi = mid
	return (lo + hi) / 2


class ArchMinimumThickness(unittest.TestCase):

	def testContinuousLimit(self):
		# Milankovitch 1907: t/R = 0.1075 for the continuous arch, the rupture joints at 54.5 deg from the crown; N = 400
		# puts a joint within 0.225 deg of any angle
		c = archMinimumThickness(400)
		self.assertAlmostEqual(c.ratio, 0.1075, delta=1e-4)
		inner = [k for k, side in c.hinges if side == 'intrados']
		self.assertEqual(len(inner), 2)
		self.assertAlmostEqual(inner[1] * 180 / 400 - 90, 54.5, delta=0.25)  # from the crown
		# finite N: never thicker than the continuous arch; equal for the N whose joints include 54 deg (multiples of 10)
		for N in range(4, 31, 2):
			self.assertLess(archMinimumThickness(N).ratio, 0.10748 + 1e-6, msg='N = %d' % N)
		for N in (10, 20, 30):
			self.assertAlmostEqual(archMinimumThickness(N).ratio, archMinimumThickness(10).ratio, delta=1e-9)

	def testStaticEqualsKinematic(self):
		# the thrust line's t_min equals the thickness at which the five-hinge mechanism through its hinges does no work
		for N in (6, 8, 12, 16):
			c = archMinimumThickness(N)
			hinges = dict((k, side) for k, side in c.hinges)
			self.assertEqual(len(c.hinges), 5, msg='N = %d: %s' % (N, c.hinges))
			self.assertEqual((hinges[0], hinges[N // 2], hinges[N]), ('extrados', 'extrados', 'extrados'))
			haunch = max(k for k, side in c.hinges if side == 'intrados')
			self.assertAlmostEqual(mechanismThickness(N, haunch), c.ratio, delta=1e-8, msg='N = %d' % N)
			# a mechanism through another joint does work only below a thinner arch: t_min is the largest such thickness
			for other in range(N // 2 + 1, N):
				if other != haunch:
					self.assertLess(mechanismThickness(N, other), c.ratio, msg='N = %d, joint %d' % (N, other))

	def testOddVoussoirsHaveAKeystone(self):
		c = archMinimumThickness(9)  # the crown is a voussoir: the extrados hinges at both of its joints
		self.assertIn((4, 'extrados'), c.hinges)
		self.assertIn((5, 'extrados'), c.hinges)

	def testFrictionNeeded(self):
		self.assertLess(archMinimumThickness(8).friction, 0.4)

	def testBadArguments(self):
		with self.assertRaisesRegex(ValueError, r'voussoirs = 1: must be an integer >= 2'):
			archMinimumThickness(1)
		with self.assertRaisesRegex(ValueError, r'voussoirs = 8.0'):
			archMinimumThickness(8.0)



def solve(A, b):
	"""Gaussian elimination with partial pivoting (small dense systems)."""
	n = len(b)
	M = [list(row) + [b[i]] for i, row in enumerate(A)]
	for c in range(n):
		p = max(range(c, n), key=lambda r: abs(M[r][c]))
		M[c], M[p] = M[p], M[c]
		for r in range(c + 1, n):
			f = M[r][c] / M[c][c]
			for k in range(c, n + 1):
				M[r][k] -= f * M[c][k]
	x = [0.0] * n
	for r in reversed(range(n)):
		x[r] = (M[r][n] - sum(M[r][k] * x[k] for k in range(r + 1, n))) / M[r][r]
	return x


def mechanismStatics(N, t, hinges):
	"""Equilibrium of the three bodies of a four-hinge mechanism (hinge forces at the hinge points, weights and the
	horizontal load lambda times them at the voussoirs' centroids): 9 equations, 8 hinge force components and lambda.
	Returns (lambda, the thrust line's r at every joint from 1 to N), independently of archTiltMultiplier's kinematics."""
	delta = math.pi / N
	ri, re = 1 - t / 2, 1 + t / 2
	rbar = (2.0 / 3.0) * (re**3 - ri**3) / (re * re - ri * ri) * math.sin(delta / 2) / (delta / 2)
	m = delta * (re * re - ri * ri) / 2
	G = [(rbar * math.cos(math.pi - (k + 0.5) * delta), rbar * math.sin(math.pi - (k + 0.5) * delta)) for k in range(N)]
	P = [((ri if side == 'intrados' else re) * math.cos(math.pi - k * delta), (ri if side == 'intrados' else re) * math.sin(math.pi - k * delta)) for k, side in hinges]
	h = [k for k, _ in hinges]
	bodies = [range(h[0], h[1]), range(h[1], h[2]), range(h[2], h[3])]
	A = [[0.0] * 9 for _ in range(9)]
	b = [0.0] * 9

	def force(row, f, sign, p):  # hinge force unknowns f, f+1 (x, z) acting with sign at p on the body of rows row..row+2
		A[row][f] += sign
		A[row + 1][f + 1] += sign
		A[row + 2][f + 1] += sign * p[0]
		A[row + 2][f] -= sign * p[1]

	for j, body in enumerate(bodies):
		r = 3 * j
		W = m * len(body)
		A[r][8] -= W  # x: -lambda W
		b[r + 1] += W  # z: -W moved to the right-hand side
		A[r + 2][8] += sum(m * G[k][1] for k in body)  # moment of (-lambda m, -m) at G: -m Gx + lambda m Gz
		b[r + 2] += sum(m * G[k][0] for k in body)
		if j == 0:
			force(r, 0, 1, P[0])
			force(r, 2, -1, P[1])
		elif j == 1:
			force(r, 2, 1, P[1])
			force(r, 4, -1, P[2])
		else:
			force(r, 4, 1, P[2])
			force(r, 6, 1, P[3])
	x = solve(A, b)
	lam = x[8]
	F, M, rs = [x[0], x[1]], P[0][0] * x[1] - P[0][1] * x[0], []
	for k in range(h[0] + 1, N + 1):  # the thrust line from the left support's force, voussoir by voussoir
		f = (-lam * m, -m)
		F = [F[0] + f[0], F[1] + f[1]]
		M += G[k - 1][0] * f[1] - G[k - 1][1] * f[0]
		a = math.pi - k * delta
		rs.append(M / (math.cos(a) * F[1] - math.sin(a) * F[0]))
	return lam, rs


class ArchTilt(unittest.TestCase):

	def testZeroAtTheMinimumThickness(self):
		for N in (8, 10):
			lam, hinges = archTiltMultiplier(N, archMinimumThickness(N).ratio)
			self.assertAlmostEqual(lam, 0, delta=1e-8)

	def testStaticsOfTheMechanism(self):
		# the least mechanism's multiplier equals the statics of its three bodies, and the thrust line of that equilibrium
		# lies inside the section at every joint: statically admissible too, so it is the exact collapse multiplier
		N = 8
		for factor in (1.2, 1.5, 2.0):
			t = factor * archMinimumThickness(N).ratio
			lam, hinges = archTiltMultiplier(N, t)
			lamStatics, rs = mechanismStatics(N, t, hinges)
			self.assertAlmostEqual(lam, lamStatics, delta=1e-9 * max(1, lam))
			for r in rs:
				self.assertTrue(1 - t / 2 - 1e-9 <= r <= 1 + t / 2 + 1e-9, 'factor %g: r = %g outside' % (factor, r))
		lam, hinges = archTiltMultiplier(N, 1.5 * archMinimumThickness(N).ratio)
		self.assertAlmostEqual(lam, 0.16361, delta=1e-5)
		self.assertEqual(hinges, [(0, 'extrados'), (2, 'intrados'), (4, 'extrados'), (7, 'intrados')])

	def testGrowsWithThickness(self):
		lams = [archTiltMultiplier(8, f * 0.10086)[0] for f in (1.1, 1.3, 1.5, 2.0)]
		self.assertEqual(lams, sorted(lams))

	def testBadArguments(self):
		with self.assertRaisesRegex(ValueError, r'ratio = 1.5: must be < 1'):
			archTiltMultiplier(8, 1.5)
		with self.assertRaisesRegex(ValueError, r'voussoirs = 2'):
			archTiltMultiplier(2, 0.1)


class OneWayWallRelation(unittest.TestCase):

	def testStaticsOfTheHalves(self):
		# at theta = 0, independently of the virtual work: moments of each half about its pivot, (y, z) from the base edge
		# on the loaded face, hinge at (0, h/2) carrying (Hh, -Nh) on the lower half with Nh = W/2 + O:
		#   lower, about (t, 0):  W t/4 - zp F/2 + t Nh - (h/2) Hh = 0
		#   upper, about (t, h):  W t/4 + zp F/2 - t Nh - (h/2) Hh = 0
		# their difference gives F = 2 t Nh / zp = (W + 2 O) t / zp
		for zp in (1.0, 0.8):
			h, t, W, O = 2.0, 0.11, 1000.0, 300.0
			w = OneWayWall(h, t, W, O, loadHeight=zp)
			Nh = W / 2 + O
			Hh = W * t / (2 * h)  # their sum
			F = w.force(0.0)
			self.assertAlmostEqual(W * t / 4 - zp * F / 2 + t * Nh - h / 2 * Hh, 0, delta=1e-9)
			self.assertAlmostEqual(W * t / 4 + zp * F / 2 - t * Nh - h / 2 * Hh, 0, delta=1e-9)
			self.assertAlmostEqual(w.initialForce, F, delta=1e-9)

	def testVirtualWorkByFiniteDifferences(self):
		# F dy_p = dV with V = (W + 2 O) B_z, B_z = t sin(theta) + h/2 cos(theta), by central differences
		w = OneWayWall(1.0, 0.1, 500.0, 100.0, loadHeight=0.45)
		V = lambda th: (w.W + 2 * w.O) * (w.t * math.sin(th) + w.h / 2 * math.cos(th))
		for th in (0.01, 0.05, 0.1, 0.15):
			d = 1e-6
			F = (V(th + d) - V(th - d)) / (w.loadDisplacement(th + d) - w.loadDisplacement(th - d))
			self.assertAlmostEqual(w.force(th) / F, 1, delta=1e-7)

	def testInstabilityDisplacementIsTheThickness(self):
		for h, t, O in ((1.0, 0.1, 0.0), (2.5, 0.23, 5e3), (0.6, 0.12, 0.0)):
			w = OneWayWall(h, t, 1e3, O)
			self.assertAlmostEqual(w.instabilityDisplacement, t, delta=1e-12)
			self.assertAlmostEqual(w.force(w.thetaU), 0, delta=1e-9)
			self.assertAlmostEqual(w.forceAt(t), 0, delta=1e-6)
			# small rotations: the linear relation F0 (1 - Delta/t) within 1 % of F0 up to Delta = t/10
			self.assertAlmostEqual(w.forceAt(0.1 * t) / w.initialForce, 0.9, delta=0.01)

	def testBadArguments(self):
		with self.assertRaisesRegex(ValueError, r'thickness = 2: must be < height = 1'):
			OneWayWall(1, 2, 1)
		with self.assertRaisesRegex(ValueError, r'overburden = -1'):
			OneWayWall(1, 0.1, 1, -1)
		with self.assertRaisesRegex(ValueError, r'loadHeight = 0.6: must be in \(0, height/2 = 0.5\]'):
			OneWayWall(1, 0.1, 1, loadHeight=0.6)


if __name__ == '__main__':
	unittest.main()
