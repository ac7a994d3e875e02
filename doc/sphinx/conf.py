# Sphinx configuration of the yade-rdem user guide. Built by tools/docs.sh, which runs Sphinx inside YADE with the
# plugin (build/bin/yade), as YADE builds its own documentation (YADE's doc/sphinx/yadeSphinx.py): the reference is
# made from the live classes' docstrings, so it documents exactly what the build contains.
#
# YADE conventions kept so that the same docstrings render here and in YADE's own documentation: the roles :yref:
# (a class or attribute; ours link into this guide, YADE's to yade-dem.org), :ydefault:, :yattrtype:, :yattrflags:
# (shown in the attribute's signature), $...$ for inline math in .rst and docstrings, [Key]_ citations of
# doc/references.bib.
import os, re, sys, inspect, textwrap
import docutils.nodes as nodes
import docutils.utils
from docutils.parsers.rst import Directive, roles
from docutils.statemachine import StringList
from sphinx import addnodes
from sphinx.util.nodes import nested_parse_with_titles

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, '..', '..'))
sys.path.insert(0, os.path.join(root, 'py'))
sys.path.insert(0, here)
import rdem_classes  # noqa: E402  the plugin's classes, read from pkg/rdem

project = 'yade-rdem'
author = 'the yade-rdem authors'
copyright = 'GPL-2.0-or-later'
extensions = ['myst_parser', 'sphinx.ext.mathjax', 'sphinx.ext.autodoc']
source_suffix = {'.rst': 'restructuredtext', '.md': 'markdown'}
master_doc = 'index'
exclude_patterns = ['_build']
myst_enable_extensions = ['dollarmath', 'colon_fence']
myst_heading_anchors = 3
# MathJax from Debian's libjs-mathjax: the guide reads offline
mathjax_path = 'file:///usr/share/javascript/mathjax/MathJax.js?config=TeX-AMS-MML_HTMLorMML'
html_theme = 'alabaster'
html_static_path = []
html_theme_options = {'page_width': '1200px', 'sidebar_width': '260px'}
autodoc_member_order = 'bysource'
autodoc_default_options = {'members': True, 'undoc-members': True}
# the Markdown reports of doc/ point at files of the repository (scripts, tests) that are not pages of the guide
suppress_warnings = ['myst.xref_missing', 'myst.header', 'ref.citation']

YADE_WRAPPER = 'https://yade-dem.org/doc/yade.wrapper.html#yade.wrapper.'

# Every Markdown page of doc/ is a topic of the guide: topics/<name>.md (generated here, not in git) includes it, so a
# page added to doc/ appears without touching the guide. theory.md (a pointer to rdemTheory.rst), validation.md and
# changelog.md have their own places. Each page gets the label rdem-<name> (doc/wall-layout.md: rdem-wall-layout;
# validation.md and changelog.md: rdem-validation, rdem-changelog), by which the docstrings of py/rdem refer to it
# (``:ref:`wall layouts <rdem-wall-layout>```), since YADE's tree has no doc/*.md (tests/python/test_doc_pointers.py).
TOPICS = os.path.join(here, 'topics')
os.makedirs(TOPICS, exist_ok=True)
for _f in os.listdir(TOPICS):
	if _f.endswith('.md'):
		os.remove(os.path.join(TOPICS, _f))
for _f in sorted(os.listdir(os.path.join(root, 'doc'))):
	if _f.endswith('.md') and _f not in ('theory.md', 'validation.md', 'changelog.md'):
		with open(os.path.join(TOPICS, _f), 'w', encoding='utf-8') as _out:
			_out.write('(rdem-%s)=\n```{include} ../../%s\n:relative-images:\n```\n' % (_f[:-3], _f))
OURS = set(rdem_classes.classNames(root))


def replaceLaTeX(s):
	"$...$ to :math:`...`, as YADE's doc/sphinx/conf.py does; \\$ to $."
	s = re.sub(r'(?<!\\)\$([^\$]+)(?<!\\)\$', r'\\ :math:`\1`\\ ', s)
	return re.sub(r'\\\$', r'$', s)


def yref_role(role, rawtext, text, lineno, inliner, options={}, content=[]):
	"A YADE class or attribute: ``:yref:`Class```, ``:yref:`Class::attr```, ``:yref:`text<target>```."
	txt = target = docutils.utils.unescape(text)
	m = re.match(r'(.*?)\s*<(.*)>\s*$', target, re.S)
	if m:
		txt, target = m.group(1), m.group(2)
	target = target.replace('::', '.')
	cls = target.split('.')[0]
	if cls in OURS:
		node = addnodes.pending_xref('', refdomain='py', reftype='attr' if '.' in target else 'class', reftarget='yade.wrapper.' + target,
		                             refexplicit=True, refwarn=True)
		node += nodes.literal(txt, txt)
		return [node], []
	return [nodes.reference(rawtext, txt, refuri=YADE_WRAPPER + target, **options)], []


def empty_role(role, rawtext, text, lineno, inliner, options={}, content=[]):
	return [], []


roles.register_canonical_role('yref', yref_role)
for r in ('ydefault', 'yattrtype', 'yattrflags'):
	roles.register_canonical_role(r, empty_role)


def parseRst(state, lines, offset, source):
	node = nodes.section()
	node.document = state.document
	nested_parse_with_titles(state, StringList(lines, source=source), node)
	return node.children


class RdemClasses(Directive):
	"""``.. rdem-classes::`` with class names as content: the live docstrings of those classes (under YADE) as py:class
	entries with their attributes and methods. With ``:others:``, every class of pkg/rdem that no other rdem-classes
	directive of the same page lists, so that a new class is never missing from the reference."""
	has_content = True
	option_spec = {'others': lambda arg: True}

	def run(self):
		names = [l.strip() for l in self.content if l.strip()]
		if 'others' in self.options:
			page = open(self.state.document.current_source, encoding='utf-8').read()
			listed = set(re.findall(r'^\s+(\w+)\s*$', page, re.M))
			names = [n for n in rdem_classes.classNames(root) if n not in listed]
			if not names:
				return parseRst(self.state, ['None.', ''], self.content_offset, 'rdem-classes')
		lines = []
		for name in names:
			lines += rdem_classes.classRst(name, replaceLaTeX)
		return parseRst(self.state, lines, self.content_offset, 'rdem-classes')


class RdemModules(Directive):
	"Every module of py/rdem, documented by autodoc from its docstrings."
	has_content = False

	def run(self):
		lines = []
		for m in rdem_classes.pythonModules(root):
			lines += [m, '-' * len(m), '', '.. automodule:: ' + m, '   :members:', '   :undoc-members:', '']
		return parseRst(self.state, lines, self.content_offset, 'rdem-modules')


class RdemBibliography(Directive):
	"The works of doc/references.bib as reST citations, so that the docstrings' [Key]_ resolve."
	has_content = False

	def run(self):
		lines = rdem_classes.bibliographyRst(os.path.join(root, 'doc', 'references.bib'))
		return parseRst(self.state, lines, self.content_offset, 'references.bib')


def fixSrc(app, docname, source):
	if app.env.doc2path(docname).endswith('.rst'):
		source[0] = replaceLaTeX(source[0])


def fixDocstring(app, what, name, obj, options, lines):
	for i in range(len(lines)):
		lines[i] = replaceLaTeX(lines[i])


def setup(app):
	app.add_directive('rdem-classes', RdemClasses)
	app.add_directive('rdem-bibliography', RdemBibliography)
	app.add_directive('rdem-modules', RdemModules)
	app.connect('source-read', fixSrc)
	app.connect('autodoc-process-docstring', fixDocstring)
