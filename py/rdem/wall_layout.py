"""Masonry wall layouts: the bricks (and mortar) of a wall as axis-aligned boxes, and which boxes touch.

Pure Python (standard library only, no YADE), so that it can be tested on its own; a YADE adapter turns the boxes into
:yref:`RdemBlock` bodies and bonds the touching pairs.

Coordinates in m: $x$ along the wall, $y$ through its thickness, $z$ up. The masonry fills
$[0, \\mathrm{length}]\\times[0, \\mathrm{thickness}]\\times[0, \\mathrm{height}]$; a base beam lies below $z = 0$, a top
beam above $z = \\mathrm{height}$. A brick has nominal length $l$, width $w$ and height $h$; joints are $t$ thick. Bond
patterns are laid on modules: $L = l + t$ along $x$ (quarters $L/4$ for closers), $W = w + t$ through the thickness
(a header is $2W - t = l$ deep when $l = 2w + t$), $h + t$ per course.

Typical use::

    from rdem.wall_layout import wallLayout
    lay = wallLayout(length=2.85, height=1.225, thickness=0.12, bond='running', blocksPerBrick=(2, 1, 1))
    for lo, hi in lay.blocks: ...                     # one body per block
    for i, j, kind, area in lay.pairs: ...            # one bond per touching pair, by kind (bed, head, ...)
    print(lay.sketch())                               # the front face, one character per (l + t)/8

See :ref:`wall layouts <rdem-wall-layout>` in the user guide for the patterns, the two mortar models and how joints are
classified.
"""
import bisect
import math
import numbers
from collections import Counter

BONDS = ('stack', 'running', 'english', 'flemish')
MORTARS = ('interface', 'layer')
UNIT_KINDS = ('brick', 'bat', 'mortar', 'beam')
PAIR_KINDS = ('internal', 'bed', 'head', 'collar', 'beam', 'mortar')

# The pieces bond patterns are made of: letter -> (length along x in quarter modules L/4, name). Header-like pieces
# (their own length runs through the wall) are two modules W deep, the others one.
_PIECES = {'S': (4, 'stretcher'), 'H': (2, 'header'), 'Q': (1, 'queen closer'), 'B': (2, 'half bat'), 'T': (3, 'three-quarter bat')}
_LETTERS = {name: letter for letter, (n, name) in _PIECES.items()}
_HEADER_LIKE = ('header', 'queen closer')
_WHOLE = ('stretcher', 'header')


class Unit:
	"""One brick, bat, mortar piece or beam of a :class:`WallLayout`.

	:ivar kind: ``'brick'`` (a whole stretcher or header), ``'bat'`` (half bat, three-quarter bat, queen closer, or a brick
	    cut by an opening), ``'mortar'`` (``mortar='layer'`` only) or ``'beam'``.
	:ivar piece: finer name: ``'stretcher'``, ``'header'``, ``'half bat'``, ``'three-quarter bat'``, ``'queen closer'``;
	    the joint of a mortar piece, ``'bed'``, ``'head'`` or ``'collar'``; ``'base'`` or ``'top'`` for beams.
	:ivar orientation: ``'stretcher'`` (own length along $x$) or ``'header'`` (own length along $y$) for bricks and bats,
	    ``None`` otherwise.
	:ivar course: course index from 0 at the bottom; the bed mortar on top of course $k$ has course $k$; base beam -1,
	    top beam $N$ (the number of courses).
	:ivar wythe: index of the module $W = w + t$ through the thickness in which the unit's front face ($y$ smallest)
	    lies; for stack and running bond the wythe; a header of a one-brick wall: 0; beams 0.
	:ivar lo, hi: corners of the unit's box [m] (the union of its blocks).
	:ivar nominalLo, nominalHi: the brick's own box without the joint halves (equal to lo, hi in ``'layer'`` mode, for
	    mortar and for beams); blocks are cut at equal fractions of it.
	:ivar cut: ``True`` if the unit was trimmed by an opening.
	:ivar blocks: indices into :attr:`WallLayout.blocks`."""
	__slots__ = ('kind', 'piece', 'orientation', 'course', 'wythe', 'lo', 'hi', 'nominalLo', 'nominalHi', 'cut', 'blocks')

	def __init__(self, kind, piece, orientation, course, wythe, lo, hi, nominalLo=None, nominalHi=None, cut=False):
		self.kind, self.piece, self.orientation, self.course, self.wythe = kind, piece, orientation, course, wythe
		self.lo, self.hi = tuple(lo), tuple(hi)
		self.nominalLo = tuple(nominalLo) if nominalLo is not None else self.lo
		self.nominalHi = tuple(nominalHi) if nominalHi is not None else self.hi
		self.cut = cut
		self.blocks = []

	def __repr__(self):
		return 'Unit(%s %s, course %d, wythe %d, lo=(%.6g, %.6g, %.6g), hi=(%.6g, %.6g, %.6g), %d blocks%s)' % (
		        self.kind, self.piece, self.course, self.wythe, *self.lo, *self.hi, len(self.blocks), ', cut' if self.cut else '')


