"""Earthquake ground motion: records of base acceleration, their velocity and displacement, readers and synthetic pulses.

Pure Python with numpy (no YADE), so that it can be tested on its own; a YADE engine reads from it the times and the
base accelerations, velocities and displacements that drive the base of a wall (see ``rdem.earthquake``).

Units are SI: time in s, acceleration in m/s², velocity in m/s, displacement in m. Files may give accelerations in g
(:data:`G` $= 9.80665$ m/s², standard gravity), in cm/s² or in m/s²; a :class:`Record` always holds m/s² and remembers
the unit of its source in :attr:`Record.units`.

Typical use::

    from rdem.ground_motion import readAT2, GroundMotion, rickerWavelet, G
    gm = GroundMotion(x=readAT2('RSN6_IMPVALL.I_I-ELC180.AT2').baselineCorrected(2).scaledTo(0.3 * G))
    t, a, v, u = gm.times(), gm.accelerations(), gm.velocities(), gm.displacements()   # (N,), (N, 3) x 3
    gm.acc(1.234), gm.vel(1.234), gm.disp(1.234)                                        # 3-tuples at any time

Integration (:meth:`Record.velocity`, :meth:`Record.displacement`): the trapezoid rule from rest,
$v_0 = 0$, $v_{i+1} = v_i + \\tfrac{\\Delta t}{2}(a_i + a_{i+1})$, $u_0 = 0$, $u_{i+1} = u_i + \\tfrac{\\Delta t}{2}(v_i + v_{i+1})$:
second order in $\\Delta t$ (the error at a fixed time is bounded by $t\\,\\Delta t^2 \\max|f''|/12$ for the integrand
$f$). The velocity is exact for the piecewise-linear acceleration that :meth:`Record.at` interpolates; the
displacement differs from that acceleration's exact double integral by $\\Delta t^2 (a(t) - a(0))/12$.

See :ref:`ground motion <rdem-ground-motion>` in the user guide for the formats, the baseline correction and the synthetic pulses.
"""
import math
import numbers
import os
import re
import warnings

import numpy as np

G = 9.80665
"""Standard gravity [m/s²], the g of records in units of g."""

UNITS = {'g': G, 'cm/s^2': 0.01, 'm/s^2': 1.0}
"""Acceleration units known to :class:`Record` and the readers: name -> factor to m/s²."""

# spellings accepted for the units of UNITS, after upper-casing, removing blanks and writing SEC as S and ** or ² as ^
_UNIT_SPELLINGS = {
        'G': 'g',
        'CM/S/S': 'cm/s^2',
        'CM/S^2': 'cm/s^2',
        'CM/S2': 'cm/s^2',
        'GAL': 'cm/s^2',
        'M/S/S': 'm/s^2',
        'M/S^2': 'm/s^2',
        'M/S2': 'm/s^2',
}
_KNOWN_UNITS = 'G, CM/S/S, CM/S^2, M/S/S, M/S^2 (any case, SEC for S; also GAL)'

_SNAP = 1e-9  # times within this fraction of a step of a node (plus the round-off of t/dt) are taken at the node
_NUMBER = r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?'
_NEXT_NUMBER = re.compile(r'\s*(' + _NUMBER + r')')


# ---------------------------------------------------------------------------------------------- arguments
def _fmt(x):
	return '%.10g' % x


def _finite(value):
	return not isinstance(value, bool) and isinstance(value, numbers.Real) and math.isfinite(value)


def _real(name, value, what):
	if not _finite(value):
		raise ValueError('%s = %r: must be a finite number %s' % (name, value, what))
	return float(value)


def _positive(name, value, what='[s]'):
	if not (_finite(value) and value > 0):
		raise ValueError('%s = %r: must be a finite number > 0 %s' % (name, value, what))
	return float(value)


def _nonNegative(name, value, what='[s]'):
	if not (_finite(value) and value >= 0):
		raise ValueError('%s = %r: must be a finite number >= 0 %s' % (name, value, what))
	return float(value)


def _unitName(name, units):
	"""The key of :data:`UNITS` for a spelling of an acceleration unit, or ValueError naming ``name``."""
	if isinstance(units, str):
		key = units.strip().upper().replace(' ', '').replace('SEC', 'S').replace('**', '^').replace('²', '^2').rstrip('.')
		if key in _UNIT_SPELLINGS:
			return _UNIT_SPELLINGS[key]
	raise ValueError('%s = %r: must be one of %s' % (name, units, _KNOWN_UNITS))


def _samples(name, values):
	"""A new 1-D float array of at least 2 finite values, or ValueError naming ``name``."""
	try:
		a = np.array(values, dtype=float)
	except (TypeError, ValueError):
		raise ValueError('%s: must be a sequence of numbers [m/s²]' % name) from None
	if a.ndim != 1 or len(a) < 2:
		raise ValueError('%s: must be a 1-D sequence of at least 2 samples (shape %s given)' % (name, a.shape))
	bad = np.flatnonzero(~np.isfinite(a))
	if len(bad):
		raise ValueError('%s[%d] = %r: every sample must be finite' % (name, bad[0], a[bad[0]]))
	return a


def _steps(x):
	"""``x`` (a number of steps) rounded to the nearest integer if within 1e-9 of it, plus 1e-14 |x| for the
	round-off of a time divided by a step."""
	r = np.rint(x)
	return np.where(np.abs(x - r) <= _SNAP + 1e-14 * np.abs(x), r, x)


def _stepCount(length, dt):
	"""The number of whole steps ``dt`` in ``length`` (a length within 1e-9 step of a multiple counts as that multiple)."""
	return int(math.floor(float(_steps(length / dt))))


def _frozen(a):
	a.flags.writeable = False
	return a


