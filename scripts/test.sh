#!/usr/bin/env bash
# Builds tetrec and runs the whole meson test suite (CGAL cross-checks included when
# libcgal-dev is installed), then the Python package's tests. Usage: scripts/test.sh [BUILD_DIR] [extra meson setup args]
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
status=0
meson test -C "$dir" --print-errorlogs --num-processes 2 || status=1

# The Python package: built by meson-python into a venv under the build dir, then its
# pytest suite (python/tests) against the installed package, run even when a C test
# failed so that one run reports both; its summary goes to $dir/pytest.log too (.ci/run
# counts it). pytest exits 5 when it collects no test: that is a failure here, not a
# pass. TETREC_SKIP_PYTHON=1 skips it (the sanitizer pass of .ci/run: meson-python
# builds the package without the sanitizers, so it would only repeat the first pass).
if [ "${TETREC_SKIP_PYTHON:-0}" = 1 ]; then
  exit "$status"
fi
bash scripts/python.sh "$dir/python-venv"
set +e
"$dir/python-venv/bin/python" -m pytest -q -p no:cacheprovider python/tests 2>&1 | tee "$dir/pytest.log"
rc=${PIPESTATUS[0]}
set -e
if [ "$rc" -eq 5 ]; then
  echo "scripts/test.sh: pytest found no Python tests in python/tests" >&2
fi
if [ "$rc" -ne 0 ]; then
  status=1
fi
exit "$status"
