#!/usr/bin/env bash
# Build YADE 2025.2.0 from Debian's source package into a cache outside the checkout.
#
# The plugin must be compiled with exactly the compile definitions of the YADE it is loaded into
# (YADE_OPENMP, YADE_REAL_BIT, EIGEN_DONT_ALIGN, ... change class layouts), and Debian's binary
# package ships no headers, so we build YADE ourselves once and cache it, keyed by version and
# options. A fresh clone on the same machine finds the cache and builds only the plugin.
#
# Usage: tools/build-yade.sh [--gui|--no-gui] [--mpi]   prints the cached prefix (building it first if needed)
#        --gui      also YADE's Qt viewer (feature GUI: yade.qt, the controller, OpenGL renderers)
#        --no-gui   headless YADE (the default)
#        --mpi      also YADE's MPI (ENABLE_MPI: yade.mpy; adds -DYADE_MPI, which changes Body and Scene, so it is a
#                   YADE of its own, cached beside the others; needs libopenmpi-dev and python3-mpi4py)
# Environment: YADE_RDEM_CACHE          cache root (default ${XDG_CACHE_HOME:-~/.cache}/yade-rdem)
#              YADE_RDEM_JOBS           parallel compile jobs (default: nproc)
set -euo pipefail

gui=OFF
mpi=OFF
for arg in "$@"; do
	case $arg in
	--gui) gui=ON ;;
	--no-gui) gui=OFF ;;
	--mpi) mpi=ON ;;
	-h | --help)
		sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
		exit 0
		;;
	*)
		echo "build-yade: error: unknown argument '$arg' (allowed: --gui, --no-gui, --mpi)" >&2
		exit 2
		;;
	esac
done

readonly YADE_VERSION=2025.2.0
readonly DEBIAN_REVISION=1
readonly TARBALL=yade_${YADE_VERSION}.orig.tar.bz2
readonly TARBALL_SHA256=42702372251bf5e8f07a364bdf30533a1318947e4db90435b1f89293dc029156
# Features: OpenMP, logger, VTK (for VTKRecorder); everything optional else off. Real = double.
# -save-temps (YADE's default for GCC) only trades memory for 4 GB of disk; we have the memory.
# The GUI options are appended only with --gui, so the headless variant keeps its cache key. The GUI variant is also a
# unity build (CMake's CMAKE_UNITY_BUILD, 8 sources per unit, which YADE's CMakeLists.txt supports): YADE's headers cost
# most of the compile time of each of its ~165 sources, and the viewer build was first made on a machine shared by three
# sessions, where a source-by-source build would have taken about five hours.
YADE_OPTIONS=(
	-DCMAKE_BUILD_TYPE=Release -DDISABLE_ALL=ON -DENABLE_OPENMP=ON -DENABLE_LOGGER=ON -DENABLE_VTK=ON
	-DENABLE_MULTI_REAL_HP=OFF -DENABLE_USEFUL_ERRORS=OFF -DDISABLE_SAVE_TEMPS=ON -DPYTHON_VERSION=3.11
	-DPYTHON_EXECUTABLE=/usr/bin/python3)
[[ $gui == ON ]] && YADE_OPTIONS+=(-DENABLE_GUI=ON -DUSE_QT5=ON -DCMAKE_UNITY_BUILD=ON)
# MPI: the unity build too (unless the GUI already asked for it).
[[ $mpi == ON ]] && YADE_OPTIONS+=(-DENABLE_MPI=ON)
[[ $mpi == ON && $gui == OFF ]] && YADE_OPTIONS+=(-DCMAKE_UNITY_BUILD=ON)
readonly YADE_OPTIONS

# Debian's python3 must win over pyenv or other interpreters on PATH (YADE's CMake loops over
# python versions otherwise and fails in cMake/YadePythonHelpers.cmake).
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:${PATH}

die() {
	echo "build-yade: error: $*" >&2
	exit 1
}
log() { echo "build-yade: $*" >&2; }

cache_root=${YADE_RDEM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/yade-rdem}
key=$(printf '%s\n' "$YADE_VERSION" "${YADE_OPTIONS[@]}" | sha1sum | cut -c1-10)
prefix=$cache_root/yade-$YADE_VERSION-$key
stamp=$prefix/BUILD-COMPLETE

if [[ -f $stamp ]]; then
	grep -qx "version=$YADE_VERSION" "$stamp" ||
		die "cache $prefix holds another YADE than $YADE_VERSION; delete it (rm -rf '$prefix') and rerun"
	echo "$prefix"
	exit 0
fi

for tool in cmake make g++ apt-get sha256sum tar; do
	command -v "$tool" >/dev/null || die "'$tool' not found; run tools/install-deps.sh first"
done
for mod in numpy IPython matplotlib pygraphviz Xlib sphinx tkinter mpmath; do
	/usr/bin/python3 -c "import $mod" 2>/dev/null ||
		die "Debian python3 lacks module '$mod'; run tools/install-deps.sh first"
done
[[ -f /usr/include/eigen3/Eigen/Core ]] || die "Eigen headers missing; run tools/install-deps.sh first"
if [[ $mpi == ON ]]; then
	command -v mpicxx >/dev/null || die "'mpicxx' (libopenmpi-dev) not found; run tools/install-deps.sh first"
	/usr/bin/python3 -c "import mpi4py" 2>/dev/null || die "Debian python3 lacks mpi4py (python3-mpi4py); run tools/install-deps.sh first"
