#!/usr/bin/env bash
# Builds a TetGen executable from a TetGen source tree (e.g. the public TetGen 1.6
# release, unpacked by the user; it is never part of this repository) for the peer
# benchmarks: bench/peer/run.sh, bench/shells/run.sh and bench/quality/run.sh take it as
# TETGEN=OUT.
# usage: bench/peer/build_tetgen.sh SRC_DIR OUT
#   SRC_DIR  the folder holding tetgen.cxx, tetgen.h and predicates.cxx
#   OUT      the executable to write
#   CXX (default g++) and CXXFLAGS (default -O3) may be set; -DNDEBUG is always added.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 SRC_DIR OUT" >&2; exit 1; }
SRC=$1
OUT=$2
for f in tetgen.cxx tetgen.h predicates.cxx; do
  [ -f "$SRC/$f" ] || { echo "$SRC/$f not found: SRC_DIR must be a TetGen source tree" >&2; exit 1; }
done
CXX=${CXX:-g++}
mkdir -p "$(dirname "$OUT")"
# predicates.cxx is Shewchuk's code: no -ffast-math or x87 excess precision
# shellcheck disable=SC2086
"$CXX" ${CXXFLAGS:--O3} -DNDEBUG -I"$SRC" -o "$OUT" "$SRC/tetgen.cxx" "$SRC/predicates.cxx" -lm
ver=$("$OUT" -h 2>/dev/null | sed -n 's/^Version *//p' | head -n 1 || true)
echo "built $OUT (TetGen version ${ver:-unknown})"
