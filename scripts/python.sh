#!/usr/bin/env bash
# Builds the tetrec Python package with meson-python and installs it into a virtual
# environment that sees Debian's numpy, meson-python, pytest and meshio (Debian 12's
# system Python refuses plain `pip install`). Needs no package index.
# Usage: scripts/python.sh VENV_DIR [WHEEL_BUILD_DIR]
set -euo pipefail
venv=${1:?usage: scripts/python.sh VENV_DIR [WHEEL_BUILD_DIR]}
builddir=${2:-$venv/wheel-build}
mkdir -p "$venv" "$builddir"
venv=$(cd "$venv" && pwd)
builddir=$(cd "$builddir" && pwd)
cd "$(dirname "$0")/.."
# Debian's python3-mesonpy and python3-numpy live in the system interpreter's
# dist-packages: pick an interpreter that has them (a pyenv or conda python3 first on
# PATH does not).
py=""
for cand in python3 /usr/bin/python3; do
  if command -v "$cand" >/dev/null && "$cand" -c 'import mesonpy, numpy, venv' 2>/dev/null; then
    py=$cand
    break
  fi
done
if [ -z "$py" ]; then
  echo "scripts/python.sh: no python3 with numpy and meson-python (bash scripts/setup.sh)" >&2
  exit 1
fi
if [ ! -x "$venv/bin/python" ]; then
  "$py" -m venv --system-site-packages "$venv"
fi
# builddir keeps meson-python's build between runs, so a second install recompiles only
# what changed; -j2 keeps to a shared 2-core machine's budget.
"$venv/bin/python" -m pip install --no-build-isolation --no-index --no-deps -q \
  --config-settings=builddir="$builddir" --config-settings=compile-args=-j2 .
"$venv/bin/python" -c 'import tetrec; print("tetrec", tetrec.__version__, "Python package installed in '"$venv"'")'
