"""Masonry buildings as boxes: brick walls interlocked at their corners and T-junctions, storeys, openings with lintels,
floors (RC slabs or timber joists) and a base beam, and which boxes touch.

Pure Python (standard library only, no YADE), built on :mod:`rdem.wall_layout` (its pieces, box cutter, block subdivision,
snapping and touching-pair search); a YADE adapter (:mod:`rdem.building`) turns the boxes into :yref:`RdemBlock` bodies
and bonds the touching pairs.

Coordinates in m, $z$ up; walls run along $x$ or $y$. A brick is $l\\times w\\times h$ with $l = 2w + t$ (a header as
long as two stretchers and a joint, which is what lets a course turn a corner), joints $t$ thick, interface mortar (each
brick reaches the mid-planes of its joints, :func:`rdem.wall_layout.wallLayout`). Bricks lie on quarter modules
$q = (l + t)/4$ along a wall and modules $W = w + t = 2q$ through it, $h + t$ per course.

Typical use::

    from rdem.building_layout import buildingLayout
    lay = buildingLayout(plan=(3.11, 2.59), storeys=[1.355], thickness=0.12,
                         openings=[('front', 0, 1.035, 0.0, 0.78, 0.965)], floors='slab')
    lay.blocks, lay.pairs, lay.unitsOf(kind='lintel'), lay.blocksOf(wall='front', storey=0)

See :ref:`buildings <rdem-building>` in the user guide for the bond at corners, the floors and how joints are
classified.
"""
import math
import numbers
from collections import Counter

from .wall_layout import Unit, _cutByBoxes, _blockCounts, _subdivide, _snap, _touching, _cuts, _finite, _fmt, _modular, _positive

BONDS = ('running', 'english')
FLOORS = ('slab', 'joists', 'none')
UNIT_KINDS = ('brick', 'bat', 'beam', 'lintel', 'slab', 'joist')
PAIR_KINDS = ('internal', 'bed', 'head', 'collar', 'beam', 'lintel', 'floor', 'slab', 'joist', 'base')
_MASONRY = ('brick', 'bat')
_STRETCHER_PIECES = {4: 'stretcher', 3: 'three-quarter bat', 2: 'half bat'}
_HEADER_PIECES = {2: 'header', 1: 'queen closer'}


class _Sizes:
	"""Brick sizes and tolerance, as :mod:`rdem.wall_layout`'s helpers read them."""

	def __init__(self, l, w, h, t):
		self.l, self.w, self.h, self.t = l, w, h, t
		self.q, self.W, self.C = (l + t) / 4, w + t, h + t
		self.tol = 1e-9 * max(l, w, h)


class WallPlan:
	"""One wall of a building (made by :func:`buildingLayout` from the plan).

	:ivar index, name: its position in :attr:`BuildingLayout.walls` and its name.
	:ivar axis: ``'x'`` or ``'y'``, the direction it runs in.
	:ivar start, end: the end points of its axis (centre line) [m], ``start`` before ``end`` along ``axis``.
	:ivar thickness, bond: [m] and one of :data:`BONDS`; :attr:`rows` modules $W$ through the thickness.
	:ivar u0: the coordinate along ``axis`` of the wall's local $u = 0$: its outer end at ``start`` (the far face of the
	    wall it meets there, or ``start`` itself at a free end) [m]; :attr:`length` its length to the outer end at ``end``.
	:ivar v0: the coordinate across ``axis`` of its face with the smaller coordinate (local $v = 0$) [m].
	:ivar ends: for ``start`` and ``end``: ``('free', None)``, ``('L', j)`` (a corner with wall ``j``) or ``('T', j)``
	    (this wall ends on the side of wall ``j``).
	:ivar stems: ``[(j, p)]``: the walls ``j`` that end on this wall's side, their face $v = 0$ at $u = p\\,q$."""

	def __init__(self, index, name, axis, start, end, thickness, bond, rows):
		self.index, self.name, self.axis, self.start, self.end = index, name, axis, start, end
		self.thickness, self.bond, self.rows = thickness, bond, rows
		self.ends, self.stems = [('free', None), ('free', None)], []
		self.u0 = self.length = self.v0 = None

	@property
	def along(self):
		"""Index of the global axis the wall runs along (0 for x, 1 for y)."""
		return 0 if self.axis == 'x' else 1

	def toGlobal(self, lo, hi):
		"""The global box of a local box ($u$ along the wall from :attr:`u0`, $v$ across from :attr:`v0`, $z$)."""
		if self.axis == 'x':
			return (self.u0 + lo[0], self.v0 + lo[1], lo[2]), (self.u0 + hi[0], self.v0 + hi[1], hi[2])
		return (self.v0 + lo[1], self.u0 + lo[0], lo[2]), (self.v0 + hi[1], self.u0 + hi[0], hi[2])

	def footprint(self):
		"""The plan rectangle ``(x0, x1, y0, y1)`` of the wall, junction squares included [m]."""
		(x0, y0, _), (x1, y1, _) = self.toGlobal((0, 0, 0), (self.length, self.thickness, 0))
		return x0, x1, y0, y1

	def __repr__(self):
		return 'WallPlan(%s along %s, %.6g m long from %s = %.6g, %.6g m thick at %.6g, %s bond, ends %s)' % (
		        self.name, self.axis, self.length, self.axis, self.u0, self.thickness, self.v0, self.bond, self.ends)


class Storey:
	"""A storey: index, masonry from :attr:`z0` to :attr:`top` [m] (:attr:`courses` courses), its floor above
	(``'slab'``, ``'joists'`` or ``'none'``; the top storey's is the roof) and the global index of its first course."""

	def __init__(self, index, z0, height, courses, floor, firstCourse):
		self.index, self.z0, self.height, self.courses, self.floor, self.firstCourse = index, z0, height, courses, floor, firstCourse

	@property
	def top(self):
		"""Height of the storey's top [m]: ``z0 + height``."""
		return self.z0 + self.height

	def __repr__(self):
		return 'Storey(%d: z %.6g to %.6g m, %d courses, floor %s)' % (self.index, self.z0, self.top, self.courses, self.floor)


