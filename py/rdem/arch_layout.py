"""Arch and barrel-vault layouts: voussoirs as pairs of boxes whose outer faces are the exact joint faces.

Pure Python (standard library only, no YADE), tested in tests/python/test_arch_layout.py; :func:`rdem.masonry.arch` turns a
layout into a scene (one clump of :yref:`RdemBlock` per voussoir).

Coordinates in m: $x$ along the span, $y$ along the depth (the vault's length), $z$ up; the centreline of the arch springs at
$x = \\pm s/2$, $z = z_s$ (0 on abutments, the pier height on piers). Shapes (centreline, radius $R$):

* ``'semicircular'``: one arc, centre $(0, z_s)$, $R = s/2$;
* ``'segmental'``: one arc of rise $f < s/2$: $R = (s^2/4 + f^2)/(2f)$, centre $(0, z_s + f - R)$, springing joints inclined
  (skewbacks);
* ``'pointed'``: two arcs meeting at the crown, each centred on the other half's side at $(\\pm e, z_s)$, $e = \\beta s/2$
  (``pointedness`` $\\beta$; 1: the equilateral arch, radius $s$), $R = s/2 + e$; the crown joint (if any) is vertical.

Joints are normal to the centreline (radial planes of each arc), the thickness $t$ measured along them; a ring of $N$
voussoirs has its joints at equal arc length $u_k = k/N$ of the centreline.

*Representation of a wedge by boxes.* Blocks of this plugin are boxes (:yref:`RdemBlock`), a voussoir is a wedge whose two
joint faces are not parallel. Each voussoir is therefore a rigid clump of three boxes (members of one clump do not
interact):

* face box $a$ has one face exactly on joint face $a$ (the rectangle $t\times$ depth between the joint's intrados and
  extrados points) and extends half the chord between the two joint faces' midpoints along that face's normal into the
  voussoir; face box $b$ likewise from joint $b$;
* a core box, a quarter of the thickness thick, along that chord, carries the rest of the mass: with a share $\eta$ of
  the voussoir's mass $m$ on each face box (centres $\mathbf{c}_a, \mathbf{c}_b$), its centre is
  $\mathbf{c} + \eta(2\mathbf{c} - \mathbf{c}_a - \mathbf{c}_b)/(1 - 2\eta)$ ($\mathbf{c}$: the wedge's centroid), so that the
  clump's mass and centroid are the wedge's; $\eta = 1/4$, smaller if the core would lie more than $t/4$ from
  $\mathbf{c}$ (voussoirs of more than about 50°);
* once clumped, the clump's rotational inertia about the depth axis is set to the wedge's (:attr:`Unit.polar`).

Hence:

* the joint geometry is exact: every joint's four vertices (where hinges form with vertex contacts) and its plane are
  those of the wedge, so the statics of dry joints (thrust line, hinges, friction) are the voussoir arch's;
* the weight and its line of action, and the in-plane rotational inertia, are exact;
* the outline is not: the intrados and extrados of the face boxes are flat and their far corners reach beyond the
  extrados by up to :attr:`ArchLayout.protrusion` (about $R\,\Delta^2/8$ for voussoirs of angle $\Delta$: 1.5 % of $R$
  for $N = 9$ on a semicircle; at the sharp crown of a pointed arch more, 7 % of $R$ for $N = 8$), which matters only for
  contacts other than the joints (fill, debris, the pieces of a collapsed arch) and for pictures; the out-of-plane
  inertias are the clumped boxes' (approximate).
"""
import math
import numbers

SHAPES = ('semicircular', 'segmental', 'pointed')
SUPPORTS = ('abutments', 'piers')
JOINTS = ('dry', 'mortar')
PAIR_KINDS = ('voussoir', 'springing', 'pier', 'foundation', 'ring')


def _positive(name, value, unit='[m]'):
	if isinstance(value, bool) or not isinstance(value, numbers.Real) or not (math.isfinite(value) and value > 0):
		raise ValueError('%s = %r: must be a finite number > 0 %s' % (name, value, unit))
	return float(value)


