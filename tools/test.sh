#!/usr/bin/env bash
# The full test suite: builds what is missing (tools/setup.sh), then runs through CTest the C++ unit tests, the
# plugin's tests inside YADE, the stability suite and YADE's own --test and --check with the plugin loaded.
# Exit status non-zero on any failure.
# Usage: tools/test.sh [ctest options]     the suite, in build/
#        tools/test.sh --mpi [options]     the tests on YADE's MPI (label mpi: three processes against serial), in
#                                          build-mpi/ (tools/setup.sh --mpi: a YADE of its own, built once)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
if [[ ${1:-} == --mpi ]]; then
	shift
	"$here/tools/setup.sh" --mpi
	cd "$here/build-mpi"
	ctest --output-on-failure --timeout 1200 -L mpi "$@"
	exit
fi
"$here/tools/setup.sh"
cd "$here/build"
ctest --output-on-failure --timeout 1200 "$@"
