#!/usr/bin/env bash
# ThreadSanitizer run of the thread tests: tests/api/test_threads.c (four threads meshing
# at once, compared with the serial meshes), tests/delaunay/test_threads.c (the
# parallel Delaunay build with 1-4 threads, compared with the serial store) and
# tests/io/test_blocks.c (the block writers on 1-64 threads and the parallel .node
# reading, compared with one thread) and tests/refine/test_rounds.c (refinement's rounds
# of parallel insertion on 1-3 threads, compared with one thread). Builds only those
# tests and the library, so it
# stays cheap enough for CI.
# Usage: scripts/tsan.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-tsan}
if [ ! -f "$dir/build.ninja" ]; then
  meson setup "$dir" -Db_sanitize=thread -Db_lundef=false -Dbench=false -Dcgal=disabled \
    >/dev/null
fi
ninja -C "$dir" tests/api/test_threads tests/delaunay/test_dt_threads tests/io/test_blocks \
  tests/refine/test_rounds
# halt_on_error: any report fails the run; second_deadlock_stack for useful reports
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" "$dir/tests/api/test_threads" "$PWD"
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" "$dir/tests/delaunay/test_dt_threads" all
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" "$dir/tests/refine/test_rounds" threads
mkdir -p "$dir/tsan-io"
for c in blocks_order writer_msh41 writer_tetgen writer_vtu_binary node_plain node_bad_number; do
  TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" "$dir/tests/io/test_blocks" "$c" \
    "$dir/tsan-io"
done