def _count(name, value, least):
	if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < least:
		raise ValueError('%s = %r: must be an integer >= %d' % (name, value, least))
	return int(value)


def _choice(name, value, allowed):
	if value not in allowed:
		raise ValueError('%s = %r: must be one of %s' % (name, value, ', '.join(repr(a) for a in allowed)))
	return value


class Centreline:
	"""The centreline of an arch as one or two circular arcs, parametrised by the fraction $u\\in[0, 1]$ of its length from the
	left springing (x < 0) to the right one. Lengths in m, angles in rad (from $+x$, counter-clockwise in the $x$-$z$ plane)."""

	def __init__(self, shape, span, thickness, rise=None, pointedness=1.0, springing=0.0):
		self.shape, self.span, self.t, self.zs = shape, span, thickness, springing
		s = span
		if shape == 'semicircular':
			self.arcs = [((0.0, springing), s / 2, math.pi, 0.0)]  # (centre, radius, angle at u = 0, angle at u = 1)
		elif shape == 'segmental':
			f = rise
			R = (s * s / 4 + f * f) / (2 * f)
			phi = math.asin(s / 2 / R)  # half the arc's angle
			self.arcs = [((0.0, springing + f - R), R, math.pi / 2 + phi, math.pi / 2 - phi)]
		else:
			e = pointedness * s / 2
			R = s / 2 + e
			crown = math.acos(-e / R)  # angle of the crown seen from the right-hand centre (e, zs), in (pi/2, pi)
			self.arcs = [((e, springing), R, math.pi, crown), ((-e, springing), R, math.pi - crown, 0.0)]
		self.radius = self.arcs[0][1]

	def _where(self, u):
		"""(arc, angle) of the point at fraction u; at the crown of a pointed arch (u = 1/2): (None, None)."""
		if len(self.arcs) == 1:
			c, R, a0, a1 = self.arcs[0]
			return self.arcs[0], a0 + u * (a1 - a0)
		if abs(u - 0.5) < 1e-12:
			return None, None
		arc = self.arcs[0] if u < 0.5 else self.arcs[1]
		c, R, a0, a1 = arc
		v = 2 * u if u < 0.5 else 2 * u - 1
		return arc, a0 + v * (a1 - a0)

	def joint(self, u):
		"""The joint face at fraction u: (intrados point, extrados point), each (x, z) [m]."""
		arc, ang = self._where(u)
		t = self.t
		if arc is None:  # the crown of a pointed arch: vertical joint on x = 0
			c, R = self.arcs[0][0], self.arcs[0][1]
			zi = c[1] + math.sqrt((R - t / 2)**2 - c[0]**2)
			ze = c[1] + math.sqrt((R + t / 2)**2 - c[0]**2)
			return (0.0, zi), (0.0, ze)
		(cx, cz), R = arc[0], arc[1]
		d = (math.cos(ang), math.sin(ang))
		return (cx + (R - t / 2) * d[0], cz + (R - t / 2) * d[1]), (cx + (R + t / 2) * d[0], cz + (R + t / 2) * d[1])

	def pieces(self, u0, u1):
		"""The arcs of the centreline between fractions u0 < u1: [(arc, angle at u0, angle at u1)]."""
		if len(self.arcs) == 1:
			return [(self.arcs[0], self._where(u0)[1], self._where(u1)[1])]
		out = []
		for k, (lo, hi) in enumerate(((0.0, 0.5), (0.5, 1.0))):
			a, b = max(u0, lo), min(u1, hi)
			if b - a > 1e-14:
				arc = self.arcs[k]
				ang = lambda u: arc[2] + ((u - lo) / 0.5) * (arc[3] - arc[2])
				out.append((arc, ang(a), ang(b)))
		return out


