"""ParaView output of what YADE's own VTKRecorder does not know: crack faces (broken segments) and Poisson elements.

Blocks themselves are written by YADE's ``VTKRecorder(recorders=['boxes'])``. Files are VTK XML unstructured grids
(``.vtu``, ASCII) plus a ``.pvd`` collection per series so ParaView can play them in time."""
import os
from yade import O
from . import build, measure


def _writeVtu(path, points, cells, cellType, cellData):
	with open(path, 'w') as f:
		f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n<UnstructuredGrid>\n')
		f.write('<Piece NumberOfPoints="%d" NumberOfCells="%d">\n<Points>\n<DataArray type="Float64" NumberOfComponents="3" format="ascii">\n' %
		        (len(points), len(cells)))
		f.write('\n'.join('%.9g %.9g %.9g' % tuple(p) for p in points))
		f.write('\n</DataArray>\n</Points>\n<Cells>\n<DataArray type="Int64" Name="connectivity" format="ascii">\n')
		f.write('\n'.join(' '.join(str(i) for i in c) for c in cells))
		f.write('\n</DataArray>\n<DataArray type="Int64" Name="offsets" format="ascii">\n')
		off = 0
		offsets = []
		for c in cells:
			off += len(c)
			offsets.append(str(off))
		f.write(' '.join(offsets))
		f.write('\n</DataArray>\n<DataArray type="UInt8" Name="types" format="ascii">\n')
		f.write(' '.join([str(cellType)] * len(cells)))
		f.write('\n</DataArray>\n</Cells>\n<CellData>\n')
		for name, values in cellData.items():
			f.write('<DataArray type="Float64" Name="%s" format="ascii">\n%s\n</DataArray>\n' % (name, ' '.join('%.9g' % v for v in values)))
		f.write('</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n')


def blockCorners(body):
	"""The 8 corners of an :yref:`RdemBlock` body in the current configuration [m], in VTK's hexahedron order (the face
	$z^-$ counter-clockwise, then $z^+$, in the block's frame)."""
	a, b, c = body.shape.extents
	p, q = body.state.pos, body.state.ori
	local = [(-a, -b, -c), (a, -b, -c), (a, b, -c), (-a, b, -c), (-a, -b, c), (a, -b, c), (a, b, c), (-a, b, c)]
	return [tuple(p + q * type(p)(*v)) for v in local]


def writeBlocks(path, blocks):
	"""Write the blocks as one ParaView file (``.vtu``, a hexahedron each): ``blocks`` a list of ``(id, rank, corners)``
	(:func:`blockCorners`), for instance gathered from every rank of a run on YADE's MPI onto one (YADE's
	``VTKRecorder`` in ``parallelMode`` writes boxes on the master only, which holds no block there). Cell data: ``id``,
	``rank``."""
	d = os.path.dirname(path)
	if d:
		os.makedirs(d, exist_ok=True)
	blocks = sorted(blocks)
	points = [p for _, _, corners in blocks for p in corners]
	cells = [list(range(8 * k, 8 * k + 8)) for k in range(len(blocks))]
	_writeVtu(path, points, cells, 12, {'id': [float(i) for i, _, _ in blocks], 'rank': [float(r) for _, r, _ in blocks]})


class CrackExport:
	"""Writes ``<prefix>cracks.<iter>.vtu`` (one quad per segment broken since the export was made: ``state`` 1 tension,
	2 shear, 3 broken, mode unknown; ``released`` 1 where the whole bond has broken through and opened) and
	``<prefix>poisson.<iter>.vtu`` (one hexahedron per Poisson element on the current centroids, with its force scale), plus
	``.pvd`` collections. Call :meth:`write` from a :yref:`PyRunner`, and :meth:`close` at the end."""

	def __init__(self, prefix):
		self.prefix = prefix
		d = os.path.dirname(prefix)
		if d:
			os.makedirs(d, exist_ok=True)
		self.series = {'cracks': [], 'poisson': []}
		self.snapshot = measure.bondSnapshot()  # the bonds of the scene when the export starts

	def write(self):
		"""Write the files of the current step: the broken segments and, if the scene has a Poisson engine, its elements."""
		self._cracks()
		try:
			self._poisson(build.poissonEngine())
		except RuntimeError:
			pass  # no Poisson engine in this scene

	def _cracks(self):
		points, cells, state, released = [], [], [], []
		for sg in measure.brokenSegments(self.snapshot):
			c, t1, t2 = sg['point'], sg['t1'], sg['t2']
			h1, h2 = sg['halfSizes']
			base = len(points)
			points += [c - h1 * t1 - h2 * t2, c + h1 * t1 - h2 * t2, c + h1 * t1 + h2 * t2, c - h1 * t1 + h2 * t2]
			cells.append([base, base + 1, base + 2, base + 3])
			state.append(sg['state'])
			released.append(1 if sg['released'] else 0)
		self._save('cracks', points, cells, 9, {'state': state, 'released': released})

	def _poisson(self, eng):
		nodes = eng.nodes
		scales = eng.elementScales()
		order = [0, 1, 3, 2, 4, 5, 7, 6]  # our node a = i + 2j + 4k to VTK_HEXAHEDRON's counter-clockwise order
		points, cells = [], []
		for e in range(eng.nElements):
			base = len(points)
			points += [O.bodies[nodes[8 * e + a]].state.pos for a in range(8)]
			cells.append([base + a for a in order])
		self._save('poisson', points, cells, 12, {'scale': scales})

	def _save(self, kind, points, cells, cellType, data):
		path = '%s%s.%d.vtu' % (self.prefix, kind, O.iter)
		_writeVtu(path, points, cells, cellType, data)
		self.series[kind].append((O.time, os.path.basename(path)))

	def close(self):
		"""Write the ``.pvd`` collections (time series for ParaView)."""
		for kind, entries in self.series.items():
			with open('%s%s.pvd' % (self.prefix, kind), 'w') as f:
				f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n')
				for t, name in entries:
					f.write('<DataSet timestep="%.9g" file="%s"/>\n' % (t, name))
				f.write('</Collection>\n</VTKFile>\n')