class WallLayout:
	"""The result of :func:`wallLayout`: units (bricks, bats, mortar pieces, beams), their blocks, and the touching pairs.

	:ivar length, height, thickness: the masonry's size [m]: the argument if it is the modular size up to round-off
	    (1e-9 of the brick size), else the modular size (the argument then differs from it by at most 1e-9 relative).
	:ivar brick: $(l, w, h)$ [m].
	:ivar joint: $t$ [m].
	:ivar bond, mortar, blocksPerBrick, openings, baseBeam, topBeam, beamBlocks: the arguments (checked, as floats
	    and ints).
	:ivar courseCount: the number of courses $N$.
	:ivar units: list of :class:`Unit`: the bricks and bats course by course, then the mortar pieces, the base beam
	    first and the top beam last.
	:ivar blocks: list of boxes ``(lo, hi)``, each a tuple of 3 floats [m]; the blocks of a unit are consecutive,
	    $x$ fastest, then $y$, then $z$.
	:ivar blockUnit: the index in :attr:`units` of each block's unit.
	:ivar pairs: list of ``(i, j, kind, area)``, block indices $i < j$ whose boxes share a face of positive area [m²];
	    ``kind`` one of :data:`PAIR_KINDS` (see :func:`wallLayout`). Sorted by $(i, j)$.
	:ivar dropped: boxes ``(lo, hi)`` of slivers left out next to openings (pieces of a unit cut by an opening that
	    were shorter than $l/4$ along $x$ or $h/4$ along $z$): blocks + dropped = wall - openings."""

	def __init__(self, **attributes):
		self.__dict__.update(attributes)

	def courses(self):
		"""Unit indices by course: a list of :attr:`courseCount` lists (bed mortar with the course below it; beams left
		out, see :meth:`beams`)."""
		out = [[] for _ in range(self.courseCount)]
		for i, u in enumerate(self.units):
			if u.kind != 'beam':
				out[u.course].append(i)
		return out

	def beams(self):
		"""Indices of the beam units (base first)."""
		return [i for i, u in enumerate(self.units) if u.kind == 'beam']

	def pairsOfKind(self, kind):
		"""The pairs ``(i, j, kind, area)`` of one kind (one of :data:`PAIR_KINDS`)."""
		if kind not in PAIR_KINDS:
			raise ValueError('kind = %r: must be one of %s' % (kind, PAIR_KINDS))
		return [p for p in self.pairs if p[2] == kind]

	def counts(self):
		"""Numbers of units, blocks and pairs, of units by kind and of pairs by kind, as one dict: keys ``'units'``,
		``'blocks'``, ``'pairs'``, ``'units:brick'``, ..., ``'pairs:bed'``, ... (every kind present, 0 if none)."""
		out = {'units': len(self.units), 'blocks': len(self.blocks), 'pairs': len(self.pairs)}
		unitKinds, pairKinds = Counter(u.kind for u in self.units), Counter(p[2] for p in self.pairs)
		out.update(('units:' + k, unitKinds[k]) for k in UNIT_KINDS)
		out.update(('pairs:' + k, pairKinds[k]) for k in PAIR_KINDS)
		return out

	def pieceCounts(self, course=None):
		"""A :class:`collections.Counter` of :attr:`Unit.piece` over all units, or over those of one ``course``."""
		return Counter(u.piece for u in self.units if course is None or u.course == course)

	def volume(self):
		"""Sum of the blocks' volumes [m³] (their union's volume: blocks do not overlap)."""
		return sum((hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]) for lo, hi in self.blocks)

	def bounds(self):
		"""Bounding box ``(lo, hi)`` of all blocks [m]."""
		return (tuple(min(b[0][d] for b in self.blocks) for d in range(3)), tuple(max(b[1][d] for b in self.blocks) for d in range(3)))

	def sketch(self, view='front', courses=None):
		"""ASCII drawing of the bricks and bats (mortar pieces not drawn), one character per $(l + t)/8$ along $x$; each
		piece drawn between ``|`` with its letter: S stretcher, H header, Q queen closer, B half bat, T three-quarter
		bat (lower case: cut by an opening). ``view='front'``: the face $y = 0$, top course first, beams as ``=``;
		``view='plan'``: for each of ``courses`` (default: 1 and 0, if there), one row per module $W$ through the
		thickness, the back face ($y$ largest) on top."""
		if view not in ('front', 'plan'):
			raise ValueError("view = %r: must be 'front' or 'plan'" % (view, ))
		(l, w, _), t = self.brick, self.joint
		col = lambda x: int(round((x + t / 2) / ((l + t) / 8)))
		ncol = col(self.length + t) + 1

		def line(units):
			chars = [' '] * ncol
			for u in units:
				s, e = col(u.nominalLo[0]), col(u.nominalHi[0] + t)
				chars[s] = chars[e] = '|'
				letter = _LETTERS.get(u.piece, '?')
				chars[(s + e) // 2 if e - s >= 2 else s] = letter.lower() if u.cut else letter
			return ''.join(chars).rstrip()

		masonry = [u for u in self.units if u.kind in ('brick', 'bat')]
		rows = []
		if view == 'front':
			beam = '     ' + '=' * ncol
			rows += [beam] if self.topBeam else []
			for k in reversed(range(self.courseCount) if courses is None else sorted(courses)):
				rows.append('%4d %s' % (k, line(u for u in masonry if u.course == k and u.nominalLo[1] <= self._tol)))
			rows += [beam] if self.baseBeam else []
			return '\n'.join(rows)
		W = w + t
		modules = int(round((self.thickness + t) / W))
		for k in ([c for c in (1, 0) if c < self.courseCount] if courses is None else courses):
			rows.append('course %d (plan, back face on top):' % k)
			for m in reversed(range(modules)):
				mid = m * W + w / 2
				rows.append('  y%d %s' % (m, line(u for u in masonry if u.course == k and u.nominalLo[1] <= mid <= u.nominalHi[1])))
		return '\n'.join(rows)

	def __repr__(self):
		c = self.counts()
		return 'WallLayout(%s bond, %s mortar, %.6g x %.6g x %.6g m, %d courses: %d units, %d blocks, %d pairs)' % (
		        self.bond, self.mortar, self.length, self.thickness, self.height, self.courseCount, c['units'], c['blocks'], c['pairs'])


# ---------------------------------------------------------------------------------------------- bond patterns
# A placement is (q0, q1, j0, j1, piece): x from quarter module q0 to q1 (x = q*L/4), y from module j0 to j1 (y = j*W);
# the brick's nominal box is [q0*L/4, q1*L/4 - t] x [j0*W, j1*W - t]. Each pattern function returns the placements of
# one course k.


def _row(codes, module, q=0):
	"""Placements of the pieces named by the letters ``codes`` side by side along $x$ from quarter ``q``: stretcher-like
	pieces in the $y$ module ``module``, header-like pieces in ``module`` and ``module + 1``."""
	out = []
	for c in codes:
		n, piece = _PIECES[c]
		out.append((q, q + n, module, module + (2 if piece in _HEADER_LIKE else 1), piece))
		q += n
	return out


def _stackCourse(k, quarters, modules):
	"""Stack bond: ``quarters/4`` stretchers in every wythe, every course alike."""
	return [p for j in range(modules) for p in _row('S' * (quarters // 4), j)]


def _runningCourse(k, quarters, modules):
	"""Running (stretcher) bond: even courses ``quarters/4`` stretchers, odd courses a half bat, one stretcher less and
	a half bat (offset $L/2$); a length of a whole number of stretchers and a half: even courses the stretchers and a half
	bat at the far end, odd courses a half bat first. Every wythe alike."""
	n = quarters // 4
	if quarters % 4:
		codes = 'S' * n + 'B' if k % 2 == 0 else 'B' + 'S' * n
	else:
		codes = 'S' * n if k % 2 == 0 else 'B' + 'S' * (n - 1) + 'B'
	return [p for j in range(modules) for p in _row(codes, j)]


def _englishCourse(k, quarters, modules):
	"""English bond, even courses stretchers on the front face, odd courses headers on it. A header run is header,
	queen closer, headers, queen closer, header ($2n - 1$ headers for $n$ stretchers), so that it laps the stretchers
	by $L/4$. A length of $n$ stretchers and three quarters ends every stretcher row with a three-quarter bat and
	the header run with headers alone (header, queen closer, $2n$ headers): its joints stay on odd quarters, a quarter
	from the stretchers' joints, as at the near end. One brick thick (2 modules): stretchers in both wythes / headers
	through. One and a half bricks (3 modules): front stretchers and a header run behind them / a header run and back
	stretchers behind it."""
	n = quarters // 4
	if quarters % 4 == 3:
		stretchers, headers = 'S' * n + 'T', 'HQ' + 'H' * (2 * n)
	else:
		stretchers, headers = 'S' * n, 'HQ' + 'H' * (2 * n - 3) + 'QH'
	if modules == 2:
		return _row(stretchers, 0) + _row(stretchers, 1) if k % 2 == 0 else _row(headers, 0)
	return _row(stretchers, 0) + _row(headers, 1) if k % 2 == 0 else _row(headers, 0) + _row(stretchers, 2)


def _flemishTokens(k, quarters):
	"""The front face of a Flemish course as tokens (letters laid together). ``quarters = 4 + 6m``: even courses
	HQ S (H S)^(m-1) QH, odd courses S (H S)^m; ``quarters = 6 + 6m``: even courses HQ S (H S)^(m-1) H T, odd
	courses S (H S)^m H ($m \\geq 1$). Headers of one course are centred on the stretchers of the next."""
	family1 = (quarters - 4) % 6 == 0
	m = (quarters - 4) // 6 if family1 else (quarters - 6) // 6
	if k % 2 == 0:
		return ['HQ', 'S'] + ['H', 'S'] * (m - 1) + (['QH'] if family1 else ['H', 'T'])
	return ['S'] + ['H', 'S'] * m + ([] if family1 else ['H'])


# One and a half bricks: what lies behind each front token (letters, first y module). Behind a stretcher two headers
# reach the back face; behind a header a half bat; behind a quoin header and its closer a three-quarter bat; behind a
# three-quarter bat (course end) a header and a queen closer.
_FLEMISH_BACK = {'S': ('HH', 1), 'H': ('B', 2), 'HQ': ('T', 2), 'QH': ('T', 2), 'T': ('HQ', 1)}


def _flemishCourse(k, quarters, modules):
	"""Flemish bond: headers and stretchers alternate in every course (see :func:`_flemishTokens`). One brick thick:
	a second stretcher behind each front stretcher (or three-quarter bat), headers and closers through. One and a half
	bricks: the back filled as :data:`_FLEMISH_BACK` says."""
	out, q = [], 0
	for token in _flemishTokens(k, quarters):
		front = _row(token, 0, q)
		out += front
		if modules == 2:
			out += [(q0, q1, 1, 2, piece) for (q0, q1, j0, j1, piece) in front if j1 == 1]
		else:
			codes, module = _FLEMISH_BACK[token]
			out += _row(codes, module, q)
		q = front[-1][1]
	return out


_COURSE_FUNCTIONS = {'stack': _stackCourse, 'running': _runningCourse, 'english': _englishCourse, 'flemish': _flemishCourse}

# Valid wall lengths per bond, as quarter modules Q (length + t = Q*L/4): (predicate, description).
_LENGTH_RULES = {
        'stack': (lambda Q: Q >= 4 and Q % 4 == 0, 'n*l + (n-1)*t, n >= 1 bricks per course'),
        'running': (lambda Q: Q >= 4 and Q % 2 == 0, 'n*l + (n-1)*t or (n+1/2)*(l+t) - t, n >= 1 bricks per course (half bats at both ends of '
                    'odd courses, or at one end of every course)'),
        'english': (lambda Q: Q >= 8 and Q % 4 in (0, 3), 'n*l + (n-1)*t, n >= 2 stretchers per stretcher course, or (n + 3/4)*(l + t) - t '
                    '(a three-quarter bat at the far end of each stretcher row)'),
        'flemish': (lambda Q: Q >= 10 and Q % 6 in (0, 4), 'length + t = (1 + 1.5*m)*(l + t) (queen closers at both ends) or (1.5 + 1.5*m)*(l + t) '
                    '(three-quarter bats at the far end), m >= 1'),
}


# ---------------------------------------------------------------------------------------------- arguments
def _fmt(x):
	return '%.10g' % x


def _finite(value):
	return not isinstance(value, bool) and isinstance(value, numbers.Real) and math.isfinite(value)


def _positive(name, value, what='[m]'):
	if not (_finite(value) and value > 0):
		raise ValueError('%s = %r: must be a finite number > 0 %s' % (name, value, what))
	return float(value)


def _count(name, value):
	if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 1:
		raise ValueError('%s = %r: must be an integer >= 1' % (name, value))
	return int(value)


def _modular(name, value, step, offset, valid, rule):
	"""The integer $n$ with ``value`` $= n\\,\\mathrm{step} - \\mathrm{offset}$ (to 1e-9 relative) and ``valid(n)``;
	otherwise ValueError naming ``name``, the ``rule`` and the nearest valid values below and above."""
	x = (value + offset) / step
	n = int(round(x))
	if valid(n) and abs(n * step - offset - value) <= 1e-9 * value:
		return n
	below = next((m for m in range(int(math.floor(x)), max(int(math.floor(x)) - 13, 0), -1) if valid(m)), None)
	above = next((m for m in range(int(math.ceil(x)), int(math.ceil(x)) + 13) if valid(m)), None)
	near = ' and '.join(_fmt(m * step - offset) for m in (below, above) if m is not None)
	raise ValueError('%s = %r: must be %s; nearest valid value%s: %s' % (name, value, rule, 's' if below and above else '', near))


def _checkOpenings(openings, length, height, tol):
	"""The openings as a tuple of ``(x0, z0, width, height)`` floats; ValueError naming ``openings[i]`` if one is not a
	rectangle inside the wall or overlaps another."""
	try:
		items = list(openings)
	except TypeError:
		raise ValueError('openings = %r: must be a sequence of rectangles (x0, z0, width, height) [m]' % (openings, )) from None
	out = []
	for i, o in enumerate(items):
		name = 'openings[%d] = %r' % (i, o)
		try:
			rect = tuple(o)
		except TypeError:
			rect = ()
		if len(rect) != 4 or not all(_finite(v) for v in rect):
			raise ValueError('%s: must be 4 finite numbers (x0, z0, width, height) [m]' % name)
		x0, z0, ow, oh = (float(v) for v in rect)
		if not (ow > 0 and oh > 0):
			raise ValueError('%s: width and height must be > 0 [m]' % name)
		if x0 < -tol or z0 < -tol or x0 + ow > length + tol or z0 + oh > height + tol:
			raise ValueError('%s: must lie inside the wall: 0 <= x0, x0 + width <= length = %s, 0 <= z0, z0 + height <= height = %s [m]' %
			                 (name, _fmt(length), _fmt(height)))
		for j, (a, b, aw, bh) in enumerate(out):
			if min(x0 + ow, a + aw) - max(x0, a) > tol and min(z0 + oh, b + bh) - max(z0, b) > tol:
				raise ValueError('%s overlaps openings[%d] = %r: openings must not overlap' % (name, j, items[j]))
		out.append((x0, z0, ow, oh))
	return tuple(out)


def _checkArguments(length, height, thickness, brick, joint, bond, blocksPerBrick, mortar, baseBeam, topBeam, beamBlocks):
	"""Every scalar argument checked; returns ``(l, w, h, t, blocksPerBrick)``."""
	for name, value in (('length', length), ('height', height), ('thickness', thickness)):
		_positive(name, value)
	try:
		sizes = tuple(brick)
	except TypeError:
		sizes = ()
	if len(sizes) != 3 or not all(_finite(v) and v > 0 for v in sizes):
		raise ValueError('brick = %r: must be 3 finite sizes > 0, (length l, width w, height h) [m]' % (brick, ))
	l, w, h = (float(v) for v in sizes)
	if bond not in BONDS:
		raise ValueError('bond = %r: must be one of %s' % (bond, ', '.join(repr(b) for b in BONDS)))
	if mortar not in MORTARS:
		raise ValueError('mortar = %r: must be one of %s' % (mortar, ', '.join(repr(m) for m in MORTARS)))
	if not (_finite(joint) and 0 <= joint < min(l / 3, w, h)):
		raise ValueError('joint = %r: must be >= 0 and < min(l/3, w, h) = %s [m]' % (joint, _fmt(min(l / 3, w, h))))
	if joint == 0 and mortar == 'layer':
		raise ValueError("joint = 0: mortar='layer' needs joint > 0 (its mortar boxes are joint thick); use mortar='interface'")
	try:
		per = tuple(blocksPerBrick)
	except TypeError:
		per = ()
	if len(per) != 3 or not all(not isinstance(n, bool) and isinstance(n, numbers.Integral) and n >= 1 for n in per):
		raise ValueError('blocksPerBrick = %r: must be 3 integers >= 1 (blocks along the brick\'s own length, width and height)' % (blocksPerBrick, ))
	for name, value in (('baseBeam', baseBeam), ('topBeam', topBeam)):
		if value is not None:
			_positive(name, value, '[m] (the beam height), or None for no beam')
	_count('beamBlocks', beamBlocks)
	return l, w, h, float(joint), tuple(int(n) for n in per)


def _fitThickness(thickness, bond, l, w, t):
	"""Number of modules $W = w + t$ through the thickness (stack/running: wythes; english/flemish: 2 or 3)."""
	W = w + t
	if bond in ('stack', 'running'):
		return _modular('thickness', thickness, W, t, lambda n: n >= 1,
		                'n*w + (n-1)*t for n >= 1 wythes with bond=%r (w = %s, t = %s)' % (bond, _fmt(w), _fmt(t)))
	if abs(l - (2 * w + t)) > 1e-9 * l:
		raise ValueError('thickness = %r: bond=%r needs bricks with l = 2*w + t (a header as deep as two stretchers and a collar joint), '
		                 'but brick = (%s, %s, ...) with joint = %s has 2*w + t = %s: no thickness is accepted with this brick' %
		                 (thickness, bond, _fmt(l), _fmt(w), _fmt(t), _fmt(2 * w + t)))
	accepted = 'l = %s (one brick) or l + t + w = %s (one and a half bricks)' % (_fmt(2 * W - t), _fmt(3 * W - t))
	n = int(round((thickness + t) / W))
	if n in (2, 3) and abs(n * W - t - thickness) <= 1e-9 * thickness:
		return n
	raise ValueError('thickness = %r: bond=%r accepts thickness = %s' % (thickness, bond, accepted))


# ---------------------------------------------------------------------------------------------- geometry
class _Frame:
	"""Sizes and module grid of a wall: $x$ of quarter $q$ is $qL/4$, $y$ of module $j$ is $jW$, $z$ of course $k$ is
	$k(h + t)$; the masonry's size follows from the numbers of quarters, modules and courses."""

	def __init__(self, l, w, h, t, quarters, modules, courses, given):
		self.l, self.w, self.h, self.t = l, w, h, t
		self.L, self.W, self.C = l + t, w + t, h + t
		self.tol = 1e-9 * max(l, w, h)
		# the size as given if it is the modular size but for round-off (2.85, not 2.8500000000000005), else the modular size
		self.length, self.thickness, self.height = (v if abs(v - m) <= self.tol else m for v, m in zip(given, (self.x(quarters) - t, self.y(modules) - t, self.z(courses) - t)))

	def x(self, q):
		return q * self.L / 4

	def y(self, j):
		return j * self.W

	def z(self, k):
		return k * self.C

	def wythe(self, y0):
		return int(math.floor((y0 + self.tol) / self.W))


def _brickUnits(placements, k, f, mortar):
	"""The units of the placements of course ``k``: nominal boxes (``'layer'``) or nominal boxes grown by $t/2$ on every
	side that is not on the wall's surface (``'interface'``)."""
	units, half = [], f.t / 2
	for (q0, q1, j0, j1, piece) in placements:
		nlo, nhi = (f.x(q0), f.y(j0), f.z(k)), (f.x(q1) - f.t, f.y(j1) - f.t, f.z(k + 1) - f.t)
		if mortar == 'interface':
			lo = (max(0.0, f.x(q0) - half), max(0.0, f.y(j0) - half), max(0.0, f.z(k) - half))
			hi = (min(f.length, f.x(q1) - half), min(f.thickness, f.y(j1) - half), min(f.height, f.z(k + 1) - half))
		else:
			lo, hi = nlo, nhi
		units.append(Unit('brick' if piece in _WHOLE else 'bat', piece, 'header' if piece in _HEADER_LIKE else 'stretcher', k, j0, lo, hi, nlo, nhi))
	return units


def _cuts(values, tol):
	"""Sorted values, those closer than ``tol`` to the previous kept one merged into it."""
	out = []
	for v in sorted(values):
		if not out or v - out[-1] > tol:
			out.append(v)
	return out


def _at(cuts, v, tol):
	"""Index of ``v`` in the sorted ``cuts`` (to ``tol``)."""
	i = bisect.bisect_left(cuts, v - tol)
	assert i < len(cuts) and abs(cuts[i] - v) <= tol, (v, cuts[i:i + 1])
	return i


def _mortarPlan(rects, xMax, yMax, tol):
	"""Plan view of the mortar of one course in ``'layer'`` mode: the rectangles ``(x0, x1, y0, y1)`` of the bricks cover
	$[0, x_{max}]\\times[0, y_{max}]$ but for the joints. Returns the joints as ``(x0, x1, y0, y1, joint)`` pieces: the grid of
	all brick edges, each mortar cell a ``'head'`` piece if a brick lies next to it along $x$, else ``'collar'``; cells
	merged along $x$ (collar) or $y$ (head) as long as the same bricks lie on both sides, so that a collar piece is cut at
	the brick edges of the wythes on both sides, a head piece at those of the bricks on both sides."""
	xs = _cuts([0.0, xMax] + [r[0] for r in rects] + [r[1] for r in rects], tol)
	ys = _cuts([0.0, yMax] + [r[2] for r in rects] + [r[3] for r in rects], tol)
	nx, ny = len(xs) - 1, len(ys) - 1
	owner = [[None] * ny for _ in range(nx)]
	for b, (x0, x1, y0, y1) in enumerate(rects):
		for i in range(_at(xs, x0, tol), _at(xs, x1, tol)):
			for j in range(_at(ys, y0, tol), _at(ys, y1, tol)):
				owner[i][j] = b
	own = lambda i, j: owner[i][j] if 0 <= i < nx and 0 <= j < ny else -1  # -1: outside the wall
	isBrick = lambda v: v is not None and v >= 0
	joint = {(i, j): 'head' if isBrick(own(i - 1, j)) or isBrick(own(i + 1, j)) else 'collar' for i in range(nx) for j in range(ny) if owner[i][j] is None}
	parent = {c: c for c in joint}

	def root(c):
		while parent[c] != c:
			parent[c] = c = parent[parent[c]]
		return c

	same = lambda a, b: isBrick(a) and a == b
	for (i, j), kind in joint.items():
		if joint.get((i + 1, j)) == kind and same(own(i, j - 1), own(i + 1, j - 1)) and same(own(i, j + 1), own(i + 1, j + 1)):
			parent[root((i + 1, j))] = root((i, j))
		if joint.get((i, j + 1)) == kind and same(own(i - 1, j), own(i - 1, j + 1)) and same(own(i + 1, j), own(i + 1, j + 1)):
			parent[root((i, j + 1))] = root((i, j))
	groups = {}
	for c in joint:
		groups.setdefault(root(c), []).append(c)
	out = []
	for cells in groups.values():
		i0, i1 = min(c[0] for c in cells), max(c[0] for c in cells)
		j0, j1 = min(c[1] for c in cells), max(c[1] for c in cells)
		assert len(cells) == (i1 - i0 + 1) * (j1 - j0 + 1), 'mortar piece is not a rectangle'
		out.append((xs[i0], xs[i1 + 1], ys[j0], ys[j1 + 1], joint[cells[0]]))
	return sorted(out)


def _overlay(below, above, tol):
	"""The non-empty intersections ``(x0, x1, y0, y1)`` of the rectangles of two plan partitions (each a list of
	``(x0, x1, y0, y1)``), in the order of ``below``."""
	above = sorted(above)
	starts = [r[0] for r in above]
	span = max(r[1] - r[0] for r in above)
	out = []
	for (x0, x1, y0, y1) in below:
		for (u0, u1, v0, v1) in above[bisect.bisect_left(starts, x0 - span - tol):bisect.bisect_left(starts, x1 - tol)]:
			a0, a1, b0, b1 = max(x0, u0), min(x1, u1), max(y0, v0), min(y1, v1)
			if a1 - a0 > tol and b1 - b0 > tol:
				out.append((a0, a1, b0, b1))
	return out


def _layerMortar(courseUnits, f):
	"""``'layer'`` mode: the head and collar pieces of every course (added to ``courseUnits[k]``) and the bed pieces
	between courses: the overlay of the plans of the course below and above, so that each bed piece lies under one unit
	and over one unit. Returns all mortar units."""
	plan = lambda units: [(u.lo[0], u.hi[0], u.lo[1], u.hi[1]) for u in units]
	mortar = []
	for k, units in enumerate(courseUnits):
		for (x0, x1, y0, y1, joint) in _mortarPlan(plan(units), f.length, f.thickness, f.tol):
			units.append(Unit('mortar', joint, None, k, f.wythe(y0), (x0, y0, f.z(k)), (x1, y1, f.z(k + 1) - f.t)))
			mortar.append(units[-1])
	for k in range(len(courseUnits) - 1):
		for (x0, x1, y0, y1) in _overlay(plan(courseUnits[k]), plan(courseUnits[k + 1]), f.tol):
			mortar.append(Unit('mortar', 'bed', None, k, f.wythe(y0), (x0, y0, f.z(k + 1) - f.t), (x1, y1, f.z(k + 1))))
	return mortar


def _cutByOpenings(unit, openings, f, dropped):
	"""The pieces of ``unit`` outside the ``openings`` (rectangles ``(x0, z0, width, height)`` through the whole thickness):
	:func:`_cutByBoxes` with boxes spanning the thickness."""
	return _cutByBoxes(unit, [((x0, -math.inf, z0), (x0 + ow, math.inf, z0 + oh)) for (x0, z0, ow, oh) in openings], f, dropped)


def _cutByBoxes(unit, boxes, f, dropped):
	"""The pieces of ``unit`` outside the ``boxes`` ``(lo, hi)`` [m]: a box overlapping one is split at the box's faces
	into the parts left and right of it (whole height and depth), below and above it (within its $x$ range) and in front
	of and behind it (within its $x$ and $z$ ranges). A piece that the cut made shorter than $l/4$ along $x$, $w/4$ along
	$y$ or $h/4$ along $z$ goes to ``dropped``. Bricks whose own (nominal) box was cut become bats; a piece's nominal box
	is the unit's cut the same way. ``f`` gives $l, w, h$ and the tolerance (a :class:`_Frame`)."""
	tol, pieces = f.tol, [(unit.lo, unit.hi)]
	for (blo, bhi) in boxes:
		nxt = []
		for lo, hi in pieces:
			mlo = tuple(max(lo[d], blo[d]) for d in range(3))
			mhi = tuple(min(hi[d], bhi[d]) for d in range(3))
			if any(mhi[d] - mlo[d] <= tol for d in range(3)):
				nxt.append((lo, hi))
				continue
			if blo[0] - lo[0] > tol:
				nxt.append((lo, (blo[0], hi[1], hi[2])))
			if hi[0] - bhi[0] > tol:
				nxt.append(((bhi[0], lo[1], lo[2]), hi))
			if blo[2] - lo[2] > tol:
				nxt.append(((mlo[0], lo[1], lo[2]), (mhi[0], hi[1], blo[2])))
			if hi[2] - bhi[2] > tol:
				nxt.append(((mlo[0], lo[1], bhi[2]), (mhi[0], hi[1], hi[2])))
			if blo[1] - lo[1] > tol:
				nxt.append(((mlo[0], lo[1], mlo[2]), (mhi[0], blo[1], mhi[2])))
			if hi[1] - bhi[1] > tol:
				nxt.append(((mlo[0], bhi[1], mlo[2]), (mhi[0], hi[1], mhi[2])))
		pieces = nxt
	if pieces == [(unit.lo, unit.hi)]:
		return [unit]
	out = []
	for lo, hi in pieces:
		short = lambda d, minimum: hi[d] - lo[d] < unit.hi[d] - unit.lo[d] - tol and hi[d] - lo[d] < minimum - tol
		if short(0, f.l / 4) or short(1, f.w / 4) or short(2, f.h / 4):
			dropped.append((lo, hi))
			continue
		nlo = tuple(max(a, b) for a, b in zip(unit.nominalLo, lo))
		nhi = tuple(min(a, b) for a, b in zip(unit.nominalHi, hi))
		if any(nhi[d] - nlo[d] <= tol for d in range(3)):
			nlo, nhi = lo, hi  # only joint left
		whole = all(abs(nlo[d] - unit.nominalLo[d]) <= tol and abs(nhi[d] - unit.nominalHi[d]) <= tol for d in range(3))
		out.append(Unit('bat' if unit.kind == 'brick' and not whole else unit.kind, unit.piece, unit.orientation, unit.course, unit.wythe, lo, hi, nlo, nhi, cut=True))
	return out


def _blockCounts(u, per, beamBlocks, f):
	"""Blocks of a unit along $x, y, z$: ``per = (a, b, c)`` along the brick's own length, width, height, scaled for bats
	to $\\max(1, \\mathrm{round}(a \\times$ their size / the brick's$))$; mortar one block; beams ``beamBlocks`` along $x$."""
	if u.kind == 'mortar':
		return (1, 1, 1)
	if u.kind == 'beam':
		return (beamBlocks, 1, 1)
	a, b, c = per
	n = lambda count, size, ref: max(1, int(math.floor(count * size / ref + 0.5)))
	sx, sy, sz = (u.nominalHi[d] - u.nominalLo[d] for d in range(3))
	if u.orientation == 'header':
		return (n(b, sx, f.w), n(a, sy, f.l), n(c, sz, f.h))
	return (n(a, sx, f.l), n(b, sy, f.w), n(c, sz, f.h))


def _subdivide(u, counts):
	"""The blocks ``(lo, hi)`` of unit ``u``: cut at equal fractions of its nominal box (the joint halves of
	``'interface'`` mode stay with the outer blocks), $x$ fastest."""
	edges = []
	for d in range(3):
		n, a, b = counts[d], u.nominalLo[d], u.nominalHi[d]
		edges.append([u.lo[d]] + [a + (b - a) * i / n for i in range(1, n)] + [u.hi[d]])
	ex, ey, ez = edges
	return [((ex[i], ey[j], ez[k]), (ex[i + 1], ey[j + 1], ez[k + 1])) for k in range(len(ez) - 1) for j in range(len(ey) - 1) for i in range(len(ex) - 1)]


def _snap(blocks, anchors, tol):
	"""Blocks with every coordinate closer than ``tol`` to another replaced by one value (an anchor of ``anchors[d]``,
	such as 0 or the wall's length, if one is in the cluster), so that touching faces are exactly equal."""
	maps = []
	for d in range(3):
		clusters = []
		for v in sorted(set(v for lo, hi in blocks for v in (lo[d], hi[d]))):
			if clusters and v - clusters[-1][0] <= tol:
				clusters[-1].append(v)
			else:
				clusters.append([v])
		rep = {}
		for c in clusters:
			r = next((a for a in anchors[d] if c[0] - tol <= a <= c[-1] + tol), c[0])
			rep.update((v, r) for v in c)
		maps.append(rep)
	mx, my, mz = maps
	return [((mx[lo[0]], my[lo[1]], mz[lo[2]]), (mx[hi[0]], my[hi[1]], mz[hi[2]])) for lo, hi in blocks]


# ---------------------------------------------------------------------------------------------- touching pairs
def _planePairs(A, B, lo, hi, e, f, tol, out):
	"""Append ``(a, b, area)`` for the blocks ``a`` of ``A`` (ending on a plane) and ``b`` of ``B`` (starting on it) whose
	faces overlap over a positive area; spatial hashing of ``B`` in the plane's axes ``e, f`` (cells of the median
	block size) when the plane holds many blocks."""
	if len(A) * len(B) <= 64:
		for a in A:
			la, ha = lo[a], hi[a]
			for b in B:
				de = min(ha[e], hi[b][e]) - max(la[e], lo[b][e])
				if de > tol:
					df = min(ha[f], hi[b][f]) - max(la[f], lo[b][f])
					if df > tol:
						out.append((a, b, de * df))
		return
	ce = sorted(hi[b][e] - lo[b][e] for b in B)[len(B) // 2]
	cf = sorted(hi[b][f] - lo[b][f] for b in B)[len(B) // 2]
	grid = {}
	for b in B:
		for i in range(int((lo[b][e] + tol) // ce), int((hi[b][e] - tol) // ce) + 1):
			for j in range(int((lo[b][f] + tol) // cf), int((hi[b][f] - tol) // cf) + 1):
				grid.setdefault((i, j), []).append(b)
	empty = ()
	for a in A:
		ae0, ae1, af0, af1 = lo[a][e], hi[a][e], lo[a][f], hi[a][f]
		i0, i1 = int((ae0 + tol) // ce), int((ae1 - tol) // ce)
		j0, j1 = int((af0 + tol) // cf), int((af1 - tol) // cf)
		seen = set() if i1 > i0 or j1 > j0 else None
		for i in range(i0, i1 + 1):
			for j in range(j0, j1 + 1):
				for b in grid.get((i, j), empty):
					if seen is not None:
						if b in seen:
							continue
						seen.add(b)
					be0, be1, bf0, bf1 = lo[b][e], hi[b][e], lo[b][f], hi[b][f]
					de = (ae1 if ae1 < be1 else be1) - (ae0 if ae0 > be0 else be0)  # the inner loop: no min()/max() calls
					if de > tol:
						df = (af1 if af1 < bf1 else bf1) - (af0 if af0 > bf0 else bf0)
						if df > tol:
							out.append((a, b, de * df))


def _touching(blocks, tol):
	"""``(i, j, axis, area)`` for every two blocks sharing a face of positive area (coordinates snapped, so the planes of
	touching faces are equal): per axis, the blocks are grouped by the plane of their upper and of their lower face,
	and only blocks of the same plane are compared. O(number of blocks)."""
	lo, hi = [b[0] for b in blocks], [b[1] for b in blocks]
	found = []
	for d, (e, f) in enumerate(((1, 2), (0, 2), (0, 1))):
		ends, starts = {}, {}
		for i, p in enumerate(hi):
			ends.setdefault(p[d], []).append(i)
		for i, p in enumerate(lo):
			starts.setdefault(p[d], []).append(i)
		for plane, A in ends.items():
			B = starts.get(plane)
			if B:
				out = []
				_planePairs(A, B, lo, hi, e, f, tol, out)
				found += [(a, b, d, area) for a, b, area in out]
	return found


def _pairKind(u, v, axis):
	"""Kind of a pair of blocks of units ``u`` and ``v`` touching across a face of normal ``axis``."""
	if u is v:
		return 'internal'
	if u.kind == 'beam' or v.kind == 'beam':
		return 'beam'
	if u.kind == 'mortar' and v.kind == 'mortar':
		return 'mortar'
	if u.kind == 'mortar' or v.kind == 'mortar':
		return u.piece if u.kind == 'mortar' else v.piece
	return ('head', 'collar', 'bed')[axis]


# ---------------------------------------------------------------------------------------------- the layout
def wallLayout(length,
               height,
               thickness,
               brick=(0.25, 0.12, 0.055),
               joint=0.01,
               bond='running',
               blocksPerBrick=(1, 1, 1),
               mortar='interface',
               openings=(),
               baseBeam=None,
               topBeam=None,
               beamBlocks=1):
	"""The geometry of a brick wall as axis-aligned boxes and the pairs of boxes that touch face to face. Lengths in m.

	:param length, height, thickness: size of the masonry [m]; each must fit the brick module to 1e-9 relative (else
	    ValueError naming it, with the nearest valid values): ``height`` $= Nh + (N-1)t$ for $N \\geq 1$ courses;
	    ``length`` $= nl + (n-1)t$ with $n \\geq 1$ bricks per course (stack, running) or $n \\geq 2$ (english), or
	    $(n + 1/2)(l + t) - t$ (running) or $(n + 3/4)(l + t) - t$ (english: a three-quarter bat ends each stretcher row);
	    flemish: ``length`` $+ t = (1 + 1.5m)(l + t)$ or $(1.5 + 1.5m)(l + t)$, $m \\geq 1$; ``thickness``
	    $= nw + (n-1)t$, $n \\geq 1$ wythes (stack, running), $l$ or $l + t + w$ (english, flemish, which need $l = 2w + t$).
	:param brick: nominal $(l, w, h)$ of a brick [m].
	:param joint: mortar joint thickness $t$ [m], $0 \\leq t < \\min(l/3, w, h)$; 0 only with ``mortar='interface'``.
	:param bond: ``'stack'`` (bricks in columns), ``'running'`` (stretcher bond: odd courses offset by $(l + t)/2$, half
	    bats at their ends), ``'english'`` (stretcher and header courses alternate; queen closers next to the end headers
	    give a quarter-brick lap) or ``'flemish'`` (headers and stretchers alternate in each course, headers centred on
	    the stretchers below; queen closers or three-quarter bats at the ends). Both wall ends are flush. See
	    :ref:`wall layouts <rdem-wall-layout>` for sketches.
	:param blocksPerBrick: $(a, b, c)$ blocks along a brick's own length, width and height (a header's length runs
	    along $y$); bats and closers get $\\max(1, \\mathrm{round}(a \\times$ their length $/ l))$ along their length, and
	    likewise for the width and height. Blocks are cut at equal fractions of the brick's nominal box.
	:param mortar: ``'interface'``: a brick's box is its nominal box plus half of every joint it shares with another
	    brick (the wall's outer faces stay at the brick surfaces); the mortar is carried by the bonds.
	    ``'layer'``: bricks keep their nominal size and the mortar has boxes of its own (one block each): bed joints
	    cut at every brick and head-joint edge of the courses below and above (each bed piece lies under one unit and
	    over one unit), head joints $t$ long and as tall as the course, collar joints $t$ thick cut at the brick edges of
	    the wythes on both sides.
	:param openings: rectangles ``(x0, z0, width, height)`` [m] through the whole thickness, inside the wall and not
	    overlapping each other. Units overlapping one are cut at its edges into boxes; a piece the cut made shorter than
	    $l/4$ along $x$ (or $h/4$ along $z$) is dropped (:attr:`WallLayout.dropped`). Put the edges on joint mid-planes
	    (``'interface'``) or brick faces (``'layer'``) to cut no brick.
	:param baseBeam, topBeam: ``None`` or the height [m] of a beam spanning the whole length and thickness below
	    $z = 0$ or above $z = $ ``height``.
	:param beamBlocks: number of equal blocks of each beam along $x$.
	:return: a :class:`WallLayout`. Pair kinds: ``'internal'`` (two blocks of one unit), ``'beam'`` (one block is a
	    beam's), ``'bed'``, ``'head'``, ``'collar'`` (faces of normal $z$, $x$, $y$ between two units; in ``'layer'``
	    mode a brick-mortar face takes the joint of the mortar piece), ``'mortar'`` (two mortar pieces).

	ValueError for any argument out of range, naming it and the allowed values."""
	l, w, h, t, per = _checkArguments(length, height, thickness, brick, joint, bond, blocksPerBrick, mortar, baseBeam, topBeam, beamBlocks)
	modules = _fitThickness(thickness, bond, l, w, t)
	courses = _modular('height', height, h + t, t, lambda n: n >= 1, 'N*h + (N-1)*t for N >= 1 courses (h = %s, t = %s)' % (_fmt(h), _fmt(t)))
	valid, rule = _LENGTH_RULES[bond]
	quarters = _modular('length', length, (l + t) / 4, t, valid, '%s for bond=%r (l = %s, t = %s)' % (rule, bond, _fmt(l), _fmt(t)))
	f = _Frame(l, w, h, t, quarters, modules, courses, (float(length), float(thickness), float(height)))
	baseBeam, topBeam = (None if b is None else float(b) for b in (baseBeam, topBeam))
	openings = _checkOpenings(openings, f.length, f.height, f.tol)

	courseUnits = [_brickUnits(_COURSE_FUNCTIONS[bond](k, quarters, modules), k, f, mortar) for k in range(courses)]
	mortarUnits = _layerMortar(courseUnits, f) if mortar == 'layer' else []
	masonry = [u for units in courseUnits for u in units if u.kind != 'mortar'] + mortarUnits  # bricks by course, then mortar
	dropped, units = [], []
	for u in masonry:
		units += _cutByOpenings(u, openings, f, dropped) if openings else [u]
	if baseBeam is not None:
		units.insert(0, Unit('beam', 'base', None, -1, 0, (0.0, 0.0, -baseBeam), (f.length, f.thickness, 0.0)))
	if topBeam is not None:
		units.append(Unit('beam', 'top', None, courses, 0, (0.0, 0.0, f.height), (f.length, f.thickness, f.height + topBeam)))

	blocks, blockUnit = [], []
	for i, u in enumerate(units):
		boxes = _subdivide(u, _blockCounts(u, per, beamBlocks, f))
		u.blocks = list(range(len(blocks), len(blocks) + len(boxes)))
		blocks += boxes
		blockUnit += [i] * len(boxes)
	anchors = ([0.0, f.length] + [o[0] for o in openings] + [o[0] + o[2] for o in openings], [0.0, f.thickness],
	           [0.0, f.height] + [o[1] for o in openings] + [o[1] + o[3] for o in openings] + [-(baseBeam or 0.0), f.height + (topBeam or 0.0)])
	blocks = _snap(blocks, anchors, f.tol)
	for u in units:
		u.lo = tuple(min(blocks[b][0][d] for b in u.blocks) for d in range(3))
		u.hi = tuple(max(blocks[b][1][d] for b in u.blocks) for d in range(3))
	pairs = sorted((min(a, b), max(a, b), _pairKind(units[blockUnit[a]], units[blockUnit[b]], axis), area) for a, b, axis, area in _touching(blocks, f.tol))
	return WallLayout(length=f.length, height=f.height, thickness=f.thickness, brick=(l, w, h), joint=t, bond=bond, mortar=mortar, blocksPerBrick=per,
	                  openings=openings, baseBeam=baseBeam, topBeam=topBeam, beamBlocks=int(beamBlocks), courseCount=courses, units=units, blocks=blocks,
	                  blockUnit=blockUnit, pairs=pairs, dropped=dropped, _tol=f.tol)
