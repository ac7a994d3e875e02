"""The rigid rocking block's exact equation of motion with Housner's impacts, integrated numerically: the reference for
overturning under ground pulses (a parapet on a roof, a free-standing wall). Pure Python (standard library only, no
YADE), tested in tests/python/test_rocking_equation.py.

A rigid block of half-width $b$ and half-height $h$ ($R = \\sqrt{b^2 + h^2}$, $\\tan\\alpha = b/h$) on a rigid base that
accelerates horizontally by $\\ddot u_g(t)$ (positive $+x$), with friction high enough that it does not slide, rocks about
its $+x$ corner ($\\theta > 0$) or its $-x$ corner ($\\theta < 0$) (Housner 1963; Zhang & Makris 2001, eq. 1):

.. math:: \\ddot\\theta = -p^2\\left[\\sin(\\alpha\\,\\mathrm{sgn}\\,\\theta - \\theta) + \\frac{\\ddot u_g}{g}\\cos(\\alpha\\,\\mathrm{sgn}\\,\\theta - \\theta)\\right],
          \\qquad p^2 = \\frac{3g}{4R}

(moments about the pivot corner with $I_O = \\tfrac43 mR^2$). From rest it lifts off when $|\\ddot u_g| > g\\tan\\alpha$, onto
the corner opposite to the acceleration. At each impact ($\\theta$ through 0) the angular momentum about the new corner
is conserved: $\\dot\\theta^+ = \\eta\\,\\dot\\theta^-$, $\\eta = 1 - \\tfrac32\\sin^2\\alpha$ (Housner 1963). Angles in rad, times in s,
accelerations in m/s².
"""
import math