# ---------------------------------------------------------------------------------------------- Record
class Record:
	"""One component of ground acceleration sampled at a constant time step.

	Records are immutable: their array is read-only, and every method returns a new record.

	:param dt: time step $\\Delta t$ [s], > 0.
	:param acc: at least 2 samples $a_0, a_1, \\dots$, in ``units``; $a_i$ is the acceleration at $t_0 + i\\,\\Delta t$.
	:param name: free text (event, station, component).
	:param units: the unit of ``acc``: ``'g'`` (:data:`G` = 9.80665 m/s²), ``'cm/s^2'`` or ``'m/s^2'`` (also spelled
	    as in .AT2 files: ``'G'``, ``'CM/S/S'``, ...). The samples are converted to m/s².
	:param t0: time of the first sample [s].

	:ivar dt: time step [s].
	:ivar acc: the accelerations [m/s²], a read-only numpy array (already converted from ``units``).
	:ivar name: free text.
	:ivar units: the unit of the source (one of the keys of :data:`UNITS`), for information: :attr:`acc` is in m/s².
	:ivar t0: time of the first sample [s]."""
	__slots__ = ('_dt', '_acc', '_name', '_units', '_t0', '_vel', '_disp')

	def __init__(self, dt, acc, name='', units='m/s^2', t0=0.0):
		dt = _positive('dt', dt, '[s]')
		units = _unitName('units', units)
		acc = _samples('acc', acc) * UNITS[units]
		if not isinstance(name, str):
			raise ValueError('name = %r: must be a string' % (name, ))
		self._set(dt, acc, name, units, _real('t0', t0, '[s]'))

	def _set(self, dt, acc, name, units, t0):
		self._dt, self._acc, self._name, self._units, self._t0 = dt, _frozen(acc), name, units, t0
		self._vel = self._disp = None

	def _new(self, acc=None, dt=None, t0=None, name=None):
		"""A record like this one with some attributes replaced (``acc`` in m/s², not checked)."""
		r = object.__new__(Record)
		r._set(self._dt if dt is None else dt, self._acc if acc is None else acc, self._name if name is None else name, self._units,
		       self._t0 if t0 is None else t0)
		return r

	dt = property(lambda self: self._dt, doc='Time step [s].')
	acc = property(lambda self: self._acc, doc='Accelerations [m/s²] (read-only array).')
	name = property(lambda self: self._name, doc='Free text.')
	units = property(lambda self: self._units, doc='Unit of the source (a key of :data:`UNITS`); :attr:`acc` is in m/s².')
	t0 = property(lambda self: self._t0, doc='Time of the first sample [s].')

	def __len__(self):
		return len(self._acc)

	@property
	def duration(self):
		"""Time from the first to the last sample, $(N - 1)\\,\\Delta t$ [s]."""
		return (len(self._acc) - 1) * self._dt

	@property
	def end(self):
		"""Time of the last sample, $t_0 + (N - 1)\\,\\Delta t$ [s]."""
		return self._t0 + self.duration

	@property
	def pga(self):
		"""Peak ground acceleration $\\max_i |a_i|$ [m/s²]."""
		return float(np.max(np.abs(self._acc)))

	@property
	def pgv(self):
		"""Peak ground velocity $\\max_i |v_i|$ [m/s] of :meth:`velocity`."""
		return float(np.max(np.abs(self.velocity())))

	@property
	def pgd(self):
		"""Peak ground displacement $\\max_i |u_i|$ [m] of :meth:`displacement`."""
		return float(np.max(np.abs(self.displacement())))

	def times(self):
		"""The sample times $t_0 + i\\,\\Delta t$ [s], a new array."""
		return self._t0 + self._dt * np.arange(len(self._acc))

	def velocity(self):
		"""Velocity at the samples [m/s] by the trapezoid rule from rest: $v_0 = 0$,
		$v_{i+1} = v_i + \\tfrac{\\Delta t}{2}(a_i + a_{i+1})$. Second order: for a smooth acceleration the error at
		time $t$ is at most $(t - t_0)\\,\\Delta t^2 \\max|\\ddot a|/12$; exact for the piecewise-linear acceleration
		of :meth:`at`. Read-only array, computed once."""
		if self._vel is None:
			a, v = self._acc, np.zeros(len(self._acc))
			np.cumsum(0.5 * self._dt * (a[1:] + a[:-1]), out=v[1:])
			self._vel = _frozen(v)
		return self._vel

	def displacement(self):
		"""Displacement at the samples [m] by the trapezoid rule applied to :meth:`velocity`: $u_0 = 0$,
		$u_{i+1} = u_i + \\tfrac{\\Delta t}{2}(v_i + v_{i+1})$. Second order: the error at time $t$ is at most
		$\\Delta t^2 \\big(\\max|\\ddot a|\\,(t - t_0)^2/2 + \\max|\\dot a|\\,(t - t_0)\\big)/12$. Read-only array,
		computed once."""
		if self._disp is None:
			v, u = self.velocity(), np.zeros(len(self._acc))
			np.cumsum(0.5 * self._dt * (v[1:] + v[:-1]), out=u[1:])
			self._disp = _frozen(u)
		return self._disp

	# ---------------------------------------------------------------------------------- values at any time
	def _interpolate(self, y, t, tail):
		"""Linear interpolation of the nodal values ``y`` at time(s) ``t``; 0 before the record, ``tail(t)`` after it."""
		if _finite(t):
			s = (t - self._t0) / self._dt
			r = round(s)
			if abs(s - r) <= _SNAP + 1e-14 * abs(s):
				s = r
			last = len(y) - 1
			if s < 0:
				return 0.0
			if s > last:
				return tail(t)
			i = min(int(s), last - 1)
			w = s - i
			return float((1 - w) * y[i] + w * y[i + 1])
		try:
			t = np.asarray(t, dtype=float)
		except (TypeError, ValueError):
			t = None
		if t is None or not np.all(np.isfinite(t)):
			raise ValueError('t: must be a finite time or an array of finite times [s]')
		s = _steps((t - self._t0) / self._dt)
		last = len(y) - 1
		i = np.clip(np.floor(s), 0, last - 1).astype(int)
		w = s - i
		out = (1 - w) * y[i] + w * y[i + 1]
		out = np.where(s < 0, 0.0, out)
		after = s > last
		if np.any(after):
			out = np.where(after, tail(t), out)
		return out if out.ndim else float(out)

	def at(self, t):
		"""Acceleration [m/s²] at time ``t`` [s] (a number or an array), linearly interpolated between the samples; 0
		before :attr:`t0` and after :attr:`end` (times within 1e-9 step of a sample take the sample's value)."""
		return self._interpolate(self._acc, t, lambda t: 0.0 * t)

	def velocityAt(self, t):
		"""Velocity [m/s] at time ``t`` [s]: :meth:`velocity` linearly interpolated; 0 before :attr:`t0`; after
		:attr:`end` the acceleration is 0, so the final velocity $v_{N-1}$ is kept."""
		v = self.velocity()
		return self._interpolate(v, t, lambda t: v[-1] + 0.0 * t)

	def displacementAt(self, t):
		"""Displacement [m] at time ``t`` [s]: :meth:`displacement` linearly interpolated; 0 before :attr:`t0`; after
		:attr:`end` the base moves on at the final velocity: $u_{N-1} + v_{N-1}(t - t_\\mathrm{end})$."""
		v, u, end = self.velocity(), self.displacement(), self.end
		return self._interpolate(u, t, lambda t: u[-1] + v[-1] * (t - end))

	# ---------------------------------------------------------------------------------- new records
	def resampled(self, dt):
		"""The record linearly interpolated onto the constant step ``dt`` [s] > 0, from the same :attr:`t0`. The new
		samples run to the last multiple of ``dt`` not after :attr:`end` (the tail shorter than ``dt`` is dropped).
		Old samples that fall on new times are copied exactly. No anti-alias filter: a larger step simply samples the
		piecewise-linear record."""
		dt = _positive('dt', dt, '[s]')
		if dt > self.duration * (1 + _SNAP):
			raise ValueError('dt = %r: must be <= the duration %s s of the record (at least 2 samples)' % (dt, _fmt(self.duration)))
		n = _stepCount(self.duration, dt) + 1
		return self._new(acc=self._atSteps(np.arange(n) * (dt / self._dt)), dt=dt)

	def _atSteps(self, s):
		"""Accelerations at the fractional sample indices ``s`` (snapped to integers within 1e-9), 0 outside."""
		s = _steps(s)
		last = len(self._acc) - 1
		i = np.clip(np.floor(s), 0, last - 1).astype(int)
		w = np.clip(s - i, 0.0, 1.0)
		return np.where((s < 0) | (s > last), 0.0, (1 - w) * self._acc[i] + w * self._acc[i + 1])

	def scaled(self, factor):
		"""The record with every acceleration multiplied by ``factor`` (a finite number, any sign)."""
		return self._new(acc=self._acc * _real('factor', factor, '(any sign)'))

	def scaledTo(self, pga):
		"""The record scaled so that its peak $|a|$ is ``pga`` [m/s²] > 0 (use ``0.3 * G`` for 0.3 g)."""
		pga = _positive('pga', pga, '[m/s²]')
		if self.pga == 0:
			raise ValueError('pga = %r: the record is zero everywhere, no factor gives it this peak' % (pga, ))
		return self._new(acc=self._acc * (pga / self.pga))

	def baselineCorrected(self, degree=2):
		"""Least-squares polynomial baseline correction, the usual strong-motion way (D. M. Boore (2001), "Effect of
		baseline corrections on displacements and response spectra for several recordings of the 1999 Chi-Chi,
		Taiwan, earthquake", Bull. Seismol. Soc. Am. 91(5):1199–1211).

		The velocity $v$ of :meth:`velocity` is fitted by least squares over the whole record with a polynomial
		$p(\\tau) = c_0 + c_1\\tau + \\dots + c_d\\tau^d$ of degree $d$ = ``degree`` (0 to 3), $\\tau = t - t_0$, and its
		derivative is subtracted from the acceleration: $a^* = a - p' + \\tfrac{\\Delta t^2}{12} p'''$ (the last term,
		nonzero only for $d = 3$ and of relative size $\\Delta t^2/T^2$, makes the trapezoid rule integrate the
		subtracted baseline to $p(\\tau) - p(0)$ exactly). ``degree=1`` removes a constant acceleration offset (a
		linear velocity drift), ``degree=2`` a linear trend of the acceleration (Boore's quadratic fit to the
		velocity); ``degree=0`` leaves the record unchanged (a constant velocity has no derivative).

		Guarantees (to round-off): the corrected velocity is $v^* = v - p + c_0$, so $v^* - c_0$ is orthogonal to
		$1, \\tau, \\dots, \\tau^d$ on the samples: the least-squares polynomial of degree $d$ through $v^*$ is the
		constant $c_0$, i.e. $v^*$ has no linear trend ($d \\ge 1$), no quadratic drift ($d \\ge 2$) and so on, and the
		displacement has no corresponding runaway ($t^2$, $t^3$, ... growth). Still $v^*(t_0) = 0$.

		Not guaranteed: the mean velocity is $c_0$, not 0 (a constant velocity cannot be removed through the
		acceleration of a record that starts from rest: $A\\sin\\omega t$ has the mean velocity $A/\\omega$, and it is
		left alone); neither the final velocity nor the final displacement is 0 in general; drifts that are not
		polynomials of degree $\\le d$ over the whole record (a baseline step at one instant, say) are only partly
		removed; the record's long-period content is altered, the short-period content hardly (the correction is a
		polynomial of degree $d - 1$), the peak acceleration may change a little; nothing is filtered. A record's own
		slow velocity is taken for drift too: for $A\sin\omega t$ over $m$ whole periods ``degree=1`` changes nothing
		(by symmetry), but ``degree=2`` subtracts a line of peak $45A/(\pi^3 m^3)$ (2.3 % of $A$ for $m = 4$, 145 %
		for $m = 1$): do not correct short synthetic pulses with $d \ge 2$."""
		if isinstance(degree, bool) or not isinstance(degree, numbers.Integral) or not 0 <= degree <= 3:
			raise ValueError('degree = %r: must be an integer from 0 to 3' % (degree, ))
		degree = int(degree)
		if degree == 0:
			return self._new()
		T = self.duration
		x = np.arange(len(self._acc)) / (len(self._acc) - 1)  # tau / T in [0, 1], for conditioning
		c = np.linalg.lstsq(np.vander(x, degree + 1, increasing=True), self.velocity(), rcond=None)[0]
		baseline = sum(k * c[k] * x**(k - 1) for k in range(1, degree + 1)) / T
		if degree == 3:
			baseline = baseline - self._dt**2 / 12 * 6 * c[3] / T**3
		return self._new(acc=self._acc - baseline)

	def padded(self, before=0.0, after=0.0):
		"""The record with zeros added: ``before`` [s] >= 0 of zeros before the first sample and ``after`` [s] >= 0
		after the last, each rounded to the nearest whole number of steps. :attr:`t0` is kept, so the motion starts
		``before`` later."""
		nb = int(round(_nonNegative('before', before) / self._dt))
		na = int(round(_nonNegative('after', after) / self._dt))
		return self._new(acc=np.concatenate((np.zeros(nb), self._acc, np.zeros(na))))

	def cut(self, t0, t1):
		"""The samples at times $t_0 \\le t \\le t_1$ [s] (times within 1e-9 step of $t_0$ or $t_1$ count as inside),
		at least 2 of them. The samples keep their times: the new record starts at the first kept sample (use
		:meth:`startingAt` to move it). Its velocity and displacement are integrated from rest at its own start."""
		t0, t1 = _real('t0', t0, '[s]'), _real('t1', t1, '[s]')
		if not t1 > t0:
			raise ValueError('t1 = %r: must be > t0 = %r [s]' % (t1, t0))
		last = len(self._acc) - 1
		i0 = max(0, int(math.ceil(float(_steps((t0 - self._t0) / self._dt)))))
		i1 = min(last, int(math.floor(float(_steps((t1 - self._t0) / self._dt)))))
		if i1 - i0 < 1:
			raise ValueError('t0, t1 = %r, %r: must contain at least 2 samples of the record (times %s to %s s, step %s s)' %
			                 (t0, t1, _fmt(self._t0), _fmt(self.end), _fmt(self._dt)))
		return self._new(acc=self._acc[i0:i1 + 1].copy(), t0=self._t0 + i0 * self._dt)

	def startingAt(self, t0):
		"""The same samples with the first at time ``t0`` [s]."""
		return self._new(t0=_real('t0', t0, '[s]'))

	def __repr__(self):
		return 'Record(%r, %d samples, dt=%s s, t0=%s s, duration=%s s, pga=%s m/s², from %s)' % (self._name, len(self._acc), _fmt(
		        self._dt), _fmt(self._t0), _fmt(self.duration), _fmt(self.pga), self._units)


