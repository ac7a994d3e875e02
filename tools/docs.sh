#!/usr/bin/env bash
# The user guide (doc/sphinx): Sphinx run inside YADE with the plugin, so that the reference is made from the live
# classes' docstrings, into build/doc/html (open build/doc/html/index.html). Needs the build (tools/setup.sh) and the
# Debian packages python3-sphinx, python3-myst-parser and libjs-mathjax (tools/install-deps.sh).
# Warnings go to build/doc/warnings.txt. Exit status non-zero if Sphinx fails or the reference lacks a class of
# pkg/rdem or a module of py/rdem. RDEM_BUILD_DIR: another build folder than build/ (CTest sets it).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${RDEM_BUILD_DIR:-$here/build}
yade=$build/bin/yade
[[ -x $yade ]] || { echo "docs: $yade missing: run tools/setup.sh first" >&2; exit 1; }
/usr/bin/python3 -c 'import sphinx, myst_parser' 2>/dev/null && [[ -f /usr/share/javascript/mathjax/MathJax.js ]] ||
	{ echo "docs: Sphinx, MyST or MathJax missing: run tools/install-deps.sh" >&2; exit 1; }
out=$build/doc
rm -rf "$out"
mkdir -p "$out"
OMP_NUM_THREADS=1 "$yade" -n -x "$here/doc/sphinx/build.py" "$here/doc/sphinx" "$out"
# the reference has every class and every module (a class the directives missed, or an import that failed, shows here)
/usr/bin/python3 - "$here" "$out/html" <<'PY'
import os, sys
root, html = sys.argv[1:]
sys.path.insert(0, os.path.join(root, 'doc', 'sphinx'))
import rdem_classes
classes = open(os.path.join(html, 'reference', 'classes.html'), encoding='utf-8').read()
python = open(os.path.join(html, 'reference', 'python.html'), encoding='utf-8').read()
missing = [c for c in rdem_classes.classNames(root) if 'id="yade.wrapper.%s"' % c not in classes]
missing += [m for m in rdem_classes.pythonModules(root) if 'id="module-%s"' % m not in python]
if missing:
    sys.exit('docs: the reference lacks ' + ', '.join(missing))
PY
echo "docs: $out/html/index.html ($(grep -c . "$out/warnings.txt" || true) warnings in $out/warnings.txt)"
