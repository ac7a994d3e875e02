"""Tests of rdem.ground_motion (numpy only, no YADE): .AT2 and column files written here in a temporary folder, the
trapezoid integration against closed forms and its error bound, baseline correction, the synthetic pulses, resampling,
GroundMotion and input validation. Nothing is downloaded.

Run: ``cd tests/python && PYTHONPATH=../../py /usr/bin/python3 -m unittest -v test_ground_motion`` (or through CTest).
Round-off: values of order 1 carry errors of a few 1e-16 per operation; "to round-off" below means within 1e-14 of
the scale of the quantity unless said otherwise (a few hundred operations accumulate at most ~1e-14)."""
import math
import os
import re
import sys
import tempfile
import unittest
import warnings

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'py'))
from rdem.ground_motion import G, UNITS, Record, GroundMotion, readAT2, readColumns, readValues, sinePulse, rickerWavelet, sweep, constant  # noqa: E402

RECORDS = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'data', 'records')

# 12 samples written as 5 + 5 + 2 per line, as PEER does (values in the file's units)
AT2_VALUES = ['.1234E-02', '-.5678E-02', '.9012E-01', '-.3456E-01', '.7890E-02', '.2468E-02', '-.1357E-02', '.0000E+00', '.1111E+00', '-.2222E+00',
              '.3333E-03', '-.4444E-03']


def at2Text(units='G', sizes='NPTS=    12, DT=   .0050 SEC', values=AT2_VALUES, perLine=5):
	rows = [' '.join('%11s' % v for v in values[i:i + perLine]) for i in range(0, len(values), perLine)]
	return '\n'.join(['PEER NGA STRONG MOTION DATABASE RECORD', 'IMPERIAL VALLEY 10/15/79 2316, EL CENTRO ARRAY #6, 230',
	                  'ACCELERATION TIME SERIES IN UNITS OF %s' % units, sizes] + rows) + '\n'


def zeroCrossings(r):
	"""Times where the piecewise-linear record changes sign (linear interpolation between samples of opposite sign)."""
	a, t = r.acc, r.times()
	i = np.flatnonzero(a[:-1] * a[1:] < 0)
	return t[i] + r.dt * a[i] / (a[i] - a[i + 1])


def trend(t, v, degree=1):
	"""Coefficients (highest first) of the least-squares polynomial through (t, v), t scaled to [0, 1]."""
	x = (t - t[0]) / (t[-1] - t[0])
	return np.polyfit(x, v, degree)


class Files(unittest.TestCase):

	def setUp(self):
		self.tmp = tempfile.TemporaryDirectory()
		self.addCleanup(self.tmp.cleanup)

	def write(self, name, text):
		path = os.path.join(self.tmp.name, name)
		with open(path, 'w') as f:
			f.write(text)
		return path


class ReadAT2(Files):

	def testHeaderAndValuesInG(self):
		path = self.write('rec.AT2', at2Text())
		r = readAT2(path)
		self.assertEqual((len(r), r.dt, r.t0, r.units), (12, 0.005, 0.0, 'g'))
		self.assertEqual(r.name, 'IMPERIAL VALLEY 10/15/79 2316, EL CENTRO ARRAY #6, 230')
		self.assertAlmostEqual(r.duration, 11 * 0.005, delta=1e-17)
		# exact: each value is the decimal in the file times 9.80665, one rounding, nothing else
		self.assertTrue(np.array_equal(r.acc, np.array([float(v) * 9.80665 for v in AT2_VALUES])))
		self.assertEqual(r.pga, 0.2222 * 9.80665)

	def testUnits(self):
		for units, factor, name in (('CM/S/S', 0.01, 'cm/s^2'), ('CM/S^2', 0.01, 'cm/s^2'), ('cm/sec/sec', 0.01, 'cm/s^2'), ('M/S/S', 1.0, 'm/s^2'),
		                            ('M/S^2', 1.0, 'm/s^2'), ('g', G, 'g')):
			with self.subTest(units=units):
				r = readAT2(self.write('u.AT2', at2Text(units=units)))
				self.assertEqual(r.units, name)
				self.assertTrue(np.array_equal(r.acc, np.array([float(v) * factor for v in AT2_VALUES])))
		self.assertEqual(UNITS, {'g': 9.80665, 'cm/s^2': 0.01, 'm/s^2': 1.0})

	def testTolerantSizeLine(self):
		for sizes in ('NPTS= 12 DT= 0.005 SEC', 'npts=12, dt=.5000E-02 sec', 'NPTS = 12, DT = 5.0D-03 SEC', 'NPTS=12,DT=0.0050', '   12    0.0050    NPTS, DT'):
			with self.subTest(sizes=sizes):
				r = readAT2(self.write('s.AT2', at2Text(sizes=sizes)))
				self.assertEqual((len(r), r.dt), (12, 0.005))

	def testLinesOfAnyLength(self):
		"""One value per line, 7 per line, and Fortran numbers: D exponents, numbers run together."""
		for perLine in (1, 7, 12):
			r = readAT2(self.write('l.AT2', at2Text(perLine=perLine)))
			self.assertTrue(np.array_equal(r.acc, np.array([float(v) * G for v in AT2_VALUES])))
		text = at2Text(values=[]).rstrip('\n') + '\n .1234E-02-.5678E-02  1.5D-03 -2.5d-01\n\n  7.0 -.5 3E1 0 1 2 3 4\n'
		r = readAT2(self.write('f.AT2', text))
		self.assertTrue(np.array_equal(r.acc, np.array([0.001234, -0.005678, 0.0015, -0.25, 7, -0.5, 30, 0, 1, 2, 3, 4]) * G))

	def testWrongNPTS(self):
		for npts in (13, 11, 120):
			path = self.write('n.AT2', at2Text(sizes='NPTS=   %d, DT=   .0050 SEC' % npts))
			with self.assertRaisesRegex(ValueError, '^%s: NPTS = %d in the header but 12 values read$' % (re.escape(path), npts)):
				readAT2(path)

	def testUnknownUnits(self):
		for units in ('INCH/S/S', 'KM/S/S', 'MG'):
			path = self.write('x.AT2', at2Text(units=units))
			with self.assertRaisesRegex(ValueError, '^%s, line 3: unknown units %r' % (re.escape(path), units)):
				readAT2(path)
		path = self.write('y.AT2', at2Text().replace('IN UNITS OF G', 'IN G'))
		with self.assertRaisesRegex(ValueError, '^%s, line 3: no units found' % re.escape(path)):
			readAT2(path)

	def testBadFiles(self):
		missing = os.path.join(self.tmp.name, 'missing.AT2')
		with self.assertRaisesRegex(FileNotFoundError, "^path = '%s': no such file$" % re.escape(missing)):
			readAT2(missing)
		path = self.write('b.AT2', at2Text().replace('.7890E-02', '.78X0E-02'))
		with self.assertRaisesRegex(ValueError, '^%s, line 5: not a number' % re.escape(path)):
			readAT2(path)
		path = self.write('h.AT2', 'PEER\nEVENT\n')
		with self.assertRaisesRegex(ValueError, '^%s: an .AT2 file starts with 4 header lines; this one has 2' % re.escape(path)):
			readAT2(path)
		for sizes, message in (('NPTS= 12.5, DT= .005', 'NPTS = 12.5 must be an integer'), ('NPTS= 12, DT= 0', 'DT = 0 must be > 0'),
		                       ('POINTS 12 STEP .005', 'expected NPTS and DT')):
			path = self.write('z.AT2', at2Text(sizes=sizes))
			with self.assertRaisesRegex(ValueError, '^%s, line 4: %s' % (re.escape(path), message)):
				readAT2(path)
		with self.assertRaisesRegex(ValueError, '^path = 5: must be a file name'):
			readAT2(5)