class BuildingLayout:
	"""The result of :func:`buildingLayout`.

	:ivar walls: list of :class:`WallPlan`; :ivar storeys: list of :class:`Storey`.
	:ivar junctions: ``(kind, i, j, (x, y))``: ``'L'`` a corner of walls ``i`` and ``j``, ``'T'`` wall ``i`` ending on the
	    side of wall ``j``; the point where their axes meet [m].
	:ivar units: list of :class:`rdem.wall_layout.Unit`: bricks and bats (``course`` global per wall, counted from the
	    ground floor), base beam pieces (``'beam'``), lintels, slab pieces, joists.
	:ivar unitWall, unitStorey: per unit, the index of its wall and storey (-1: none; a floor belongs to the storey below it,
	    the base to none).
	:ivar unitMass: per unit, the mass of the floor or roof load it carries [kg] (added to its blocks by volume).
	:ivar blocks, blockUnit, pairs, dropped: as :class:`rdem.wall_layout.WallLayout`: boxes ``(lo, hi)``, each block's unit,
	    touching pairs ``(i, j, kind, area)`` with ``kind`` in :data:`PAIR_KINDS`, slivers left out next to openings and
	    joist pockets.
	:ivar openings: ``(wall, storey, u0, z0, width, height)`` as checked ($u_0$ along the wall from its outer end at
	    ``start``, $z_0$ from the storey's floor) [m]; :ivar lintels: the unit index of each opening's lintel.
	:ivar brick, joint, blocksPerBrick, slabThickness, baseHeight: the arguments."""

	def __init__(self, **attributes):
		self.__dict__.update(attributes)

	def wallIndex(self, wall):
		"""The index of a wall given by index or name; ValueError otherwise."""
		if isinstance(wall, str):
			for w in self.walls:
				if w.name == wall:
					return w.index
		elif isinstance(wall, numbers.Integral) and 0 <= wall < len(self.walls):
			return int(wall)
		raise ValueError('wall = %r: must be a wall name (%s) or an index below %d' % (wall, ', '.join(w.name for w in self.walls), len(self.walls)))

	def unitsOf(self, kind=None, wall=None, storey=None):
		"""Indices of the units of a ``kind`` (one of :data:`UNIT_KINDS`, or ``'masonry'`` for bricks and bats), ``wall``
		(name or index) and ``storey`` (index); ``None`` selects all."""
		if kind is not None and kind not in UNIT_KINDS + ('masonry', ):
			raise ValueError('kind = %r: must be one of %s or masonry' % (kind, ', '.join(UNIT_KINDS)))
		kinds = _MASONRY if kind == 'masonry' else (kind, )
		w = None if wall is None else self.wallIndex(wall)
		return [i for i, u in enumerate(self.units) if (kind is None or u.kind in kinds) and (w is None or self.unitWall[i] == w) and
		        (storey is None or self.unitStorey[i] == storey)]

	def blocksOf(self, kind=None, wall=None, storey=None):
		"""Indices of the blocks of the units :meth:`unitsOf` selects."""
		return [b for i in self.unitsOf(kind, wall, storey) for b in self.units[i].blocks]

	def pairsOfKind(self, kind):
		"""The pairs ``(i, j, kind, area)`` of one kind (one of :data:`PAIR_KINDS`)."""
		if kind not in PAIR_KINDS:
			raise ValueError('kind = %r: must be one of %s' % (kind, PAIR_KINDS))
		return [p for p in self.pairs if p[2] == kind]

	def pairWalls(self, pair):
		"""The walls (indices, -1 for none) of the two blocks of a pair."""
		return self.unitWall[self.blockUnit[pair[0]]], self.unitWall[self.blockUnit[pair[1]]]

	def counts(self):
		"""Numbers of units, blocks and pairs, by kind: keys ``'units'``, ``'blocks'``, ``'pairs'``, ``'units:brick'``, ...,
		``'pairs:bed'``, ... (every kind present, 0 if none)."""
		out = {'units': len(self.units), 'blocks': len(self.blocks), 'pairs': len(self.pairs)}
		uk, pk = Counter(u.kind for u in self.units), Counter(p[2] for p in self.pairs)
		out.update(('units:' + k, uk[k]) for k in UNIT_KINDS)
		out.update(('pairs:' + k, pk[k]) for k in PAIR_KINDS)
		return out

	def volume(self, kind=None):
		"""Sum of the volumes of the blocks of the units of ``kind`` (all if ``None``) [m³]."""
		return sum((hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]) for b in (self.blocksOf(kind) if kind else range(len(self.blocks)))
		           for lo, hi in (self.blocks[b], ))

	def bounds(self):
		"""Bounding box ``(lo, hi)`` of all blocks [m]."""
		return (tuple(min(b[0][d] for b in self.blocks) for d in range(3)), tuple(max(b[1][d] for b in self.blocks) for d in range(3)))

	def sketch(self, course, window=None):
		"""ASCII plan of the bricks and bats of global ``course``, one character per $q/2 = (l + t)/8$ square, $y$ up:
		each brick drawn with the first letter of its wall's name, upper and lower case alternating from brick to brick
		along each row of the wall so that the head joints show. ``window``: ``(x0, x1, y0, y1)`` [m] to draw (default: everything)."""
		(x0, y0, _), (x1, y1, _) = self.bounds()
		if window is not None:
			x0, x1, y0, y1 = window
		step = (self.brick[0] + self.joint) / 8
		nx, ny = int(round((x1 - x0) / step)), int(round((y1 - y0) / step))
		rows = [[' '] * nx for _ in range(ny)]
		key = lambda i: (self.unitWall[i], self.units[i].lo[1 - self.walls[self.unitWall[i]].along], self.units[i].lo[self.walls[self.unitWall[i]].along])
		units = sorted((i for i in self.unitsOf('masonry') if self.units[i].course == course), key=key)
		for n, i in enumerate(units):
			u, letter = self.units[i], self.walls[self.unitWall[i]].name[0]
			letter = letter.upper() if n % 2 == 0 else letter.lower()
			for ix in range(nx):
				for iy in range(ny):
					x, y = x0 + (ix + 0.5) * step, y0 + (iy + 0.5) * step
					if u.lo[0] < x < u.hi[0] and u.lo[1] < y < u.hi[1]:
						rows[iy][ix] = letter
		return '\n'.join(''.join(r).rstrip() for r in reversed(rows))

	def __repr__(self):
		c = self.counts()
		return 'BuildingLayout(%d walls, %d storeys: %d units, %d blocks, %d pairs; %d bricks and bats, %d lintels, %d slab pieces, %d joists)' % (
		        len(self.walls), len(self.storeys), c['units'], c['blocks'], c['pairs'], c['units:brick'] + c['units:bat'], c['units:lintel'],
		        c['units:slab'], c['units:joist'])


