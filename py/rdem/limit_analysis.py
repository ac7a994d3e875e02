"""Rigid-block limit analysis (Heyman 1966: rigid blocks, joints without tension, unlimited compressive strength): the
tilt at which a dry-stacked wall collapses on a tilting base (:func:`stackTilt`, de Felice 2011's tilting-table test) and
the minimum thickness of a semicircular arch of voussoirs (:func:`archMinimumThickness`). Pure Python (standard library only, no YADE), tested in tests/python/test_limit_analysis.py.

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


class ArchLimit:
	"""The result of :func:`archMinimumThickness`.

	:ivar ratio: $t_{min}/R$ [-].
	:ivar thrust: horizontal thrust $H$ at $t_{min}$ over the arch's weight $W$ [-].
	:ivar crownHeight: height $z_0$ of the thrust line at the crown (the symmetry plane) over $R$ [-].
	:ivar hinges: the joints where the thrust line touches the intrados or extrados at $t_{min}$, ``[(k, 'intrados' or
	    'extrados')]``, $k$ counted from the left springing (0) to the right one ($N$), both halves.
	:ivar joints: per joint of the right half from the crown, ``(k, angle from the crown [rad], r/R of the thrust line's
	    point on the joint)``.
	:ivar friction: the largest $|T|/N$ of the resultant over the joints at $t_{min}$ (the friction coefficient the arch needs
	    to collapse by hinging only) [-]."""

	def __init__(self, ratio, thrust, crownHeight, hinges, joints, friction):
		self.ratio, self.thrust, self.crownHeight, self.hinges, self.joints, self.friction = ratio, thrust, crownHeight, hinges, joints, friction

	def __repr__(self):
		return 'ArchLimit(t/R = %.6f, H/W = %.4f, hinges %s, friction %.3f)' % (self.ratio, self.thrust, self.hinges, self.friction)


def _archJoints(N):
	"""A function of t giving, for the right half's joints from the crown (the crown joint, phi = 0, first if N is even),
	(phi, W, X): angle from the crown, weight (area, unit weight per area) and horizontal centroid of the part between the
	crown's symmetry plane and the joint; R = 1."""
	delta = math.pi / N
	phis = [k * delta for k in range(N // 2 + 1)] if N % 2 == 0 else [(k + 0.5) * delta for k in range(N // 2 + 1)]

	def table(t):
		ri, re = 1 - t / 2, 1 + t / 2
		out = []
		for phi in phis:
			W = phi * (re * re - ri * ri) / 2  # annular sector from the crown to phi
			if phi == 0:
				out.append((phi, 0.0, 0.0))
				continue
			rho = (2.0 / 3.0) * (re**3 - ri**3) / (re * re - ri * ri)
			out.append((phi, W, rho * math.sin(phi / 2) / (phi / 2) * math.sin(phi / 2)))
		return out

	return table


def _archSlack(t, table):
	"""max over H >= 0 of g(H) = min_j upper_j(H) - max_j lower_j(H) (the room for p = H z0; concave in H), and its argmax.
	Constraint of joint j (thrust line point r on the joint at angle phi from the crown, R = 1):
	(1 - t/2)(H cos phi + W sin phi) <= p + W X <= (1 + t/2)(H cos phi + W sin phi)."""
	rows = table(t)
	ri, re = 1 - t / 2, 1 + t / 2

	def g(H):
		lo = max(ri * (H * math.cos(phi) + W * math.sin(phi)) - W * X for phi, W, X in rows)
		hi = min(re * (H * math.cos(phi) + W * math.sin(phi)) - W * X for phi, W, X in rows)
		return hi - lo, lo

	Wt = rows[-1][1]
	a, b = 0.0, 2.0 * Wt  # the thrust of a semicircular arch is well below its half weight
	for _ in range(200):  # golden-section search of the concave g
		c, d = b - 0.6180339887498949 * (b - a), a + 0.6180339887498949 * (b - a)
		if g(c)[0] < g(d)[0]:
			a = c
		else:
			b = d
		if b - a < 1e-15 * Wt:
			break
	H = (a + b) / 2
	slack, p = g(H)
	return slack, H, p, rows


def archMinimumThickness(voussoirs, tolerance=1e-10):
	"""Minimum thickness of a semicircular arch of $N$ equal voussoirs with radial joints under its own weight: the
	smallest $t/R$ for which a thrust line lies inside the section at every joint (Heyman 1966's safe theorem; no tension,
	infinite compressive strength, no sliding).

	By symmetry the thrust line can be taken symmetric (the mirror image of an admissible line is admissible and the set
	is convex), horizontal at the crown's symmetry plane with thrust $H$ at height $z_0$ above the centre. Moments about
	the point at radius $r$ on the joint at angle $\\phi$ from the crown, of $H$ and of the weight $W(\\phi)$ between the
	crown and the joint (centroid at $x = X(\\phi)$ from the vertical axis) give

	.. math:: r(\\phi) = \\frac{H z_0 + W X}{H\\cos\\phi + W\\sin\\phi},\\qquad W = \\phi R t\\rho_w,\\quad
	          X = \\bar r\\,\\frac{\\sin^2(\\phi/2)}{\\phi/2},\\quad \\bar r = \\frac{2}{3}\\frac{R_e^3 - R_i^3}{R_e^2 - R_i^2}

	(annular sector, $R_{i,e} = R \\mp t/2$; $\\rho_w$ weight per unit area). With $p = H z_0$ the conditions
	$R_i \\le r \\le R_e$ are linear in $(H, p)$: for each $H$ they bound $p$ to an interval, whose length $g(H)$ is
	concave; the arch is safe iff $\\max_H g \\ge 0$ (found by golden-section search), and $t_{min}$ is found by bisection.
	At $t_{min}$ the thrust line touches the section at the hinges of the collapse mechanism: for $N$ even the crown's
	extrados, the haunches' intrados and the springings' extrados (five hinges). For $N$ odd the crown is a voussoir
	(the keystone), the symmetry plane is not a joint.

	As $N\\to\\infty$, $t_{min}/R \\to 0.1075$ with the rupture joints at 54.5° from the crown (Milankovitch 1907; the
	continuous arch); Heyman 1982's simplified calculation gives 0.106. For finite $N$ the value depends on how close a
	joint comes to 54.5° (:ref:`arches <rdem-arches>`, §1). Units: lengths over $R$; angles in rad.

	:param voussoirs: $N \\ge 2$.
	:param tolerance: on $t/R$.
	:return: an :class:`ArchLimit`."""
	if isinstance(voussoirs, bool) or not isinstance(voussoirs, numbers.Integral) or voussoirs < 2:
		raise ValueError('voussoirs = %r: must be an integer >= 2' % (voussoirs, ))
	_positive('tolerance', tolerance)
	N = int(voussoirs)
	table = _archJoints(N)
	lo, hi = 0.0, 1.0
	while hi - lo > tolerance:
		mid = (lo + hi) / 2
		if _archSlack(mid, table)[0] >= 0:
			hi = mid
		else:
			lo = mid
	t = hi
	slack, H, p, rows = _archSlack(t, table)
	ri, re = 1 - t / 2, 1 + t / 2
	joints, hinges, friction = [], [], 0.0
	for j, (phi, W, X) in enumerate(rows):
		n = H * math.cos(phi) + W * math.sin(phi)
		r = (p + W * X) / n
		k = N // 2 + j if N % 2 == 0 else (N + 1) // 2 + j  # joint index from the left springing
		joints.append((k, phi, r))
		friction = max(friction, abs(H * math.sin(phi) - W * math.cos(phi)) / n)
		for side, bound in (('intrados', ri), ('extrados', re)):
			if abs(r - bound) < 1e-5 * t:
				hinges += [(k, side)] + ([(N - k, side)] if N - k != k else [])
	W = rows[-1][1] * 2
	return ArchLimit(t, H / W, p / H if H > 0 else float('nan'), sorted(hinges), joints, friction)


class OneWayWall:
	"""Rigid-body force against displacement of a wall spanning one way between a base and a top support, pushed out of its
	plane by a horizontal load at two heights symmetric about mid-height (the mechanism of Doherty, Griffith, Lam & Wilson
	2002: two rigid halves and three hinges). Lengths in m, forces in N, angles in rad.

	The wall ($h$ tall, $t$ thick, weight $W$) stands on a base and is held horizontally at its top, where an overburden $O$
	bears (a slab that stays horizontal and moves vertically). Pushed towards $+y$ (its face at $y = 0$ is the loaded one)
	it cracks at the base, at mid-height and at the top: the lower half turns by $\\theta$ about its base edge on the far
	face ($y = t$), the upper half, the lower's mirror image about the mid-height hinge, by $\\theta$ about its top edge on
	the far face, and the halves hinge on the loaded face at mid-height, at $B = (t(1 - \\cos\\theta) + \\tfrac h2\\sin\\theta,\\;
	t\\sin\\theta + \\tfrac h2\\cos\\theta)$ in $(y, z)$ from the base edge on the loaded face. The halves' weights rise with
	$B_z$ and the overburden with the top, at $2B_z$: the potential energy is $V = (W + 2O)\\,B_z$. The load $F$ (total)
	acts on the wall's middle plane ($y = t/2$) at height $z_p$ above the base on the lower half and at $h - z_p$ on the upper
	half: its points move by $y_p = t - \\tfrac t2\\cos\\theta + z_p\\sin\\theta$. Virtual work, $F\\,dy_p = dV$, gives the exact
	(large-rotation) rigid relation

	.. math:: F(\\theta) = (W + 2O)\\,\\frac{t\\cos\\theta - \\tfrac h2\\sin\\theta}{\\tfrac t2\\sin\\theta + z_p\\cos\\theta},
	          \\qquad \\Delta(\\theta) = t(1 - \\cos\\theta) + \\tfrac h2\\sin\\theta

	($\\Delta$: the mid-height displacement of the loaded face, the hinge). At $\\theta = 0$, $F_0 = (W + 2O)\\,t/z_p$
	($2(W + 2O)t/h$ at mid-height); $F = 0$ at $\\tan\\theta_u = 2t/h$, where $\\Delta_u = t$: the instability
	displacement is the wall's thickness. For small rotations $F \\approx F_0(1 - \\Delta/t)$ for $z_p = h/2$, the linear
	rigid relation Doherty et al. 2002 use.

	:param height: $h$ [m] > 0.
	:param thickness: $t$ [m], $0 < t < h$.
	:param weight: $W$ [N] > 0.
	:param overburden: $O$ [N] >= 0.
	:param loadHeight: $z_p$ [m], in $(0, h/2]$ (default $h/2$)."""

	def __init__(self, height, thickness, weight, overburden=0.0, loadHeight=None):
		self.h = _positive('height', height)
		self.t = _positive('thickness', thickness)
		if not self.t < self.h:
			raise ValueError('thickness = %r: must be < height = %g [m]' % (thickness, self.h))
		self.W = _positive('weight', weight)
		if isinstance(overburden, bool) or not isinstance(overburden, numbers.Real) or not (math.isfinite(overburden) and overburden >= 0):
			raise ValueError('overburden = %r: must be a finite number >= 0 [N]' % (overburden, ))
		self.O = float(overburden)
		self.zp = self.h / 2 if loadHeight is None else _positive('loadHeight', loadHeight)
		if not self.zp <= self.h / 2:
			raise ValueError('loadHeight = %r: must be in (0, height/2 = %g] [m]' % (loadHeight, self.h / 2))
		self.thetaU = math.atan(2 * self.t / self.h)

	def force(self, theta):
		"""$F(\\theta)$ [N]."""
		t, h = self.t, self.h
		return (self.W + 2 * self.O) * (t * math.cos(theta) - h / 2 * math.sin(theta)) / (t / 2 * math.sin(theta) + self.zp * math.cos(theta))

	def displacement(self, theta):
		"""$\\Delta(\\theta)$ [m], the mid-height displacement of the loaded face."""
		return self.t * (1 - math.cos(theta)) + self.h / 2 * math.sin(theta)

	def loadDisplacement(self, theta):
		"""$y_p(\\theta) - t/2$ [m], the displacement of the load's points."""
		return self.t / 2 * (1 - math.cos(theta)) + self.zp * math.sin(theta)

	def rotation(self, displacement):
		"""$\\theta$ for a mid-height displacement $\\Delta$ in $[0, \\Delta(\\pi/2)]$ (bisection)."""
		lo, hi = 0.0, math.pi / 2
		for _ in range(100):
			mid = (lo + hi) / 2
			if self.displacement(mid) < displacement:
				lo = mid
			else:
				hi = mid
		return (lo + hi) / 2

	def forceAt(self, displacement):
		"""$F$ [N] at mid-height displacement $\\Delta$ [m]."""
		return self.force(self.rotation(displacement))

	@property
	def initialForce(self):
		"""$F_0 = (W + 2O)\\,t/z_p$ [N]."""
		return (self.W + 2 * self.O) * self.t / self.zp

	@property
	def instabilityDisplacement(self):
		"""$\\Delta_u = \\Delta(\\theta_u) = t$ [m]."""
		return self.displacement(self.thetaU)


def archTiltMultiplier(voussoirs, ratio):
	"""Collapse multiplier $\\lambda_c$ of a semicircular arch of $N$ equal voussoirs with radial joints and thickness
	``ratio`` $= t/R$ on fixed abutments, under its weight and a horizontal body force $\\lambda$ times it towards $-x$ (a
	tilt of the base by $\\arctan\\lambda$, or a quasi-static horizontal ground acceleration $\\lambda g$): the least
	multiplier over the four-hinge mechanisms with hinges on the joints (kinematic theorem, Heyman 1966; no sliding).

	A mechanism has hinges at joints $h_1 < h_2 < h_3 < h_4$ ($0..N$ from the left springing), each on the intrados or the
	extrados; the voussoirs between $h_1$ and $h_2$ turn about hinge 1, those between $h_3$ and $h_4$ about hinge 4, those
	between $h_2$ and $h_3$ about the intersection of the lines through hinges 1–2 and 4–3. It is admissible if every hinge
	opens its joint on the other side (an intrados hinge opens the extrados). Its multiplier makes the virtual power of
	the loads vanish, $\\lambda = -\\sum m v_z / \\sum m v_x$ over the voussoirs' centroids, with the motion that the
	horizontal load drives ($-\\sum m v_x > 0$). Lengths over $R$.

	:param voussoirs: $N \\ge 3$.
	:param ratio: $t/R$ in $(0, 1)$.
	:return: ``(multiplier, hinges)``, hinges ``[(joint, 'intrados' or 'extrados')]``; the multiplier is negative if the
	    arch cannot stand under its weight alone ($t$ below $t_{min}$)."""
	if isinstance(voussoirs, bool) or not isinstance(voussoirs, numbers.Integral) or voussoirs < 3:
		raise ValueError('voussoirs = %r: must be an integer >= 3' % (voussoirs, ))
	t = _positive('ratio', ratio)
	if not t < 1:
		raise ValueError('ratio = %r: must be < 1' % (ratio, ))
	N = int(voussoirs)
	delta = math.pi / N
	ri, re = 1 - t / 2, 1 + t / 2
	rbar = (2.0 / 3.0) * (re**3 - ri**3) / (re * re - ri * ri) * math.sin(delta / 2) / (delta / 2)
	G = [(rbar * math.cos(math.pi - (k + 0.5) * delta), rbar * math.sin(math.pi - (k + 0.5) * delta)) for k in range(N)]

	def point(k, side):
		r = ri if side == 'intrados' else re
		a = math.pi - k * delta
		return (r * math.cos(a), r * math.sin(a))

	def velocity(centre, omega, p):
		return (-omega * (p[1] - centre[1]), omega * (p[0] - centre[0]))

	best = (float('inf'), None)
	sides = ('intrados', 'extrados')
	for h1 in range(N + 1):
		for h2 in range(h1 + 1, N + 1):
			for h3 in range(h2 + 1, N + 1):
				for h4 in range(h3 + 1, N + 1):
					for s in ((0, 1, 0, 1), (1, 0, 1, 0)):
						hs = [(h1, sides[s[0]]), (h2, sides[s[1]]), (h3, sides[s[2]]), (h4, sides[s[3]])]
						P = [point(k, side) for k, side in hs]
						# instantaneous centre of the middle body: lines P1P2 and P4P3
						d1, d2 = (P[1][0] - P[0][0], P[1][1] - P[0][1]), (P[2][0] - P[3][0], P[2][1] - P[3][1])
						den = d1[0] * d2[1] - d1[1] * d2[0]
						if abs(den) < 1e-14:
							continue
						u = ((P[3][0] - P[0][0]) * d2[1] - (P[3][1] - P[0][1]) * d2[0]) / den
						I = (P[0][0] + u * d1[0], P[0][1] + u * d1[1])
						wa = 1.0
						# same velocity of hinge 2 on bodies a and b, of hinge 3 on bodies b and c (collinear centres)
						k2 = 0 if abs(P[1][0] - I[0]) > abs(P[1][1] - I[1]) else 1
						wb = wa * (P[1][k2] - P[0][k2]) / (P[1][k2] - I[k2])
						k3 = 0 if abs(P[2][0] - P[3][0]) > abs(P[2][1] - P[3][1]) else 1
						wc = wb * (P[2][k3] - I[k3]) / (P[2][k3] - P[3][k3])
						rel = [wa - 0.0, wb - wa, wc - wb, 0.0 - wc]  # right minus left at each hinge
						sx = sz = 0.0
						for k in range(h1, h4):
							centre, w = (P[0], wa) if k < h2 else ((I, wb) if k < h3 else (P[3], wc))
							v = velocity(centre, w, G[k])
							sx, sz = sx + v[0], sz + v[1]
						if sx > 0:  # the motion the load (towards -x) drives: -sum v_x > 0
							rel, sx, sz = [-r for r in rel], -sx, -sz
						if sx == 0:
							continue
						# admissible: an intrados hinge needs a negative relative rotation, an extrados hinge a positive one
						if not all((r < 0) if side == 'intrados' else (r > 0) for r, (_, side) in zip(rel, hs)):
							continue
						lam = -sz / sx
						if lam < best[0]:
							best = (lam, hs)
	return best
