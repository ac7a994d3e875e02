"""The plugin's classes and works cited, as reST for the user guide (doc/sphinx/conf.py) and for the docstring tests
(tests/yade/test_docstrings.py). The class names come from the sources (the YADE_PLUGIN lists of pkg/rdem/*.cpp), the
text from the live classes of the running YADE (``yade.wrapper``), so the guide documents exactly what the build has."""
import glob, inspect, os, re

ROLES = re.compile(r':(ydefault|yattrtype|yattrflags):`([^`]*)`')


def classNames(root):
	"The classes pkg/rdem registers with YADE (its YADE_PLUGIN lists), in file order."
	names = []
	for f in sorted(glob.glob(os.path.join(root, 'pkg', 'rdem', '*.cpp'))):
		for m in re.finditer(r'YADE_PLUGIN\(\s*((?:\(\s*\w+\s*\)\s*)+)\)', open(f, encoding='utf-8').read()):
			names += re.findall(r'\((\w+)\)', m.group(1))
	return names


def liveClass(name):
	"The class from yade.wrapper, or None (a renderer in a YADE without its viewer)."
	import yade.wrapper
	return getattr(yade.wrapper, name, None)


def splitAttrDoc(doc):
	"""YADE's attribute docstring ``text :ydefault:`d` :yattrtype:`T` [:yattrflags:`f`]`` (lib/serialization/Serializable.hpp)
	as (text, {'ydefault': d, 'yattrtype': T, 'yattrflags': f})."""
	doc = (doc or '').replace('|ystatic|', '')
	fields = {k: v for k, v in ROLES.findall(doc)}
	return ROLES.sub('', doc).strip(), fields


def isBoostFunction(obj):
	return type(obj).__name__ == 'function' and type(obj).__module__ == 'Boost.Python'


STATIC = re.compile(r'^\.\. ystaticattr:: (\w+)\.(\w+)\(=(.*)\)\n\n((?:\t.*\n?|\n)*)', re.M)


def staticAttrs(cls):
	"""Static attributes (YADE_CLASS_BASE_DOC_STATICATTRS): YADE appends their docs to the class docstring as
	``.. ystaticattr:: Class.name(=default)`` blocks (lib/serialization/Serializable.hpp); {name: (text, default)}."""
	return {m.group(2): (inspect.cleandoc(m.group(4)), m.group(3)) for m in STATIC.finditer(cls.__doc__ or '')}


def members(cls):
	"""The attributes and methods a class itself defines (not its bases'): lists of (name, docstring text, fields) and
	(name, docstring), in the order YADE registers them; names starting with _ left out."""
	attrs, methods = [], []
	static = staticAttrs(cls)
	for k, v in vars(cls).items():
		if k.startswith('_'):
			continue
		if type(v).__name__ == 'StaticProperty':
			text, default = static.get(k, ('', ''))
			attrs.append((k, text, {'ydefault': default, 'static': True}))
		elif isinstance(v, property):
			text, fields = splitAttrDoc(v.__doc__)
			attrs.append((k, text, fields))
		elif isBoostFunction(v) or inspect.isfunction(v) or inspect.isroutine(v):
			methods.append((k, (v.__doc__ or '').strip()))
	return attrs, methods


def methodDoc(doc):
	"A Boost.Python function's docstring without the signature lines it may start with."
	lines = [l for l in doc.splitlines() if not re.match(r'^\s*\w+\(.*\)\s*(->.*)?:?\s*$', l)]
	return inspect.cleandoc('\n'.join(lines))


def classDoc(cls):
	"The class docstring without the blocks of its static attributes (documented as attributes)."
	return inspect.cleandoc(STATIC.sub('', cls.__doc__ or ''))


def indent(text, n):
	return [(' ' * n + l) if l.strip() else '' for l in text.splitlines()]


