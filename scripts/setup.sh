#!/usr/bin/env bash
# Installs everything tetrec needs to build, test, fuzz and benchmark on Debian 12.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential meson ninja-build pkg-config cmake \
  libgmp-dev libmpfr-dev libcgal-dev \
  clang libfuzzer-14-dev libclang-rt-14-dev \
  tetgen libcgal-demo python3 python3-meshio libopenmesh-dev gmsh \
  python3-dev python3-venv python3-numpy python3-mesonpy python3-pytest time >/dev/null
# The tetrec Python package, into .venv (README: Python).
bash "$(dirname "$0")/python.sh" "$(dirname "$0")/../.venv"