# ---------------------------------------------------------------------------------------------- arguments
def rectangle(length, width, thickness, bond='running'):
	"""The four walls of a rectangular plan of outer size ``length`` ($x$) by ``width`` ($y$) [m], as wall axes for
	:func:`buildingLayout`: ``front`` ($y$ smallest), ``right``, ``back``, ``left``."""
	length, width = _positive('plan[0] (length)', length), _positive('plan[1] (width)', width)
	t2 = _positive('thickness', thickness) / 2
	if not (length > 2 * thickness and width > 2 * thickness):
		raise ValueError('plan = (%r, %r): both sides must exceed twice the thickness %r [m]' % (length, width, thickness))
	return [
	        dict(name='front', start=(t2, t2), end=(length - t2, t2), thickness=thickness, bond=bond),
	        dict(name='right', start=(length - t2, t2), end=(length - t2, width - t2), thickness=thickness, bond=bond),
	        dict(name='back', start=(t2, width - t2), end=(length - t2, width - t2), thickness=thickness, bond=bond),
	        dict(name='left', start=(t2, t2), end=(t2, width - t2), thickness=thickness, bond=bond),
	]


def _point(name, value):
	try:
		p = tuple(value)
	except TypeError:
		p = ()
	if len(p) != 2 or not all(_finite(c) for c in p):
		raise ValueError('%s = %r: must be 2 finite numbers (x, y) [m]' % (name, value))
	return tuple(float(c) for c in p)


def _rows(name, thickness, bond, s):
	"""Modules through the thickness: running bond $n \\geq 1$ wythes, English bond one brick ($l$)."""
	W, t = s.W, s.t
	n = int(round((thickness + t) / W))
	ok = n >= 1 and abs(n * W - t - thickness) <= 1e-9 * thickness and (bond == 'running' or n == 2)
	if not ok:
		allowed = 'n*w + (n-1)*t for n >= 1 wythes (%s, %s, ...)' % (_fmt(s.w), _fmt(2 * W - t)) if bond == 'running' else 'l = %s (one brick)' % _fmt(2 * W - t)
		raise ValueError('%s = %r: with bond=%r must be %s' % (name, thickness, bond, allowed))
	return n


def _walls(plan, thickness, bond, s):
	"""The :class:`WallPlan` list of a plan (its axes checked)."""
	if isinstance(plan, (tuple, list)) and len(plan) == 2 and all(_finite(v) for v in plan):
		plan = rectangle(plan[0], plan[1], thickness, bond)
	try:
		items = list(plan)
	except TypeError:
		items = None
	if not items:
		raise ValueError('plan = %r: must be (length, width) [m] of a rectangle or a list of wall axes, each a dict(start=(x, y), end=(x, y), '
		                 'thickness=..., bond=..., name=...) or a tuple (start, end[, thickness[, bond]])' % (plan, ))
	walls, names = [], set()
	for i, item in enumerate(items):
		where = 'plan[%d]' % i
		if isinstance(item, dict):
			unknown = set(item) - {'start', 'end', 'thickness', 'bond', 'name'}
			if unknown:
				raise ValueError('%s: unknown key(s) %s (start, end, thickness, bond, name)' % (where, sorted(unknown)))
			if 'start' not in item or 'end' not in item:
				raise ValueError('%s = %r: needs start and end (the axis end points (x, y) [m])' % (where, item))
			d = dict(item)
		else:
			try:
				parts = tuple(item)
			except TypeError:
				parts = ()
			if not 2 <= len(parts) <= 4:
				raise ValueError('%s = %r: must be a dict or a tuple (start, end[, thickness[, bond]])' % (where, item))
			d = dict(zip(('start', 'end', 'thickness', 'bond'), parts))
		a, b = _point(where + '.start', d['start']), _point(where + '.end', d['end'])
		wb = d.get('bond', bond)
		if wb not in BONDS:
			raise ValueError('%s.bond = %r: must be one of %s (corners need a bond that can turn them)' % (where, wb, ', '.join(repr(x) for x in BONDS)))
		wt = _positive(where + '.thickness', d.get('thickness', thickness))
		name = d.get('name', 'wall%d' % i)
		if not isinstance(name, str) or not name or name in names:
			raise ValueError('%s.name = %r: must be a non-empty string, unique among the walls' % (where, name))
		names.add(name)
		if abs(a[1] - b[1]) <= s.tol and abs(b[0] - a[0]) > s.tol:
			axis = 'x'
		elif abs(a[0] - b[0]) <= s.tol and abs(b[1] - a[1]) > s.tol:
			axis = 'y'
		else:
			raise ValueError('%s: start %r and end %r must differ along x or along y only (walls run along x or y)' % (where, a, b))
		k = 0 if axis == 'x' else 1
		if a[k] > b[k]:
			a, b = b, a
		walls.append(WallPlan(i, name, axis, a, b, wt, wb, _rows(where + '.thickness', wt, wb, s)))
	return walls


def _onSegment(p, w, tol):
	"""Where point ``p`` lies on the axis of wall ``w``: ``'start'``, ``'end'``, ``'inside'`` or ``None``."""
	k, c = w.along, 1 - w.along
	if abs(p[c] - w.start[c]) > tol or p[k] < w.start[k] - tol or p[k] > w.end[k] + tol:
		return None
	if abs(p[k] - w.start[k]) <= tol:
		return 'start'
	if abs(p[k] - w.end[k]) <= tol:
		return 'end'
	return 'inside'