# ---------------------------------------------------------------------------------------------- readers
def _readLines(path):
	if not isinstance(path, (str, os.PathLike)):
		raise ValueError('path = %r: must be a file name' % (path, ))
	if not os.path.isfile(path):
		raise FileNotFoundError('path = %r: no such file' % (os.fspath(path), ))
	with open(path, encoding='latin-1') as f:
		return f.read().splitlines()


def _numbers(line, where):
	"""The numbers of a line of values (blank separated; Fortran forms such as ``.1234E-02``, ``1.5D+01`` and numbers
	run together like ``.1E-02-.2E-02`` accepted), or ValueError naming ``where``."""
	out, pos, line = [], 0, line.rstrip()
	while pos < len(line):
		m = _NEXT_NUMBER.match(line, pos)
		if m is None:
			raise ValueError('%s: not a number: %r' % (where, line[pos:].split()[0]))
		out.append(float(m.group(1).replace('D', 'E').replace('d', 'e')))
		pos = m.end()
		if pos < len(line) and not (line[pos].isspace() or line[pos] in '+-'):
			raise ValueError('%s: not a number: %r' % (where, m.group(1) + line[pos:].split()[0]))
	return out


def _at2Sizes(line, where):
	"""NPTS and DT from the 4th line of an .AT2 file: ``NPTS=  7998, DT=   .0050 SEC`` (any case, ``=`` or ``:``,
	with or without comma) or the older ``  3930    0.0100    NPTS, DT``."""
	n = re.search(r'NPTS\s*[=:]?\s*(' + _NUMBER + ')', line, re.I)
	d = re.search(r'\bDT\s*[=:]?\s*(' + _NUMBER + ')', line, re.I)
	if n and d:
		npts, dt = n.group(1), d.group(1)
	else:
		m = re.match(r'\s*(' + _NUMBER + r')[\s,]+(' + _NUMBER + r')[\s,]+NPTS\b', line, re.I)
		if m is None:
			raise ValueError('%s: expected NPTS and DT (e.g. "NPTS=  7998, DT=   .0050 SEC"), found %r' % (where, line.strip()))
		npts, dt = m.group(1), m.group(2)
	npts, dt = float(npts.replace('D', 'E').replace('d', 'e')), float(dt.replace('D', 'E').replace('d', 'e'))
	if npts != int(npts) or npts < 2:
		raise ValueError('%s: NPTS = %s must be an integer >= 2' % (where, _fmt(npts)))
	if not (math.isfinite(dt) and dt > 0):
		raise ValueError('%s: DT = %s must be > 0 [s]' % (where, _fmt(dt)))
	return int(npts), dt