def classRst(name, tex=lambda s: s):
	"The reST of one class: base, docstring, then its own attributes (type, default, flags) and methods."
	cls = liveClass(name)
	out = ['.. py:class:: %s' % name, '   :module: yade.wrapper', '']
	if cls is None:
		return out + ['   Not in this build (compiled only in a YADE with its viewer, ``tools/setup.sh`` without ``--no-gui``).', '']
	bases = [b.__name__ for b in cls.__mro__[1:] if b.__module__ == cls.__module__ and b.__name__ not in ('instance', 'object')]
	if bases:
		out += ['   Inherits ' + ' » '.join(':yref:`%s`' % b for b in bases) + '.', '']
	out += indent(tex(classDoc(cls)), 3) + ['']
	attrs, methods = members(cls)
	for k, text, fields in attrs:
		out += ['   .. py:attribute:: %s' % k]
		if fields.get('yattrtype'):
			out += ['      :type: %s' % fields['yattrtype']]
		if fields.get('ydefault'):
			out += ['      :value: %s' % fields['ydefault']]
		out += ['']
		flags = int(fields.get('yattrflags') or 0)
		note = ', '.join(n for bit, n in ((2, 'read-only'), (1, 'not saved'), (4, 'checked on change')) if flags & bit)
		if fields.get('static'):
			note = 'static: one value for the class' + (', ' + note if note else '')
		out += indent(tex(text) + ('\n\n*(%s)*' % note if note else ''), 6) + ['']
	for k, doc in methods:
		out += ['   .. py:method:: %s(...)' % k, ''] + indent(tex(methodDoc(doc)), 6) + ['']
	return out


def bibEntries(path):
	"doc/references.bib as a list of (key, {field: value}); a small parser for the entries this project writes."
	text = open(path, encoding='utf-8').read()
	out = []
	for m in re.finditer(r'@(\w+)\s*\{\s*([^,\s]+)\s*,', text):
		i, depth = m.end(), 1
		while depth and i < len(text):
			depth += {'{': 1, '}': -1}.get(text[i], 0)
			i += 1
		body, fields = text[m.end():i - 1], {}
		for f in re.finditer(r'(\w+)\s*=\s*', body):
			j = f.end()
			if body[j] == '{':
				d, k = 1, j + 1
				while d and k < len(body):
					d += {'{': 1, '}': -1}.get(body[k], 0)
					k += 1
				val = body[j + 1:k - 1]
			elif body[j] == '"':
				k = body.index('"', j + 1)
				val = body[j + 1:k]
			else:
				val = re.match(r'[^,\s]*', body[j:]).group(0)
			fields.setdefault(f.group(1).lower(), re.sub(r'\s+', ' ', val.replace('{', '').replace('}', '')).strip())
		out.append((m.group(2), fields))
	return out


def bibliographyRst(path):
	out = []
	for key, f in bibEntries(path):
		parts = [f.get('author', f.get('editor', '')), '(%s)' % f['year'] if 'year' in f else '', f.get('title', '') + '.',
		         ', '.join(x for x in (f.get('journal') or f.get('booktitle') or f.get('publisher') or f.get('institution') or f.get('howpublished', ''),
		                               f.get('volume', ''), f.get('pages', '')) if x)]
		ref = ' '.join(p for p in parts if p.strip(' .')).replace('\\', '').replace('*', '\\*')
		if f.get('doi'):
			ref += ' doi:%s' % f['doi']
		elif f.get('url'):
			ref += ' %s' % f['url']
		out += ['.. [%s] %s' % (key, ref), '']
	return out


def pythonModules(root):
	"""The modules of py/rdem, as ``yade.rdem.X``: the package's name in the launcher (``rdem`` is an alias of it,
	tools/python-path/sitecustomize.py) and in YADE's tree once merged, so that autodoc finds its functions there."""
	return ['yade.rdem'] + ['yade.rdem.' + os.path.basename(f)[:-3] for f in sorted(glob.glob(os.path.join(root, 'py', 'rdem', '*.py'))) if not f.endswith('__init__.py')]
