#!/usr/bin/env bash
# Builds tetrec and runs the whole meson test suite (CGAL cross-checks included when
# libcgal-dev is installed). Usage: scripts/test.sh [BUILD_DIR] [extra meson setup args]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build}
shift || true
if [ -f "$dir/build.ninja" ]; then
  meson setup --reconfigure "$dir" "$@" >/dev/null
else
  meson setup "$dir" "$@" >/dev/null
fi
ninja -C "$dir"
meson test -C "$dir" --print-errorlogs --num-processes 2