def readAT2(path):
	"""Read one component of a PEER NGA strong-motion record (``.AT2``).

	The format: 4 header lines, then the NPTS samples, several per line (usually 5; the last line may be short), in
	the units of line 3::

	    PEER NGA STRONG MOTION DATABASE RECORD
	    IMPERIAL VALLEY 10/15/79 2316, EL CENTRO ARRAY #6, 230
	    ACCELERATION TIME SERIES IN UNITS OF G
	    NPTS=  3930, DT=   .0100 SEC
	      .1234E-02  .2345E-02 -.1111E-02 ...

	Tolerated: any case, ``NPTS= 3930 DT= 0.01 SEC`` without comma, the older 4th line ``  3930    0.0100    NPTS, DT``,
	Fortran numbers (``.1234E-02``, ``1.2D-03``). Units (line 3, after ``UNITS OF``): ``G`` (:data:`G` = 9.80665 m/s²),
	``CM/S/S``, ``CM/S^2``, ``M/S/S``, ``M/S^2`` (``SEC`` for ``S`` accepted); anything else is a ValueError naming
	the file and the unit found. The number of values must equal NPTS (else a ValueError naming the file and both
	numbers).

	:param path: the file.
	:return: a :class:`Record` in m/s², ``t0 = 0``, named after line 2 (the event, date, station and component), or
	    after the file if line 2 is blank."""
	lines = _readLines(path)
	where = os.fspath(path)
	if len(lines) < 4:
		raise ValueError('%s: an .AT2 file starts with 4 header lines; this one has %d lines' % (where, len(lines)))
	m = re.search(r'UNITS\s+OF\s+([^\s,;]+)', lines[2], re.I)
	if m is None:
		raise ValueError('%s, line 3: no units found in %r (expected e.g. "ACCELERATION TIME SERIES IN UNITS OF G")' % (where, lines[2].strip()))
	try:
		units = _unitName('units', m.group(1))
	except ValueError:
		raise ValueError('%s, line 3: unknown units %r; known: %s' % (where, m.group(1), _KNOWN_UNITS)) from None
	npts, dt = _at2Sizes(lines[3], '%s, line 4' % where)
	values = []
	for k, line in enumerate(lines[4:], start=5):
		values += _numbers(line, '%s, line %d' % (where, k))
	if len(values) != npts:
		raise ValueError('%s: NPTS = %d in the header but %d values read' % (where, npts, len(values)))
	name = lines[1].strip() or os.path.basename(where)
	return Record(dt, values, name=name, units=units)


