"""Earthquakes: a ground motion (:mod:`rdem.ground_motion`: records read from PEER ``.AT2`` or two-column files, synthetic
pulses) applied to a scene by :yref:`RdemGroundShaker` (doc/earthquake.md).

Typical use::

    from rdem import ground_motion as gm
    motion = gm.GroundMotion(x=gm.readAT2('RSN6_IMPVALL.I_I-ELC180.AT2').baselineCorrected(2))
    rdem.earthquake.shaker(motion, ids=w.beams['base'])          # the base beam moves with the ground
    O.run(int(motion.duration / O.dt))
"""
from yade import O, Vector3
from yade.wrapper import RdemGroundShaker
from rdem import ground_motion
import rdem.build as build

MODES = ('prescribed', 'inertial')


def shaker(motion, ids=None, mode='prescribed', scale=1.0):
	"""Put an :yref:`RdemGroundShaker` playing ``motion`` into ``O.engines``, right before the :yref:`NewtonIntegrator`, and
	return it.

	:param motion: a :class:`rdem.ground_motion.GroundMotion`, or one :class:`rdem.ground_motion.Record` (taken as the x
	    component). Its velocity and displacement are integrated from its acceleration (baseline-correct the record first).
	:param ids: the base blocks that move with the ground (``mode='prescribed'``); their DOFs are blocked here.
	:param mode: ``'prescribed'`` (the base blocks follow the ground displacement exactly, as on a shaking table) or
	    ``'inertial'`` (no base motion; every body feels $-m\\,\\mathbf{a}_g(t)$ through :yref:`NewtonIntegrator::gravity`).
	:param scale: factor on the motion."""
	if isinstance(motion, ground_motion.Record):
		motion = ground_motion.GroundMotion(x=motion)
	if not isinstance(motion, ground_motion.GroundMotion):
		raise ValueError('motion = %r: must be an rdem.ground_motion.GroundMotion or Record' % (motion, ))
	if mode not in MODES:
		raise ValueError('mode = %r: must be one of %s' % (mode, MODES))
	newton = build.newtonIntegrator()
	ids = list(ids or [])
	if mode == 'prescribed':
		if not ids:
			raise ValueError("ids = %r: mode='prescribed' needs the base blocks that move with the ground" % (ids, ))
		for i in ids:
			if O.bodies[i] is None:
				raise ValueError('ids: body %s does not exist' % i)
			O.bodies[i].state.blockedDOFs = 'xyzXYZ'
	toVectors = lambda a: [Vector3(float(r[0]), float(r[1]), float(r[2])) for r in a]
	eng = RdemGroundShaker(mode=mode, times=[float(t) for t in motion.times()], accelerations=toVectors(motion.accelerations()),
	                       velocities=toVectors(motion.velocities()), displacements=toVectors(motion.displacements()), ids=ids,
	                       gravity=Vector3(newton.gravity), scale=float(scale), label='groundShaker')
	engines = list(O.engines)
	engines.insert(engines.index(newton), eng)
	O.engines = engines
	return eng
