"""rdem.distributed's reading of a scene (features) and the refusals it leads to, and RdemBondKeeper's record of the bonds
across a cut, on real scenes of the plugin, in any YADE (without MPI every body counts as on the master, and the keeper
refuses). The runs on mpy are tests/mpi/test_mpy.py."""
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


if __name__ == '__main__':
	harness.run(Features)
