"""The sources of pkg/rdem point only at documentation YADE will have once the plugin is merged (issue #28): no path of
a Markdown page of this project's doc/ (YADE has no such file), and every pointer to the theory page,
doc/sphinx/rdemTheory.rst (carried by tools/upstream.sh into YADE's doc/sphinx), names a section that exists there: a
``:ref:`… <rdem-theory-N-M>``` label in a docstring or ``doc/sphinx/rdemTheory.rst §N.M`` in a comment."""
import glob
import os
import re
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
THEORY = os.path.join(ROOT, 'doc', 'sphinx', 'rdemTheory.rst')


def sources(pattern=os.path.join('pkg', '**', '*.[ch]pp')):
	files = sorted(glob.glob(os.path.join(ROOT, pattern), recursive=True))
	out = []
	for f in files:
		with open(f, encoding='utf-8') as fh:
			out.append((os.path.relpath(f, ROOT), fh.read()))
	return out


def mdPaths(text):
	"Paths of Markdown files under doc/ named in a text."
	return re.findall(r'\bdoc/[\w./-]*\.md\b', text)


class DocPointers(unittest.TestCase):

	def test_sources_found(self):
		self.assertGreaterEqual(len(sources()), 40)

	def test_no_markdown_page_of_doc(self):
		found = ['%s: %s' % (f, p) for f, text in sources() for p in mdPaths(text)]
		self.assertEqual(found, [], 'pkg/ points at doc/*.md, which YADE does not have; use the theory page (docstrings: '
		                 ':ref:`theory §N <rdem-theory-N>`, comments: doc/sphinx/rdemTheory.rst §N) or state the fact: ' + '; '.join(found))

	def test_the_check_sees_a_pointer(self):
		self.assertEqual(mdPaths('see (doc/theory.md §5.4) and doc/performance.md.'), ['doc/theory.md', 'doc/performance.md'])
		self.assertEqual(mdPaths('doc/sphinx/rdemTheory.rst §5.4, rdem.md'), [])

	def test_theory_labels_exist(self):
		with open(THEORY, encoding='utf-8') as fh:
			theory = fh.read()
		labels = set(re.findall(r'^\.\. _(rdem-theory[\w-]*):$', theory, re.M))
		sections = set(re.findall(r'^(\d+(?:\.\d+)?)\.?\s.*\n[-~=]{4,}$', theory, re.M))
		self.assertIn('rdem-theory-5-4', labels)
		self.assertIn('5.4', sections)
		bad, used = [], 0
		# pkg/rdem, and the docstrings of py/rdem (also carried into YADE's tree)
		for f, text in sources() + sources(os.path.join('py', 'rdem', '*.py')):
			for label in re.findall(r'<(rdem-theory[\w-]*)>`', text):
				used += 1
				if label not in labels:
					bad.append('%s: label %s' % (f, label))
			for sec in re.findall(r'doc/sphinx/rdemTheory\.rst §(\d+(?:\.\d+)?)', text):
				used += 1
				if sec not in sections:
					bad.append('%s: §%s' % (f, sec))
		self.assertGreater(used, 40)
		self.assertEqual(bad, [], 'pointers to sections the theory page does not have: ' + '; '.join(bad))


if __name__ == '__main__':
	unittest.main()
