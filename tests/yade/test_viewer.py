"""YADE's Qt viewer shows the cracked cube: a 3D view of the compression test (4x4x4 blocks, scripts/compression.py's
scene reduced as in test_compression_reduced.py) is saved to PNG before loading and after the cube has cracked, and the
pictures are read back.

What must hold, and why it can fail:
* the picture is not blank: the standard deviation of its grey levels is above 0.02 (a blank or one-colour frame, e.g.
  a view that never drew, has 0);
* before loading no pixel has a crack colour (Gl1_RdemPhys draws broken segments only; a crack colour in the intact
  picture would be something else drawn in it);
* after cracking, at least MIN_CRACK_PIXELS pixels have the tension colour (the cracks are tensile splitting, paper
  §5.3): Gl1_RdemPhys draws without lighting, so its pixels have exactly Gl1_RdemPhys.tensionColor (within 8/255 per
  channel for the 8-bit picture and the driver's rounding).

Runs under xvfb-run through CTest (CMakeLists.txt) when YADE was built with its GUI; otherwise it prints why and
reports itself skipped (exit code 77)."""
import os
import sys
import tempfile
import unittest
import harness
import yade
import yade.config
import yade.runtime
from yade import O
from yade import rdem
from yade.rdem import gui

SKIP = 77  # CTest's SKIP_RETURN_CODE for this test
# One broken 2x2 segment of the 4-block cube (5 cm blocks, 2.5 cm segments, quads at fill 0.9) covers about 15x15 pixels
# in the 600x600 view of the 24 cm tall scene; the splitting cracks break dozens of segments, so 300 pixels (about two
# segments' worth, partly hidden behind others) is a floor well below what a cracked cube shows and far above zero.
MIN_CRACK_PIXELS = 300
COLOUR_TOL = 8 / 255.0


def crackPixels(image, colour):
	"""Number of pixels of image (an H x W x 3+ float array in [0, 1]) within COLOUR_TOL of colour in every channel."""
	import numpy
	return int(numpy.all(numpy.abs(image[:, :, :3] - numpy.array(colour)) <= COLOUR_TOL, axis=2).sum())


def load(fileName):
	"""RGB of a snapshot as floats in [0, 1] (QGLViewer writes JPEG by default, whatever the extension)."""
	import numpy
	from PIL import Image
	with Image.open(fileName) as im:
		return numpy.asarray(im.convert('RGB'), dtype=float) / 255


class Viewer(unittest.TestCase):

	def testCrackedCubeIsDrawn(self):
		import numpy
		from yade.rdem.scenes import CompressionTest
		harness.freshScene()
		CompressionTest(blocksPerEdge=4, formulation='consistent', rate=10e-3)  # dt 2e-6 s, 10 000 steps to 0.2 mm
		view = gui.view()
		view.screenSize = (600, 600)
		view.showEntireScene()
		out = tempfile.mkdtemp(prefix='rdem-viewer-')
		intact = load(gui.snapshot(view, os.path.join(out, 'intact.jpg')))
		gui.run(int(round(0.2e-3 / 10e-3 / O.dt)))  # 0.2 mm of the loading plate: past the splitting failure
		broken = sum(rdem.breakCounts())  # a bond broken through becomes a sampled contact: count the breaks
		self.assertGreater(broken, 20, 'the cube did not crack: %d broken springs' % broken)
		cracked = load(gui.snapshot(view, os.path.join(out, 'cracked.jpg')))
		red = yade.wrapper.Gl1_RdemPhys().tensionColor
		for name, picture in (('intact', intact), ('cracked', cracked)):
			grey = numpy.mean(picture[:, :, :3], axis=2)
			self.assertGreater(float(grey.std()), 0.02, '%s picture is blank (grey levels %.3f ± %.3f)' % (name, grey.mean(), grey.std()))
		nIntact, nCracked = crackPixels(intact, red), crackPixels(cracked, red)
		print('viewer: %d broken springs; tension-coloured pixels: %d intact, %d cracked (of %d); pictures in %s' %
		      (broken, nIntact, nCracked, cracked.shape[0] * cracked.shape[1], out))
		self.assertEqual(nIntact, 0)
		self.assertGreaterEqual(nCracked, MIN_CRACK_PIXELS)


if __name__ == '__main__':
	if not gui.available():
		print('test_viewer: SKIPPED: no Qt viewer here (YADE features: %s, the viewer needs QT5; display: %s); it runs under '
		      'xvfb-run when YADE is built with its GUI (tools/setup.sh --gui) and xvfb-run is installed' %
		      (' '.join(yade.config.features), 'yes' if getattr(yade.runtime, 'hasDisplay', False) else 'none or -n'))
		sys.exit(SKIP)
	harness.run(Viewer)