fi
[[ -d /usr/include/vtk-9.1 ]] || die "VTK 9.1 headers missing (libvtk9-dev); run tools/install-deps.sh first"
if [[ $gui == ON ]]; then
	# YADE's CMake finds these itself, but a missing one only turns the GUI silently off (or fails late).
	[[ -f /usr/include/QGLViewer/qglviewer.h ]] || die "libQGLViewer (qt5) headers missing; run tools/install-deps.sh first"
	[[ -f /usr/include/GL/freeglut.h ]] || die "freeglut headers missing; run tools/install-deps.sh first"
	for tool in pyuic5 pyrcc5; do
		command -v "$tool" >/dev/null || die "'$tool' (pyqt5-dev-tools) not found; run tools/install-deps.sh first"
	done
	/usr/bin/python3 -c "import PyQt5.QtWidgets" 2>/dev/null || die "Debian python3 lacks PyQt5; run tools/install-deps.sh first"
fi

mkdir -p "$prefix"
exec 9>"$prefix/.lock"
flock 9 # one build at a time per cache entry
[[ -f $stamp ]] && {
	echo "$prefix"
	exit 0
}

# 1. Source: Debian's source package, through a private apt configuration that only adds a
#    deb-src entry derived from this machine's own sources (no host name is written anywhere).
dl=$prefix/download
mkdir -p "$dl"
if [[ ! -f $dl/$TARBALL ]] || ! echo "$TARBALL_SHA256  $dl/$TARBALL" | sha256sum --check --status; then
	apt_dir=$prefix/apt
	mkdir -p "$apt_dir/parts" "$apt_dir/lists/partial"
	src_entries=$(cat /etc/apt/sources.list.d/*.sources 2>/dev/null || true)
	[[ -n $src_entries ]] || die "no deb822 entries in /etc/apt/sources.list.d/*.sources to derive a deb-src entry from"
	# The first non-security stanza, turned into a deb-src entry for the suite that carries 2025.2.0.
	awk 'BEGIN { RS = ""; ORS = "\n\n" } /Types: *deb/ && $0 !~ /security/ {
		sub(/Types:[^\n]*/, "Types: deb-src"); sub(/Suites:[^\n]*/, "Suites: trixie"); print; exit }' \
		/etc/apt/sources.list.d/*.sources >"$apt_dir/parts/yade-src.sources"
	[[ -s $apt_dir/parts/yade-src.sources ]] || die "could not derive a deb-src entry from /etc/apt/sources.list.d"
	apt_opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$apt_dir/parts"
		-o "Dir::State::Lists=$apt_dir/lists")
	log "fetching source index"
	apt-get "${apt_opts[@]}" update >"$apt_dir/update.log" 2>&1 || die "apt-get update failed, see $apt_dir/update.log"
	log "fetching $TARBALL"
	# The .dsc and debian.tar.xz of this source package are not served (404), so apt's exit code is
	# non-zero even when the tarball arrives: the checksum below is the real test.
	(cd "$dl" && apt-get "${apt_opts[@]}" source --download-only "yade=$YADE_VERSION-$DEBIAN_REVISION" >"$apt_dir/source.log" 2>&1) || true
	[[ -f $dl/$TARBALL ]] || die "apt-get source did not deliver $TARBALL, see $apt_dir/source.log"
	echo "$TARBALL_SHA256  $dl/$TARBALL" | sha256sum --check --status ||
		die "checksum of $dl/$TARBALL is not $TARBALL_SHA256; delete it and rerun"
fi

# 2. Unpack, configure, build, install.
src=$prefix/src
if [[ ! -f $src/CMakeLists.txt ]]; then
	rm -rf "$src" "$prefix/trunk-$YADE_VERSION"
	tar -C "$prefix" -xjf "$dl/$TARBALL"
	mv "$prefix/trunk-$YADE_VERSION" "$src"
fi
build=$prefix/build
install=$prefix/install
mkdir -p "$build"
jobs=${YADE_RDEM_JOBS:-$(nproc)}
log "configuring YADE $YADE_VERSION in $build"
cmake -S "$src" -B "$build" -DCMAKE_INSTALL_PREFIX="$install" "${YADE_OPTIONS[@]}" >"$build/configure.log" 2>&1 ||
	die "YADE configure failed, see $build/configure.log"
if [[ $gui == ON ]]; then
	grep -q 'CMAKE_CXX_FLAGS = .*-DYADE_OPENGL' "$build/configure.log" ||
		die "YADE's configure turned the GUI off (a Qt5/QGLViewer/GL package missing?), see $build/configure.log"
fi
log "building YADE with $jobs jobs (about an hour on 2 cores the first time); log: $build/build.log"
start=$(date +%s)
# CPU time (user+sys of make and all compilers) is recorded with the wall time: on a shared machine it is
# the figure that compares two variants' cost.
TIMEFORMAT='real=%R user=%U sys=%S'
{ time make -C "$build" -j"$jobs" >"$build/build.log" 2>&1; } 2>"$build/build-time.txt" ||
	die "YADE build failed, see $build/build.log"
make -C "$build" install >"$build/install.log" 2>&1 || die "YADE install failed, see $build/install.log"
log "built in $(($(date +%s) - start)) s"
# Object files are not needed once installed; headers stay in src/ and generated ones in build/.
find "$build" -name '*.o' -delete
printf 'version=%s\noptions=%s\nbuild_seconds=%s\nbuild_time=%s\n' "$YADE_VERSION" "${YADE_OPTIONS[*]}" \
	"$(($(date +%s) - start))" "$(cat "$build/build-time.txt")" >"$stamp"
echo "$prefix"
