#!/usr/bin/env bash
# The full test suite: builds what is missing (tools/setup.sh), then runs through CTest the C++ unit tests, the
# plugin's tests inside YADE, the stability suite and YADE's own --test and --check with the plugin loaded.
# Exit status non-zero on any failure.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/tools/setup.sh"
cd "$here/build"
ctest --output-on-failure --timeout 1200 "$@"