class RockingBlockEquation:
	"""The block and its equation of motion.

	:param b: half-width [m] > 0.
	:param h: half-height [m] > 0.
	:param g: gravity [m/s²] > 0.
	:param eta: ratio of angular velocities through an impact (default Housner's $1 - 1.5\\sin^2\\alpha$), in [0, 1]."""

	def __init__(self, b, h, g=9.81, eta=None):
		for name, value in (('b', b), ('h', h), ('g', g)):
			if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
				raise ValueError('%s = %r: must be a finite number > 0' % (name, value))
		self.b, self.h, self.g = float(b), float(h), float(g)
		self.alpha = math.atan2(b, h)
		self.R = math.hypot(b, h)
		self.p = math.sqrt(3 * g / (4 * self.R))
		self.eta = 1 - 1.5 * math.sin(self.alpha)**2 if eta is None else float(eta)
		if not 0 <= self.eta <= 1:
			raise ValueError('eta = %r: must be in [0, 1]' % (eta, ))

	def _acc(self, side, th, ag):
		a = self.alpha
		return -self.p**2 * (side * math.sin(a - side * th) + ag / self.g * math.cos(a - side * th))

	def response(self, ground, duration, dt=None, stopAt=None, theta0=0.0):
		"""Integrate from rest at $\\theta$ = ``theta0`` (default 0: standing on its base) under the ground acceleration ``ground(t)`` [m/s²] up to ``duration`` [s] by
		fourth-order Runge-Kutta with steps ``dt`` (default $1/(2000p)$); impacts located within a step by the cubic
		Hermite interpolant of $\\theta$.

		:param stopAt: stop once $|\\theta|$ exceeds this [rad] (default: $\\pi/2$, the block lies on its side).
		:return: dict with ``theta`` and ``time`` (every step), ``impacts`` (times), ``maxTheta`` (the largest $|\\theta|$)."""
		dt = dt or 1 / (2000 * self.p)
		stop = stopAt if stopAt is not None else math.pi / 2
		uplift = self.g * math.tan(self.alpha)
		t, th, om = 0.0, float(theta0), 0.0
		side = (th > 0) - (th < 0)  # 0: at rest on its base
		times, thetas, impacts = [0.0], [th], []
		while t < duration and abs(th) < stop:
			if side == 0:
				ag = ground(t)
				if abs(ag) > uplift:
					side = -1 if ag > 0 else 1
				else:
					t += dt
					times.append(t)
					thetas.append(0.0)
					continue
			f = lambda tt, x, w: (w, self._acc(side, x, ground(tt)))
			k1 = f(t, th, om)
			k2 = f(t + dt / 2, th + dt / 2 * k1[0], om + dt / 2 * k1[1])
			k3 = f(t + dt / 2, th + dt / 2 * k2[0], om + dt / 2 * k2[1])
			k4 = f(t + dt, th + dt * k3[0], om + dt * k3[1])
			th1 = th + dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
			om1 = om + dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
			if side * th1 < 0:  # through theta = 0 within the step: impact
				s = self._crossing(th, om, th1, om1, dt)
				# the state at the crossing: Hermite interpolant of omega's integral is theta; omega linearly
				omc = om + s * (om1 - om)
				t += s * dt
				impacts.append(t)
				om = self.eta * omc
				th = 0.0
				side = -side
				if abs(om) < 1e-9 * self.p:  # no energy left: it rests until the ground lifts it again
					side, om = 0, 0.0
				times.append(t)
				thetas.append(0.0)
				continue
			t, th, om = t + dt, th1, om1
			times.append(t)
			thetas.append(th)
		return {'time': times, 'theta': thetas, 'impacts': impacts, 'maxTheta': max(abs(x) for x in thetas)}

	@staticmethod
	def _crossing(th0, om0, th1, om1, dt):
		"""Fraction s in [0, 1] of the step at which the cubic Hermite interpolant of theta vanishes (bisection)."""
		def hermite(s):
			h00, h10, h01, h11 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2
			return h00 * th0 + h10 * dt * om0 + h01 * th1 + h11 * dt * om1
		lo, hi = 0.0, 1.0
		for _ in range(60):
			mid = (lo + hi) / 2
			if (hermite(mid) > 0) == (th0 > 0):
				lo = mid
			else:
				hi = mid
		return (lo + hi) / 2

	def overturns(self, ground, pulseEnd, dt=None):
		"""Whether the block overturns under ``ground``, which is 0 after ``pulseEnd`` [s]: it reaches $|\\theta| = \\pi/2$, or
		$|\\theta| > \\alpha$ after the pulse (then gravity takes it over). Integrated up to ``pulseEnd``
		$+ 8/p$ (several times the block's time scale $1/p$: long enough for it to fall or come back)."""
		r = self.response(ground, pulseEnd + 8 / self.p, dt=dt)
		if r['maxTheta'] >= math.pi / 2 - 1e-9:
			return True
		return any(abs(th) > self.alpha for tt, th in zip(r['time'], r['theta']) if tt > pulseEnd)

	def minimumOverturningAmplitude(self, period, step=0.01, upTo=20.0, tolerance=1e-4, dt=None):
		"""Smallest amplitude $A$ [m/s²] of the one-sine pulse $\\ddot u_g = A\\sin(2\\pi t/T)$, $0 \\le t \\le T$, that
		overturns the block: amplitudes scanned upwards from $g\\tan\\alpha$ by ``step`` (relative) up to ``upTo`` times
		$g\\tan\\alpha$, the first overturning one refined by bisection to ``tolerance`` (relative). The scan matters: the
		overturning amplitudes of a one-sine pulse are not an interval (Zhang & Makris 2001, Fig. 5: above the first
		there can be amplitudes that do not overturn).

		:return: $A_{min}$ [m/s²], or ``None`` if none up to ``upTo``."""
		T = float(period)
		if not (math.isfinite(T) and T > 0):
			raise ValueError('period = %r: must be a finite number > 0 [s]' % (period, ))
		a0 = self.g * math.tan(self.alpha)
		pulse = lambda A: (lambda t: A * math.sin(2 * math.pi * t / T) if 0 <= t <= T else 0.0)
		lo = a0
		A = a0 * (1 + step)
		while A <= upTo * a0:
			if self.overturns(pulse(A), T, dt=dt):
				hi = A
				while hi - lo > tolerance * lo:
					mid = (lo + hi) / 2
					if self.overturns(pulse(mid), T, dt=dt):
						hi = mid
					else:
						lo = mid
				return hi
			lo, A = A, A * (1 + step)
		return None
