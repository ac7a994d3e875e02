#!/usr/bin/env bash
# The plugin merged into YADE 2025.2.0's own source tree, built there as YADE builds itself, as a maintainer would
# before accepting it:
#   1. writes YADE's source tree (from the tarball tools/build-yade.sh fetched) with pkg/rdem, py/rdem (installed as the
#      module yade.rdem), the plugin's checks (scripts/checks-and-tests/checks), the theory page
#      (doc/sphinx/rdemTheory.rst, listed in YADE's theory toctree; the docstrings' :ref:`rdem-theory-…` point at it) and
#      the bib entries merged in;
#   2. builds and installs it with YADE's CMake, the features of tools/build-yade.sh and -DENABLE_USEFUL_ERRORS=ON
#      (YADE's full warning set, as errors);
#   3. runs `yade --test` and `yade --check` of that installation (the plugin's check among YADE's);
#   4. configures the same tree for long double (-DREAL_PRECISION_BITS=80) and compiles the plugin's library there.
# A full YADE build: about an hour on two cores, so not part of CI. Cached outside the checkout in
# ${YADE_RDEM_CACHE:-~/.cache/yade-rdem}/upstream-2025.2.0/ (source, builds, install, logs); rerun to redo it all.
# Prints a summary and writes it to summary.txt there; exit status non-zero if a step failed.
# Usage: tools/upstream.sh                 all four steps, from a fresh tree
#        tools/upstream.sh --long-double   steps 1 and 4 only
#        tools/upstream.sh --refresh       all four steps on the tree and builds of an earlier run: the plugin's files
#                                          copied in again, then only what depends on them rebuilt (minutes)
set -euo pipefail
full=1 refresh=0
case ${1:-} in
--long-double) full=0 ;;
--refresh) refresh=1 ;;
"") ;;
*)
	echo "usage: $0 [--long-double|--refresh]" >&2
	exit 2
	;;
esac
here=$(cd "$(dirname "$0")/.." && pwd)
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:${PATH}
readonly YADE_VERSION=2025.2.0
jobs=${YADE_RDEM_JOBS:-$(nproc)}

yade_cache=$("$here/tools/build-yade.sh") # also fetches and checks the tarball
root=${YADE_RDEM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/yade-rdem}/upstream-$YADE_VERSION
src=$root/src
mkdir -p "$root"
log() { echo "upstream: $*" | tee -a "$root/summary.txt" >&2; }
: >"$root/summary.txt"
log "$(date -u +%F' '%H:%M) UTC, yade-rdem $(git -C "$here" rev-parse --short HEAD)$(git -C "$here" diff --quiet HEAD || echo ' (with uncommitted changes)')"

# 1. The merged tree. With --refresh, the plugin's files are replaced in the tree of an earlier run; YADE's own files
# keep the times the tarball gave them, so make rebuilds only what depends on the plugin.
if ((refresh)); then
	[[ -f $root/build/CMakeCache.txt && -d $src/pkg/rdem ]] || { log "--refresh: no earlier run in $root (run $0 first)"; exit 1; }
	rm -rf "$src/pkg/rdem" "$src/py/rdem"
else
	rm -rf "$src" "$root/trunk-$YADE_VERSION"
	tar -C "$root" -xjf "$yade_cache/download/yade_$YADE_VERSION.orig.tar.bz2"
	mv "$root/trunk-$YADE_VERSION" "$src"
	cat >>"$src/py/CMakeLists.txt" <<'EOF'
