"""Every class the plugin registers (the YADE_PLUGIN lists of pkg/rdem), every attribute it defines and every method it
adds has a docstring in the live build: the user guide's reference (tools/docs.sh) is made from them, as YADE's is.
The classes are found in the sources, not listed here, so a new class without a docstring fails this test. Renderers
(Gl*) exist only in a YADE built with its viewer and are checked there. (Python functions of py/rdem:
tests/python/test_docstrings.py.)"""
import os
import sys
import unittest
import harness
import yade

ROOT = os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', '..')  # under YADE, __file__ names its launcher
sys.path.insert(0, os.path.join(ROOT, 'doc', 'sphinx'))
import rdem_classes  # noqa: E402  the guide's reader of the classes, so that the test checks what the guide shows

GUI = hasattr(yade.wrapper, 'OpenGLRenderer')
# a class docstring shorter than this is a placeholder, not documentation
MIN_CLASS_DOC = 40


class Docstrings(unittest.TestCase):

	def setUp(self):
		self.names = rdem_classes.classNames(ROOT)

	def classes(self):
		for name in self.names:
			cls = rdem_classes.liveClass(name)
			if cls is None and name.startswith('Gl') and not GUI:
				continue  # a renderer, compiled only with the viewer
			self.assertIsNotNone(cls, '%s is registered by pkg/rdem but not in yade.wrapper' % name)
			yield name, cls

	def test_classes_found(self):
		# the checks below must not pass because the sources were not read
		for name in ('RdemMat', 'RdemBlock', 'RdemPhys', 'Law2_RdemGeom_RdemPhys_FaceSprings', 'RdemPoissonEngine', 'RdemTimeStepper'):
			self.assertIn(name, self.names)
		self.assertGreaterEqual(len(self.names), 15)

	def test_class_docstrings(self):
		short = ['%s (%d characters)' % (n, len(rdem_classes.classDoc(c))) for n, c in self.classes() if len(rdem_classes.classDoc(c)) < MIN_CLASS_DOC]
		self.assertEqual(short, [], 'classes without a docstring: ' + ', '.join(short))

	def test_attribute_docstrings(self):
		missing, count = [], 0
		for name, cls in self.classes():
			attrs, _ = rdem_classes.members(cls)
			count += len(attrs)
			missing += ['%s.%s' % (name, k) for k, text, fields in attrs if not text.strip()]
		self.assertGreater(count, 50)  # RdemMat alone has more than ten
		self.assertEqual(missing, [], 'attributes without a docstring: ' + ', '.join(missing))

	def test_method_docstrings(self):
		missing = []
		for name, cls in self.classes():
			_, methods = rdem_classes.members(cls)
			missing += ['%s.%s' % (name, k) for k, doc in methods if not rdem_classes.methodDoc(doc).strip()]
		self.assertEqual(missing, [], 'methods without a docstring: ' + ', '.join(missing))

	def test_attribute_types_and_defaults_read(self):
		# what the reference shows of an attribute: its text, type and default, read from YADE's docstring format
		attrs, _ = rdem_classes.members(yade.wrapper.RdemMat)
		young = {k: (text, fields) for k, text, fields in attrs}['young']
		self.assertIn('Young', young[0])
		self.assertEqual(young[1]['yattrtype'], 'Real')
		self.assertNotIn(':ydefault:', young[0])
		self.assertEqual(rdem_classes.splitAttrDoc(' :ydefault:`0` :yattrtype:`Real` :yattrflags:`2` ')[0], '')


if __name__ == '__main__':
	harness.run(Docstrings)
