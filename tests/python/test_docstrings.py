"""Every public function, class and method of the Python package rdem (py/rdem) has a docstring, since the user
guide's reference (tools/docs.sh, doc/sphinx/reference/python.rst) is made from them; every command-line option of the
scripts (scripts/, and the option groups py/rdem adds to them) has a help text, since ``--help`` is their documentation.
Read from the sources with ast, so that the modules that need YADE are checked too, without it. Public: a name that
does not start with _, defined at module level or in a public class; a property or method counts once.
(The plugin's C++ classes and attributes: tests/yade/test_docstrings.py.)"""
import ast
import glob
import os
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
PY = os.path.join(ROOT, 'py', 'rdem')


def undocumented(path):
	"The public definitions of one module without a docstring, as 'module.name' or 'module.Class.name'."
	with open(path, encoding='utf-8') as f:
		tree = ast.parse(f.read(), path)
	mod = os.path.basename(path)[:-3]
	out = [] if ast.get_docstring(tree) else [mod + ' (module)']
	defs = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)
	for node in tree.body:
		if not isinstance(node, defs) or node.name.startswith('_'):
			continue
		if not ast.get_docstring(node):
			out.append('%s.%s' % (mod, node.name))
		if isinstance(node, ast.ClassDef):
			for sub in node.body:
				if isinstance(sub, defs) and not sub.name.startswith('_') and not ast.get_docstring(sub):
					setter = any(isinstance(d, ast.Attribute) and d.attr in ('setter', 'deleter') for d in sub.decorator_list)
					if not setter:
						out.append('%s.%s.%s' % (mod, node.name, sub.name))
	return out


def optionsWithoutHelp(path):
	"""The ``add_argument`` calls of a file without a non-empty ``help=``, as 'file:line --option'. Parsers made with
	``add_help=False`` (a first pass that reads one option before the real parser is built) are left out."""
	with open(path, encoding='utf-8') as f:
		tree = ast.parse(f.read(), path)
	silent = set()
	for node in ast.walk(tree):
		if isinstance(node, ast.Assign) and isinstance(node.value, ast.Call):
			kw = {k.arg: k.value for k in node.value.keywords}
			if isinstance(kw.get('add_help'), ast.Constant) and kw['add_help'].value is False:
				silent.update(t.id for t in node.targets if isinstance(t, ast.Name))
	out = []
	for node in ast.walk(tree):
		if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == 'add_argument':
			if isinstance(node.func.value, ast.Name) and node.func.value.id in silent:
				continue
			h = {k.arg: k.value for k in node.keywords}.get('help')
			if h is None or (isinstance(h, ast.Constant) and not str(h.value).strip()):
				name = node.args[0].value if node.args and isinstance(node.args[0], ast.Constant) else '?'
				out.append('%s:%d %s' % (os.path.relpath(path, ROOT), node.lineno, name))
	return out


class Docstrings(unittest.TestCase):

	def test_modules_found(self):
		# the check below must not pass because it found nothing
		self.assertGreaterEqual(len(glob.glob(os.path.join(PY, '*.py'))), 10)

	def test_every_public_definition_has_a_docstring(self):
		missing = []
		for path in sorted(glob.glob(os.path.join(PY, '*.py'))):
			missing += undocumented(path)
		self.assertEqual(missing, [], 'public definitions of py/rdem without a docstring (the reference is made from them): ' + ', '.join(missing))

	def test_every_script_option_has_help(self):
		files = sorted(glob.glob(os.path.join(ROOT, 'scripts', '*.py')) + glob.glob(os.path.join(PY, '*.py')))
		self.assertGreaterEqual(len(files), 20)
		missing = [m for f in files for m in optionsWithoutHelp(f)]
		self.assertEqual(missing, [], 'options without a help text (--help is their documentation): ' + ', '.join(missing))

	def test_the_check_sees_an_option_without_help(self):
		import tempfile
		with tempfile.NamedTemporaryFile('w', suffix='.py', delete=False) as f:
			f.write("import argparse\npre = argparse.ArgumentParser(add_help=False)\npre.add_argument('--a')\n"
			        "p = argparse.ArgumentParser()\np.add_argument('--a', help='A')\np.add_argument('--b')\np.add_argument('--c', help='')\n")
		try:
			self.assertEqual([m.split(' ')[1] for m in optionsWithoutHelp(f.name)], ['--b', '--c'])
		finally:
			os.unlink(f.name)

	def test_the_check_sees_a_missing_docstring(self):
		import tempfile
		with tempfile.NamedTemporaryFile('w', suffix='.py', delete=False) as f:
			f.write('"""m"""\ndef a():\n\t"""a"""\ndef b():\n\tpass\nclass C:\n\t"""C"""\n\tdef m(self):\n\t\tpass\n\tdef _p(self):\n\t\tpass\n')
		try:
			mod = os.path.basename(f.name)[:-3]
			self.assertEqual(undocumented(f.name), [mod + '.b', mod + '.C.m'])
		finally:
			os.unlink(f.name)


if __name__ == '__main__':
	unittest.main()
