"""Makes this checkout's py/rdem importable as ``yade.rdem`` (and, the same modules, as ``rdem``) in the launcher
build/bin/yade, which puts this folder on PYTHONPATH.

Merged into YADE's tree (tools/upstream.sh), py/rdem is installed inside YADE's own ``yade`` package and none of this is
needed. Out of tree, YADE's ``yade`` package lives in the cached install, which must stay shared between checkouts, so
the package is mapped in by an import finder instead: ``yade.rdem`` loads from py/rdem (its submodules then follow from
its ``__path__``), and ``rdem``/``rdem.X`` are the very module objects of ``yade.rdem``/``yade.rdem.X`` (one copy of
each module, whichever name a script uses). Python imports ``sitecustomize`` at start-up; Debian's own one, which this
file shadows, is run first."""
import importlib
import importlib.abc
import importlib.util
import os
import runpy
import sys

_SYSTEM = os.path.join(os.path.dirname(os.__file__), 'sitecustomize.py')
if os.path.exists(_SYSTEM):
	runpy.run_path(_SYSTEM)

_PACKAGE = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'py', 'rdem')


class _Alias(importlib.abc.Loader):
	"""Loads ``rdem.X`` as the already imported ``yade.rdem.X``."""

	def __init__(self, target):
		self.target = target

	def create_module(self, spec):
		return importlib.import_module(self.target)

	def exec_module(self, module):
		pass


class _Finder(importlib.abc.MetaPathFinder):

	def find_spec(self, name, path=None, target=None):
		if name == 'yade.rdem':
			return importlib.util.spec_from_file_location(name, os.path.join(_PACKAGE, '__init__.py'), submodule_search_locations=[_PACKAGE])
		if name == 'rdem' or name.startswith('rdem.'):
			return importlib.util.spec_from_loader(name, _Alias('yade.' + name), is_package=(name == 'rdem'))
		return None


sys.meta_path.insert(0, _Finder())