class ReadColumns(Files):

	def testEvenStep(self):
		text = '# time [s]  acc [g]\n\n' + ''.join('%.3f %r  # sample %d\n' % (0.01 * k, 0.1 * (k % 3) - 0.05, k) for k in range(50))
		r = readColumns(self.write('even.txt', text))
		self.assertEqual((len(r), r.t0, r.units, r.name), (50, 0.0, 'g', 'even.txt'))
		self.assertEqual(r.dt, 0.01)  # mean step (0.49 - 0)/49, to 10 digits
		self.assertTrue(np.array_equal(r.acc, np.array([0.1 * (k % 3) - 0.05 for k in range(50)]) * G))
		for units, factor in (('cm/s^2', 0.01), ('m/s^2', 1.0), ('CM/S/S', 0.01)):
			self.assertTrue(np.array_equal(readColumns(self.write('even.txt', text), units=units).acc, np.array([0.1 * (k % 3) - 0.05 for k in range(50)]) * factor))
		# CSV, three columns, acceleration in the third, a record starting at 2 s
		csv = ''.join('%.2f,%d,%r\n' % (2 + 0.02 * k, 7, 0.5 * k) for k in range(10))
		r = readColumns(self.write('three.csv', csv), units='m/s^2', accColumn=2, delimiter=',', name='csv')
		self.assertEqual((len(r), r.t0, r.name), (10, 2.0, 'csv'))
		self.assertEqual(r.dt, 0.02)  # (2.18 - 2)/9 = 0.020000000000000018, to 10 digits
		self.assertTrue(np.array_equal(r.acc, 0.5 * np.arange(10)))

	def testUnevenStepResampled(self):
		"""Times 0, .01, .03, .04, .07, .08 (steps .01 to .03) and a = 1 + 20 t (in g): resampled to dt = 0.01 with a
		warning; the file's samples are linear in t, so the interpolated values are the line itself."""
		times = [0.0, 0.01, 0.03, 0.04, 0.07, 0.08]
		text = ''.join('%r %r\n' % (t, 1 + 20 * t) for t in times)
		with self.assertWarnsRegex(UserWarning, r'uneven time step \(0.01 to 0.03 s\): resampled linearly to the smallest step, dt = 0.01 s'):
			r = readColumns(self.write('uneven.txt', text))
		self.assertEqual((len(r), r.dt, r.t0), (9, 0.01, 0.0))
		# 1e-14 relative: np.interp of a line at times k*0.01 that differ from the file's decimals by round-off
		np.testing.assert_allclose(r.acc, (1 + 20 * 0.01 * np.arange(9)) * G, rtol=1e-14)
		with warnings.catch_warnings():
			warnings.simplefilter('error')  # dt given: no warning
			r = readColumns(self.write('uneven.txt', text), dt=0.005)
		self.assertEqual((len(r), r.dt), (17, 0.005))
		np.testing.assert_allclose(r.acc, (1 + 20 * 0.005 * np.arange(17)) * G, rtol=1e-14)
		# an even file with dt given: resampled too
		r = readColumns(self.write('even.txt', '0 0\n0.1 1\n0.2 0\n'), dt=0.05, units='m/s^2')
		np.testing.assert_allclose(r.acc, [0, 0.5, 1, 0.5, 0], rtol=0, atol=1e-15)  # interpolation weights from decimal times: round-off

	def testTimesMustIncrease(self):
		for text, line, t, before in (('0 1\n0.01 2\n0.01 3\n', 3, '0.01', '0.01'), ('# c\n0 1\n0.02 2\n\n0.01 3\n', 5, '0.01', '0.02')):
			path = self.write('bad.txt', text)
			with self.assertRaisesRegex(ValueError, r'^%s, line %d: times must increase, but t = %s s follows t = %s s' % (re.escape(path), line, t, before)):
				readColumns(path)

	def testBadLines(self):
		path = self.write('h.txt', 'time acc\n0 1\n0.1 2\n')
		with self.assertRaisesRegex(ValueError, r"^%s, line 1: not numbers in columns 0, 1: 'time acc'" % re.escape(path)):
			readColumns(path)
		path = self.write('c.txt', '0 1\n0.1\n')
		with self.assertRaisesRegex(ValueError, r'^%s, line 2: 1 columns, needs column 1' % re.escape(path)):
			readColumns(path)
		path = self.write('o.txt', '# nothing\n0 1\n')
		with self.assertRaisesRegex(ValueError, r'^%s: needs at least 2 samples, found 1' % re.escape(path)):
			readColumns(path)
		path = self.write('n.txt', '0 1\n0.1 nan\n')
		with self.assertRaisesRegex(ValueError, r'^%s, line 2: time and acceleration must be finite' % re.escape(path)):
			readColumns(path)
		with self.assertRaisesRegex(FileNotFoundError, '^path = .*nowhere.txt.: no such file'):
			readColumns(os.path.join(self.tmp.name, 'nowhere.txt'))


