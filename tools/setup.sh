#!/usr/bin/env bash
# Everything needed before the first run, idempotent: Debian packages, YADE 2025.2.0 (built once, cached outside the
# checkout), then the plugin, the unit tests and the launcher build/bin/yade in ./build.
# First run on a new machine: about an hour (YADE itself); afterwards, with the cache: about a minute.
#
# Usage: tools/setup.sh [--gui|--no-gui]
#   --gui     YADE with its Qt viewer (the default; README, "The viewer")
#   --no-gui  headless YADE (a YADE build of its own, cached beside the GUI one: no Qt, no OpenGL)
# Without either, a build/ configured before keeps its choice.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:${PATH} # Debian's python3 and cmake before pyenv shims or others

variant=
for arg in "$@"; do
	case $arg in
	--gui | --no-gui) variant=$arg ;;
	*)
		echo "setup: error: unknown argument '$arg' (allowed: --gui, --no-gui)" >&2
		exit 2
		;;
	esac
done
if [[ -z $variant ]]; then # keep the variant of an earlier configure of build/
	variant=--gui
	grep -qs '^RDEM_GUI:INTERNAL=OFF' "$here/build/CMakeCache.txt" && variant=--no-gui
fi

"$here/tools/install-deps.sh"
yade_cache=$("$here/tools/build-yade.sh" "$variant")
echo "setup: YADE in $yade_cache"
cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release -DYADE_CACHE="$yade_cache" >"$here/build.configure.log" 2>&1 ||
	{
		cat "$here/build.configure.log" >&2
		echo "setup: error: configuring the plugin failed (log above, also in build.configure.log)" >&2
		exit 1
	}
start=$(date +%s)
cmake --build "$here/build" -j"$(nproc)"
echo "setup: plugin, unit tests and launcher built in $(($(date +%s) - start)) s; run YADE with $here/build/bin/yade"
