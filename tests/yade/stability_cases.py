"""Scenes and measurements of the stability suite, shared by tests/yade/test_stability.py and scripts/stability_sweep.py.

Energy. Leapfrog (YADE's NewtonIntegrator) conserves exactly, for a quadratic potential U, the *shadow* energy
H_n = 1/2 v_{n-1/2}.M v_{n+1/2} + U(x_n) (the discrete energy of the Stormer-Verlet scheme: Hairer, Lubich & Wanner,
Geometric Numerical Integration, 2nd ed., §I.1.4 and §IX; the proof for quadratic U is one line: H_{n+1} - H_n =
1/2 v_{n+1/2}.(F_n + F_{n+1}) dt - 1/2 (F_n + F_{n+1}).(x_{n+1} - x_n) = 0). O.energy['kinetic'] uses one half-step
velocity only, so kinetic + elastic oscillates by O(omega dt) even in a perfectly stable run; :func:`shadowEnergy`
takes one extra step to form H_n, so what remains is the true error: geometric non-linearity (finite rotations) and
round-off, and exponential growth when the step is beyond the stability limit.
U = rdemElastic (springs) + rdemPoisson (Poisson elements), both evaluated at x_n during step n."""
import math
import random
import numpy as np
from yade import O, Vector3, Quaternion
from yade.wrapper import RdemMat
from yade import rdem

E = 30e9  # concrete, paper Table 1 [Pa]
H = 0.01  # half-size of the 2 cm blocks of the paper's §5 [m]
INF = float('inf')


def elasticEnergy():
	"""Springs plus Poisson elements at x_n [J] (needs O.trackEnergy)."""
	d = dict(O.energy.items())
	return d.get('rdemElastic', 0) + d.get('rdemPoisson', 0)


def dissipatedEnergy():
	"""The plugin's cumulated dissipated energies (rdem.dissipatedEnergy) [J]."""
	return rdem.dissipatedEnergy()


def _velocities():
	return [(b.state.mass, Vector3(b.state.vel), Vector3(b.state.inertia), Vector3(b.state.angVel)) for b in O.bodies]


def shadowEnergy():
	"""Make one step and return H = 1/2 v_{n-1/2}.M v_{n+1/2} + U(x_n) + dissipated of that step [J] (module docstring).
	Rotation: 1/2 w_{n-1/2}.I w_{n+1/2} with the principal inertia (blocks rotate little in these tests)."""
	before = _velocities()
	O.step()
	after = _velocities()
	kin = 0
	for (m, v0, I, w0), (_, v1, _, w1) in zip(before, after):
		kin += 0.5 * m * v0.dot(v1) + 0.5 * sum(I[k] * w0[k] * w1[k] for k in range(3))
	return kin + elasticEnergy() + dissipatedEnergy()


def stateIsFinite():
	"""Whether every body's position, orientation, velocity and angular velocity is finite."""
	for b in O.bodies:
		s = b.state
		vals = list(s.pos) + list(s.vel) + list(s.angVel) + [s.ori[k] for k in range(4)]
		if not all(math.isfinite(v) for v in vals):
			return False
	return True


def deepestPenetration(ids):
	"""Largest depth, relative to the smaller half-extent, by which a corner or the centroid of one block of ids lies
	inside another (0 if none): blocks passing through one another. Grid neighbours touch, with round-off overlaps."""
	pos = np.array([list(O.bodies[i].state.pos) for i in ids])
	rot = np.array([np.array(O.bodies[i].state.ori.toRotationMatrix()) for i in ids])
	half = np.array([list(O.bodies[i].shape.extents) for i in ids])
	signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)] + [[0, 0, 0]], float)
	worst = 0.0
	for a in range(len(ids)):
		pts = pos[a] + (signs * half[a]) @ rot[a].T  # 8 corners + centroid of block a
		for b in range(len(ids)):
			if a == b or np.linalg.norm(pos[a] - pos[b]) > np.linalg.norm(half[a]) + np.linalg.norm(half[b]):
				continue
			local = (pts - pos[b]) @ rot[b]  # in b's frame
			depth = np.min(half[b] - np.abs(local), axis=1)  # > 0 inside b
			worst = max(worst, float(depth.max()) / min(half[a].min(), half[b].min()))
	return worst