class ReadValues(Files):

	def testValuesInG(self):
		path = self.write('v.txt', '#Some record\n#units g\n   0.10000  -0.20000   0.30000\n  -0.40000\n')
		r = readValues(path, dt=0.01)
		self.assertEqual((len(r), r.dt, r.name, r.units), (4, 0.01, 'Some record', 'g'))
		np.testing.assert_array_equal(r.acc, np.array([0.1, -0.2, 0.3, -0.4]) * G)

	def testArguments(self):
		path = self.write('v.txt', '1 2 3\n')
		with self.assertRaisesRegex(ValueError, r'dt = 0: must be a finite number > 0'):
			readValues(path, dt=0)
		with self.assertRaisesRegex(ValueError, r"units = 'furlong': must be one of"):
			readValues(path, dt=0.01, units='furlong')
		with self.assertRaisesRegex(ValueError, r'line 1: not a number'):
			readValues(self.write('bad.txt', '1 x 3\n'), dt=0.01)
		with self.assertRaisesRegex(ValueError, r'needs at least 2 samples, found 1'):
			readValues(self.write('one.txt', '1\n'), dt=0.01)


class ElCentro(unittest.TestCase):
	"""The record in data/records/ (its README): El Centro 1940, north-south, 0.02 s, in g; its known figures."""

	def testKnownFigures(self):
		path = os.path.join(RECORDS, 'elcentro-1940-ns.txt')
		if not os.path.exists(path):
			self.skipTest('%s is not there: the record is not in the repository, data/records/README.md says where it comes from' % path)
		r = readValues(path, dt=0.02)
		self.assertEqual(len(r), 1560)  # 1559 stated in the header, plus a final 0
		self.assertEqual(r.dt, 0.02)
		self.assertAlmostEqual(r.duration, 31.18, delta=1e-12)
		self.assertEqual(r.name, 'Data for El Centro 1940 North South Component (Peknold Version)')
		self.assertAlmostEqual(r.pga / G, 0.31882, delta=1e-12)  # the published 0.319 g of this component, exactly as written
		self.assertAlmostEqual(float(r.times()[np.argmax(np.abs(r.acc))]), 2.02, delta=1e-12)
		# figures of this file, to catch a changed or truncated copy (computed here, not quoted from the literature): 5 % and
		# 95 % of the Arias intensity (the integral of a^2) are reached at 1.66 s and 25.50 s (the samples where the
		# cumulative sum first reaches them), the peak velocity of the record corrected with degree 2 is 0.36407 m/s
		a2 = np.cumsum(r.acc**2)
		t05, t95 = (float(r.times()[np.searchsorted(a2, f * a2[-1])]) for f in (0.05, 0.95))
		self.assertAlmostEqual(t05, 1.66, delta=1e-9)
		self.assertAlmostEqual(t95, 25.50, delta=1e-9)
		self.assertAlmostEqual(r.baselineCorrected(2).pgv, 0.36407, delta=1e-5)