def readColumns(path, units='g', timeColumn=0, accColumn=1, comments='#', delimiter=None, dt=None, name=None):
	"""Read a record from a text file of columns: time [s] and acceleration (in ``units``), one sample per line.

	Lines are cut at ``comments`` (a string, or ``None`` for none); blank lines are skipped; fields are split at
	``delimiter`` (``None``: any blanks; ``','`` for CSV). Times must increase strictly. If the steps are equal
	(to 1e-6 relative) the record keeps the samples, its step the mean step. Otherwise the time step is uneven and
	the record is **resampled** by linear interpolation to the smallest step found, from the first time to the last
	multiple of that step not after the last time; a :class:`UserWarning` says so. Steps found in the file are
	rounded to 10 significant digits (the differences of decimal times carry round-off: 0.04 - 0.03 is
	0.009999999999999995). With ``dt`` given, the record is always resampled to ``dt`` that way.

	:param path: the file.
	:param units: the unit of the acceleration column: ``'g'`` (:data:`G` = 9.80665 m/s²), ``'cm/s^2'``, ``'m/s^2'``.
	:param timeColumn, accColumn: column indices from 0, different.
	:param dt: step [s] > 0 to resample to, or ``None``.
	:param name: the record's name; default the file's name.
	:return: a :class:`Record` in m/s² starting at the first time of the file."""
	units = _unitName('units', units)
	for key, c in (('timeColumn', timeColumn), ('accColumn', accColumn)):
		if isinstance(c, bool) or not isinstance(c, numbers.Integral) or c < 0:
			raise ValueError('%s = %r: must be an integer >= 0 (a column index from 0)' % (key, c))
	if timeColumn == accColumn:
		raise ValueError('accColumn = %r: must differ from timeColumn = %r' % (accColumn, timeColumn))
	if comments is not None and not (isinstance(comments, str) and comments):
		raise ValueError('comments = %r: must be a non-empty string or None' % (comments, ))
	if delimiter is not None and not (isinstance(delimiter, str) and delimiter):
		raise ValueError('delimiter = %r: must be a non-empty string or None (blanks)' % (delimiter, ))
	if dt is not None:
		dt = _positive('dt', dt, '[s]')
	if name is not None and not isinstance(name, str):
		raise ValueError('name = %r: must be a string or None' % (name, ))
	where = os.fspath(path) if isinstance(path, (str, os.PathLike)) else path
	lines = _readLines(path)
	times, acc, lineOf = [], [], []
	for k, line in enumerate(lines, start=1):
		if comments is not None:
			line = line.split(comments, 1)[0]
		if not line.strip():
			continue
		fields = line.split(delimiter)
		if max(timeColumn, accColumn) >= len(fields):
			raise ValueError('%s, line %d: %d columns, needs column %d (timeColumn = %d, accColumn = %d)' %
			                 (where, k, len(fields), max(timeColumn, accColumn), timeColumn, accColumn))
		try:
			t, a = (float(fields[c].strip().replace('D', 'E').replace('d', 'e')) for c in (timeColumn, accColumn))
		except ValueError:
			raise ValueError('%s, line %d: not numbers in columns %d, %d: %r' % (where, k, timeColumn, accColumn, line.strip())) from None
		if not (math.isfinite(t) and math.isfinite(a)):
			raise ValueError('%s, line %d: time and acceleration must be finite: %r' % (where, k, line.strip()))
		if times and not t > times[-1]:
			raise ValueError('%s, line %d: times must increase, but t = %s s follows t = %s s (line %d)' % (where, k, _fmt(t), _fmt(times[-1]), lineOf[-1]))
		times.append(t)
		acc.append(a)
		lineOf.append(k)
	if len(times) < 2:
		raise ValueError('%s: needs at least 2 samples, found %d' % (where, len(times)))
	t, a = np.array(times), np.array(acc)
	steps = np.diff(t)
	mean = (t[-1] - t[0]) / (len(t) - 1)
	even = steps.max() - steps.min() <= 1e-6 * mean
	if dt is None and even:
		return Record(float('%.10g' % mean), a, name=os.path.basename(where) if name is None else name, units=units, t0=t[0])
	if dt is None:
		dt = float('%.10g' % steps.min())
		warnings.warn('%s: uneven time step (%s to %s s): resampled linearly to the smallest step, dt = %s s' %
		              (where, _fmt(steps.min()), _fmt(steps.max()), _fmt(dt)), stacklevel=2)
	if dt > (t[-1] - t[0]) * (1 + _SNAP):
		raise ValueError('dt = %r: must be <= the duration %s s of the record in %s' % (dt, _fmt(t[-1] - t[0]), where))
	n = _stepCount(t[-1] - t[0], dt) + 1
	tn = t[0] + dt * np.arange(n)
	tn[-1] = min(tn[-1], t[-1])  # round-off must not take the last time out of the file's range
	return Record(dt, np.interp(tn, t, a), name=os.path.basename(where) if name is None else name, units=units, t0=t[0])