def removeRigidMotion(ids):
	"""Subtract the rigid translation and rotation of ids from their velocities (zero linear and angular momentum)."""
	m = np.array([O.bodies[i].state.mass for i in ids])
	x = np.array([list(O.bodies[i].state.pos) for i in ids])
	v = np.array([list(O.bodies[i].state.vel) for i in ids])
	w = np.array([list(O.bodies[i].state.angVel) for i in ids])
	Ib = np.array([list(O.bodies[i].state.inertia) for i in ids])
	c = (m[:, None] * x).sum(0) / m.sum()
	v -= (m[:, None] * v).sum(0) / m.sum()
	r = x - c
	L = (m[:, None] * np.cross(r, v)).sum(0) + (Ib * w).sum(0)
	J = sum(mi * (ri.dot(ri) * np.eye(3) - np.outer(ri, ri)) + np.diag(Ii) for mi, ri, Ii in zip(m, r, Ib))
	omega = np.linalg.solve(J, L)
	v -= np.cross(omega, r)
	w -= omega
	for k, i in enumerate(ids):
		O.bodies[i].state.vel = Vector3(*v[k])
		O.bodies[i].state.angVel = Vector3(*w[k])


def perturb(ids, speed, seed=1):
	"""Random velocities of magnitude ~speed [m/s] and angular velocities ~speed/H, free of rigid motion: a free
	assembly then only vibrates (with net angular momentum, the paper's non-corotational Poisson elements turn a slow
	rigid rotation into a growing mode at high nu; doc/stability.md)."""
	rnd = random.Random(seed)
	for i in ids:
		O.bodies[i].state.vel = Vector3(*(rnd.uniform(-speed, speed) for _ in range(3)))
		O.bodies[i].state.angVel = Vector3(*(rnd.uniform(-speed, speed) / H for _ in range(3)))
	removeRigidMotion(ids)


def setDtFraction(fraction, method='lanczos'):
	"""O.dt = fraction * RdemTimeStepper's estimate of the current scene by method ('lanczos', the default, within 0.1 %
	below the exact limit; 'gershgorin', 2.2-2.7 times below it); returns the estimate [s]. Above the Lanczos estimate
	the stepper's refusal is switched off (to measure instability on purpose)."""
	est = rdem.timeStepper().estimate(method)
	rdem.timeStepper().refuseUnstableDt = fraction * est <= rdem.timeStepper().estimate('lanczos')
	O.dt = fraction * est
	return est


def exactCriticalDt(ids):
	"""The exact linear limit 2/omega_max [s] of the free DOFs of ids (every other body held fixed), omega_max^2 the
	largest eigenvalue of M^-1/2 K M^-1/2, K the stiffness assembled column by column from one-sided finite
	differences of the forces and torques (1e-9 m and 1e-7 rad: linear range, 7 digits above the round-off of the
	forces); blocks aligned with the global axes (principal inertia = global). The scene is restored (positions,
	orientations, blocked DOFs, O.dt) but its iteration count advances by 6 per DOF plus 1."""
	saved = [(O.bodies[i].state.blockedDOFs, Vector3(O.bodies[i].state.pos), Quaternion(O.bodies[i].state.ori), Vector3(O.bodies[i].state.vel),
	          Vector3(O.bodies[i].state.angVel)) for i in ids]
	dt, refuse = O.dt, rdem.timeStepper().refuseUnstableDt
	free = [(a, d) for a, i in enumerate(ids) for d in range(6) if 'xyzXYZ'[d] not in saved[a][0]]
	O.dt = 1e-12
	rdem.timeStepper().refuseUnstableDt = False
	for i in ids:  # held in place: blocked, at rest (a blocked DOF keeps moving at its velocity)
		O.bodies[i].state.blockedDOFs = 'xyzXYZ'
		O.bodies[i].state.vel = O.bodies[i].state.angVel = Vector3.Zero
	h = 1e-9

	def forces():
		O.step()
		return np.array([(list(O.forces.f(ids[a])) + list(O.forces.t(ids[a])))[d] for a, d in free])

	try:
		f0 = forces()
		K = np.zeros((len(free), len(free)))
		for col, (a, d) in enumerate(free):
			s = O.bodies[ids[a]].state
			axis = Vector3(*[1.0 if k == d % 3 else 0.0 for k in range(3)])
			if d < 3:
				s.pos, step = saved[a][1] + axis * h, h
			else:
				s.ori, step = Quaternion(axis, h / 0.01) * saved[a][2], h / 0.01
			K[:, col] = -(forces() - f0) / step
			s.pos, s.ori = saved[a][1], saved[a][2]
	finally:
		for i, (blocked, pos, ori, vel, angVel) in zip(ids, saved):
			s = O.bodies[i].state
			s.blockedDOFs, s.pos, s.ori, s.vel, s.angVel = blocked, pos, ori, vel, angVel
		O.dt = dt
		rdem.timeStepper().refuseUnstableDt = refuse
	m = np.array([(O.bodies[ids[a]].state.mass if d < 3 else O.bodies[ids[a]].state.inertia[d - 3]) for a, d in free])
	A = K / np.sqrt(np.outer(m, m))
	return 2 / math.sqrt(np.linalg.eigvalsh((A + A.T) / 2).max())