class Integration(unittest.TestCase):
	"""a(t) = A sin(wt) from rest: v = (A/w)(1 - cos wt), u = (A/w)(t - sin(wt)/w)."""
	A, T, DT = 2.0, 0.5, 0.005  # 100 samples per period, 4 periods
	W = 2 * math.pi / T

	def testSineAgainstClosedForms(self):
		A, w, dt = self.A, self.W, self.DT
		r = sinePulse(A, self.T, cycles=4, dt=dt)
		t = r.times()
		v, u = r.velocity(), r.displacement()
		self.assertEqual((v[0], u[0]), (0.0, 0.0))
		ve, ue = A / w * (1 - np.cos(w * t)), A / w * (t - np.sin(w * t) / w)
		# trapezoid error bounds: v: t dt^2 max|a''| / 12 with max|a''| = A w^2; u: the trapezoid sum of the velocity
		# error (t^2/2 dt^2 A w^2 / 12) plus the rule's own error on v (t dt^2 max|v''| / 12, max|v''| = A w)
		boundV = t * dt**2 * A * w**2 / 12
		boundU = dt**2 * A * w**2 / 12 * t**2 / 2 + t * dt**2 * A * w / 12
		errV, errU = np.abs(v - ve), np.abs(u - ue)
		self.assertTrue(np.all(errV <= boundV + 1e-15), (errV - boundV).max())
		self.assertTrue(np.all(errU <= boundU + 1e-15), (errU - boundU).max())
		# measured: max |v - ve| = 1.05e-4 m/s (bound at 2 s: 1.32e-3), max |u - ue| = 1.08e-4 m (bound 1.42e-3)
		self.assertAlmostEqual(errV.max(), 1.0473e-4, delta=1e-8)
		self.assertAlmostEqual(errU.max(), 1.0758e-4, delta=1e-8)
		# the trapezoid sums of sin and cos in closed form: v_i = A c (1 - cos wt_i), u_i = A c (t_i - c sin wt_i),
		# c = (dt/2) cot(w dt/2): equal to round-off (v, u ~ 0.3; 400 additions)
		c = dt / 2 / math.tan(w * dt / 2)
		self.assertLess(np.abs(v - A * c * (1 - np.cos(w * t))).max(), 1e-14)
		self.assertLess(np.abs(u - A * c * (t - c * np.sin(w * t))).max(), 1e-14)

	def testSecondOrder(self):
		"""Halving dt divides the error of the final displacement by 4 (to 1 %: the next term is O(dt^4))."""
		errors = []
		for dt in (self.DT, self.DT / 2, self.DT / 4):
			r = sinePulse(self.A, self.T, cycles=4, dt=dt)
			errors.append(abs(r.displacement()[-1] - self.A / self.W * 2.0))
		self.assertAlmostEqual(errors[0] / errors[1], 4.0, delta=0.04)
		self.assertAlmostEqual(errors[1] / errors[2], 4.0, delta=0.04)

	def testConstantIsExact(self):
		"""The trapezoid rule integrates constants and lines exactly: v = a t, u = a t^2/2 to round-off."""
		r = constant(-0.3 * G, 2.0, 0.01)
		t = r.times()
		self.assertEqual((len(r), r.duration), (201, 2.0))
		np.testing.assert_allclose(r.velocity(), -0.3 * G * t, rtol=1e-13, atol=1e-15)
		np.testing.assert_allclose(r.displacement(), -0.3 * G * t**2 / 2, rtol=1e-13, atol=1e-15)

	def testRickerReturnsToRest(self):
		"""v = A(tau e^{-q} - tau_s e^{-q_s}), u from rest, q = (pi f tau)^2: the wavelet ends at rest where it started
		(to the start value ~1e-10 of the wavelet); trapezoid error (dt f)^2 ~ 1e-4 relative."""
		A, f, dt = 3.0, 4.0, 0.0005
		r = rickerWavelet(A, f, dt)
		tau, ts = r.times() - 1.5 / f, -1.5 / f
		k = (math.pi * f)**2
		ve = A * (tau * np.exp(-k * tau**2) - ts * math.exp(-k * ts**2))
		ue = A / (2 * k) * (math.exp(-k * ts**2) - np.exp(-k * tau**2)) - A * ts * math.exp(-k * ts**2) * (tau - ts)
		# bounds as for the sine with max|a''| = 12 A k (at tau = 0) and max|a'| < 3 A sqrt(k)
		D = r.duration
		self.assertLess(np.abs(r.velocity() - ve).max(), D * dt**2 * 12 * A * k / 12)
		self.assertLess(np.abs(r.displacement() - ue).max(), dt**2 * (12 * A * k * D**2 / 2 + 3 * A * math.sqrt(k) * D) / 12)
		self.assertLess(abs(r.velocity()[-1]), 1e-9 * A / f)
		# the start value a(0) = -1e-8 A leaves the velocity A t_d e^{-q_s} ~ 2.6e-10 A/f and, over the duration, the
		# displacement 2 A t_d^2 e^{-q_s} ~ 1e-9 A/f^2 (the closed form ue includes it)
		self.assertLess(abs(r.displacement()[-1]), 2e-9 * A / f**2)

	def testPiecewiseLinear(self):
		"""For the piecewise-linear acceleration of at(), the trapezoid velocity is the exact integral and the
		trapezoid displacement is the exact double integral u*_{i+1} = u*_i + dt v_i + dt^2 (a_i/3 + a_{i+1}/6) plus
		dt^2 (a_i - a_0)/12 (to round-off of u ~ 1e-2)."""
		rng = np.random.default_rng(3)
		a = rng.standard_normal(50)
		r, dt = Record(0.02, a), 0.02
		v, exact = r.velocity(), np.zeros(50)
		for i in range(1, 50):
			exact[i] = exact[i - 1] + dt * v[i - 1] + dt**2 * (a[i - 1] / 3 + a[i] / 6)
		self.assertLess(np.abs(r.displacement() - (exact + dt**2 / 12 * (a - a[0]))).max(), 1e-16)

	def testValuesAtAnyTime(self):
		r = Record(0.1, [0.0, 1.0, -1.0, 2.0], t0=1.0)
		self.assertAlmostEqual(r.at(1.05), 0.5, delta=1e-14)  # (1.05 - 1)/0.1 = 0.5000000000000004: round-off
		self.assertEqual(r.at(1.1), 1.0)  # within 1e-9 step of a sample: the sample
		self.assertEqual(r.at(1.3), 2.0)
		self.assertEqual(r.at(1.3 + 1e-12), 2.0)  # within 1e-9 step of the last sample
		self.assertEqual((r.at(0.99), r.at(1.31), r.at(-5)), (0.0, 0.0, 0.0))
		np.testing.assert_allclose(r.at(np.array([0.5, 1.0, 1.05, 1.2, 1.4])), [0.0, 0.0, 0.5, -1.0, 0.0], rtol=0, atol=1e-14)
		v, u = r.velocity(), r.displacement()
		self.assertTrue(np.allclose(v, [0, 0.05, 0.05, 0.1], rtol=0, atol=1e-16))
		self.assertEqual(r.velocityAt(0.5), 0.0)
		self.assertEqual(r.velocityAt(5.0), v[-1])  # a = 0 after the record: v constant
		self.assertAlmostEqual(r.displacementAt(5.0), u[-1] + v[-1] * (5.0 - 1.3), delta=1e-16)  # u moves on at v
		self.assertEqual(r.displacementAt(1.2), u[2])
		self.assertAlmostEqual(r.displacementAt(1.25), (u[2] + u[3]) / 2, delta=1e-17)
		np.testing.assert_allclose(r.velocityAt(np.array([0.0, 1.3, 9.0])), [0, v[-1], v[-1]], rtol=0, atol=1e-17)
		self.assertAlmostEqual(r.pgv, 0.1, delta=1e-16)
		self.assertEqual(r.pgd, u[-1])