def _junctions(walls, s):
	"""Find the corners and T-junctions, set each wall's ends, extent ($u_0$, length, $v_0$) and stems; check the module
	grid and that walls meet only there."""
	tol, q = s.tol, s.q
	junctions = []
	for w in walls:
		for e, p in enumerate((w.start, w.end)):
			found = [(o, _onSegment(p, o, tol)) for o in walls if o is not w]
			found = [(o, where) for o, where in found if where]
			if len(found) > 1:
				raise ValueError('plan: %d walls meet at (%s, %s) (%s): at most two walls may meet at a point' %
				                 (len(found) + 1, _fmt(p[0]), _fmt(p[1]), ', '.join([w.name] + [o.name for o, _ in found])))
			if not found:
				continue
			o, where = found[0]
			if o.axis == w.axis:
				raise ValueError('plan: walls %s and %s are collinear and meet at (%s, %s): make them one wall' % (w.name, o.name, _fmt(p[0]), _fmt(p[1])))
			w.ends[e] = ('L' if where in ('start', 'end') else 'T', o.index)
			if where == 'inside':
				junctions.append(('T', w.index, o.index, p))
			elif w.index < o.index:
				junctions.append(('L', w.index, o.index, p))
	for w in walls:  # walls crossing each other away from their ends
		for o in walls:
			if o.axis == 'y' and w.axis == 'x':
				p = (o.start[0], w.start[1])
				if _onSegment(p, w, tol) == 'inside' and _onSegment(p, o, tol) == 'inside':
					raise ValueError('plan: walls %s and %s cross at (%s, %s): a wall may end on another (a T-junction) but not cross it' %
					                 (w.name, o.name, _fmt(p[0]), _fmt(p[1])))
	for w in walls:
		k = w.along
		ext = [walls[j].thickness / 2 if kind != 'free' else 0.0 for kind, j in w.ends]
		w.u0 = w.start[k] - ext[0]
		w.length = w.end[k] + ext[1] - w.u0
		w.v0 = w.start[1 - k] - w.thickness / 2
		n = (w.length + s.t) / q
		if abs(n - round(n)) > 1e-6 or round(n) < 4:
			below, above = max(4, int(math.floor(n))), max(4, int(math.ceil(n)))
			raise ValueError('plan: wall %s is %s m long from end to end (junction squares included); a wall must be n*(l+t)/4 - t long, n >= 4 '
			                 '(nearest: %s or %s m)' % (w.name, _fmt(w.length), _fmt(below * q - s.t), _fmt(above * q - s.t)))
	for kind, i, j, p in junctions:
		if kind == 'T':
			stem, bar = walls[i], walls[j]
			x = (stem.v0 - bar.u0) / q
			if abs(x - round(x)) > 1e-6:
				raise ValueError('plan: wall %s ends on wall %s with its face at %s m from that wall\'s outer end; the face must lie on the module grid, '
				                 'a multiple of (l+t)/4 = %s m' % (stem.name, bar.name, _fmt(stem.v0 - bar.u0), _fmt(q)))
			bar.stems.append((i, int(round(x))))
	partners = {(i, j) for _, i, j, _ in junctions} | {(j, i) for _, i, j, _ in junctions}
	for a in walls:
		for b in walls:
			if a.index < b.index and (a.index, b.index) not in partners:
				(ax0, ax1, ay0, ay1), (bx0, bx1, by0, by1) = a.footprint(), b.footprint()
				if min(ax1, bx1) - max(ax0, bx0) > -tol and min(ay1, by1) - max(ay0, by0) > -tol:
					raise ValueError('plan: walls %s and %s touch or overlap without a junction (their axes must meet end to end or end to side)' % (a.name, b.name))
	return junctions


def _storeys(storeys, floors, slabThickness, s):
	"""The :class:`Storey` list; floors one of :data:`FLOORS` or one per storey."""
	try:
		heights = list(storeys)
	except TypeError:
		heights = []
	if not heights:
		raise ValueError('storeys = %r: must be a list of storey heights [m] (the masonry of each, floor to floor slab)' % (storeys, ))
	if isinstance(floors, str) or floors is None:
		floors = [floors] * len(heights)
	floors = list(floors)
	if len(floors) != len(heights):
		raise ValueError('floors = %r: must be one of %s or a list of one per storey (%d)' % (floors, FLOORS, len(heights)))
	out, z, first = [], 0.0, 0
	for i, (H, fl) in enumerate(zip(heights, floors)):
		fl = 'none' if fl is None else fl
		if fl not in FLOORS:
			raise ValueError('floors[%d] = %r: must be one of %s' % (i, fl, ', '.join(repr(f) for f in FLOORS)))
		_positive('storeys[%d]' % i, H)
		n = _modular('storeys[%d]' % i, H, s.C, s.t, lambda n: n >= 3, 'N*h + (N-1)*t for N >= 3 courses (h = %s, t = %s)' % (_fmt(s.h), _fmt(s.t)))
		height = n * s.C - s.t
		out.append(Storey(i, z, height, n, fl, first))
		z += height + (slabThickness if fl == 'slab' else s.t)
		first += n
	return out


# ---------------------------------------------------------------------------------------------- courses
def _owner(w, k):
	"""Whether wall ``w`` runs through its corners in global course ``k``: walls along x in even courses, along y in odd
	ones, so that every corner alternates course by course."""
	return (k % 2 == 0) == (w.axis == 'x')


def _outerRow(w, other, atStart, tol):
	"""The row of ``w`` on the outside of its corner with ``other`` (away from ``other``'s body, which runs from the corner
	towards larger coordinates if the corner is ``other``'s start)."""
	return 0 if _onSegment(w.start if atStart else w.end, other, tol) == 'start' else w.rows - 1


def _boundary(w, walls, k, row, atStart, tol):
	"""Where row ``row`` of wall ``w`` starts (or ends: quarters from that end) in course ``k``, in quarter modules from
	the wall's outer end: 0 at a free end; at a corner, the row on the outside runs through (0) in the wall's own courses
	and the others stop at the other wall's inner face, and in the other wall's courses every row stops behind that
	wall's outer row (2 quarters = one module $W$); at a T the wall runs through the other (0) in its own courses and stops
	at the other's near face in the other's courses."""
	kind, j = w.ends[0 if atStart else 1]
	if kind == 'free':
		return 0
	o = walls[j]
	if kind == 'T':
		return 0 if _owner(w, k) else 2 * o.rows
	if _owner(w, k):
		return 0 if row == _outerRow(w, o, atStart, tol) else 2 * o.rows
	return 2