def readValues(path, dt, units='g', comments='#', name=None):
	"""Read a record from a text file of accelerations only, several per line (``8F10.5``, as the El Centro 1940 file
	in data/records/), at the constant step ``dt``.

	Lines are cut at ``comments`` (a string, or ``None``); the numbers of all lines, in order, are the samples.

	:param path: the file.
	:param dt: the time step [s] > 0 (such files state it in their header, which this reader does not parse).
	:param units: of the values: ``'g'`` (:data:`G` = 9.80665 m/s²), ``'cm/s^2'`` or ``'m/s^2'``.
	:param name: the record's name; default the file's first comment line, else the file's name.
	:return: a :class:`Record` in m/s², ``t0 = 0``."""
	dt = _positive('dt', dt, '[s]')
	units = _unitName('units', units)
	if comments is not None and not (isinstance(comments, str) and comments):
		raise ValueError('comments = %r: must be a non-empty string or None' % (comments, ))
	if name is not None and not isinstance(name, str):
		raise ValueError('name = %r: must be a string or None' % (name, ))
	lines = _readLines(path)
	where = os.fspath(path)
	values, title = [], None
	for k, line in enumerate(lines, start=1):
		if comments is not None and comments in line:
			line, note = line.split(comments, 1)
			title = note.strip() if title is None and note.strip() else title
		values += _numbers(line, '%s, line %d' % (where, k))
	if len(values) < 2:
		raise ValueError('%s: needs at least 2 samples, found %d' % (where, len(values)))
	return Record(dt, values, name=name if name is not None else (title or os.path.basename(where)), units=units)


# ---------------------------------------------------------------------------------------------- synthetic inputs
def _nodes(length, dt, what):
	"""Times $0, \\Delta t, \\dots$ up to ``length`` (the last multiple of dt not after it), at least 2 of them."""
	n = _stepCount(length, dt)
	if n < 1:
		raise ValueError('dt = %r: must be <= %s = %s [s] (at least 2 samples)' % (dt, what, _fmt(length)))
	return dt * np.arange(n + 1)


def sinePulse(amplitude, period, cycles=1, dt=None, before=0.0, after=0.0):
	"""A sine pulse: $a(t) = A\\sin(2\\pi t/T)$ for $0 \\le t \\le n_c T$, sampled at $t = k\\,\\Delta t$ (up to the
	last multiple of $\\Delta t$ not after $n_c T$; choose $\\Delta t$ dividing $T$), with zeros added before and
	after (:meth:`Record.padded`: the pulse then starts at ``before``, rounded to whole steps).

	From rest its velocity is $(A/\\omega)(1 - \\cos\\omega t)$ and displacement $(A/\\omega)(t - \\sin(\\omega t)/\\omega)$,
	$\\omega = 2\\pi/T$: after whole cycles the velocity is back to 0 and the base has moved by $A n_c T/\\omega$.

	:param amplitude: $A$ [m/s²], finite (any sign; ``0.2 * G`` for 0.2 g).
	:param period: $T$ [s] > 0.
	:param cycles: $n_c$ > 0 (not necessarily whole: 0.5 is a half-sine pulse).
	:param dt: step [s], > 0 and < T/2 (Nyquist); default T/100.
	:param before, after: zeros [s] >= 0."""
	A = _real('amplitude', amplitude, '[m/s²]')
	T = _positive('period', period, '[s]')
	cycles = _positive('cycles', cycles, '(number of periods)')
	dt = T / 100 if dt is None else _positive('dt', dt, '[s]')
	if not dt < T / 2:
		raise ValueError('dt = %r: must be < period/2 = %s [s] (Nyquist: more than 2 samples per period)' % (dt, _fmt(T / 2)))
	t = _nodes(cycles * T, dt, 'cycles*period')
	r = Record(dt, A * np.sin(2 * math.pi * t / T), name='sine pulse: A = %s m/s², T = %s s, %s cycles' % (_fmt(A), _fmt(T), _fmt(cycles)))
	return r.padded(before, after)