class BaselineCorrection(unittest.TestCase):
	"""A sine of 4 whole periods (A = 1 m/s^2, T = 0.5 s, dt = 5 ms) plus a constant offset a0 = 0.05 m/s^2."""
	A, T, DT, M, A0 = 1.0, 0.5, 0.005, 4, 0.05

	def setUp(self):
		self.sine = sinePulse(self.A, self.T, cycles=self.M, dt=self.DT)
		self.shifted = Record(self.DT, self.sine.acc + self.A0)

	def testOffsetDriftRemoved(self):
		t, D = self.shifted.times(), self.shifted.duration
		v = self.shifted.velocity()
		# before: the sine's velocity returns to 0 after whole periods, the offset adds a0 t exactly (trapezoid)
		self.assertAlmostEqual(v[-1], self.A0 * D, delta=1e-14)
		# its linear trend is a0 exactly: (1 - cos) is symmetric about D/2, t - D/2 antisymmetric (slope in x = t/D)
		self.assertAlmostEqual(trend(t, v)[0], self.A0 * D, delta=1e-14)
		for degree in (1, 2, 3):
			with self.subTest(degree=degree):
				c = self.shifted.baselineCorrected(degree)
				vc = c.velocity()
				self.assertEqual(vc[0], 0.0)
				self.assertLess(abs(vc[-1]), 1e-14)  # round-off of v ~ 0.1 m/s
				for d in range(1, degree + 1):  # the least-squares polynomial of degree d of vc: all but the constant 0
					self.assertLess(np.abs(trend(t, vc, d)[:-1]).max(), 1e-14)
				self.assertLess(abs(trend(t, vc)[0]), 1e-14)  # the linear trend in particular
				# degree 1: the final displacement of the pure sine (A/w) D = 0.159 m, to round-off; degree 2 and 3
				# also remove the P2 part of the sine's own velocity (see testPureSineKept), which shifts the final
				# displacement by -D x its P2 coefficient at the start, -15 (A/w) D / (pi^2 m^2) = -0.0151 m (-9.5 %),
				# times the same sampling factor 1.1172
				du = c.displacement()[-1] - self.sine.displacement()[-1]
				if degree == 1:
					self.assertLess(abs(du), 1e-14)
				else:
					K = self.A / (2 * math.pi / self.T)
					self.assertAlmostEqual(du / (-15 * K * D / (math.pi**2 * self.M**2)), 1.1172, delta=1e-3)

	def testPureSineKept(self):
		"""Degree 1 leaves the sine unchanged to round-off (its velocity has no linear trend, by symmetry). Degree 2
		subtracts the derivative of the sine's own quadratic velocity component: for m whole periods the P2
		(Legendre) part of (A/w)(1 - cos wt) is -15A/(w pi^2 m^2) P2, whose derivative peaks at 45 A/(pi^3 m^3) at
		both ends: 2.3 % of A for m = 4 (0.28 % for m = 8, but 145 % for a single period: no quadratic correction
		on short pulses). Degree 3 adds nothing here (the velocity is symmetric about the middle: no P3 part)."""
		change = lambda d: np.abs(self.shifted.baselineCorrected(d).acc - self.sine.acc).max()
		self.assertLess(change(1), 1e-15)  # a0 removed exactly, nothing else: round-off of a ~ 1
		predicted = 45 * self.A / (math.pi**3 * self.M**3)
		self.assertAlmostEqual(predicted, 0.022677, delta=1e-6)
		# sampled at n = 100 per period (N = n m samples): with equal weights on the samples P2 is not orthogonal to the
		# constant, sum P2(x_i) = 1 instead of 0 (the end samples), so the large mean velocity A/w leaks into the
		# quadratic term: (5 (A/w) / N) / (15 (A/w) / (pi^2 m^2)) = pi^2 m / (3 n) = 13 % estimated, 11.7 % measured
		self.assertAlmostEqual(change(2) / predicted, 1.1172, delta=1e-3)
		self.assertAlmostEqual(change(3), change(2), delta=1e-14)
		# at n = 1000 the sums approach the integrals: 1.2 % measured (1.3 % estimated), first order in dt
		fine = sinePulse(self.A, self.T, cycles=self.M, dt=self.T / 1000)
		self.assertAlmostEqual(np.abs(fine.baselineCorrected(2).acc - fine.acc).max() / predicted, 1.0119, delta=1e-3)

	def testDefinition(self):
		"""The correction is the derivative of np.polyfit's least-squares polynomial of the velocity (an independent
		implementation of the definition; 1e-12 relative: two least-squares solvers on a well-conditioned problem),
		plus dt^2 p'''/12 for degree 3; and vc = v - p + p(0) to round-off (the guarantee)."""
		rng = np.random.default_rng(1)
		r = Record(0.01, sweep(1.0, 0.5, 8.0, 6.0, 0.01).acc + 0.02 + 0.01 * np.linspace(0, 1, 601)**2 + 0.01 * rng.standard_normal(601))
		t = r.times()
		for degree in (1, 2, 3):
			p = np.polyfit(t, r.velocity(), degree)
			baseline = np.polyval(np.polyder(p), t) - (r.dt**2 / 12 * np.polyval(np.polyder(p, 3), t) if degree == 3 else 0)
			c = r.baselineCorrected(degree)
			scale = np.abs(baseline).max()
			self.assertLess(np.abs((r.acc - c.acc) - baseline).max(), 1e-12 * scale)
			self.assertLess(np.abs(c.velocity() - (r.velocity() - np.polyval(p, t) + np.polyval(p, 0))).max(), 1e-13)
		self.assertTrue(np.array_equal(r.baselineCorrected(0).acc, r.acc))

	def testGroundMotion(self):
		gm = GroundMotion(x=self.shifted, z=self.shifted.scaled(2.0)).baselineCorrected(1)
		self.assertLess(np.abs(gm.accelerations()[:, 0] - self.sine.acc).max(), 1e-15)
		self.assertLess(np.abs(gm.accelerations()[:, 2] - 2 * self.sine.acc).max(), 2e-15)
		self.assertIsNone(gm.y)


