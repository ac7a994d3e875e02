"""Arches and barrel vaults as refined-DEM scenes (``rdem.masonry.arch``): :func:`arch` lays one out
(:func:`rdem.arch_layout.archLayout`, :ref:`arches <rdem-arches>`), appends its blocks to ``O.bodies``, clumps each voussoir's three
boxes into one rigid body with the wedge's mass, centroid and in-plane rotational inertia, fixes the abutments or
foundations, and bonds the joints if they are mortared. :class:`Arch` measures what an engineer looks at: the drop of
the crown, and the opening of every joint on its intrados and extrados side (where hinges form).

Typical use::

    O.engines = rdem.engines(formulation=None, recontact='always', contactSamples=1, gravity=(0, 0, -9.81), damping=0.2)
    stone = RdemMat(young=1e9, poisson=0.2, density=2000, tensileStrength=float('inf'), frictionAngle=math.atan(1.0))
    a = rdem.masonry.arch(span=2.0, thickness=0.1, depth=0.2, voussoirs=8, material=stone)
"""
import math
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemJoint
from . import build
from .arch_layout import archLayout
from .masonry import _material

#: Colours by unit kind.
ARCH_COLORS = {'voussoir': Vector3(0.78, 0.7, 0.55), 'abutment': Vector3(0.5, 0.55, 0.65), 'pier': Vector3(0.7, 0.6, 0.5), 'foundation': Vector3(0.5, 0.55, 0.65)}