def _section(line, u0, u1, samples=256):
	"""Area [m²], centroid (x, z) [m] and polar second moment about the centroid [m⁴] of the voussoir between the joints at
	u0 and u1, by Green's theorem along its outline (arcs sampled by Simpson's rule with ``samples`` intervals per arc,
	relative error below 1e-10; the joint faces are straight, integrated exactly)."""
	# Outline, counter-clockwise: along the intrados from u1 to u0 would be clockwise; build the closed polygon path as
	# [extrados u0 -> u1], [joint u1 down], [intrados u1 -> u0], [joint u0 up] and take the absolute area.
	pieces = line.pieces(u0, u1)
	t = line.t

	def arcIntegrals(c, r, a0, a1):
		# integrals along the arc p(a) = c + r(cos a, sin a) of x dz - z dx, x^2 dz, z^2 dx, x^3 dz, z^3 dx
		n = samples
		h = (a1 - a0) / n
		acc = [0.0] * 5
		for k in range(n + 1):
			a = a0 + k * h
			w = (1 if k in (0, n) else (4 if k % 2 else 2)) * h / 3
			x, z = c[0] + r * math.cos(a), c[1] + r * math.sin(a)
			dx, dz = -r * math.sin(a), r * math.cos(a)
			for i, v in enumerate((x * dz - z * dx, x * x * dz, z * z * dx, x**3 * dz, z**3 * dx)):
				acc[i] += w * v
		return acc

	def segIntegrals(p, q):
		# exact for polynomials of degree <= 3 along a segment: 2-point Gauss-Legendre
		acc = [0.0] * 5
		dx, dz = q[0] - p[0], q[1] - p[1]
		for s in (0.5 - 0.5 / math.sqrt(3), 0.5 + 0.5 / math.sqrt(3)):
			x, z = p[0] + s * dx, p[1] + s * dz
			for i, v in enumerate((x * dz - z * dx, x * x * dz, z * z * dx, x**3 * dz, z**3 * dx)):
				acc[i] += 0.5 * v
		return acc

	total = [0.0] * 5

	def add(v):
		for i in range(5):
			total[i] += v[i]

	def ends(c, r, a0, a1):
		# at the crown of a pointed arch the intrados and extrados reach x = 0 at angles of their own
		crown = lambda: math.acos(-c[0] / r)
		return (crown() if len(line.arcs) == 2 and abs(u0 - 0.5) < 1e-12 else a0, crown() if len(line.arcs) == 2 and abs(u1 - 0.5) < 1e-12 else a1)

	for (c, R, _, _), a0, a1 in pieces:  # extrados, u0 -> u1
		add(arcIntegrals(c, R + t / 2, *ends(c, R + t / 2, a0, a1)))
	i1, e1 = line.joint(u1)
	add(segIntegrals(e1, i1))
	for (c, R, _, _), a0, a1 in reversed(pieces):  # intrados, u1 -> u0
		b0, b1 = ends(c, R - t / 2, a0, a1)
		add(arcIntegrals(c, R - t / 2, b1, b0))
	i0, e0 = line.joint(u0)
	add(segIntegrals(i0, e0))
	A = total[0] / 2
	sx, sz = total[1] / 2, -total[2] / 2  # integrals of x and z over the area
	Ixx, Izz = total[3] / 3, -total[4] / 3  # integrals of x^2 and z^2
	if A < 0:
		A, sx, sz, Ixx, Izz = -A, -sx, -sz, -Ixx, -Izz
	cx, cz = sx / A, sz / A
	J = Ixx - A * cx * cx + Izz - A * cz * cz
	return A, (cx, cz), J


