#!/usr/bin/env bash
# Install, from Debian's archive, everything needed to build YADE 2025.2.0 and the plugin and to
# run the tests. Idempotent: packages already present are left alone. Needs root or sudo.
set -euo pipefail

readonly PACKAGES=(
	build-essential cmake pkg-config bzip2 ca-certificates
	libboost-all-dev libeigen3-dev libbz2-dev zlib1g-dev libvtk9-dev libgtest-dev
	python3-dev python3-numpy python3-ipython python3-matplotlib python3-pygraphviz python3-xlib
	python3-sphinx python3-tk python3-mpmath python3-future
	# the user guide (tools/docs.sh): Markdown pages through MyST, formulas by MathJax from Debian's copy (offline)
	python3-myst-parser libjs-mathjax
	# YADE's Qt viewer (feature GUI: gui/CMakeLists.txt and cMake/Find*.cmake of YADE 2025.2.0) and its Python side
	qtbase5-dev libqt5opengl5-dev libqglviewer-dev-qt5 freeglut3-dev libglu1-mesa-dev libglib2.0-dev
	pyqt5-dev-tools python3-pyqt5 python3-pyqt5.qtwebkit python3-pyqt5.qtsvg # yade.qt imports QtWebKit (or QtWebEngine); IPython's Qt check needs QtSvg
	# the viewer test renders offscreen under Xvfb (xvfb-run needs xauth)
	xvfb xauth
	# YADE's MPI (tools/setup.sh --mpi: ENABLE_MPI, yade.mpy) and the mpiexec that starts the parallel runs
	libopenmpi-dev openmpi-bin python3-mpi4py)

missing=()
for pkg in "${PACKAGES[@]}"; do
	dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
done
if ((${#missing[@]} == 0)); then
	echo "install-deps: all ${#PACKAGES[@]} Debian packages present"
	exit 0
fi

sudo=()
if ((EUID != 0)); then
	command -v sudo >/dev/null || {
		echo "install-deps: error: need root or sudo to install: ${missing[*]}" >&2
		exit 1
	}
	sudo=(sudo)
fi
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null ||
	{
		echo "install-deps: error: apt-get install failed for: ${missing[*]}" >&2
		exit 1
	}
