"""YADE's Qt viewer for refined-DEM scenes: blocks, broken springs coloured by failure mode, Poisson elements.

The blocks are :yref:`Box` es drawn by YADE's ``Gl1_Box``; the broken springs are drawn per segment by
``Gl1_RdemPhys`` (red tension, blue shear, amber crushing, green outline: a closed crack in contact) and, once a bond
has broken through and opened, by ``GlExtra_RdemReleasedBonds``; the Poisson
elements by ``GlExtra_RdemPoissonElements`` (off unless asked for). A YADE built without its GUI (``tools/setup.sh``
without ``--gui``), ``yade -n`` or a missing display leave :func:`available` false; scripts then run headless::

    from yade.rdem import gui
    if gui.available():
        gui.view()                  # a 3D view beside the controller YADE opens by itself
    gui.run(nSteps)                 # rdem.run(nSteps); with a view, O.run(nSteps) while the view draws
"""
import os
import time

import yade
from yade import O
from . import build


def available():
	"""Whether YADE's Qt viewer can be opened: a YADE with feature QT5 (GUI), started without ``-n``, with a display."""
	import yade.config
	import yade.runtime
	return 'QT5' in yade.config.features and bool(getattr(yade.runtime, 'hasDisplay', False))


def _require():
	if not available():
		raise RuntimeError('rdem.gui: no Qt viewer here (YADE built without GUI, started with -n, or no DISPLAY); '
		                   'check rdem.gui.available() first')


def configure(poissonElements=False, wireBlocks=True):
	"""Set YADE's renderer (``yade.qt.Renderer()``) up for the refined DEM and return it: interactions drawn by their
	physics (``intrPhys``, so ``Gl1_RdemPhys`` draws the broken segments), blocks as wire boxes unless ``wireBlocks`` is
	False (solid boxes hide the cracks inside the specimen), and among the extra drawers one
	``GlExtra_RdemReleasedBonds`` (the bonds broken through and opened, which no interaction shows any more) and one
	``GlExtra_RdemPoissonElements``, switched off (``dead``) unless ``poissonElements``."""
	_require()
	from yade import qt
	r = qt.Renderer()
	r.intrPhys = True
	r.wire = bool(wireBlocks)
	ours = (yade.wrapper.GlExtra_RdemPoissonElements, yade.wrapper.GlExtra_RdemReleasedBonds)
	drawers = [d for d in r.extraDrawers if not isinstance(d, ours)]
	r.extraDrawers = drawers + [yade.wrapper.GlExtra_RdemReleasedBonds(), yade.wrapper.GlExtra_RdemPoissonElements(dead=not poissonElements)]
	return r


def view(poissonElements=False, wireBlocks=True, viewDir=(-1.0, -1.6, -0.7), upVector=(0, 0, 1)):
	"""Open a 3D view (``yade.qt.View()``) of the whole scene seen along ``viewDir`` with ``upVector`` up, the renderer
	set by :func:`configure`, and return it. Raises RuntimeError when :func:`available` is false."""
	r = configure(poissonElements=poissonElements, wireBlocks=wireBlocks)
	from yade import qt
	v = qt.View()
	v.upVector = yade.Vector3(*upVector)
	v.viewDir = yade.Vector3(*viewDir)
	v.showEntireScene()
	_processEvents()
	return v


def _processEvents():
	from PyQt5.QtWidgets import QApplication
	app = QApplication.instance()
	if app is not None:
		app.processEvents()


def run(nSteps, poll=0.05):
	"""Make ``nSteps`` steps. Headless, :func:`rdem.run` (``O.step()`` in this thread: an engine's error is raised here
	with its own type). With the viewer, ``O.run(nSteps)`` in YADE's simulation thread while the Qt events are
	processed, so that the view and the controller keep drawing (a script runs in Qt's thread before YADE's shell
	starts its event loop). poll: seconds between two rounds of events."""
	if not available():
		build.run(nSteps)
		return
	O.run(nSteps)
	while O.running:
		_processEvents()
		time.sleep(poll)
	# An exception of the simulation thread ends the run and is printed by YADE (ThreadRunner's LOG_FATAL), but is not
	# raised here: O.wait() returns at once once the run has stopped, without looking at it (yadeWrapper.cpp, wait)
	O.wait()
	_processEvents()


def snapshot(view, fileName, timeout=20.0):
	"""Save ``view``'s next frame to ``fileName`` (``saveSnapshot`` of YADE's GLViewer, which writes it when it next
	draws, in QGLViewer's ``snapshotFormat``, JPEG by default, whatever the extension) and wait until the image is
	complete. Raises RuntimeError after ``timeout`` seconds."""
	_require()
	fileName = os.path.abspath(fileName)
	if os.path.exists(fileName):
		os.remove(fileName)
	view.saveSnapshot(fileName)
	end, size = time.time() + timeout, -1
	while True:  # written when the view next draws: wait for a complete image whose size no longer changes
		_processEvents()
		time.sleep(0.05)
		now = os.path.getsize(fileName) if os.path.exists(fileName) else 0
		if now > 0 and now == size and _isComplete(fileName):
			return fileName
		size = now
		if time.time() > end:
			raise RuntimeError('rdem.gui.snapshot: %s not written within %g s' % (fileName, timeout))


def _isComplete(fileName):
	"""Whether the file is a complete image (QGLViewer writes its ``snapshotFormat``, JPEG by default, whatever the
	file's extension)."""
	from PIL import Image
	try:
		with Image.open(fileName) as im:
			im.load()
		return True
	except Exception:
		return False
