#!/usr/bin/env bash
# A hexagonal prism whose hexagons ear clipping alone turns into a fan with a 2.3 degree
# angle (the top one not planar, so refinement cannot merge it away): after the flips of
# src/io/polyflip.c its caps have no small angle to protect, so quality refinement adds no
# point, with or without --keep-edges, and both meshes check (exact conformity, volume).
# usage: polygon_mesh.sh TETREC SURFACE WORKDIR
set -u
T=$1 S=$2 W=$3
mkdir -p "$W"
fails=0
for opt in "" "--keep-edges"; do
  "$T" mesh "$S" --quality 1.414 $opt -o "$W/p.node" --exact >"$W/mesh.log" 2>&1 ||
    { echo "FAIL: mesh $opt"; cat "$W/mesh.log"; fails=$((fails + 1)); continue; }
  grep -q "refinement added 0 points" "$W/mesh.log" ||
    { echo "FAIL: refinement added points ($opt):"; cat "$W/mesh.log"; fails=$((fails + 1)); }
  "$T" check "$S" "$W/p.node" >"$W/check.log" 2>&1 &&
    grep -q "conforms exactly.*volume equals" "$W/check.log" ||
    { echo "FAIL: check ($opt):"; cat "$W/check.log"; fails=$((fails + 1)); }
done
exit $((fails > 0))