def _fill(a, b, phase, period, header, where, avoid=(), shift=1):
	"""The pieces ``(q0, q1, name)`` of one row (or header row pair) from quarter ``a`` to ``b``: joints on the grid
	``phase + n*period`` and at both ends. Stretcher rows: 4 quarters a stretcher, 3 a three-quarter bat, 2 a half bat; a
	piece one quarter long is merged with its neighbour (1 + 4 = half bat at the end + three-quarter bat, which keeps a
	quarter lap with the courses above and below). Header rows: 2 a header, 1 a queen closer. A joint that would fall on
	one of the quarters ``avoid`` (where the courses above and below have the face of a wall running through this one) is
	replaced by two, ``shift`` quarters to either side."""
	cuts = [a] + [g for g in range(a + 1, b) if (g - phase) % period == 0] + [b]
	for e in avoid:  # a joint where the courses above and below have the side of a wall running through: move it aside
		if e in cuts[1:-1]:
			i = cuts.index(e)
			if cuts[i - 1] + 2 <= e - shift and e + shift + 2 <= cuts[i + 1]:
				cuts[i:i + 1] = [e - shift, e + shift]
	pieces = [[cuts[i], cuts[i + 1]] for i in range(len(cuts) - 1)]
	names = _HEADER_PIECES if header else _STRETCHER_PIECES
	if not header:
		if len(pieces) == 1 and pieces[0][1] - pieces[0][0] == 1:
			raise ValueError('%s: a course segment one quarter module long; move the junctions or openings' % where)
		for first in (True, False):
			p = pieces[0] if first else pieces[-1]
			if p[1] - p[0] == 1:
				n = pieces[1] if first else pieces[-2]
				lo, hi = min(p[0], n[0]), max(p[1], n[1])
				merged = [[lo, lo + 2], [lo + 2, hi]] if first and hi - lo == 5 else [[lo, hi - 2], [hi - 2, hi]] if hi - lo == 5 else [[lo, hi]]
				pieces = merged + pieces[2:] if first else pieces[:-2] + merged
	return [(q0, q1, names[q1 - q0]) for q0, q1 in pieces]


def _courseUnits(w, walls, storey, k, s):
	"""The brick and bat units of wall ``w`` in global course ``k`` (nominal boxes, global coordinates)."""
	t, q, W = s.t, s.q, s.W
	own = _owner(w, k)
	total = int(round((w.length + t) / q))
	if w.bond == 'running':
		groups = [(range(r, r + 1), 0 if own else 2, 4, False) for r in range(w.rows)]
	elif own:
		groups = [(range(r, r + 1), 0, 4, False) for r in range(2)]
	else:
		groups = [(range(0, 2), 1, 2, True)]
	gaps = [] if own else [(p, p + 2 * walls[j].rows) for j, p in w.stems]
	avoid = [e for j, p in w.stems for e in (p, p + 2 * walls[j].rows)] if own else []
	shift = 1 if w.bond == 'running' else 2
	z0 = storey.z0 + (k - storey.firstCourse) * s.C
	units = []
	for rows, phase, period, header in groups:
		a = {_boundary(w, walls, k, r, True, s.tol) for r in rows}
		b = {total - _boundary(w, walls, k, r, False, s.tol) for r in rows}
		assert len(a) == 1 and len(b) == 1, 'a header spanning rows that end differently'
		intervals, lo = [], a.pop()
		for g0, g1 in sorted(gaps):
			intervals.append((lo, g0))
			lo = g1
		intervals.append((lo, b.pop()))
		for i0, i1 in intervals:
			for q0, q1, piece in _fill(i0, i1, phase, period, header, 'wall %s, course %d' % (w.name, k), avoid, shift):
				nlo, nhi = (q0 * q, rows[0] * W, z0), (q1 * q - t, rows[-1] * W + W - t, z0 + s.h)
				glo, ghi = w.toGlobal(nlo, nhi)
				local = 'header' if header else 'stretcher'
				orientation = local if w.axis == 'x' else {'header': 'stretcher', 'stretcher': 'header'}[local]
				units.append(Unit('brick' if piece in ('stretcher', 'header') else 'bat', piece, orientation, k, rows[0], glo, ghi))
	return units


def _grow(units, t, tol):
	"""Interface mortar: each brick's box reaches into every joint it shares with another brick, so that the two touch.
	Across a joint the two faces grow by $t$ together: by $t/2$ each, except where a face is covered only in part by
	bricks (the end of a brick against the side of a brick of another wall, which lies open beyond it): that face stays
	at the brick surface and the faces across it grow by the whole $t$ (and the faces across those by 0, and so on).
	Faces without neighbours stay at the brick surface. Sets each unit's ``lo``, ``hi``."""
	half = t / 2
	boxes = [(tuple(c - half for c in u.nominalLo), tuple(c + half for c in u.nominalHi)) for u in units]
	boxes = _snap(boxes, ([], [], []), tol)
	area = lambda i, d: math.prod(boxes[i][1][e] - boxes[i][0][e] for e in range(3) if e != d)
	covered, partners = {}, {}
	for a, b, d, ar in _touching(boxes, tol):
		for face, other in (((a, d, 1), (b, d, 0)), ((b, d, 0), (a, d, 1))):
			covered[face] = covered.get(face, 0.0) + ar
			partners.setdefault(face, []).append(other)
	full = {f: covered[f] >= area(f[0], f[1]) * (1 - 1e-9) for f in partners}
	grow = {f: (0.0 if any(full[g] for g in partners[f]) else half) for f in partners if not full[f]}
	order = list(grow) + [f for f in partners if full[f]]
	for seed in order:
		if seed not in grow:
			grow[seed] = half
		stack = [seed]
		while stack:
			f = stack.pop()
			for g in partners[f]:
				want = t - grow[f]
				if g not in grow:
					grow[g] = want
					stack.append(g)
				elif abs(grow[g] - want) > tol:
					raise AssertionError('bricks %d and %d: joints that cannot all be closed (%s and %s)' % (f[0], g[0], grow[g], want))
	for i, u in enumerate(units):
		lo, hi = list(u.nominalLo), list(u.nominalHi)
		for d in range(3):
			lo[d] -= grow.get((i, d, 0), 0.0)
			hi[d] += grow.get((i, d, 1), 0.0)
		u.lo, u.hi = tuple(lo), tuple(hi)


def _planGrid(walls, size, tol):
	"""Lines of the floor and base grid along $x$ and $y$: the bounding box and every wall face, and between them equal
	steps of at most ``size``."""
	grids = []
	for d in range(2):
		faces = _cuts([c for w in walls for c in (w.footprint()[2 * d], w.footprint()[2 * d + 1])], tol)
		lines = [faces[0]]
		for a, b in zip(faces, faces[1:]):
			n = max(1, int(math.ceil((b - a) / size - 1e-9)))
			lines += [a + (b - a) * i / n for i in range(1, n)] + [b]
		grids.append(lines)
	return grids


