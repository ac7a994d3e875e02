"""Quasi-static loading in fewer steps: the math of the scheme of the :ref:`validation <rdem-validation>` ("Quasi-static loading in fewer
steps"), pure Python (standard library only), tested in tests/python/test_quasi_static.py; rdem.walltest applies it.

A quasi-static test run as explicit dynamics costs (travel / rate) / Δt steps. Two levers keep the answer static:

* **Time scaling** (the loading rate): with rate-independent springs, scaling every mass by $s^2$ (gravity and the
  applied loads keeping the true masses) is the same as loading $s$ times faster: the equations of motion in the time
  $t/s$ are the same, the contact dashpots $c = 2h\\sqrt{m k}$ (eq. 13) giving the same forces. So uniform density
  scaling buys nothing a faster push does not, and the push's rate is the one knob; whether it is slow enough is
  checked by running at half the rate. Cundall's non-viscous damping ([Cundall1987]_) acts only on accelerating
  motion (its force is $-D |F| \\mathrm{sign}(v)$ per degree of freedom), so it does not lag a steady push and can be
  strong.
* **Rotational inertia scaling**: the critical step of a block assembly is set by its highest frequencies, and in a
  block's Gershgorin row (RdemTimeStepper) the rotational terms outweigh the translational ones (for MI1's half
  bricks by about 2 to 1: a face spring's arm is comparable with the block's radius of gyration, and it counts in
  three rotational terms). Scaling each block's moments of inertia by :func:`rotationalInertiaScale` makes the
  rotational terms of its row no larger than the translational ones, without touching its mass: the weight, the
  applied loads and every static state are unchanged; only the rotations respond more slowly. Whether that moves the
  result is measured (:ref:`validation <rdem-validation>`), as for the rate.
* **Partial density scaling** ([Itasca2020]_'s density scaling for quasi-static problems): unlike a uniform one, scaling
  the inertia of only the few light or stiff blocks that set the critical step raises the step without slowing the
  rest of the wall. :func:`inertialScales` gives each block the smallest factor $\\mu_b \\ge 1$ of its mass and moments of
  inertia that brings its own damped limit up to a target step; gravity and the applied loads keep the true masses
  (:yref:`RdemDensityScaling`), so every static state is unchanged and only those blocks respond more slowly.
"""
import math


def rotationalInertiaScale(halfExtents):
	"""The factor $s$ of a rectangular block's principal moments of inertia (half-extents $a \\ge b \\ge c$ [m], any
	order given) that makes the rotational terms of its Gershgorin row no larger than its translational ones:

	every spring $i$ on the block's faces has an arm $|\\mathbf r_i|^2 \\le a^2 + b^2 + c^2$ from the centroid, so its
	rotational stiffness
	$k_{r,i} = A(\\bar k_n |\\mathbf r\\times\\mathbf n|^2 + \\bar k_s (|\\mathbf r|^2 + (\\mathbf r\\cdot\\mathbf n)^2)) \\le 3 k_{t,i} |\\mathbf r_i|^2$ with $k_{t,i} = \\max(\\bar k_n, \\bar k_s) A$ (RdemTimeStepper's
	Gershgorin bound); with $I_{min} = m (b^2 + c^2)/3$,

	.. math:: \\sum_i \\frac{k_{r,i}}{s I_{min}} \\le \\sum_i \\frac{k_{t,i}}{m} \\quad\\text{for}\\quad s = \\frac{9 (a^2 + b^2 + c^2)}{b^2 + c^2}.

	A cube gets $s = 13.5$, MI1's half brick (62.5 × 60 × 27.5 mm) 17.1. ValueError if a half-extent is not > 0."""
	h = sorted((float(x) for x in halfExtents), reverse=True)
	if len(h) != 3 or not all(math.isfinite(x) and x > 0 for x in h):
		raise ValueError('halfExtents = %r: must be 3 finite half-extents > 0 [m]' % (halfExtents, ))
	a, b, c = h
	return 9 * (a * a + b * b + c * c) / (b * b + c * c)


def pushSteps(travel, rate, dt):
	"""Steps of a push over ``travel`` [m] at ``rate`` [m/s] with the time step ``dt`` [s]: travel / (rate dt), rounded
	up. ValueError if an argument is not > 0."""
	for name, v in (('travel', travel), ('rate', rate), ('dt', dt)):
		if not (math.isfinite(v) and v > 0):
			raise ValueError('%s = %r: must be finite and > 0' % (name, v))
	return int(math.ceil(travel / (rate * dt)))


