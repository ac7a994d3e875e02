#!/usr/bin/env bash
# Everything needed before the first run, idempotent: Debian packages, YADE 2025.2.0 (built once, cached outside the
# checkout), then the plugin, the unit tests and the launcher build/bin/yade in ./build.
# First run on a new machine: about an hour (YADE itself); afterwards, with the cache: about a minute.
#
# Usage: tools/setup.sh [--gui|--no-gui|--mpi]
#   --gui     YADE with its Qt viewer (the default; README, "The viewer")
#   --no-gui  headless YADE (a YADE build of its own, cached beside the GUI one: no Qt, no OpenGL)
#   --mpi     headless YADE with MPI (yade.mpy: tools/build-yade.sh --mpi, a YADE of its own) and the plugin built
#             against it in ./build-mpi (launcher build-mpi/bin/yade); build/ is left as it is (doc/mpi.md)
# Without any, a build/ configured before keeps its choice.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:${PATH} # Debian's python3 and cmake before pyenv shims or others

variant=
for arg in "$@"; do
	case $arg in
	--gui | --no-gui | --mpi) variant=$arg ;;
	*)
		echo "setup: error: unknown argument '$arg' (allowed: --gui, --no-gui, --mpi)" >&2
		exit 2
		;;
	esac
done
if [[ -z $variant ]]; then # keep the variant of an earlier configure of build/
	variant=--gui
	grep -qs '^RDEM_GUI:INTERNAL=OFF' "$here/build/CMakeCache.txt" && variant=--no-gui
fi
# The MPI YADE has another Body and Scene (-DYADE_MPI): the plugin built against it goes to a directory of its own.
build=$here/build
[[ $variant == --mpi ]] && build=$here/build-mpi
log=$build.configure.log

"$here/tools/install-deps.sh"
yade_cache=$("$here/tools/build-yade.sh" "$variant")
echo "setup: YADE in $yade_cache"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DYADE_CACHE="$yade_cache" >"$log" 2>&1 ||
	{
		cat "$log" >&2
		echo "setup: error: configuring the plugin failed (log above, also in $log)" >&2
		exit 1
	}
start=$(date +%s)
cmake --build "$build" -j"$(nproc)"
echo "setup: plugin, unit tests and launcher built in $(($(date +%s) - start)) s; run YADE with $build/bin/yade"
if [[ $variant == --mpi ]]; then
	echo "setup: in parallel (doc/mpi.md): mpiexec -n 3 $build/bin/yade -n script.py"
fi