class Block:
	"""One box of an :class:`ArchLayout`.

	:ivar centre: (x, y, z) [m].
	:ivar half: half-extents along the box's own axes (a, b, c) [m]; own $y$ is the global $y$.
	:ivar angle: rotation about $+y$ from the global axes to the box's [rad] (``Quaternion((0, 1, 0), angle)``); its own $x$
	    axis is $(\\cos\\psi, 0, -\\sin\\psi)$.
	:ivar mass: mass per unit density [m³] (the mass is ``density * mass``); for a voussoir's box, the share of the
	    voussoir's mass it carries, not its own volume.
	:ivar inertia: principal inertias about its own axes per unit density [m⁵].
	:ivar unit: index into :attr:`ArchLayout.units`."""
	__slots__ = ('centre', 'half', 'angle', 'mass', 'inertia', 'unit')

	def __init__(self, centre, half, angle, mass, inertia, unit):
		self.centre, self.half, self.angle, self.mass, self.inertia, self.unit = centre, half, angle, mass, inertia, unit

	def axes(self):
		"""Own x and z axes in the global x-z plane: ((x_x, x_z), (z_x, z_z))."""
		c, s = math.cos(self.angle), math.sin(self.angle)
		return (c, -s), (s, c)

	def corners(self):
		"""The four corners of the box in the x-z plane [(x, z)] (its section; it spans y ± half[1])."""
		(ax, az), (bx, bz) = self.axes()
		a, c = self.half[0], self.half[2]
		return [(self.centre[0] + i * a * ax + j * c * bx, self.centre[2] + i * a * az + j * c * bz) for i in (-1, 1) for j in (-1, 1)]


class Unit:
	"""A voussoir, abutment, pier course or foundation of an :class:`ArchLayout`.

	:ivar kind: ``'voussoir'``, ``'abutment'`` (fixed), ``'pier'`` (a course of a pier) or ``'foundation'`` (fixed).
	:ivar ring: ring of a vault (0 for an arch and for supports).
	:ivar index: voussoir index from the left springing in its ring; pier course from the bottom; 0 left / 1 right support.
	:ivar side: for supports, ``'left'`` or ``'right'``; ``None`` for voussoirs.
	:ivar joints: for voussoirs, the centreline fractions (u0, u1) of their two joints.
	:ivar area: section area in the x-z plane [m²] (voussoirs: exact).
	:ivar centroid: (x, y, z) [m] (voussoirs: exact).
	:ivar polar: in-plane second moment of the section about the centroid, $\\int r^2\\,dA$ [m⁴].
	:ivar blocks: indices into :attr:`ArchLayout.blocks` (two per voussoir, clumped)."""
	__slots__ = ('kind', 'ring', 'index', 'side', 'joints', 'area', 'centroid', 'polar', 'blocks')

	def __init__(self, kind, ring, index, side=None, joints=None, area=0.0, centroid=None, polar=0.0):
		self.kind, self.ring, self.index, self.side, self.joints = kind, ring, index, side, joints
		self.area, self.centroid, self.polar, self.blocks = area, centroid, polar, []


class ArchLayout:
	"""The blocks of an arch or vault (:func:`archLayout`).

	:ivar blocks: :class:`Block` list.
	:ivar units: :class:`Unit` list; ``voussoirs(ring)`` those of one ring, left to right.
	:ivar pairs: touching block pairs ``(i, j, kind)``, kind in ``'voussoir'`` (a joint between two voussoirs, exact common
	    face), ``'springing'`` (voussoir on its abutment or pier), ``'pier'`` (between pier courses), ``'foundation'`` (pier on
	    its foundation), ``'ring'`` (voussoirs of neighbouring rings of a vault, facing each other across the ring gap on
	    a plane $y$ = const; their faces are not aligned, so these joints are always dry).
	:ivar jointFaces: per ring, the joint faces of its voussoirs from the left springing: [(intrados (x, z), extrados (x, z))].
	:ivar radius: centreline radius $R$ [m] (each arc's, for a pointed arch).
	:ivar protrusion: largest distance by which a voussoir box's corner lies outside the exact outline of the arch (beyond
	    its extrados) [m]."""

	def __init__(self, **params):
		self.params = params
		self.blocks, self.units, self.pairs, self.jointFaces = [], [], [], []
		self.radius, self.protrusion, self.rings = 0.0, 0.0, 0

	def voussoirs(self, ring=0):
		"""The voussoir units of one ring, from the left springing."""
		return [u for u in self.units if u.kind == 'voussoir' and u.ring == ring]

	def supports(self):
		"""The units that are not voussoirs."""
		return [u for u in self.units if u.kind != 'voussoir']

	def fixed(self):
		"""Block indices of the fixed units (abutments, foundations)."""
		return [b for u in self.units if u.kind in ('abutment', 'foundation') for b in u.blocks]

	def __repr__(self):
		return 'ArchLayout(%s, %d rings, %d voussoirs, %d blocks, %d pairs)' % (self.params['shape'], self.rings, len(
		        [u for u in self.units if u.kind == 'voussoir']), len(self.blocks), len(self.pairs))