def rickerWavelet(amplitude, frequency, dt, duration=None, delay=None):
	"""The Ricker ("Mexican hat") wavelet of peak frequency $f_p$ (N. Ricker (1953), "The form and laws of propagation
	of seismic wavelets", Geophysics 18(1):10–40):

	$a(t) = A\\,(1 - 2\\pi^2 f_p^2\\tau^2)\\exp(-\\pi^2 f_p^2\\tau^2)$, $\\tau = t - t_d$,

	sampled at $t = k\\,\\Delta t$ from 0 to ``duration``. Its peak $a = A$ is at $\\tau = 0$, its zeros at
	$\\tau = \\pm 1/(\\pi f_p\\sqrt{2})$, its two minima $-2A e^{-3/2} \\approx -0.446 A$ at
	$\\tau = \\pm\\sqrt{3/2}/(\\pi f_p)$. With the default delay $t_d = 1.5/f_p$ it starts and ends at
	$a \\approx -1.0\\times 10^{-8} A$. Its velocity $A\\tau e^{-\\pi^2 f_p^2\\tau^2}$ and displacement
	$-A e^{-\\pi^2 f_p^2\\tau^2}/(2\\pi^2 f_p^2)$ (up to constants) both return to their initial values: the base
	comes back to rest where it started. The spectrum $\\propto (f/f_p)^2 e^{-(f/f_p)^2}$ peaks at $f_p$ and is
	below 0.3 % of its peak above $3 f_p$.

	:param amplitude: $A$ [m/s²], finite (any sign).
	:param frequency: $f_p$ [Hz] > 0.
	:param dt: step [s], > 0 and < $1/(6 f_p)$ (Nyquist for $3 f_p$).
	:param duration: [s] > 0; default $2 t_d$ (symmetric about the peak).
	:param delay: $t_d$ [s] >= 0, the time of the peak; default $1.5/f_p$."""
	A = _real('amplitude', amplitude, '[m/s²]')
	f = _positive('frequency', frequency, '[Hz]')
	dt = _positive('dt', dt, '[s]')
	if not dt < 1 / (6 * f):
		raise ValueError('dt = %r: must be < 1/(6*frequency) = %s [s] (Nyquist for 3 f_p, above which the spectrum is < 0.3 %% of its peak)' %
		                 (dt, _fmt(1 / (6 * f))))
	td = 1.5 / f if delay is None else _nonNegative('delay', delay, '[s]')
	duration = 2 * td if duration is None else _positive('duration', duration, '[s]')
	if duration == 0:
		raise ValueError('duration = 0 (from delay = 0): give a duration > 0 [s]')
	t = _nodes(duration, dt, 'duration')
	q = (math.pi * f * (t - td))**2
	return Record(dt, A * (1 - 2 * q) * np.exp(-q), name='Ricker wavelet: A = %s m/s², f_p = %s Hz, t_d = %s s' % (_fmt(A), _fmt(f), _fmt(td)))


def sweep(amplitude, f0, f1, duration, dt):
	"""A linear chirp: $a(t) = A\\sin\\big(2\\pi(f_0 t + (f_1 - f_0)\\,t^2/(2D))\\big)$ for $0 \\le t \\le D$: its
	instantaneous frequency (the phase's rate over $2\\pi$) runs linearly from $f_0$ at $t = 0$ to $f_1$ at $t = D$
	(up or down). Sampled at $t = k\\,\\Delta t$ up to the last multiple not after $D$.

	:param amplitude: $A$ [m/s²], finite.
	:param f0, f1: start and end frequencies [Hz] > 0.
	:param duration: $D$ [s] > 0.
	:param dt: step [s], > 0 and < $1/(2\\max(f_0, f_1))$ (Nyquist)."""
	A = _real('amplitude', amplitude, '[m/s²]')
	f0, f1 = _positive('f0', f0, '[Hz]'), _positive('f1', f1, '[Hz]')
	D = _positive('duration', duration, '[s]')
	dt = _positive('dt', dt, '[s]')
	if not dt < 1 / (2 * max(f0, f1)):
		raise ValueError('dt = %r: must be < 1/(2*max(f0, f1)) = %s [s] (Nyquist)' % (dt, _fmt(1 / (2 * max(f0, f1)))))
	t = _nodes(D, dt, 'duration')
	phase = 2 * math.pi * (f0 * t + (f1 - f0) * t * t / (2 * D))
	return Record(dt, A * np.sin(phase), name='sweep: A = %s m/s², %s to %s Hz in %s s' % (_fmt(A), _fmt(f0), _fmt(f1), _fmt(D)))


def constant(value, duration, dt):
	"""A constant acceleration $a(t) = a_c$ for $0 \\le t \\le D$ (a step from rest), e.g. a horizontal acceleration
	that tilts gravity: velocity $a_c t$ and displacement $a_c t^2/2$, both exact under the trapezoid rule.

	:param value: $a_c$ [m/s²], finite (any sign).
	:param duration: $D$ [s] > 0.
	:param dt: step [s], > 0 and <= D."""
	a = _real('value', value, '[m/s²]')
	D = _positive('duration', duration, '[s]')
	dt = _positive('dt', dt, '[s]')
	t = _nodes(D, dt, 'duration')
	return Record(dt, np.full(len(t), a), name='constant: %s m/s² for %s s' % (_fmt(a), _fmt(D)))