FILE(GLOB filesPYRdem "${CMAKE_CURRENT_SOURCE_DIR}/rdem/*.py")
INSTALL(FILES ${filesPYRdem} DESTINATION ${YADE_PY_PATH}/yade/rdem)
EOF
fi
cp -r "$here/pkg/rdem" "$src/pkg/rdem"
mkdir -p "$src/py/rdem"
cp "$here"/py/rdem/*.py "$src/py/rdem/"
cp "$here"/scripts/checks-and-tests/checks/*.py "$src/scripts/checks-and-tests/checks/"
# the theory page, at the same path as here, in YADE's "Theoretical background" toctree after formulation.rst
cp "$here/doc/sphinx/rdemTheory.rst" "$src/doc/sphinx/rdemTheory.rst"
grep -q 'rdemTheory.rst' "$src/doc/sphinx/index-toctree-theory.rst" ||
	sed -i 's/^\( *\)formulation\.rst$/&\n\1rdemTheory.rst/' "$src/doc/sphinx/index-toctree-theory.rst"
grep -q 'rdemTheory.rst' "$src/doc/sphinx/index-toctree-theory.rst" || { log "could not add rdemTheory.rst to YADE's doc/sphinx/index-toctree-theory.rst"; exit 1; }
# bib entries YADE's doc/references.bib does not have yet (by key; so a --refresh adds only new ones)
python3 - "$here/doc/references.bib" "$src/doc/references.bib" <<'EOF'
import re, sys
ours, theirs = open(sys.argv[1]).read(), open(sys.argv[2]).read()
have = set(k.strip().lower() for k in re.findall(r'^@\w+\s*\{\s*([^,]+),', theirs, re.M))
entries = re.findall(r'^(@\w+\s*\{\s*([^,]+),.*?^\})', ours, re.M | re.S)
new = [e for e, k in entries if k.strip().lower() not in have]
open(sys.argv[2], 'a').write('\n' + '\n\n'.join(new) + '\n')
print('upstream: %d bib entries merged (%d already in YADE)' % (len(new), len(entries) - len(new)), file=sys.stderr)
EOF
log "merged tree in $src"

options=(-DCMAKE_BUILD_TYPE=Release -DDISABLE_ALL=ON -DENABLE_OPENMP=ON -DENABLE_LOGGER=ON -DENABLE_VTK=ON
	-DENABLE_MULTI_REAL_HP=OFF -DDISABLE_SAVE_TEMPS=ON -DPYTHON_VERSION=3.11 -DPYTHON_EXECUTABLE=/usr/bin/python3)
status=0
if ((full)); then
	# 2. Build with YADE's useful errors, same features as the cached YADE.
	build=$root/build install=$root/install
	((refresh)) || rm -rf "$build" "$install"
	cmake -S "$src" -B "$build" -DCMAKE_INSTALL_PREFIX="$install" "${options[@]}" -DENABLE_USEFUL_ERRORS=ON >"$root/configure.log" 2>&1 ||
		{ log "configure failed: $root/configure.log"; exit 1; }
	start=$(date +%s)
	if make -C "$build" -j"$jobs" >"$root/build.log" 2>&1 && make -C "$build" install >"$root/install.log" 2>&1; then
		log "in-tree build with -DENABLE_USEFUL_ERRORS=ON: passed in $(($(date +%s) - start)) s"
	else
		log "in-tree build failed; errors:"
		grep -E 'error:' "$root/build.log" | head -20 | tee -a "$root/summary.txt" >&2
		exit 1
	fi
	warnings=$(grep -E '^[^ ]*pkg/rdem/[^ ]*: warning:' "$root/build.log" | sort -u || true)
	log "warnings in pkg/rdem: $(printf '%s' "$warnings" | grep -c . || true)"
	[[ -z $warnings ]] || printf '%s\n' "$warnings" | tee -a "$root/summary.txt" >&2

	# 3. YADE's own tests and checks, with the plugin inside.
	yade=("/usr/bin/python3" "$install/bin/yade-$YADE_VERSION")
	for what in test check; do
		if "${yade[@]}" -n --"$what" >"$root/$what.log" 2>&1; then
			log "yade --$what: passed ($(grep -cE '^running:|\.\.\. ok$' "$root/$what.log" || true) items run)"
		else
			log "yade --$what: FAILED, see $root/$what.log"
			status=1
		fi
	done
	grep -A3 'running:  checkRdem' "$root/check.log" | tee -a "$root/summary.txt" >&2 || true
fi

# 4. The plugin against a long-double YADE (configure only, then the plugin's library alone). RealHP<N> on, YADE's
# default: with it off, YADE 2025.2.0's own lib/high-precision/RealIO.hpp does not compile for long double
# (toStringHP<Complex>, measured 2026-11-24).
build_ld=$root/build-long-double
((refresh)) || rm -rf "$build_ld"
cmake -S "$src" -B "$build_ld" "${options[@]}" -DENABLE_USEFUL_ERRORS=ON -DREAL_PRECISION_BITS=80 -DENABLE_MULTI_REAL_HP=ON >"$root/configure-long-double.log" 2>&1 ||
	{ log "long-double configure failed: $root/configure-long-double.log"; exit 1; }
start=$(date +%s)
if make -k -C "$build_ld" -j"$jobs" pkg_rdem >"$root/build-long-double.log" 2>&1; then
	log "plugin compiled against long-double YADE (Real = long double, useful errors on): passed in $(($(date +%s) - start)) s"
else
	log "plugin against long-double YADE: FAILED; errors:"
	grep -E 'error:' "$root/build-long-double.log" | sort -u | head -30 | tee -a "$root/summary.txt" >&2
	status=1
fi
log "summary in $root/summary.txt"
exit $status