def _sub(p, q):
	return (p[0] - q[0], p[1] - q[1])


def _unit(v):
	n = math.hypot(v[0], v[1])
	return (v[0] / n, v[1] / n)


def _boxInertia(mass, half):
	a, b, c = half
	return (mass * (b * b + c * c) / 3, mass * (a * a + c * c) / 3, mass * (a * a + b * b) / 3)


def archLayout(span,
               thickness,
               depth,
               voussoirs,
               shape='semicircular',
               rise=None,
               pointedness=1.0,
               supports='abutments',
               pierHeight=None,
               pierWidth=None,
               pierCourses=4,
               foundation=None,
               length=None,
               rings=1,
               stagger=True,
               ringGap=1e-3):
	"""Lay out an arch (``length=None``) or a barrel vault (an arch extruded along $y$ over ``length`` in ``rings`` rings,
	every other ring's joints shifted by half a voussoir with ``stagger``: its end voussoirs are half voussoirs).

	:param span: $s$, horizontal distance between the centreline's springing points [m].
	:param thickness: $t$, the ring thickness measured along the joints [m] (< the radius).
	:param depth: the arch's extent along $y$ [m] (for a vault: ignored, each ring is ``length/rings`` deep).
	:param voussoirs: $N$ per ring (a staggered ring has $N + 1$); >= 3 (the boxes of a voussoir of more than a right angle
	    would cross its far joint); for a pointed arch even (the crown joint is vertical).
	:param shape: ``'semicircular'``, ``'segmental'`` or ``'pointed'``.
	:param rise: $f$ of a segmental arch, $0 < f < s/2$ [m].
	:param pointedness: $\\beta > 0$ of a pointed arch (centres at $\\pm\\beta s/2$; 1: equilateral).
	:param ringGap: gap between neighbouring rings of a vault, relative to the ring depth (default 1e-3): the rings touch
	    only once they move towards each other. Rings that touch face to face from the start exchange forces along $y$ through
	    the contacts of voussoirs that touch both across a joint and across the ring plane (the contact normal of such a
	    pair is the axis of least overlap, $y$, while the joint between them is compressed): about 100 N per pair in a vault
	    of 8 voussoirs, $t/R = 0.15$, that stands either way. Each ring has abutments (or piers) of its own, as deep as the
	    ring, so that the rings are independent in their plane.
	:param supports: ``'abutments'``: a fixed block under each springing joint (inclined for a segmental arch), twice as
	    wide as the joint (centred on it); ``'piers'``
	    (semicircular and pointed arches): a pier of ``pierCourses`` courses, ``pierWidth`` wide, its inner face flush with
	    the intrados, ``pierHeight`` tall, on a fixed foundation ``foundation`` thick (default: the pier width).
	:return: an :class:`ArchLayout`; ValueError naming the argument if one is out of range."""
	s = _positive('span', span)
	t = _positive('thickness', thickness)
	_choice('shape', shape, SHAPES)
	_choice('supports', supports, SUPPORTS)
	N = _count('voussoirs', voussoirs, 3)
	if shape == 'pointed' and N % 2:
		raise ValueError('voussoirs = %d: a pointed arch needs an even number (its crown joint is vertical)' % N)
	if shape == 'segmental':
		if rise is None:
			raise ValueError('rise = None: a segmental arch needs its rise f, 0 < f < span/2 [m]')
		f = _positive('rise', rise)
		if not f < s / 2:
			raise ValueError('rise = %r: must be < span/2 = %g [m] (a semicircular arch has f = span/2)' % (rise, s / 2))
	elif rise is not None:
		raise ValueError("rise = %r: only for shape='segmental'" % (rise, ))
	beta = _positive('pointedness', pointedness, '[-]')
	if length is None:
		nRings = _count('rings', rings, 1)
		if nRings != 1:
			raise ValueError('rings = %r: an arch (length=None) has one ring; give length for a vault' % (rings, ))
		ringDepth = _positive('depth', depth)
	else:
		L = _positive('length', length)
		nRings = _count('rings', rings, 1)
		ringDepth = L / nRings
	if isinstance(ringGap, bool) or not isinstance(ringGap, numbers.Real) or not (0 <= ringGap < 0.5):
		raise ValueError('ringGap = %r: must be in [0, 0.5) (relative to the ring depth)' % (ringGap, ))
	gap = ringGap * ringDepth if nRings > 1 else 0.0
	zs = 0.0
	if supports == 'piers':
		if shape == 'segmental':
			raise ValueError("supports = 'piers': only for semicircular and pointed arches (horizontal springing joints); a segmental arch "
			                 "stands on its skewbacks: supports='abutments'")
		hp = _positive('pierHeight', pierHeight if pierHeight is not None else float('nan'))
		wp = _positive('pierWidth', pierWidth if pierWidth is not None else float('nan'))
		if not wp >= t:
			raise ValueError('pierWidth = %r: must be >= thickness = %g [m] (the springing joint rests on the pier)' % (pierWidth, t))
		nCourses = _count('pierCourses', pierCourses, 1)
		hf = _positive('foundation', foundation) if foundation is not None else wp
		zs = hp
	line = Centreline(shape, s, t, rise=rise if shape == 'segmental' else None, pointedness=beta, springing=zs)
	R = line.radius
	if not t < R:
		raise ValueError('thickness = %r: must be < the centreline radius %g [m]' % (thickness, R))
	lay = ArchLayout(span=s, thickness=t, depth=ringDepth * nRings, voussoirs=N, shape=shape, rise=rise, pointedness=beta, supports=supports,
	                 pierHeight=pierHeight, pierWidth=pierWidth, pierCourses=pierCourses, length=length, rings=nRings, stagger=stagger,
	                 ringGap=ringGap)
	lay.radius, lay.rings = R, nRings
	unitOfJointBlock = {}  # (ring, joint index, side 'a'|'b') -> block index
	for r in range(nRings):
		y0 = r * ringDepth
		yc = y0 + ringDepth / 2
		shifted = stagger and length is not None and r % 2 == 1
		us = [0.0] + [(k + 0.5) / N for k in range(N)] + [1.0] if shifted else [k / N for k in range(N + 1)]
		faces = [line.joint(u) for u in us]
		lay.jointFaces.append(faces)
		for k in range(len(us) - 1):
			A, (cx, cz), J = _section(line, us[k], us[k + 1])
			unit = Unit('voussoir', r, k, joints=(us[k], us[k + 1]), area=A, centroid=(cx, yc, cz), polar=J)
			m = A * ringDepth
			(ia, ea), (ib, eb) = faces[k], faces[k + 1]
			Ma, Mb = ((ia[0] + ea[0]) / 2, (ia[1] + ea[1]) / 2), ((ib[0] + eb[0]) / 2, (ib[1] + eb[1]) / 2)
			wa, wb = math.hypot(*_sub(ea, ia)), math.hypot(*_sub(eb, ib))
			fa, fb = _unit(_sub(ea, ia)), _unit(_sub(eb, ib))
			# normals into the voussoir: perpendicular to each face, pointing towards the other face's midpoint
			na, nb = (fa[1], -fa[0]), (fb[1], -fb[0])
			if na[0] * (Mb[0] - Ma[0]) + na[1] * (Mb[1] - Ma[1]) < 0:
				na = (-na[0], -na[1])
			if nb[0] * (Ma[0] - Mb[0]) + nb[1] * (Ma[1] - Mb[1]) < 0:
				nb = (-nb[0], -nb[1])
			# face boxes a and b: from each joint face half the chord between the faces' midpoints along the face's normal
			chord = math.hypot(*_sub(Mb, Ma))
			Lx = chord / 2
			ca = (Ma[0] + na[0] * Lx / 2, Ma[1] + na[1] * Lx / 2)
			cb = (Mb[0] + nb[0] * Lx / 2, Mb[1] + nb[1] * Lx / 2)
			# the core box c carries the rest of the mass, placed so that the clump's centroid is the voussoir's: with a share
			# eta of the mass on each face box, its centre is C + eta (2C - ca - cb)/(1 - 2 eta), kept within t/4 of C
			off = (2 * cx - ca[0] - cb[0], 2 * cz - ca[1] - cb[1])
			eta = 0.25
			if math.hypot(*off) > 0:
				g = min(eta / (1 - 2 * eta), 0.25 * t / math.hypot(*off))
				eta = g / (1 + 2 * g)
			cc = (cx + eta * off[0] / (1 - 2 * eta), cz + eta * off[1] / (1 - 2 * eta))
			u = _unit(_sub(Mb, Ma))  # the core lies along the chord, a quarter of the thickness thick
			boxes = []
			hy = ringDepth / 2 - gap / 2  # the boxes' half-depth: rings apart by the gap
			for centre, n, half, mass in ((ca, na, (Lx / 2, hy, wa / 2), eta * m), (cb, nb, (Lx / 2, hy, wb / 2), eta * m),
			                              (cc, u, (chord / 4, hy, t / 8), (1 - 2 * eta) * m)):
				boxes.append(Block((centre[0], yc, centre[1]), half, math.atan2(-n[1], n[0]), mass, list(_boxInertia(mass, half)), len(lay.units)))
			# the boxes must stay on their side of the voussoir's other joint (else they would touch the next voussoir)
			for b in boxes:
				for q in b.corners():
					if min((q[0] - P[0]) * n[0] + (q[1] - P[1]) * n[1] for P, n in ((ia, na), (ib, nb))) < -1e-9 * R:
						raise ValueError('voussoirs = %d: too few for this arch (a box of voussoir %d would cross the voussoir\'s other joint)' % (N, k))
			for b in boxes:
				for q in b.corners():  # distance beyond the extrados of the voussoir's arc(s)
					best = min(math.hypot(q[0] - c[0], q[1] - c[1]) - (Rarc + t / 2) for (c, Rarc, _, _), _, _ in line.pieces(*unit.joints))
					lay.protrusion = max(lay.protrusion, best)
			unit.blocks = [len(lay.blocks), len(lay.blocks) + 1, len(lay.blocks) + 2]
			unitOfJointBlock[(r, k, 'a')] = len(lay.blocks)
			unitOfJointBlock[(r, k + 1, 'b')] = len(lay.blocks) + 1
			lay.blocks += boxes
			lay.units.append(unit)
		for k in range(1, len(us) - 1):
			lay.pairs.append((unitOfJointBlock[(r, k, 'b')], unitOfJointBlock[(r, k, 'a')], 'voussoir'))
	# rings of a vault touch on the planes between them: pairs of boxes whose sections overlap
	if nRings > 1:
		for r in range(nRings - 1):
			lower = [i for u in lay.voussoirs(r) for i in u.blocks]
			upper = [i for u in lay.voussoirs(r + 1) for i in u.blocks]
			for i in lower:
				for j in upper:
					if _sectionsOverlap(lay.blocks[i], lay.blocks[j]):
						lay.pairs.append((i, j, 'ring'))
	_addSupports(lay, line, supports, ringDepth, nRings, zs, t, locals())
	return lay


