#!/usr/bin/env bash
# Make a YADE_PREFIX overlay: <overlay>/<libsubdir> mirrors <install>/<libsubdir> with symlinks to files (YADE's
# plugin scan does not follow symlinked directories) and holds a symlink to the plugin library and to the plugin's
# checks in YADE's form, where `yade --check` runs them beside YADE's own (YADE reads them from the prefix's library
# folder, py/yade/tests/checks).
# Usage: make-overlay.sh <yade install prefix> <lib subdir> <overlay dir> <plugin.so> <folder of the plugin's checks>
set -euo pipefail
install=$1 libsub=$2 overlay=$3 plugin=$4 checks=$5
rm -rf "$overlay"
mkdir -p "$overlay"
(cd "$install" && find . -mindepth 1 -type d) | while read -r d; do mkdir -p "$overlay/$d"; done
(cd "$install" && find . \( -type f -o -type l \)) | while read -r f; do ln -s "$install/${f#./}" "$overlay/$f"; done
ln -s "$(readlink -f "$plugin")" "$overlay/$libsub/$(basename "$plugin")"
for check in "$checks"/*.py; do ln -s "$check" "$overlay/$libsub/py/yade/tests/checks/"; done
