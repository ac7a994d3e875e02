#!/usr/bin/env bash
# The user guide (doc/sphinx): Sphinx run inside YADE with the plugin, so that the reference is made from the live
# classes' docstrings, into build/doc/html (open build/doc/html/index.html). Needs the build (tools/setup.sh) and the
# Debian packages python3-sphinx, python3-myst-parser and libjs-mathjax (tools/install-deps.sh).
# Warnings go to build/doc/warnings.txt; exit status non-zero if Sphinx fails.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
yade=$here/build/bin/yade
[[ -x $yade ]] || { echo "docs: $yade missing: run tools/setup.sh first" >&2; exit 1; }
/usr/bin/python3 -c 'import sphinx, myst_parser' 2>/dev/null && [[ -f /usr/share/javascript/mathjax/MathJax.js ]] ||
	{ echo "docs: Sphinx, MyST or MathJax missing: run tools/install-deps.sh" >&2; exit 1; }
out=$here/build/doc
rm -rf "$out"
mkdir -p "$out"
OMP_NUM_THREADS=1 "$yade" -n -x "$here/doc/sphinx/build.py" "$here/doc/sphinx" "$out"
echo "docs: $out/html/index.html ($(grep -c . "$out/warnings.txt" || true) warnings in $out/warnings.txt)"