def _sectionsOverlap(p, q):
	"""Whether the x-z sections (rectangles) of two blocks overlap with positive area (separating-axis test)."""
	P, Q = p.corners(), q.corners()
	for b in (p, q):
		for axis in b.axes():
			a = [x * axis[0] + z * axis[1] for x, z in P]
			c = [x * axis[0] + z * axis[1] for x, z in Q]
			if min(max(a), max(c)) - max(min(a), min(c)) <= 1e-9 * (max(a) - min(a)):
				return False
	return True


def _addSupports(lay, line, supports, ringDepth, nRings, zs, t, args):
	"""Abutments (one fixed box under each springing joint) or piers with foundations, one per ring of a vault (apart by
	the ring gap, as the rings); the springing pairs."""
	hy = ringDepth / 2 - args['gap'] / 2
	for side, ukey in (('left', 0), ('right', -1)):
		inner, outer = lay.jointFaces[0][ukey]
		for r in range(nRings):
			vs = lay.voussoirs(r)
			springing = vs[0].blocks[0] if side == 'left' else vs[-1].blocks[1]
			yc = (r + 0.5) * ringDepth
			if supports == 'abutments':
				f = _unit(_sub(outer, inner))
				n = (f[1], -f[0])  # normal pointing away from the arch (outwards, down the thrust)
				first = lay.blocks[springing]
				if n[0] * (first.centre[0] - inner[0]) + n[1] * (first.centre[2] - inner[1]) > 0:
					n = (-n[0], -n[1])
				w = math.hypot(*_sub(outer, inner))
				M = ((inner[0] + outer[0]) / 2, (inner[1] + outer[1]) / 2)
				# as long as the joint is wide, and wider than the joint by half of it on either side: the voussoir's
				# vertices sample the abutment's face inside it, not on its edges (a vertex on an edge is lost to contact
				# as soon as the voussoir turns outwards: the arches page of the user guide, §1)
				Lx = w
				half = (Lx / 2, hy, w)
				vol = 8 * half[0] * half[1] * half[2]
				unit = Unit('abutment', r, 0 if side == 'left' else 1, side=side, area=Lx * w, centroid=(M[0] + n[0] * Lx / 2, yc, M[1] + n[1] * Lx / 2))
				unit.blocks = [len(lay.blocks)]
				lay.blocks.append(Block(unit.centroid, half, math.atan2(-n[1], n[0]), vol, list(_boxInertia(vol, half)), len(lay.units)))
				lay.units.append(unit)
				lay.pairs.append((springing, unit.blocks[0], 'springing'))
			else:
				hp, wp, nc, hf = args['hp'], args['wp'], args['nCourses'], args['hf']
				xIn = inner[0]  # pier's inner face flush with the intrados
				x0, x1 = (xIn - wp, xIn) if side == 'left' else (xIn, xIn + wp)
				if (side == 'left' and outer[0] < x0) or (side == 'right' and outer[0] > x1):
					raise ValueError('pierWidth = %r: too narrow for the springing joint' % wp)
				ch = hp / nc
				prev = None
				for k in range(-1, nc):
					z0, z1 = (-hf, 0.0) if k < 0 else (k * ch, (k + 1) * ch)
					half = ((x1 - x0) / 2, hy, (z1 - z0) / 2)
					vol = 8 * half[0] * half[1] * half[2]
					unit = Unit('foundation' if k < 0 else 'pier', r, k if k >= 0 else (0 if side == 'left' else 1), side=side, area=(x1 - x0) * (z1 - z0),
					            centroid=((x0 + x1) / 2, yc, (z0 + z1) / 2))
					unit.blocks = [len(lay.blocks)]
					lay.blocks.append(Block(unit.centroid, half, 0.0, vol, list(_boxInertia(vol, half)), len(lay.units)))
					lay.units.append(unit)
					if prev is not None:
						lay.pairs.append((prev, unit.blocks[0], 'foundation' if k == 0 else 'pier'))
					prev = unit.blocks[0]
				lay.pairs.append((springing, prev, 'springing'))
