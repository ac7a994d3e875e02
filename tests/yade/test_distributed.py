"""rdem.distributed's reading of a scene (features) and the refusals it leads to, and RdemBondKeeper's record of the bonds
across a cut, on real scenes of the plugin, in any YADE (without MPI every body counts as on the master, and the keeper
refuses). The runs on mpy are tests/mpi/test_mpy.py."""
import os
import unittest
import harness
from yade import O
from yade.rdem import scenes, build, partition, distributed


def cube(formulation):
	O.reset()
	t = scenes.CompressionTest(blocksPerEdge=4, formulation=formulation)
	if formulation == 'consistent':
		build.poissonEngine().elements = 'cells'
		build.poissonEngine().build(t.ids)
	return t


class Features(unittest.TestCase):

	def test_hexahedra_refused(self):
		cube('paper')
		f = distributed.features()
		self.assertEqual(f['hex8'], 45)  # 3 x 3 x 5 elements on the 4 x 4 x 6 grid of blocks (cube and platens)
		self.assertTrue(any('hexahedral' in r for r in partition.refusals(f)))

	def test_cells_need_the_exchange(self):
		cube('consistent')
		f = distributed.features()
		self.assertEqual((f['cells'], f['hex8'], f['exchange']), (96, 0, False))
		self.assertTrue(any('RdemGhostExchange' in r for r in partition.refusals(f)))

	def test_springs_only_on_workers(self):
		cube(None)
		f = distributed.features()
		self.assertEqual((f['cells'], f['hex8'], len(f['others'])), (0, 0, 0))
		# every block is on the master in a YADE without MPI (or before assign): moving ones are refused there
		self.assertEqual(len(f['masterMoving']), 96)
		self.assertEqual(len(partition.refusals(f)), 1)

	def test_bond_keeper_records_the_bonds_across_the_cut(self):
		from yade import Body
		from yade.wrapper import RdemBondKeeper
		t = cube(None)
		keeper = RdemBondKeeper()
		if not hasattr(Body(), 'subdomain'):  # a YADE without MPI has no subdomains: keep() says so
			with self.assertRaisesRegex(RuntimeError, 'built without MPI'):
				keeper.keep()
			return
		distributed.assign(2)
		# the 4 x 4 x 6 grid (cube and platens) cut between its 3rd and 4th layers: 16 bonds across the cut
		self.assertEqual(keeper.keep(), 16)
		self.assertEqual(len(t.ids), 96)

	def partWall(self, only=None):
		"""A running-bond wall with cells, or the part ``only`` chooses (rdem.masonry.wall(only=), as a rank makes it in a
		set-up per rank: rdem.distributed.PerRank, which needs mpy; here the same choice by rdem.partition directly)."""
		from yade.wrapper import RdemMat, RdemJoint
		from yade.rdem import masonry
		O.reset()
		brick = RdemMat(young=16.7e9, poisson=0.15, density=1800, tensileStrength=2e6, cohesion=4e6, frictionAngle=0.6)
		O.materials.append(brick)
		O.engines = build.engines(formulation='consistent', failureStress='total', recontact='always', dt=1e-9)
		mortar = RdemJoint(young=5e9, poisson=0.2, tensileStrength=0.3e6, cohesion=0.5e6, frictionAngle=0.6)
		w = masonry.wall(8 * 0.26 - 0.01, 6 * 0.065 - 0.01, 0.12, bond='running', brickMaterial=brick, jointMaterial=mortar, only=only)
		build.poissonEngine().elements = 'cells'
		build.poissonEngine().build(w.made)
		bonds = {(I.id1, I.id2): (I.phys.cellCoef1, I.phys.cellCoef2, I.phys.weightNormal, I.phys.weightShear) for I in O.interactions if I.isReal}
		cells = {i: (O.bodies[i].state.pos, O.bodies[i].state.cellVolume, O.bodies[i].state.cellStiffness) for i in w.made}
		return w, bonds, cells

	def test_a_part_of_a_wall_is_the_whole_walls_there(self):
		whole, wholeBonds, wholeCells = self.partWall()
		lay = whole.layout
		parts = [p + 1 for p in partition.bisect([tuple((lo[d] + hi[d]) / 2 for d in range(3)) for lo, hi in lay.blocks], 2)]
		own = [k for k in range(len(parts)) if parts[k] == 1]
		chosen = partition.neighbourhood(parts, [(p[0], p[1]) for p in lay.pairs], 1)
		part, bonds, cells = self.partWall(only=lambda layout: chosen)
		self.assertEqual(part.ids, whole.ids)  # the whole wall's ids, on every rank alike
		self.assertEqual(part.made, [whole.ids[k] for k in chosen])
		self.assertLess(len(part.made), len(whole.ids))
		self.assertEqual(len(O.bodies), max(part.made) + 1)
		# every pair of two blocks made is bonded, as in the whole wall
		made = set(part.made)
		self.assertEqual(set(bonds), set(k for k in wholeBonds if k[0] in made and k[1] in made))
		# the rank's blocks and those one bond out (its ghosts) have the whole wall's cells, and their bonds its
		# coefficients and weights: the second layer gives the ghosts all their bonds
		ghosts = set(j for i, j, *_ in lay.pairs if parts[i] == 1 and parts[j] != 1) | set(i for i, j, *_ in lay.pairs if parts[j] == 1 and parts[i] != 1)
		near = set(whole.ids[k] for k in own) | set(whole.ids[k] for k in ghosts)
		self.assertTrue(ghosts)
		for i in near:
			self.assertEqual(cells[i], wholeCells[i], i)
		for k, v in bonds.items():
			if k[0] in near and k[1] in near:
				self.assertEqual(v, wholeBonds[k], k)