class Arch:
	"""An arch or vault made by :func:`arch`.

	:ivar layout: the :class:`rdem.arch_layout.ArchLayout`.
	:ivar ids: every block (clump members, supports).
	:ivar blocks: body id of each layout block (same order as ``layout.blocks``).
	:ivar voussoirs: per ring, the clump body ids of its voussoirs from the left springing.
	:ivar supports: body ids of the abutments, piers and foundations.
	:ivar fixed: body ids of the fixed blocks (abutments or foundations).
	:ivar nBonds: bonds made (mortared joints)."""

	def __init__(self, layout, blocks, clumps, nBonds):
		self.layout, self.blocks, self.nBonds = layout, blocks, nBonds
		self.ids = list(blocks)
		self.voussoirs = [[clumps[lay_u] for lay_u, u in enumerate(layout.units) if u.kind == 'voussoir' and u.ring == r] for r in range(layout.rings)]
		self.supports = [blocks[i] for u in layout.units if u.kind != 'voussoir' for i in u.blocks]
		self.fixed = [blocks[i] for i in layout.fixed()]
		self._clumpOfUnit = clumps
		self._ref = {}
		self.reference()

	def reference(self):
		"""Take the current state as the reference of :meth:`crownDrop` and :meth:`jointOpenings` (done at creation)."""
		self._ref = {}
		for k, u in enumerate(self.layout.units):
			b = O.bodies[self._bodyOf(k)]
			self._ref[k] = (Vector3(b.state.pos), Quaternion(b.state.ori))

	def _bodyOf(self, unit):
		u = self.layout.units[unit]
		return self._clumpOfUnit[unit] if u.kind == 'voussoir' else self.blocks[u.blocks[0]]

	def _now(self, unit, p):
		"""Where the material point of unit ``unit`` that was at ``p`` (x, y, z) in the reference is now."""
		pos0, ori0 = self._ref[unit]
		s = O.bodies[self._bodyOf(unit)].state
		return s.pos + s.ori * (ori0.conjugate() * (Vector3(*p) - pos0))

	def crownDrop(self, ring=0):
		"""Downward displacement of the crown's intrados [m]: of the voussoirs' joint at the crown (even N) or of the
		keystone's middle (odd N), at ring ``ring``."""
		vs = self.layout.voussoirs(ring)
		n = len(vs)
		faces = self.layout.jointFaces[ring]
		yc = vs[0].centroid[1]
		if n % 2 == 0:
			P = faces[n // 2][0]
			unit = self.layout.units.index(vs[n // 2])
		else:
			a, b = faces[n // 2][0], faces[n // 2 + 1][0]
			P = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
			unit = self.layout.units.index(vs[n // 2])
		return P[1] - self._now(unit, (P[0], yc, P[1]))[2]

	def jointOpenings(self, ring=0):
		"""Per joint of the ring from the left springing (0) to the right one: ``(intrados gap, extrados gap, relative
		rotation)``, the gaps [m] being the separation along the joint's normal of the two sides' material points that were
		at the joint's intrados and extrados points (positive: open, negative: the contact springs' compression), the rotation [rad] that of the right-hand voussoir
		(or support) relative to the left-hand one about $+y$. A hinge at the intrados has a closed intrados and an open
		extrados."""
		lay = self.layout
		vs = lay.voussoirs(ring)
		units = [lay.units.index(v) for v in vs]
		sup = {u.side: k for k, u in enumerate(lay.units) if u.ring == ring and u.kind in ('abutment', 'pier') and (u.kind == 'abutment' or u.index == lay.params['pierCourses'] - 1)}
		sides = [sup['left']] + units + [sup['right']]
		out = []
		yc = vs[0].centroid[1]
		for k, (P, Q) in enumerate(lay.jointFaces[ring]):
			left, right = sides[k], sides[k + 1]
			f = ((Q[0] - P[0]), (Q[1] - P[1]))
			n = Vector3(f[1], 0, -f[0]).normalized()  # normal to the joint in the x-z plane, towards the right-hand side
			gaps = []
			for p in (P, Q):
				a, b = self._now(left, (p[0], yc, p[1])), self._now(right, (p[0], yc, p[1]))
				gaps.append((b - a).dot(n))
			rot = []
			for unit in (left, right):
				q = O.bodies[self._bodyOf(unit)].state.ori * self._ref[unit][1].conjugate()
				axis, angle = q.toAxisAngle()
				rot.append(angle * axis[1])
			out.append((gaps[0], gaps[1], rot[1] - rot[0]))
		return out

	def hinges(self, ring=0, opening=None):
		"""The joints whose one side is open by more than ``opening`` [m] (default 1 % of the thickness) while the other
		stays closed: ``[(joint, 'intrados' or 'extrados')]``, the side where the joint turns (the closed one)."""
		tol = 0.01 * self.layout.params['thickness'] if opening is None else opening
		out = []
		for k, (gi, ge, _) in enumerate(self.jointOpenings(ring)):
			if max(gi, ge) > tol and min(gi, ge) < max(gi, ge) / 4:
				out.append((k, 'intrados' if gi < ge else 'extrados'))
		return out

	def __repr__(self):
		return 'Arch(%s, %d rings, %d voussoirs, %d blocks, %d bonds)' % (self.layout.params['shape'], self.layout.rings, sum(len(r) for r in self.voussoirs), len(self.ids),
		                                                                   self.nBonds)


def arch(span,
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
         ringGap=1e-3,
         joints='dry',
         material=None,
         jointMaterial=None,
         supportMaterial=None,
         origin=(0, 0, 0)):
	"""Build an arch or barrel vault into the current scene. The first sixteen arguments are :func:`rdem.arch_layout.archLayout`'s
	(lengths in m); ``O.engines`` must come from :func:`rdem.engines` first (for dry joints: ``recontact='always'`` and
	``contactSamples=1``, so that hinges form on the joints' edges as in the distinct element codes, :ref:`theory §4.2 <rdem-theory-4-2>`).

	:param joints: ``'dry'`` (voussoirs touch only through contacts) or ``'mortar'`` (every joint of a ring, the springings
	    and the pier courses bonded with ``jointMaterial``; rings of a vault stay dry).
	:param material: :yref:`RdemMat` of the voussoirs (its density gives their masses; friction of the dry joints).
	:param jointMaterial: :yref:`RdemJoint` of the mortared joints (``joints='mortar'`` only).
	:param supportMaterial: :yref:`RdemMat` of abutments, piers and foundations (default: ``material``).
	:param origin: where the layout's origin (the centreline's springing level, midspan, front face) goes [m].
	:return: an :class:`Arch`; ValueError naming the argument if one is out of range."""
	if material is None:
		raise ValueError('material = None: must be an RdemMat (or its index in O.materials)')
	mat = _material(material, 'material')
	supMat = _material(supportMaterial, 'supportMaterial') if supportMaterial is not None else mat
	if joints not in ('dry', 'mortar'):
		raise ValueError("joints = %r: must be 'dry' or 'mortar'" % (joints, ))
	if joints == 'mortar' and not isinstance(jointMaterial, RdemJoint):
		raise ValueError("jointMaterial = %r: joints='mortar' needs an RdemJoint" % (jointMaterial, ))
	if joints == 'dry' and jointMaterial is not None:
		raise ValueError("jointMaterial is for joints='mortar'; dry joints have the voussoirs' friction (material.frictionAngle)")
	if len(origin) != 3 or not all(math.isfinite(c) for c in origin):
		raise ValueError('origin = %r: must be 3 finite numbers [m]' % (origin, ))
	build.geomFunctor()  # fail early and clearly if the engines are not there
	lay = archLayout(span, thickness, depth, voussoirs, shape=shape, rise=rise, pointedness=pointedness, supports=supports, pierHeight=pierHeight,
	                 pierWidth=pierWidth, pierCourses=pierCourses, foundation=foundation, length=length, rings=rings, stagger=stagger, ringGap=ringGap)
	o = Vector3(*origin)
	bodies = []
	for blk in lay.blocks:
		unit = lay.units[blk.unit]
		m = supMat if unit.kind != 'voussoir' else mat
		b = build.block(o + Vector3(*blk.centre), blk.half, m, orientation=Quaternion(Vector3(0, 1, 0), blk.angle), color=ARCH_COLORS[unit.kind])
		if unit.kind == 'voussoir':  # the mass the layout gives each member (not the box's own volume)
			b.state.mass = m.density * blk.mass
			b.state.inertia = Vector3(*blk.inertia) * m.density
		bodies.append(b)
	blocks = O.bodies.append(bodies)
	clumps = {}
	for k, u in enumerate(lay.units):
		if u.kind == 'voussoir':
			c = O.bodies.clump([blocks[i] for i in u.blocks])
			clumps[k] = c
			s = O.bodies[c].state
			# the in-plane inertia: the wedge's (the y axis is principal: every member has it as one of its own)
			R = s.ori.toRotationMatrix()
			j = max(range(3), key=lambda c_: abs(R[1, c_]))
			inertia = Vector3(s.inertia)
			inertia[j] = mat.density * u.polar * lay.params['depth'] / lay.rings
			s.inertia = inertia
		else:
			clumps[k] = None
	for i in lay.fixed():
		O.bodies[blocks[i]].state.blockedDOFs = 'xyzXYZ'
	nBonds = 0
	if joints == 'mortar':
		pairs = [(blocks[i], blocks[j]) for i, j, kind in lay.pairs if kind != 'ring']
		nBonds = build.bondPairs(pairs, joint=jointMaterial)
	return Arch(lay, blocks, clumps, nBonds)