def _inside(x, y, rects, tol):
	return any(x0 - tol <= x <= x1 + tol and y0 - tol <= y <= y1 + tol for x0, x1, y0, y1 in rects)


def _checkOpenings(openings, walls, storeys, lintelHeight, lintelBearing, s):
	"""The openings as tuples ``(wall, storey, u0, z0, width, height)``; ValueError naming ``openings[i]`` unless each
	lies, with its lintel, in the clear part of its wall (clear of junctions) and of its storey, apart from the others."""
	try:
		items = list(openings)
	except TypeError:
		raise ValueError('openings = %r: must be a list of (wall, storey, u0, z0, width, height)' % (openings, )) from None
	out, tol = [], s.tol
	for i, o in enumerate(items):
		name = 'openings[%d] = %r' % (i, o)
		try:
			o = tuple(o)
		except TypeError:
			o = ()
		if len(o) != 6:
			raise ValueError('%s: must be (wall, storey, u0, z0, width, height): wall name or index, storey index, lengths [m]' % name)
		wall = o[0]
		w = next((x for x in walls if x.name == wall), None) if isinstance(wall, str) else (walls[wall] if isinstance(wall, numbers.Integral) and
		                                                                                    not isinstance(wall, bool) and 0 <= wall < len(walls) else None)
		if w is None:
			raise ValueError('%s: wall must be one of %s or an index below %d' % (name, ', '.join(x.name for x in walls), len(walls)))
		st = o[1]
		if isinstance(st, bool) or not isinstance(st, numbers.Integral) or not 0 <= st < len(storeys):
			raise ValueError('%s: storey must be an index from 0 to %d' % (name, len(storeys) - 1))
		if not all(_finite(v) for v in o[2:]) or not (o[4] > 0 and o[5] > 0):
			raise ValueError('%s: u0, z0 must be finite and width, height > 0 [m]' % name)
		u0, z0, ow, oh = (float(v) for v in o[2:])
		clear0 = walls[w.ends[0][1]].thickness + s.t / 2 if w.ends[0][0] != 'free' else 0.0
		clear1 = w.length - (walls[w.ends[1][1]].thickness + s.t / 2 if w.ends[1][0] != 'free' else 0.0)
		a, b = u0 - lintelBearing, u0 + ow + lintelBearing
		if a < clear0 - tol or b > clear1 + tol:
			raise ValueError('%s: with its lintel (bearing %s m each side) it must lie within u = %s to %s m of wall %s (clear of its junctions)' %
			                 (name, _fmt(lintelBearing), _fmt(clear0), _fmt(clear1), w.name))
		for j, p in w.stems:
			s0, s1 = p * s.q - s.t / 2, p * s.q + walls[j].thickness + s.t / 2
			if min(b, s1) - max(a, s0) > tol:
				raise ValueError('%s: with its lintel it overlaps the junction with wall %s (u = %s to %s m)' % (name, walls[j].name, _fmt(s0), _fmt(s1)))
		H = storeys[st].height
		if z0 < -tol or z0 + oh + lintelHeight > H + tol:
			raise ValueError('%s: z0 >= 0 and z0 + height + lintel height (%s m) <= the storey height %s m' % (name, _fmt(lintelHeight), _fmt(H)))
		for k, (w2, st2, u2, z2, ow2, oh2) in enumerate(out):
			if w2 == w.index and st2 == st and min(b, u2 + ow2 + lintelBearing) - max(a, u2 - lintelBearing) > tol and min(z0 + oh + lintelHeight, z2 + oh2 +
			                                                                                                                   lintelHeight) - max(z0, z2) > tol:
				raise ValueError('%s overlaps openings[%d] (lintels included): openings must not overlap' % (name, k))
		out.append((w.index, st, u0, z0, ow, oh))
	return out


def _joists(walls, storey, direction, width, depth, spacing, bearing, top, s):
	"""Joist boxes ``(lo, hi)`` of a timber floor on ``storey``: along ``direction`` (0: x, 1: y), in each bay between
	the walls parallel to them $n = \\max(1, \\mathrm{round}(B/\\mathrm{spacing}))$ joists evenly spaced over the bay's
	clear width $B$; each spans between two consecutive walls across it and reaches ``bearing`` into each (a pocket cut in
	the masonry). Their top is ``top`` [m]."""
	parallel = sorted((w for w in walls if w.along == direction), key=lambda w: w.v0)
	across = [w for w in walls if w.along != direction]
	lo, hi = (min(w.footprint()[2 * (1 - direction)] for w in walls), max(w.footprint()[2 * (1 - direction) + 1] for w in walls))
	faces = _cuts([lo, hi] + [c for w in parallel for c in (w.v0, w.v0 + w.thickness)], s.tol)
	solid = [(w.v0, w.v0 + w.thickness) for w in parallel] + [(lo - 1, lo), (hi, hi + 1)]
	out = []
	for a, b in zip(faces, faces[1:]):
		if any(s0 - s.tol <= a and b <= s1 + s.tol for s0, s1 in solid):
			continue  # inside a wall
		n = max(1, int(round((b - a) / spacing)))
		if width >= (b - a) / n:
			raise ValueError('joistSection = %r: joists %s m wide do not fit %d to a bay %s m wide (spacing %s m)' % ((width, depth), _fmt(width), n, _fmt(b - a), _fmt(spacing)))
		for i in range(n):
			c = a + (b - a) * (i + 0.5) / n
			supports = sorted((w for w in across if w.u0 + s.tol < c - width / 2 and c + width / 2 < w.u0 + w.length - s.tol), key=lambda w: w.v0)
			for w1, w2 in zip(supports, supports[1:]):
				y0, y1 = w1.v0 + w1.thickness - min(bearing, w1.thickness), w2.v0 + min(bearing, w2.thickness)
				box = [[0, 0, top - depth], [0, 0, top]]
				box[0][direction], box[1][direction] = y0, y1
				box[0][1 - direction], box[1][1 - direction] = c - width / 2, c + width / 2
				out.append((tuple(box[0]), tuple(box[1]), (b - a) / n * (w2.v0 - w1.v0 - w1.thickness)))
	return out