# ---------------------------------------------------------------------------------------------- GroundMotion
class GroundMotion:
	"""Up to three components of ground acceleration along the global $x$, $y$, $z$ axes on one time axis (in
	:mod:`rdem.wall_layout`, $x$ runs along the wall, $y$ through it and $z$ up).

	The common step is the smallest step of the components; the common axis runs from the earliest :attr:`Record.t0`
	to the latest :attr:`Record.end` (its last node the last multiple of the step not after it). A component already
	on that axis is copied exactly (zeros added where it has no samples); any other is linearly interpolated onto it
	(:meth:`Record.at`, 0 outside its own record). Missing components (``None``) are zero.

	:param x, y, z: :class:`Record` or ``None``, at least one given.

	:ivar x, y, z: the components on the common axis (:class:`Record` or ``None``)."""

	def __init__(self, x=None, y=None, z=None):
		given = {}
		for key, r in (('x', x), ('y', y), ('z', z)):
			if r is not None and not isinstance(r, Record):
				raise ValueError('%s = %r: must be a Record or None' % (key, r))
			if r is not None:
				given[key] = r
		if not given:
			raise ValueError('x, y, z = None, None, None: at least one component must be a Record')
		dt = min(r.dt for r in given.values())
		t0 = min(r.t0 for r in given.values())
		n = _stepCount(max(r.end for r in given.values()) - t0, dt) + 1
		self._dt, self._t0, self._n = dt, t0, n
		for key in 'xyz':
			setattr(self, '_' + key, self._onAxis(given[key]) if key in given else None)
		self._cache = {}

	@classmethod
	def _of(cls, x, y, z):
		"""A motion of components already on one axis."""
		gm = object.__new__(cls)
		r = next(c for c in (x, y, z) if c is not None)
		gm._dt, gm._t0, gm._n, gm._x, gm._y, gm._z, gm._cache = r.dt, r.t0, len(r), x, y, z, {}
		return gm

	def _onAxis(self, r):
		shift = float(_steps((r.t0 - self._t0) / self._dt))
		if r.dt == self._dt and shift == int(shift):
			k = int(shift)
			acc = np.zeros(self._n)
			m = min(len(r), self._n - k)
			acc[k:k + m] = r.acc[:m]
		else:
			acc = r._atSteps(np.arange(self._n) * (self._dt / r.dt) - (r.t0 - self._t0) / r.dt)
		return r._new(acc=acc, dt=self._dt, t0=self._t0)

	x = property(lambda self: self._x, doc='The $x$ component on the common axis, or ``None``.')
	y = property(lambda self: self._y, doc='The $y$ component on the common axis, or ``None``.')
	z = property(lambda self: self._z, doc='The $z$ component on the common axis, or ``None``.')
	dt = property(lambda self: self._dt, doc='Common time step [s].')
	t0 = property(lambda self: self._t0, doc='Time of the first sample [s].')

	@property
	def components(self):
		"""``(x, y, z)``."""
		return (self._x, self._y, self._z)

	def __len__(self):
		return self._n

	@property
	def duration(self):
		"""$(N - 1)\\,\\Delta t$ [s]."""
		return (self._n - 1) * self._dt

	@property
	def end(self):
		"""Time of the last sample [s]."""
		return self._t0 + self.duration

	def times(self):
		"""Sample times [s], shape (N,)."""
		return self._t0 + self._dt * np.arange(self._n)

	def _stack(self, what, column):
		if what not in self._cache:
			cols = [column(r) if r is not None else np.zeros(self._n) for r in self.components]
			self._cache[what] = _frozen(np.column_stack(cols))
		return self._cache[what]

	def accelerations(self):
		"""Accelerations [m/s²], shape (N, 3), zero columns for missing components (read-only)."""
		return self._stack('acc', lambda r: r.acc)

	def velocities(self):
		"""Velocities [m/s], shape (N, 3): :meth:`Record.velocity` of each component (read-only)."""
		return self._stack('vel', Record.velocity)

	def displacements(self):
		"""Displacements [m], shape (N, 3): :meth:`Record.displacement` of each component (read-only)."""
		return self._stack('disp', Record.displacement)

	def acc(self, t):
		"""``(a_x, a_y, a_z)`` [m/s²] at time ``t`` [s] (:meth:`Record.at`; 0 outside the record)."""
		return tuple(r.at(t) if r is not None else 0.0 for r in self.components)

	def vel(self, t):
		"""``(v_x, v_y, v_z)`` [m/s] at time ``t`` [s] (:meth:`Record.velocityAt`)."""
		return tuple(r.velocityAt(t) if r is not None else 0.0 for r in self.components)

	def disp(self, t):
		"""``(u_x, u_y, u_z)`` [m] at time ``t`` [s] (:meth:`Record.displacementAt`)."""
		return tuple(r.displacementAt(t) if r is not None else 0.0 for r in self.components)

	def scaled(self, factor):
		"""Every component multiplied by ``factor`` (finite, any sign)."""
		factor = _real('factor', factor, '(any sign)')
		return GroundMotion._of(*(r.scaled(factor) if r is not None else None for r in self.components))

	def baselineCorrected(self, degree=2):
		"""Every component by :meth:`Record.baselineCorrected` with this ``degree`` (0 to 3)."""
		if isinstance(degree, bool) or not isinstance(degree, numbers.Integral) or not 0 <= degree <= 3:
			raise ValueError('degree = %r: must be an integer from 0 to 3' % (degree, ))
		return GroundMotion._of(*(r.baselineCorrected(degree) if r is not None else None for r in self.components))

	def __repr__(self):
		return 'GroundMotion(%s; %d samples, dt=%s s, t0=%s s, duration=%s s)' % (', '.join(
		        '%s: %s' % (k, 'pga %s m/s²' % _fmt(r.pga) if r is not None else 'None') for k, r in zip('xyz', self.components)), self._n, _fmt(
		                self._dt), _fmt(self._t0), _fmt(self.duration))