class Synthetic(unittest.TestCase):

	def testSinePulse(self):
		r = sinePulse(0.4 * G, 0.2, cycles=3, dt=0.001, before=0.05, after=0.1)
		self.assertEqual((len(r), r.dt, r.t0, r.units), (50 + 601 + 100, 0.001, 0.0, 'm/s^2'))
		self.assertAlmostEqual(r.duration, 0.05 + 0.6 + 0.1, delta=1e-14)
		self.assertTrue(np.all(r.acc[:50] == 0) and np.all(r.acc[651:] == 0))
		self.assertEqual(r.pga, 0.4 * G)  # the peaks at T/4 + k T are samples (dt divides T/4): sin(pi/2) = 1 exactly
		self.assertEqual(r.at(0.05 + 0.05), 0.4 * G)
		self.assertLess(abs(r.acc[50]), 1e-15)
		self.assertLess(abs(r.acc[650]), 1e-14)  # sin(6 pi) = -7e-16, times 3.9
		# default dt T/100; half a period
		h = sinePulse(1.0, 1.0, cycles=0.5)
		self.assertEqual((len(h), h.dt), (51, 0.01))
		self.assertGreaterEqual(h.acc.min(), 0.0)

	def testRicker(self):
		A, f, dt = 2.0, 5.0, 0.0001
		r = rickerWavelet(A, f, dt)
		td = 1.5 / f
		self.assertEqual(len(r), 6001)
		self.assertAlmostEqual(r.duration, 2 * td, delta=1e-14)
		self.assertEqual(r.at(td), A)  # tau = 0 is sample 3000: exactly A
		self.assertEqual(r.pga, A)
		self.assertAlmostEqual(r.acc[0], A * (1 - 2 * 2.25 * math.pi**2) * math.exp(-2.25 * math.pi**2), delta=1e-20)
		self.assertLess(abs(r.acc[0]), 1e-8 * A)
		# zeros at tau = +-1/(pi f sqrt 2): 1 - 2 pi^2 f^2 tau^2 = 0. Linear interpolation between samples places a
		# zero within dt^2 |a''| / (8 |a'|) of it; there |a'| = 4 A k tau e^{-1/2}, |a''| <= 10 A k (k = pi^2 f^2):
		# at most dt^2 * 10 k / (32 k tau e^{-1/2}) = 1.1e-7 s here (measured 1.5e-8 s)
		tz = 1 / (math.pi * f * math.sqrt(2))
		z = zeroCrossings(r)
		self.assertEqual(len(z), 2)
		np.testing.assert_allclose(z, [td - tz, td + tz], rtol=0, atol=dt**2 * 10 / (32 * tz * math.exp(-0.5)))
		# minima -2 A e^{-3/2} at tau = +-sqrt(3/2)/(pi f): sampled within dt of it, so within |a''| dt^2/2 of the value
		i = np.argmin(r.acc)
		self.assertAlmostEqual(r.acc.min(), -2 * A * math.exp(-1.5), delta=(math.pi * f * dt)**2 * 10 * A)
		self.assertAlmostEqual(abs(r.times()[i] - td), math.sqrt(1.5) / (math.pi * f), delta=dt)
		# duration and delay
		s = rickerWavelet(1.0, 2.0, 0.01, duration=3.0, delay=1.0)
		self.assertEqual((len(s), s.at(1.0)), (301, 1.0))

	def testSweep(self):
		"""Zero crossings at the phase's multiples of pi: f0 t + (f1 - f0) t^2/(2D) = k/2; between two of them the mean
		frequency 1/(2 gap) is the instantaneous one at the midpoint (the frequency is linear in t)."""
		A, f0, f1, D, dt = 1.5, 1.0, 6.0, 4.0, 0.0005
		r = sweep(A, f0, f1, D, dt)
		self.assertEqual(len(r), 8001)
		self.assertEqual(r.acc[0], 0.0)
		z = zeroCrossings(r)
		self.assertEqual(len(z), int((f0 + f1) * D) - 1)  # the phase ends at pi (f0 + f1) D = 28 pi: crossings 1 .. 27
		b = f1 - f0
		k = np.arange(1, len(z) + 1)
		exact = (-f0 + np.sqrt(f0**2 + 2 * b / D * k / 2)) / (b / D)
		# linear interpolation error dt^2 |a''|/(8 |a'|) at a zero: |a''| <= A (2 pi f)^2 + ..., |a'| = 2 pi f A:
		# about dt^2 pi f / 4 <= 1.2e-6 s for f = 6 Hz (x 1.1 for the phase's curvature; measured 1.8e-8 s)
		np.testing.assert_allclose(z, exact, rtol=0, atol=dt**2 * math.pi * f1 / 4 * 1.1)
		fMid = 1 / (2 * np.diff(z))
		np.testing.assert_allclose(fMid, f0 + b * (z[1:] + z[:-1]) / 2 / D, rtol=1e-4)  # 2 x 1.2e-6 s on gaps >= 0.083 s
		self.assertAlmostEqual(fMid[0], f0 + b * (z[0] + z[1]) / 2 / D, delta=1e-5)
		self.assertGreater(fMid[0], f0)
		self.assertLess(fMid[-1], f1)
		self.assertAlmostEqual(r.pga, A, delta=A * (2 * math.pi * f1 * dt)**2 / 2)  # peaks sampled within dt/2
		down = sweep(A, f1, f0, D, dt)  # 6 Hz down to 1 Hz
		zd = zeroCrossings(down)
		np.testing.assert_allclose(1 / (2 * np.diff(zd)), f1 - b * (zd[1:] + zd[:-1]) / 2 / D, rtol=1e-4)

	def testConstant(self):
		r = constant(2.5, 1.0, 0.1)
		self.assertEqual((len(r), r.pga, r.duration), (11, 2.5, 1.0))
		self.assertTrue(np.all(r.acc == 2.5))
		self.assertEqual(r.at(1.0), 2.5)
		self.assertEqual(r.at(1.1), 0.0)


