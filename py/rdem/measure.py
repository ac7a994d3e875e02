"""Post-processing: per-segment state, break counts, apparent elastic constants."""
from yade import O
from yade.wrapper import RdemGeom, RdemPhys
from . import build


def segmentTable():
	"""Every bonded segment of the scene as a list of dicts: ``id1``, ``id2``, ``point`` (global), ``normal`` (global, body 1 to 2),
	``area``, ``state`` (0 intact, 1 broken in tension, 2 broken in shear), ``sigma`` (positive in tension) and ``tau`` [Pa]."""
	rows = []
	for I in O.interactions:
		if not I.isReal or not isinstance(I.geom, RdemGeom) or not isinstance(I.phys, RdemPhys):
			continue
		g, p = I.geom, I.phys
		s1 = O.bodies[I.id1].state
		n = s1.ori * g.segNormal1
		for k, (pt, area) in enumerate(zip(g.segPoint1, g.segArea)):
			rows.append(dict(id1=I.id1, id2=I.id2, point=s1.pos + s1.ori * pt, normal=n, area=area, state=p.segState[k], sigma=p.segSigma[k], tau=p.segTau[k]))
	return rows


def bondSnapshot():
	"""Every bonded segment of the scene now, to follow later which ones break (a bond whose springs have all broken
	and opened is released, and then no longer appears among the interactions): a list of tuples
	(id1, id2, k, point and normal in body 1's frame, in-plane axis t1 in body 1's frame, half-sizes)."""
	snap = []
	for I in O.interactions:
		if I.isReal and isinstance(I.geom, RdemGeom) and isinstance(I.phys, RdemPhys):
			g = I.geom
			for k, pt in enumerate(g.segPoint1):
				snap.append((I.id1, I.id2, k, pt, g.segNormal1, g.segTangent1, (g.segHalfSizes[0], g.segHalfSizes[1])))
	return snap


def brokenSegments(snapshot):
	"""The segments of a :func:`bondSnapshot` whose restoring spring has broken since, in global coordinates: dicts with
	``point``, ``normal``, ``t1``, ``t2``, ``halfSizes``, ``state`` (1 tension, 2 shear) and ``released`` (True once the
	whole bond has broken through and opened: the law released it and keeps its record in
	:yref:`Law2_RdemGeom_RdemPhys_FaceSprings.releasedBonds`; ``state`` is then read there, and is 3 if that list was
	cleared)."""
	records = {}
	for r in build.law().releasedBonds:
		records[(r.id1, r.id2)] = r.segState
	out = []
	for id1, id2, k, pt, n1, t1, half in snapshot:
		I = O.interactions[id1, id2] if O.interactions.has(id1, id2) else None
		real = I is not None and I.isReal and isinstance(I.phys, RdemPhys) and len(I.phys.segState) > k
		if real:
			state = I.phys.segState[k]
		else:
			record = records.get((id1, id2))
			state = record[k] if record is not None and len(record) > k else 3
		if state == 0:
			continue
		s1 = O.bodies[id1].state
		n, t = s1.ori * n1, s1.ori * t1
		out.append(dict(id1=id1, id2=id2, point=s1.pos + s1.ori * pt, normal=n, t1=t, t2=n.cross(t), halfSizes=half, state=state, released=not real))
	return out


#: The plugin's cumulated dissipated energies in O.energy [J]: the springs' (Law2_RdemGeom_RdemPhys_FaceSprings: dashpots,
#: friction, broken springs, contact springs dropped while loaded, and with softening bonds fracture and crushing) and the
#: Poisson cells' released by cracks (RdemPoissonEngine); not YADE's own (``nonviscDamp``, Cundall's damping).
DISSIPATED = ('rdemBondBreak', 'rdemContactRelease', 'rdemDashpot', 'rdemFriction', 'rdemPoissonRelease', 'rdemFractureTension', 'rdemFractureShear', 'rdemCrushing')


def dissipatedEnergy(energies=None):
	"""The sum of :data:`DISSIPATED` in ``energies`` (a dict of O.energy's items; default: O.energy now), each absent one 0 [J]."""
	e = dict(O.energy.items()) if energies is None else energies
	return sum(e.get(name, 0.0) for name in DISSIPATED)


def breakCounts():
	"""(tension, shear): restoring springs broken so far (eqs. 15, 16)."""
	law = build.law()
	return int(law.tensionBreaks), int(law.shearBreaks)


def pairStrain(i, j):
	"""Engineering strain of the centroid distance of bodies i and j along their reference direction (positive = longer)."""
	a, b = O.bodies[i].state, O.bodies[j].state
	d0 = b.refPos - a.refPos
	return (b.pos - a.pos - d0).dot(d0) / d0.squaredNorm()


def apparentPoisson(lateralPairs, axialPairs):
	"""Apparent Poisson's ratio from centroid displacements, as in the paper's §5.3.1: $\\nu_{app} = -\\varepsilon_{lat}/\\varepsilon_{ax}$,
	each strain the mean :func:`pairStrain` of the given pairs of body ids."""
	eAx = sum(pairStrain(i, j) for i, j in axialPairs) / len(axialPairs)
	eLat = sum(pairStrain(i, j) for i, j in lateralPairs) / len(lateralPairs)
	return -eLat / eAx if eAx else float('nan')


def engineShare(engineClass, steps, repeats=3):
	"""Share of the step time spent in the engine of class ``engineClass`` of O.engines, from YADE's per-engine timing
	(:yref:`O.timingEnabled<Omega.timingEnabled>`) over ``repeats`` runs of ``steps`` steps; the run with the smallest
	share counts (execTime is wall time: other processes on the machine inflate single runs). Returns (share, engine
	time per step, total engine time per step) [-, µs, µs]."""
	shares = []
	for k in range(repeats):
		for e in O.engines:
			e.execTime = 0
		O.timingEnabled = True
		build.run(steps)
		O.timingEnabled = False
		engine = next(e for e in O.engines if isinstance(e, engineClass)).execTime
		total = sum(e.execTime for e in O.engines)
		shares.append((engine / total, engine / steps / 1e3, total / steps / 1e3))
	return min(shares)


def totalNormalStress(I):
	"""Total normal stress of a bond's face in the last step, tension > 0 [Pa]: its springs' largest σ plus the Poisson
	cells' normal stress on it, (c₁S₁ + c₂S₂)/(w_n A) (:yref:`RdemState.cellStress`, :yref:`RdemPhys.cellCoef1`), what the
	springs break on with :yref:`Law2_RdemGeom_RdemPhys_FaceSprings.totalStress` (:ref:`theory §5.6 <rdem-theory-5-6>`)."""
	g, p = I.geom, I.phys
	a, b = O.bodies[I.id1].state, O.bodies[I.id2].state
	ax1 = max(range(3), key=lambda k: abs(g.segNormal1[k]))
	ax2 = max(range(3), key=lambda k: abs(g.segNormal2[k]))
	return max(p.segSigma) + (p.cellCoef1 * a.cellStress[ax1] + p.cellCoef2 * b.cellStress[ax2]) / (p.weightNormal * g.segArea[0] * len(g.segArea))
