#!/usr/bin/env bash
# Builds tetrec and runs it on a bundled example surface.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build
if [ -f "$dir/build.ninja" ]; then meson setup --reconfigure "$dir" >/dev/null; else meson setup "$dir" >/dev/null; fi
ninja -C "$dir" src/cli/tetrec >/dev/null
out=$(mktemp -d)
"$dir/src/cli/tetrec" mesh examples/data/cube.off -o "$out/cube.mesh" --stats "$out/cube.json"
"$dir/src/cli/tetrec" check examples/data/cube.off "$out/cube.mesh"
# the same mesh with exact Steiner coordinates: check then verifies exact conformity and volume
"$dir/src/cli/tetrec" mesh examples/data/cube.off -o "$out/cube.node" --exact -Q
"$dir/src/cli/tetrec" check examples/data/cube.off "$out/cube.node"
echo "wrote $out/cube.mesh"
