"""Subdomains of blocks for YADE's MPI (``yade.mpy``) by recursive coordinate bisection.

Pure Python (standard library only, no YADE), so that it can be tested on its own; :mod:`rdem.distributed` writes the
result to :yref:`Body.subdomain`.

mpy (YADE 2025.2.0, ``py/mpy.py``) runs a master (rank 0) and workers (ranks 1 … N-1); each worker integrates the bodies
whose ``subdomain`` is its rank and sees, as ghosts, the bodies of other subdomains whose bounding boxes overlap the
bounding box of its own (one layer of blocks across a planar cut). Its own bisection
(``yade.bisectionDecomposition``) leaves every ``Box`` on the master, and :yref:`RdemBlock` is a ``Box``: the plugin
assigns its blocks itself.

Recursive coordinate bisection (Berger & Bokhari 1987, [Berger1987]_): the set of centroids is cut by a plane normal to
the longest side of its bounding box into two sets whose counts are in the ratio of the numbers of subdomains they get
(⌊k/2⌋ : ⌈k/2⌉), and each set again, until there is one set per subdomain. The plane is put between two distinct
coordinates (never through a layer of blocks whose centroids share that coordinate), at the gap nearest to the balanced
count: a grid is cut between its layers, a running-bond wall between its bricks, so that each subdomain is a
contiguous slab whose bounding box overlaps its neighbours' by one layer of blocks only.

Typical use::

    from rdem.partition import bisect
    parts = bisect([(0.1, 0, 0), (0.3, 0, 0), (0.5, 0, 0), (0.7, 0, 0)], 2)   # [0, 0, 1, 1]
"""

__all__ = ['bisect', 'counts', 'ranks', 'neighbourhood', 'refusals']


def _cut(order, coord, wanted, tol):
	"""Index k in 1 … len(order)-1: order[:k] below the plane, order[k:] above it, with coord[order[k-1]] and
	coord[order[k]] more than tol apart, k nearest to wanted (ties: the smaller k). None if all coordinates are equal."""
	best = None
	for k in range(1, len(order)):
		if coord(order[k]) - coord(order[k - 1]) > tol and (best is None or abs(k - wanted) < abs(best - wanted)):
			best = k
	return best


def bisect(centres, parts, tolerance=1e-9):
	"""Subdomain index 0 … parts-1 of each centroid (a list of the same length as ``centres``), by recursive coordinate
	bisection (see the module's description).

	:param centres: sequence of (x, y, z) [m].
	:param parts: number of subdomains, an integer >= 1 (mpy's workers: ranks 1 … parts; add 1 to the result).
	:param tolerance: coordinates closer than ``tolerance`` times the largest side of the bounding box of all centroids
	    are one layer, never cut between.
	:raises ValueError: ``parts`` not an integer >= 1, more parts than centroids, or a set that cannot be cut because
	    all its centroids coincide (then say so rather than make an empty subdomain)."""
	if not (isinstance(parts, int) and parts >= 1):
		raise ValueError('parts = %r: must be an integer >= 1' % (parts, ))
	pts = [tuple(float(c) for c in p) for p in centres]
	if any(len(p) != 3 for p in pts):
		raise ValueError('centres: every centroid must have 3 coordinates (x, y, z) [m]')
	if parts > len(pts):
		raise ValueError('parts = %d: more subdomains than blocks (%d); every subdomain must own at least one block' % (parts, len(pts)))
	result = [0] * len(pts)
	if not pts:
		return result
	span = max(max(p[d] for p in pts) - min(p[d] for p in pts) for d in range(3))
	tol = tolerance * span

	def split(ids, first, k):
		if k == 1:
			for i in ids:
				result[i] = first
			return
		kLow = k // 2
		lo = [min(pts[i][d] for i in ids) for d in range(3)]
		hi = [max(pts[i][d] for i in ids) for d in range(3)]
		# the longest side first; a side of one layer cannot be cut, then the next longest
		for d in sorted(range(3), key=lambda d: -(hi[d] - lo[d])):
			order = sorted(ids, key=lambda i: (pts[i][d], i))
			cut = _cut(order, lambda i: pts[i][d], len(ids) * kLow / k, tol)
			if cut is not None:
				break
		else:
			raise ValueError('bisect: %d blocks whose centroids coincide cannot be split into %d subdomains' % (len(ids), k))
		low, high = order[:cut], order[cut:]
		if len(low) < kLow or len(high) < k - kLow:
			raise ValueError('bisect: a cut between layers leaves %d and %d blocks for %d and %d subdomains; use fewer subdomains' %
			                 (len(low), len(high), kLow, k - kLow))
		split(low, first, kLow)
		split(high, first + kLow, k - kLow)

	split(list(range(len(pts))), 0, parts)
	return result


def counts(parts, n):
	"""Number of centroids in each of the n subdomains of ``parts`` (the result of :func:`bisect`)."""
	c = [0] * n
	for p in parts:
		c[p] += 1
	return c