class Transformations(unittest.TestCase):

	def testHalvedStepIsExactAtOldNodes(self):
		rng = np.random.default_rng(7)
		r = Record(0.01, rng.uniform(-3, 3, 101), t0=0.5)
		h = r.resampled(0.005)
		self.assertEqual((len(h), h.dt, h.t0), (201, 0.005, 0.5))
		self.assertTrue(np.array_equal(h.acc[::2], r.acc))  # old nodes copied exactly
		self.assertLess(np.abs(h.acc[1::2] - (r.acc[:-1] + r.acc[1:]) / 2).max(), 1e-15)  # midpoints: the mean, one rounding of ~3
		c = r.resampled(0.03)
		self.assertEqual(len(c), 34)
		self.assertTrue(np.array_equal(c.acc, r.acc[::3]))
		# a step that does not divide the old one: np.interp on the times, to round-off of the times (1e-13 s x |a'| <= 600)
		o = r.resampled(0.007)
		self.assertEqual(len(o), 143)
		self.assertLess(np.abs(o.acc - np.interp(o.times(), r.times(), r.acc)).max(), 1e-12)
		# resampling back onto the old step after halving: the identity
		self.assertTrue(np.array_equal(h.resampled(0.01).acc, r.acc))

	def testScalePadCut(self):
		r = Record(0.1, [0.0, 1.0, -2.0, 0.5], name='r', t0=0.0)
		self.assertTrue(np.array_equal(r.scaled(-3).acc, [0.0, -3.0, 6.0, -1.5]))
		self.assertEqual(r.scaledTo(0.5 * G).pga, 0.5 * G)
		p = r.padded(before=0.2, after=0.3)
		self.assertTrue(np.array_equal(p.acc, [0, 0, 0, 1, -2, 0.5, 0, 0, 0]))
		self.assertEqual((p.t0, p.name), (0.0, 'r'))
		self.assertEqual(p.at(0.3), 1.0)  # the motion starts 0.2 s later
		c = r.cut(0.1, 0.25)
		self.assertTrue(np.array_equal(c.acc, [1.0, -2.0]))
		self.assertAlmostEqual(c.t0, 0.1, delta=1e-17)
		self.assertEqual(c.at(0.2), -2.0)  # times kept
		self.assertEqual(c.velocity()[0], 0.0)  # from rest at its own start
		self.assertTrue(np.array_equal(r.cut(-5, 5).acc, r.acc))
		self.assertEqual(c.startingAt(0).at(0.1), -2.0)
		# immutability
		with self.assertRaises(ValueError):
			r.acc[0] = 1.0
		with self.assertRaises(AttributeError):
			r.dt = 0.2
		self.assertTrue(np.array_equal(r.acc, [0.0, 1.0, -2.0, 0.5]))

	def testUnitsOfTheConstructor(self):
		r = Record(0.01, [1.0, -0.5], units='g')
		self.assertTrue(np.array_equal(r.acc, [G, -0.5 * G]))
		self.assertEqual(r.units, 'g')
		self.assertTrue(np.array_equal(Record(0.01, [100.0, 1.0], units='cm/s^2').acc, [1.0, 0.01]))


class GroundMotionTests(unittest.TestCase):

	def setUp(self):
		self.x = sinePulse(1.0, 0.2, cycles=5, dt=0.005)  # 1.0 s, 201 samples
		self.y = Record(0.01, np.linspace(0, 1, 101) ** 2)  # 1.0 s, coarser
		self.z = rickerWavelet(0.5, 5.0, 0.02, duration=0.6).startingAt(0.1)  # 0.1 to 0.7 s, coarser, later
		self.gm = GroundMotion(self.x, self.y, self.z)

	def testCommonStep(self):
		gm = self.gm
		self.assertEqual((gm.dt, gm.t0, len(gm)), (0.005, 0.0, 201))
		np.testing.assert_allclose(gm.times(), 0.005 * np.arange(201), rtol=0, atol=1e-15)
		a = gm.accelerations()
		self.assertEqual(a.shape, (201, 3))
		self.assertTrue(np.array_equal(a[:, 0], self.x.acc))  # already on the axis: copied
		self.assertTrue(np.array_equal(a[:, 1], self.y.resampled(0.005).acc))
		# z: linear interpolation, 0 outside 0.1 .. 0.7 s; its old nodes every 4th sample from 0.1 s
		self.assertTrue(np.all(a[:20, 2] == 0) and np.all(a[141:, 2] == 0))
		self.assertLess(np.abs(a[20:141:4, 2] - self.z.acc).max(), 1e-15)
		self.assertEqual(gm.z.t0, 0.0)

	def testValuesAtNodesEqualTheArrays(self):
		gm = self.gm
		a, v, u = gm.accelerations(), gm.velocities(), gm.displacements()
		for i in (0, 1, 57, 120, 200):
			t = i * 0.005
			self.assertEqual(gm.acc(t), tuple(a[i]))
			self.assertEqual(gm.vel(t), tuple(v[i]))
			self.assertEqual(gm.disp(t), tuple(u[i]))
		for k, r in enumerate(gm.components):
			self.assertTrue(np.array_equal(v[:, k], r.velocity()))
			self.assertTrue(np.array_equal(u[:, k], r.displacement()))
		# between nodes: linear interpolation of the arrays (to round-off of values ~ 1)
		np.testing.assert_allclose(gm.disp(0.5025), (u[100] + u[101]) / 2, rtol=0, atol=1e-16)
		self.assertEqual(gm.acc(-1.0), (0.0, 0.0, 0.0))
		self.assertEqual(gm.vel(5.0), tuple(v[-1]))

	def testMissingComponentsAndScaling(self):
		gm = GroundMotion(z=self.z)
		self.assertEqual((gm.dt, gm.t0, len(gm)), (0.02, 0.1, 31))
		self.assertIsNone(gm.x)
		self.assertTrue(np.all(gm.accelerations()[:, :2] == 0))
		self.assertEqual(gm.acc(0.4)[:2], (0.0, 0.0))
		s = self.gm.scaled(2.0)
		self.assertTrue(np.array_equal(s.accelerations(), 2 * self.gm.accelerations()))
		self.assertTrue(np.array_equal(s.times(), self.gm.times()))


