"""Walls for the tests of the Poisson cells (doc/theory.md §5.4): a homogeneous wall (joints of the brick's own material)
between frictionless platens, and the residual of a uniform uniaxial-stress state.

Platens are plates of the same material extruded from the wall's blocks on the two faces normal to the load axis (one
plate block per wall block, as the paper's 10×10 plates), their translation along that axis prescribed, rotations
blocked: free to follow the lateral expansion, so the specimen is in uniaxial stress."""
from yade import O, Vector3
from yade.wrapper import RdemMat, RdemJoint
from yade import rdem

E = 16.7e9  # [Pa]
BRICK, JOINT = (0.25, 0.12, 0.055), 0.01  # [m]
PLATE = 0.02  # plate thickness [m]


def wallSize(bond, wythes, bricks=3, courses=4):
	"""(length, height, thickness) of a wall of ``bricks`` stretchers per course and ``courses`` courses [m]."""
	l, w, h = BRICK
	t = JOINT
	thickness = {'running': wythes * w + (wythes - 1) * t, 'stack': wythes * w + (wythes - 1) * t, 'english': l, 'flemish': l}[bond]
	return bricks * l + (bricks - 1) * t, courses * h + (courses - 1) * t, thickness


def homogeneousWall(bond, wythes, blocksPerBrick, nu, load, bricks=3, courses=4, elements='auto'):
	"""A wall whose joints have the brick's E and nu (so the body is homogeneous) between platens normal to axis ``load``,
	consistent formulation, Poisson engine built with ``elements``. Returns (wall, plates): plates = ([ids on the low side], [ids on the high side])."""
	O.reset()
	mat = O.materials.append(RdemMat(young=E, poisson=nu, density=1800, tensileStrength=float('inf'), cohesion=float('inf'), label='brick'))
	O.engines = rdem.engines(formulation='consistent', recontact=False, dt=1e-9)
	same = RdemJoint(young=E, poisson=nu, tensileStrength=float('inf'), cohesion=float('inf'))
	length, height, thickness = wallSize(bond, wythes, bricks, courses)
	wall = rdem.masonry.wall(length, height, thickness, brick=BRICK, joint=JOINT, bond=bond, blocksPerBrick=blocksPerBrick, brickMaterial=mat,
	                         jointMaterial=same)
	hi = Vector3(length, thickness, height)
	plates = ([], [])
	pairs = []
	for i in wall.ids:
		b = O.bodies[i]
		c, h = b.state.pos, b.shape.extents
		for side, at in ((0, 0.0), (1, hi[load])):
			face = c[load] + (h[load] if side else -h[load])
			if abs(face - at) > 1e-9:
				continue
			centre, half = Vector3(c), Vector3(h)
			half[load] = PLATE / 2
			centre[load] = at + (PLATE / 2 if side else -PLATE / 2)
			p = O.bodies.append(rdem.block(centre, half, mat))
			plates[side].append(p)
			pairs.append((i, p))
	rdem.bondPairs(pairs)
	rdem.bond(plates[0])
	rdem.bond(plates[1])
	for p in plates[0] + plates[1]:
		O.bodies[p].state.blockedDOFs = 'xyz'[load] + 'XYZ'
	rdem.poissonEngine().elements = elements
	rdem.poissonEngine().build(wall.ids + plates[0] + plates[1])
	return wall, plates


def uniformResidual(wall, plates, nu, load, eps=1e-5):
	"""Place every block on the uniform uniaxial-stress field (strain eps along ``load``, -nu*eps across), block it, run one
	step. Returns (largest free-DOF force over a bed face's spring force, largest torque over that force times a brick
	length, apparent E / E from the reaction on the high-side plates)."""
	ids = wall.ids + plates[0] + plates[1]
	strain = Vector3(-nu * eps, -nu * eps, -nu * eps)
	strain[load] = eps
	for i in ids:
		s = O.bodies[i].state
		s.pos = s.refPos + Vector3(*(strain[d] * s.refPos[d] for d in range(3)))
		s.vel = s.angVel = Vector3.Zero
		s.blockedDOFs = 'xyzXYZ'
	O.step()
	l, w, h = BRICK
	lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
	scale = (lam + 2 * mu) * abs(eps) * l * w  # one bed face's spring force: the scale of the terms that cancel
	platen = set(plates[0] + plates[1])
	worstF = worstT = 0
	for i in ids:
		f, t = O.forces.f(i), O.forces.t(i)
		free = [f[d] for d in range(3) if not (i in platen and d == load)]
		worstF = max(worstF, max(abs(x) for x in free) / scale)
		worstT = max(worstT, t.norm() / (scale * l))
	area = sum(4 * O.bodies[p].shape.extents[(load + 1) % 3] * O.bodies[p].shape.extents[(load + 2) % 3] for p in plates[1])
	reaction = sum(O.forces.f(p)[load] for p in plates[1])
	return worstF, worstT, -reaction / (area * E * eps)
