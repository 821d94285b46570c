#!/bin/sh
# Meshes every CGAL sample surface (libcgal-dev's data.tar.gz) that tr_plc_validate accepts
# and prints a table: model, points, triangles, Steiner points, tets, time, valid (both
# validators). Table 14 statistics per model go to $OUT/stats/NAME.json.
# usage: [MODE=keep] bench/models/run.sh [BUILD_DIR] [MAXTRIS (0 = all)]
# MODE=keep meshes with --keep-surface and checks that the boundary is the input surface.
set -e
build=${1:-build}
maxtris=${2:-0}
root=$(cd "$(dirname "$0")/../.." && pwd)
bin="$root/$build/tests/pipeline/test_models"
[ -x "$bin" ] || { echo "build $bin first (ninja -C $build)"; exit 1; }
out="$root/$build/bench-models"
mkdir -p "$out/stats${MODE:+-$MODE}"
if [ ! -d "$out/data/meshes" ]; then
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$out" --wildcards 'data/meshes/*.off'
fi
"$bin" "$out/data/meshes" "$maxtris" 0 "$out/stats${MODE:+-$MODE}" ${MODE:-} | tee "$out/table${MODE:+-$MODE}.txt"