class Validation(unittest.TestCase):
	"""A bad value of every argument raises ValueError whose message starts with the argument's name."""

	def refused(self, function, name, *values, message=None, **good):
		for v in values:
			with self.subTest(function=function.__name__, **{name: v}):
				with self.assertRaisesRegex(ValueError, '^' + re.escape(message or name)):
					function(**dict(good, **{name: v}))

	def testRecord(self):
		good = dict(dt=0.01, acc=[0.0, 1.0, 0.0])
		self.refused(Record, 'dt', 0, -0.01, float('nan'), float('inf'), '0.01', None, True, **good)
		self.refused(Record, 'acc', [], [1.0], [[1.0, 2.0]], 'abc', [0, float('nan')], [0, float('inf')], None, **good)
		self.refused(Record, 'units', 'inch/s^2', 'kg', None, 9.81, **good)
		self.refused(Record, 't0', float('nan'), None, **good)
		self.refused(Record, 'name', 5, **good)

	def testMethods(self):
		r = Record(0.01, [0.0, 1.0, -1.0, 0.5])
		self.refused(r.resampled, 'dt', 0, -0.005, float('nan'), 0.05)
		self.refused(r.scaled, 'factor', float('inf'), 'two', None)
		self.refused(r.scaledTo, 'pga', 0, -1.0, float('nan'))
		self.refused(Record(0.01, [0.0, 0.0]).scaledTo, 'pga', 1.0)
		self.refused(r.baselineCorrected, 'degree', -1, 4, 1.5, True, '2', None)
		self.refused(r.padded, 'before', -0.1, float('nan'))
		self.refused(r.padded, 'after', -0.1, None)
		self.refused(r.cut, 't0', float('nan'), None, t1=0.02)
		self.refused(r.cut, 't1', float('inf'), 0.0, -1.0, t0=0.0)
		self.refused(r.startingAt, 't0', float('nan'))
		self.refused(r.at, 't', float('nan'), [0.0, float('inf')], 'now')
		self.refused(GroundMotion(x=r).baselineCorrected, 'degree', 5)

	def testCutWithoutSamples(self):
		r = Record(0.01, [0.0, 1.0, -1.0, 0.5])
		for t0, t1 in ((5.0, 6.0), (0.005, 0.009), (0.005, 0.015)):
			with self.assertRaisesRegex(ValueError, r'^t0, t1 = %r, %r: must contain at least 2 samples of the record' % (t0, t1)):
				r.cut(t0, t1)

	def testSinePulse(self):
		good = dict(amplitude=1.0, period=0.5)
		self.refused(sinePulse, 'amplitude', float('nan'), float('inf'), None, '1', **good)
		self.refused(sinePulse, 'period', 0, -0.5, float('nan'), **good)
		self.refused(sinePulse, 'cycles', 0, -1, float('inf'), **good)
		self.refused(sinePulse, 'dt', 0, -0.01, 0.25, 0.3, float('nan'), **good)  # dt < T/2 (Nyquist)
		self.refused(sinePulse, 'dt', 0.2, cycles=0.1, **dict(good))  # shorter than one step
		self.refused(sinePulse, 'before', -1.0, float('nan'), **good)
		self.refused(sinePulse, 'after', -1.0, **good)

	def testRicker(self):
		good = dict(amplitude=1.0, frequency=5.0, dt=0.001)
		self.refused(rickerWavelet, 'amplitude', float('nan'), None, **good)
		self.refused(rickerWavelet, 'frequency', 0, -5.0, float('inf'), **good)
		self.refused(rickerWavelet, 'dt', 0, -0.001, 1 / 30, 0.1, **good)  # dt < 1/(6 f)
		self.refused(rickerWavelet, 'duration', 0, -1.0, float('nan'), **good)
		self.refused(rickerWavelet, 'delay', -0.1, float('inf'), **good)
		self.refused(rickerWavelet, 'duration', 0, message='duration = 0', delay=0, **{k: v for k, v in good.items()})

	def testSweep(self):
		good = dict(amplitude=1.0, f0=1.0, f1=10.0, duration=5.0, dt=0.01)
		self.refused(sweep, 'amplitude', float('inf'), **good)
		self.refused(sweep, 'f0', 0, -1.0, float('nan'), **good)
		self.refused(sweep, 'f1', 0, -10.0, None, **good)
		self.refused(sweep, 'duration', 0, -5.0, **good)
		self.refused(sweep, 'dt', 0, 0.05, 0.06, **good)  # dt < 1/(2 max(f0, f1)) = 0.05

	def testConstant(self):
		good = dict(value=1.0, duration=1.0, dt=0.01)
		self.refused(constant, 'value', float('nan'), None, **good)
		self.refused(constant, 'duration', 0, -1.0, **good)
		self.refused(constant, 'dt', 0, 2.0, **good)

	def testReadColumnsArguments(self):
		with tempfile.TemporaryDirectory() as tmp:
			path = os.path.join(tmp, 'r.txt')
			with open(path, 'w') as f:
				f.write('0 1\n0.1 2\n0.2 3\n')
			good = dict(path=path)
			self.refused(readColumns, 'units', 'mm', None, **good)
			self.refused(readColumns, 'timeColumn', -1, 1.5, True, **good)
			self.refused(readColumns, 'accColumn', -1, None, 0, **good)  # 0: the time column
			self.refused(readColumns, 'comments', '', 5, **good)
			self.refused(readColumns, 'delimiter', '', 5, **good)
			self.refused(readColumns, 'dt', 0, -0.1, 0.5, **good)  # 0.5: longer than the record
			self.refused(readColumns, 'name', 5, **good)
			self.refused(readColumns, 'path', 5, None, **good)

	def testGroundMotion(self):
		with self.assertRaisesRegex(ValueError, r'^x, y, z = None, None, None: at least one component must be a Record'):
			GroundMotion()
		self.refused(GroundMotion, 'y', [0.0, 1.0], 'file.AT2')


if __name__ == '__main__':
	unittest.main()