def _pairKind(u, v, wu, wv, axis, walls):
	"""Kind of a pair of blocks of units ``u`` and ``v`` (of walls ``wu``, ``wv``) touching across a face of normal
	``axis``."""
	if u is v:
		return 'internal'
	kinds = {u.kind, v.kind}
	if kinds == {'beam'}:
		return 'base'
	for k in ('joist', 'beam', 'lintel'):
		if k in kinds:
			return k if k != 'lintel' or 'slab' not in kinds else 'floor'
	if kinds == {'slab'}:
		return 'slab'
	if 'slab' in kinds:
		return 'floor'
	if axis == 2:
		return 'bed'
	if wu != wv:
		return 'head'
	return 'head' if axis == walls[wu].along else 'collar'


def buildingLayout(plan,
                   storeys,
                   thickness=0.12,
                   bond='running',
                   brick=(0.25, 0.12, 0.055),
                   joint=0.01,
                   blocksPerBrick=(1, 1, 1),
                   openings=(),
                   lintelHeight=None,
                   lintelBearing=None,
                   floors='slab',
                   slabThickness=0.15,
                   slabBlock=0.6,
                   joistSection=(0.1, 0.195),
                   joistSpacing=0.6,
                   joistDirection='auto',
                   joistBearing=None,
                   floorLoad=0.0,
                   roofLoad=0.0,
                   baseHeight=0.2):
	"""The geometry of a masonry building as axis-aligned boxes and the pairs that touch face to face (lengths in m,
	masses in kg). See :ref:`buildings <rdem-building>`.

	:param plan: ``(length, width)``: a rectangle of that outer size (walls ``front``, ``right``, ``back``, ``left`` of
	    :func:`rectangle`), or a list of wall axes, each ``dict(start=(x, y), end=(x, y), thickness=..., bond=...,
	    name=...)`` or a tuple ``(start, end[, thickness[, bond]])``; walls run along $x$ or $y$, meet end to end (a
	    corner) or end to side (a T-junction, the ending wall's face on the module grid $(l + t)/4$ of the other), at most
	    two at a point; each wall, junction squares included, is $n(l + t)/4 - t$ long, $n \\geq 4$.
	:param storeys: heights of the storeys' masonry [m], each $Nh + (N - 1)t$, $N \\geq 3$, the ground floor first.
	:param thickness, bond: of walls that do not give their own: ``'running'`` ($n$ wythes, $nw + (n-1)t$) or ``'english'``
	    (one brick, $l$). At every corner the courses alternate: walls along $x$ run through in even courses (their
	    outer row to the corner's outer face, in English bond the stretcher courses) and those along $y$ stop behind
	    it, the reverse in odd courses; at a T the ending wall runs through the other in its own courses.
	:param brick: $(l, w, h)$ [m] with $l = 2w + t$. :param joint: $t$ [m], $0 < t < \\min(l/3, w, h)$.
	:param blocksPerBrick: as :func:`rdem.wall_layout.wallLayout`.
	:param openings: ``(wall, storey, u0, z0, width, height)``: wall name or index, storey index, the opening from $u_0$
	    along the wall (from its outer end at ``start``) and $z_0$ above the storey's floor [m]. Each gets a lintel
	    ``lintelHeight`` high (default two courses, $2(h + t)$) bearing ``lintelBearing`` (default $(l + t)/2$) on each jamb.
	:param floors: ``'slab'`` (an RC slab over the whole plan, ``slabThickness`` thick, pieces of at most ``slabBlock``
	    cut at every wall face; the next storey stands on it), ``'joists'`` (timber joists of ``joistSection`` (width,
	    depth) at about ``joistSpacing`` along ``joistDirection`` (``'x'``, ``'y'`` or ``'auto'``: the shorter span of the
	    plan), in pockets ``joistBearing`` deep (default half the wall thickness) in the top courses of the walls across
	    them; the next storey's masonry continues on the walls), ``'none'``; one value or one per storey (the last is
	    the roof).
	:param floorLoad, roofLoad: mass per plan area on the floors and on the roof [kg/m²] (dead and quasi-permanent live
	    load over $g$), carried by the slab pieces or joists.
	:param baseHeight: height of the base beam under every wall [m], cut into pieces on the floor grid.
	:return: a :class:`BuildingLayout`.

	ValueError for any argument out of range, naming it and what is allowed."""
	try:
		sizes = tuple(brick)
	except TypeError:
		sizes = ()
	if len(sizes) != 3 or not all(_finite(v) and v > 0 for v in sizes):
		raise ValueError('brick = %r: must be 3 finite sizes > 0, (length l, width w, height h) [m]' % (brick, ))
	l, w_, h = (float(v) for v in sizes)
	if not (_finite(joint) and 0 < joint < min(l / 3, w_, h)):
		raise ValueError('joint = %r: must be > 0 and < min(l/3, w, h) = %s [m]' % (joint, _fmt(min(l / 3, w_, h))))
	t = float(joint)
	if abs(l - (2 * w_ + t)) > 1e-9 * l:
		raise ValueError('brick = %r: a building needs l = 2*w + t (= %s with joint = %s) so that a course can turn a corner' % (brick, _fmt(2 * w_ + t), _fmt(t)))
	s = _Sizes(l, w_, h, t)
	try:
		per = tuple(blocksPerBrick)
	except TypeError:
		per = ()
	if len(per) != 3 or not all(not isinstance(n, bool) and isinstance(n, numbers.Integral) and n >= 1 for n in per):
		raise ValueError("blocksPerBrick = %r: must be 3 integers >= 1 (blocks along the brick's own length, width and height)" % (blocksPerBrick, ))
	if bond not in BONDS:
		raise ValueError('bond = %r: must be one of %s' % (bond, ', '.join(repr(b) for b in BONDS)))
	_positive('thickness', thickness)
	slabThickness = _positive('slabThickness', slabThickness)
	slabBlock = _positive('slabBlock', slabBlock)
	baseHeight = _positive('baseHeight', baseHeight)
	lintelHeight = 2 * s.C if lintelHeight is None else _positive('lintelHeight', lintelHeight)
	lintelBearing = 2 * s.q if lintelBearing is None else _positive('lintelBearing', lintelBearing)
	for name, value in (('floorLoad', floorLoad), ('roofLoad', roofLoad)):
		if not (_finite(value) and value >= 0):
			raise ValueError('%s = %r: must be a finite number >= 0 [kg/m2]' % (name, value))
	try:
		jw, jd = (float(v) for v in joistSection)
	except (TypeError, ValueError):
		jw = jd = float('nan')
	if not (_finite(jw) and _finite(jd) and jw > 0 and jd > 0):
		raise ValueError('joistSection = %r: must be (width, depth), 2 finite numbers > 0 [m]' % (joistSection, ))
	joistSpacing = _positive('joistSpacing', joistSpacing)
	if joistDirection not in ('auto', 'x', 'y'):
		raise ValueError("joistDirection = %r: must be 'x', 'y' or 'auto'" % (joistDirection, ))
	if joistBearing is not None:
		_positive('joistBearing', joistBearing)

	walls = _walls(plan, thickness, bond, s)
	junctions = _junctions(walls, s)
	levels = _storeys(storeys, floors, slabThickness, s)
	for st in levels[:-1]:
		if st.floor == 'joists' and jd > st.height - lintelHeight:
			raise ValueError('joistSection = %r: joists %s m deep do not fit storey %d' % (joistSection, _fmt(jd), st.index))
	openings = _checkOpenings(openings, walls, levels, lintelHeight, lintelBearing, s)

	# bricks and bats, course by course, grown into their joints
	masonry, info = [], []
	for st in levels:
		for k in range(st.firstCourse, st.firstCourse + st.courses):
			for w in walls:
				for u in _courseUnits(w, walls, st, k, s):
					masonry.append(u)
					info.append((w.index, st.index))
	_grow(masonry, t, s.tol)

	# openings, lintels and joist pockets cut the masonry
	cutsOf = {}
	units, unitWall, unitStorey, unitMass = [], [], [], []

	def add(u, wall, storey, mass=0.0):
		units.append(u)
		unitWall.append(wall)
		unitStorey.append(storey)
		unitMass.append(mass)
		return len(units) - 1

	lintelBoxes = []
	for (wi, st, u0, z0, ow, oh) in openings:
		w, z = walls[wi], levels[st].z0 + z0
		cutsOf.setdefault(wi, []).append(w.toGlobal((u0, 0, z), (u0 + ow, w.thickness, z + oh)))
		lb = w.toGlobal((u0 - lintelBearing, 0, z + oh), (u0 + ow + lintelBearing, w.thickness, z + oh + lintelHeight))
		cutsOf[wi].append(lb)
		lintelBoxes.append((lb, wi, st))
	joists = []
	rects = [w.footprint() for w in walls]
	(bx0, bx1), (by0, by1) = (min(r[0] for r in rects), max(r[1] for r in rects)), (min(r[2] for r in rects), max(r[3] for r in rects))
	for st in levels:
		if st.floor != 'joists':
			continue
		direction = (1 if by1 - by0 < bx1 - bx0 else 0) if joistDirection == 'auto' else 'xy'.index(joistDirection)
		top = st.top + (t / 2 if st.index + 1 < len(levels) else 0.0)
		bearing = joistBearing if joistBearing is not None else min(w.thickness for w in walls) / 2
		for lo, hi, area in _joists(walls, st, direction, jw, jd, joistSpacing, bearing, top, s):
			for (olo, ohi), _, ost in lintelBoxes:
				if ost == st.index and all(min(hi[d], ohi[d]) - max(lo[d], olo[d]) > s.tol for d in range(3)):
					raise ValueError('joistSection, joistSpacing: a joist at %s hits a lintel of storey %d; move the opening or change the joists' %
					                 (tuple(round(c, 4) for c in lo), st.index))
			joists.append((lo, hi, st.index, area * (roofLoad if st.index == len(levels) - 1 else floorLoad)))
	allJoistBoxes = [(lo, hi) for lo, hi, _, _ in joists]
	dropped = []
	for u, (wi, st) in zip(masonry, info):
		boxes = cutsOf.get(wi, []) + allJoistBoxes
		for piece in (_cutByBoxes(u, boxes, s, dropped) if boxes else [u]):
			add(piece, wi, st)
	lintels = []
	for (lo, hi), wi, st in lintelBoxes:
		lintels.append(add(Unit('lintel', 'lintel', None, -1, 0, lo, hi), wi, st))
	for lo, hi, st, mass in joists:
		add(Unit('joist', 'joist', None, -1, 0, lo, hi), -1, st, mass)
	xs, ys = _planGrid(walls, slabBlock, s.tol)
	for st in levels:
		if st.floor != 'slab':
			continue
		load = roofLoad if st.index == len(levels) - 1 else floorLoad
		for i in range(len(xs) - 1):
			for j in range(len(ys) - 1):
				lo, hi = (xs[i], ys[j], st.top), (xs[i + 1], ys[j + 1], st.top + slabThickness)
				add(Unit('slab', 'slab', None, -1, 0, lo, hi), -1, st.index, load * (hi[0] - lo[0]) * (hi[1] - lo[1]))
	for i in range(len(xs) - 1):
		for j in range(len(ys) - 1):
			if _inside((xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2, rects, -s.tol):
				add(Unit('beam', 'base', None, -1, 0, (xs[i], ys[j], -baseHeight), (xs[i + 1], ys[j + 1], 0.0)), -1, -1)

	blocks, blockUnit = [], []
	for i, u in enumerate(units):
		if u.kind in _MASONRY:
			counts = _blockCounts(u, per, 1, s)
		else:
			counts = (1, 1, 1)
		boxes = _subdivide(u, counts)
		u.blocks = list(range(len(blocks), len(blocks) + len(boxes)))
		blocks += boxes
		blockUnit += [i] * len(boxes)
	blocks = _snap(blocks, ([], [], [0.0]), s.tol)
	for u in units:
		u.lo = tuple(min(blocks[b][0][d] for b in u.blocks) for d in range(3))
		u.hi = tuple(max(blocks[b][1][d] for b in u.blocks) for d in range(3))
	pairs = sorted((min(a, b), max(a, b), _pairKind(units[blockUnit[a]], units[blockUnit[b]], unitWall[blockUnit[a]], unitWall[blockUnit[b]], axis, walls), area)
	               for a, b, axis, area in _touching(blocks, s.tol))
	return BuildingLayout(walls=walls, storeys=levels, junctions=junctions, units=units, unitWall=unitWall, unitStorey=unitStorey, unitMass=unitMass,
	                      blocks=blocks, blockUnit=blockUnit, pairs=pairs, dropped=dropped, openings=openings, lintels=lintels, brick=(l, w_, h), joint=t,
	                      blocksPerBrick=tuple(int(n) for n in per), slabThickness=slabThickness, baseHeight=baseHeight, lintelHeight=lintelHeight,
	                      lintelBearing=lintelBearing)
