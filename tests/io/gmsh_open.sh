#!/usr/bin/env bash
# Gmsh (Debian's gmsh, installed by scripts/setup.sh) opens the .msh files tetrec writes,
# 4.1 and 2.2: `gmsh -check` reads them (nodes and elements: the tets and the boundary
# triangles) and finds the mesh coherent; Gmsh's own re-export of each reads back in
# `tetrec check` as a valid mesh that conforms exactly to the input.
# usage: gmsh_open.sh TETREC SURFACE WORKDIR   (exit 77, skipped, without gmsh)
set -u
T=$1 S=$2 W=$3
command -v gmsh >/dev/null || { echo "gmsh not installed (scripts/setup.sh installs it)"; exit 77; }
mkdir -p "$W"
fails=0
say() { echo "FAIL: $*"; fails=$((fails + 1)); }
for v in 4.1 2.2; do
  out=$W/g$v.msh
  "$T" mesh -q "$S" -o "$out" --msh-version $v || { say "tetrec mesh -> $out: exit $?"; continue; }
  env -u DISPLAY gmsh -check "$out" >"$W/check$v.log" 2>&1 || say "gmsh -check $out: exit $?"
  grep -q "Done reading '$out'" "$W/check$v.log" || say "gmsh did not read $out: $(cat "$W/check$v.log")"
  grep -q "Done checking mesh coherence" "$W/check$v.log" || say "gmsh found $out incoherent"
  ! grep -qi "^Error" "$W/check$v.log" || say "gmsh errors on $out: $(grep -i '^Error' "$W/check$v.log")"
  # Gmsh's own writing of what it read, in the other version, checked by tetrec
  back=$W/back$v.msh
  other=$([ $v = 4.1 ] && echo msh22 || echo msh41)
  env -u DISPLAY gmsh "$out" -0 -o "$back" -format $other >"$W/back$v.log" 2>&1 ||
    say "gmsh re-export of $out: exit $?"
  "$T" check "$S" "$back" >"$W/tcheck$v.log" 2>&1 || say "tetrec check of gmsh's $back: $(cat "$W/tcheck$v.log")"
  grep -q "conforms exactly" "$W/tcheck$v.log" || say "gmsh's $back does not conform: $(cat "$W/tcheck$v.log")"
  echo "msh $v: $(grep -E 'nodes|elements' "$W/check$v.log" | head -2 | tr -s ' \n' ' ')"
done
exit $((fails != 0))
