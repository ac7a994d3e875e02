"""Rigid-block limit analysis of a dry-stacked wall on a tilting base (a tilting-table test, de Felice 2011): the tilt at
which it collapses. Pure Python (standard library only, no YADE), tested in tests/python/test_limit_analysis.py.

A base tilted by $\\theta$ about the wall's length, or gravity turned by $\\theta$ about that axis (the same thing in the
base's frame), loads the wall by its weight $W\\cos\\theta$ normal to the bed joints and $W\\sin\\theta$ along them: a
static horizontal load of $\\lambda = \\tan\\theta$ times the weight (the collapse multiplier of a seismic check).

Blocks are rigid, joints resist no tension, have unlimited compressive strength and Coulomb friction $\\mu$ (Heyman 1966;
the assumptions of Housner 1963 for a single block). Sign convention: the wall leans towards $+y$ (the tilt's downhill
side) and turns about the downhill edge of a bed joint. Lengths in m, angles in rad.
"""
import math
import numbers


class TiltCollapse:
	"""The result of :func:`stackTilt`.

	:ivar angle: tilt at collapse $\\theta_c$ [rad].
	:ivar multiplier: $\\lambda_c = \\tan\\theta_c$ [-].
	:ivar mechanism: ``'overturning'`` (the part above a bed joint turns about its downhill edge) or ``'sliding'`` (it
	    slides on the joint).
	:ivar joint: index of the bed joint where the mechanism forms (0: on the base).
	:ivar overturning: per bed joint, the multiplier $t/(H - z_k)$ at which the part above it overturns [-]."""

	def __init__(self, angle, multiplier, mechanism, joint, overturning):
		self.angle, self.multiplier, self.mechanism, self.joint, self.overturning = angle, multiplier, mechanism, joint, overturning

	def __repr__(self):
		return 'TiltCollapse(%s at joint %d: tilt %.6g rad = %.4f deg, multiplier %.6g)' % (self.mechanism, self.joint, self.angle, math.degrees(self.angle),
		                                                                                   self.multiplier)


def _positive(name, value):
	if isinstance(value, bool) or not isinstance(value, numbers.Real) or not (math.isfinite(value) and value > 0):
		raise ValueError('%s = %r: must be a finite number > 0' % (name, value))
	return float(value)


def stackTilt(thickness, height, joints, friction):
	"""Tilt at which a free-standing wall of courses that each span its whole thickness (one wythe, any bond along its
	length, dry joints) collapses out of its plane on a tilting base.

	Statics of the part above bed joint $k$ at height $z_k$: a prism $H - z_k$ tall and $t$ thick of uniform density,
	its weight acting at its mid-height $(H - z_k)/2$ above the joint and turned by $\\theta$. Its resultant leaves the
	joint through the downhill edge, and the part overturns, when $\\tan\\theta\\,(H - z_k)/2 = t/2$ (Housner 1963's
	$\\tan\\alpha = b/h$ for that part); it slides when $\\tan\\theta = \\mu$. Below both, the thrust line (Heyman 1966)
	lies inside every joint with $|T|/N = \\tan\\theta \\le \\mu$: a statically admissible state, so no collapse (lower
	bound); at the smaller of the two a mechanism forms with no sliding (if it overturns) or no rotation (if it slides),
	so the two bounds meet and the value is exact even with non-associative friction. The lowest overturning multiplier
	is the base joint's, $t/H$:

	.. math:: \\tan\\theta_c = \\min(t/H, \\mu)

	:param thickness: $t$ [m].
	:param height: $H$, from the base joint to the top of the wall [m].
	:param joints: heights $z_k$ of the bed joints above the base, the base joint (0) included [m], each in $[0, H)$.
	:param friction: Coulomb coefficient $\\mu$ of the joints (and of the base) [-].
	:return: a :class:`TiltCollapse`; ValueError naming the argument if one is out of range."""
	t, H, mu = _positive('thickness', thickness), _positive('height', height), _positive('friction', friction)
	try:
		zs = [float(z) for z in joints]
	except (TypeError, ValueError):
		raise ValueError('joints = %r: must be a sequence of heights [m]' % (joints, )) from None
	if not zs or not all(math.isfinite(z) and 0 <= z < H for z in zs):
		raise ValueError('joints = %r: must be one or more heights in [0, height = %g) [m]' % (joints, H))
	overturning = [t / (H - z) for z in zs]
	k = min(range(len(zs)), key=lambda i: overturning[i])
	if overturning[k] <= mu:
		return TiltCollapse(math.atan(overturning[k]), overturning[k], 'overturning', k, overturning)
	return TiltCollapse(math.atan(mu), mu, 'sliding', min(range(len(zs)), key=lambda i: zs[i]), overturning)