def grid(nu=0.2, formulation='consistent', counts=(3, 3, 3), corotational=False, tensileStrength=INF, cohesion=INF):
	"""A free, bonded grid of 2 cm concrete cubes (no collider: nothing breaks or separates unless strengths are finite)."""
	O.reset()
	mat = O.materials.append(RdemMat(young=E, poisson=nu, tensileStrength=tensileStrength, cohesion=cohesion))
	breakable = tensileStrength < INF or cohesion < INF
	O.engines = rdem.engines(formulation=formulation, corotational=corotational, recontact=breakable, dt=1e-9)
	ids = rdem.blockGrid(counts, (2 * H, ) * 3, mat)
	rdem.bond(ids)
	if formulation:
		rdem.poissonEngine().build(ids)
	O.trackEnergy = True
	return ids


def brickMortar(contrast, nx=3, ny=2):
	"""Masonry-like stack of 3 brick layers (E, blocks 4 x 2 x 2 cm, aspect 2:1) and 2 mortar layers (E/contrast,
	blocks 4 x 2 x 0.4 cm, aspect 10:1), all bonded, consistent Poisson elements across the layers."""
	O.reset()
	brick = O.materials.append(RdemMat(young=E, poisson=0.2, tensileStrength=INF, label='brick'))
	mortar = O.materials.append(RdemMat(young=E / contrast, poisson=0.2, tensileStrength=INF, label='mortar'))
	O.engines = rdem.engines(formulation='consistent', recontact=False, dt=1e-9)
	ids, z = [], 0.0
	for mat, height in ((brick, 0.02), (mortar, 0.004), (brick, 0.02), (mortar, 0.004), (brick, 0.02)):
		ids += rdem.blockGrid((nx, ny, 1), (0.04, 0.02, height), mat, origin=(0, 0, z))
		z += height
	rdem.bond(ids)
	rdem.poissonEngine().elements = 'hex8'  # the elements across the layers are the case (elements='auto' would take cells)
	rdem.poissonEngine().build(ids)
	O.trackEnergy = True
	return ids


def energyRun(steps, samples=20):
	"""Run steps (plus one per sample) and return (H0, [H_k]) of :func:`shadowEnergy`, stopping early if the state
	is no longer finite."""
	H0 = shadowEnergy()
	hist = []
	chunk = max(1, steps // samples - 1)
	for _ in range(samples):
		try:
			rdem.run(chunk)
			h = shadowEnergy()
		except RuntimeError:  # RdemFiniteGuard: a position, velocity or force became NaN or infinite
			hist.append(INF)
			break
		hist.append(h)
		if not (math.isfinite(h) and stateIsFinite()):
			break
	return H0, hist


def worstTotalDeviation(steps):
	"""Largest |E - E0|/|E0| of O.energy.total() over the steps, E0 after the first two (the first tracked step has
	no earlier velocity to pair with: NewtonIntegrator's value stands there)."""
	rdem.run(2)
	E0 = O.energy.total()
	worst = 0.0
	for _ in range(steps):
		O.step()
		worst = max(worst, abs(O.energy.total() - E0) / abs(E0))
	return worst


def worstEnergyError(H0, hist):
	"""max |H_k - H0| / H0 (inf if a sample is not finite)."""
	return max((abs(h - H0) / H0 if math.isfinite(h) else INF) for h in hist)