class SerialScenesUnderMpiexec(unittest.TestCase):
	"""A serial scene launched by mpiexec would run whole on every process (each writing the same outputs): rdem.engines
	refuses it unless it is made for YADE's MPI (distributed=True). The launcher's environment is set here as
	Open MPI's and MPICH's mpiexec set it for 3 processes."""

	LAUNCHERS = ('OMPI_COMM_WORLD_SIZE', 'PMI_SIZE')

	def launchedBy(self, name):
		"""The environment of a process that mpiexec launched as one of 3 (name: the launcher's variable), or of a process
		it did not launch (None); the test's environment is restored at its end."""
		saved = {n: os.environ.get(n) for n in self.LAUNCHERS}

		def restore():
			for n, v in saved.items():
				if v is None:
					os.environ.pop(n, None)
				else:
					os.environ[n] = v

		self.addCleanup(restore)
		for n in self.LAUNCHERS:
			os.environ.pop(n, None)
		if name:
			os.environ[name] = '3'

	def test_refused_unless_distributed(self):
		for name in self.LAUNCHERS:
			self.launchedBy(name)
			self.assertEqual(build.mpiProcesses(), 3)
			O.reset()
			with self.assertRaisesRegex(RuntimeError, 'one of 3 that mpiexec launched'):
				build.engines()
			with self.assertRaisesRegex(RuntimeError, 'one of 3 that mpiexec launched'):
				scenes.CompressionTest(blocksPerEdge=2)
			self.assertGreater(len(build.engines(distributed=True)), 0)
			self.assertEqual(len(scenes.CompressionTest(blocksPerEdge=2, distributed=True).ids), 16)

	def test_serial_process(self):
		self.launchedBy(None)
		self.assertEqual(build.mpiProcesses(), 1)
		self.assertGreater(len(build.engines()), 0)
		with self.assertRaisesRegex(ValueError, '^distributed'):
			build.engines(distributed='yes')
		with self.assertRaisesRegex(ValueError, '^beamCell'):
			scenes.runningBondWall(100, beamCell='no')


if __name__ == '__main__':
	harness.run(Features, SerialScenesUnderMpiexec)