def _rows(omega2, dashpotRate):
	"""The per-block rows as two lists of floats, checked (see :func:`inertialScales`)."""
	w2, c = [float(x) for x in omega2], [float(x) for x in dashpotRate]
	if len(w2) != len(c):
		raise ValueError('omega2 and dashpotRate: %d and %d values: must have one per block each' % (len(w2), len(c)))
	for name, values in (('omega2', w2), ('dashpotRate', c)):
		for i, v in enumerate(values):
			if not (math.isfinite(v) and v >= 0):
				raise ValueError('%s[%d] = %r: must be finite and >= 0 [1/s2, 1/s]' % (name, i, v))
	return w2, c


def localDampedStep(omega2, dashpotRate):
	"""The damped limit of one block's own row [s]: the root of $\\Delta t^2\\omega_b^2 + 2\\Delta t\\,c_b = 4$,

	.. math:: \\Delta t_b = \\frac{4}{c_b + \\sqrt{c_b^2 + 4\\omega_b^2}},

	with $\\omega_b^2$ [1/s²] and $c_b$ [1/s] the block's Gershgorin rows of the mass-normalised stiffness $\\tilde K$ and
	dashpots $\\tilde C$ (:yref:`RdemTimeStepper.blockRows`). Leapfrog with dashpots on the mid-step velocity is stable while
	$\\lambda_{max}(\\Delta t^2\\tilde K + 2\\Delta t\\tilde C) \\le 4$ (:yref:`RdemTimeStepper`), and that largest
	eigenvalue is at most the largest row $\\Delta t^2\\omega_b^2 + 2\\Delta t c_b$ (both are bounds by rows of a sum of
	pair terms); for one oscillator of damping ratio $\\zeta = c/(2\\omega)$ it is $(2/\\omega)(\\sqrt{1+\\zeta^2}-\\zeta)$
	([Belytschko2000]_). inf for a block without rows (fixed, or no springs). ValueError if a row is negative or not finite."""
	(w2, ), (c, ) = _rows([omega2], [dashpotRate])
	if w2 == 0 and c == 0:
		return float('inf')
	return 4 / (c + math.sqrt(c * c + 4 * w2))


def inertialScales(omega2, dashpotRate, target):
	"""Per block, the factor $\\mu_b \\ge 1$ of its mass and moments of inertia that brings its own damped limit
	(:func:`localDampedStep`) up to the step ``target`` [s]: its scaled rows are $\\omega_b^2/\\mu_b$ and $c_b/\\mu_b$
	(each row is over the block's own mass; the dashpots' coefficients, eq. 13 with the densities of the materials, are
	unchanged), so $\\Delta t^2\\omega_b^2/\\mu_b + 2\\Delta t\\,c_b/\\mu_b \\le 4$ at $\\Delta t$ = ``target`` for

	.. math:: \\mu_b = \\max\\left(1, \\frac{T^2\\omega_b^2 + 2 T c_b}{4}\\right),

	with $T$ the target, $\\omega_b^2$ [1/s²] and $c_b$ [1/s] the block's unscaled rows (lists of equal length, e.g. from
	:yref:`RdemTimeStepper.blockRows` with no scaling set). The density scaling of YADE's :yref:`State` is
	$s_b = 1/\\mu_b$ (:yref:`RdemDensityScaling`). A block whose own limit is already above $T$ keeps $\\mu_b = 1$.
	Examples: $\\omega_b^2 = 10^{10}$ s⁻², $c_b = 0$ (limit 20 µs) and $T$ = 40 µs give $\\mu_b = 4$; with
	$c_b = 5\\cdot 10^4$ s⁻¹ the limit is $4/(c + \\sqrt{c^2 + 4\\omega^2}) = 16.0$ µs and $T$ = 40 µs needs
	$\\mu_b = 4 + 1 = 5$.
	ValueError naming the argument if ``target`` is not finite and > 0 or a row is negative or not finite."""
	w2, c = _rows(omega2, dashpotRate)
	T = float(target)
	if not (math.isfinite(T) and T > 0):
		raise ValueError('target = %r: must be finite and > 0 [s]' % (target, ))
	return [max(1.0, (T * T * a + 2 * T * b) / 4) for a, b in zip(w2, c)]


def densityScalingTarget(omega2, dashpotRate, factor):
	"""The target step of :func:`inertialScales` for a gain ``factor`` >= 1 on the step: ``factor`` times the smallest
	:func:`localDampedStep` over the blocks [s], so that the bound of the scaled assembly by its rows rises by ``factor``
	(the Lanczos limit that :yref:`RdemTimeStepper` uses rises about as much while the blocks scaled are those of the
	stiffest and most damped modes; measured in :ref:`validation <rdem-validation>`). inf if no block has a row.
	ValueError if ``factor`` is not finite and >= 1, or a row is bad."""
	f = float(factor)
	if not (math.isfinite(f) and f >= 1):
		raise ValueError('factor = %r: must be finite and >= 1 (the gain on the time step)' % (factor, ))
	w2, c = _rows(omega2, dashpotRate)
	return f * min((localDampedStep(a, b) for a, b in zip(w2, c)), default=float('inf'))