def ranks(centres, master, workers):
	"""The rank of each block on mpy, and the number of blocks of each worker: the blocks whose indices are in ``master``
	stay on the master (rank 0), the others go to ranks 1 … ``workers`` by :func:`bisect` of their centroids
	(``centres``, in the order of the blocks). What :func:`rdem.distributed.assign` and :class:`rdem.distributed.PerRank`
	give :yref:`Body.subdomain`.

	:raises ValueError: what :func:`bisect` refuses."""
	others = [k for k in range(len(centres)) if k not in master]
	parts = bisect([centres[k] for k in others], workers)
	rank = [0] * len(centres)
	for k, p in zip(others, parts):
		rank[k] = p + 1
	return rank, counts(parts, workers)


def neighbourhood(parts, pairs, part, layers=2):
	"""Indices of the blocks of subdomain ``part`` and of every block within ``layers`` bonds of them, sorted: what a rank
	makes in a distributed set-up (mpy's ``DISTRIBUTED_INSERT``, :class:`rdem.distributed.PerRank`). One layer gives the
	rank's blocks all their bonds; the second gives each block of the first layer (a ghost after mpy's split) all of its
	bonds as well, so that the Poisson cells built on the rank (:yref:`RdemPoissonEngine` ``.build``), which take every
	bond of a block, are the serial ones for the rank's blocks and its ghosts, and with them the cell coefficients of the
	bonds between the two.

	:param parts: subdomain of each block (a list indexed by block).
	:param pairs: bonded pairs ``(i, j)`` of block indices.
	:param part: the subdomain whose neighbourhood to take.
	:param layers: bonds to go out from the subdomain's blocks (an integer >= 0).
	:raises ValueError: ``layers`` not an integer >= 0, or a pair naming a block outside ``parts``."""
	if not (isinstance(layers, int) and layers >= 0):
		raise ValueError('layers = %r: must be an integer >= 0' % (layers, ))
	n = len(parts)
	near = [[] for _ in range(n)]
	for i, j in pairs:
		if not (0 <= i < n and 0 <= j < n):
			raise ValueError('pairs: (%r, %r) names a block outside the %d of parts' % (i, j, n))
		near[i].append(j)
		near[j].append(i)
	chosen = set(k for k in range(n) if parts[k] == part)
	front = chosen
	for _ in range(layers):
		front = set(j for i in front for j in near[i]) - chosen
		chosen |= front
	return sorted(chosen)


def refusals(f):
	"""What keeps a scene from running on mpy identical to the serial run, as a list of messages (empty: it can run).

	``f`` is a dict of what the scene has (read by :func:`rdem.distributed.features`): ``others`` (ids of bodies that are
	not blocks), ``masterMoving`` (ids on the master that are not fixed), ``masterCells`` (ids on the master with a
	Poisson cell), ``hex8`` (the paper's hexahedra),
	``cells`` (blocks with a Poisson cell), ``exchange`` (an :yref:`RdemGhostExchange` in the engines), ``masterCellsReduced``
	(one that completes the cells on the master, :yref:`RdemGhostExchange::masterCells`), ``breakable`` (springs that can break). Missing keys count as absent."""
	out = []
	if f.get('others'):
		out.append('bodies that are not RdemBlock (ids %s...): only blocks are assigned to subdomains and exchanged' % (sorted(f['others'])[:5], ))
	if f.get('masterMoving'):
		out.append('bodies on the master (subdomain 0) that move (ids %s...): mpy sends the master\'s states to no worker, so only fixed '
		           'bodies (all DOFs blocked, at rest) may stay there' % (sorted(f['masterMoving'])[:5], ))
	if f.get('masterCells') and not f.get('masterCellsReduced'):
		out.append('bodies on the master (subdomain 0) with a Poisson cell (ids %s...): a cell\'s strain sums all its bonds, which mpy leaves '
		           'on the workers of the blocks they join, and no RdemGhostExchange completes them (RdemGhostExchange.masterCells, which '
		           'rdem.distributed.prepare sets); each worker would take the strain of its own part' % (sorted(f['masterCells'])[:5], ))
	if f.get('cells') and not f.get('exchange'):
		out.append('%d Poisson cells without an RdemGhostExchange: the strains of ghost blocks would come from the bonds the rank has, '
		           'not from all of theirs (rdem.distributed.prepare inserts it)' % f['cells'])
	if f.get('hex8'):
		out.append('%d hexahedral Poisson elements: an element across a subdomain boundary takes its scale from its 12 bonds, and the '
		           'bonds between two ghosts are reset by YADE\'s InteractionLoop on the ranks that hold them as ghosts, which would '
		           'release the element there at the first step; element scales are not exchanged yet (use cells: '
		           'RdemPoissonEngine.elements = \'cells\' with the consistent formulation)' % f['hex8'])
	return out
