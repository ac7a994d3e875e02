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
