#!/usr/bin/env bash
# Gmsh and tetrec's binary .msh, both ways: Gmsh reads the binary 4.1 and 2.2 files tetrec
# writes (`gmsh -check`: the same node and element counts as for the text file of the
# same mesh, and a coherent mesh), and its ASCII re-export reads back in `tetrec check` as
# a valid mesh that conforms exactly; tetrec reads the binary files Gmsh writes (-bin) of
# tetrec's mesh, again valid and conforming. (Gmsh 4.8 reads neither .meshb nor .vtu, so
# those are checked with meshio, interop_binary.py.)
# usage: gmsh_binary.sh TETREC SURFACE WORKDIR   (exit 77, skipped, without gmsh)
set -u
T=$1 S=$2 W=$3
command -v gmsh >/dev/null || { echo "gmsh not installed (scripts/setup.sh installs it)"; exit 77; }
mkdir -p "$W"
fails=0
say() { echo "FAIL: $*"; fails=$((fails + 1)); }
counts() { grep -E "^Info *: [0-9]+ (nodes|elements)$" "$1" | tr -s ' \n' ' '; }
for v in 4.1 2.2; do
  txt=$W/t$v.msh bin=$W/b$v.msh
  "$T" mesh -q "$S" -o "$txt" --msh-version $v || { say "tetrec mesh -> $txt: exit $?"; continue; }
  "$T" mesh -q "$S" -o "$bin" --msh-version ${v}b || { say "tetrec mesh -> $bin: exit $?"; continue; }
  env -u DISPLAY gmsh -check "$txt" >"$W/ct$v.log" 2>&1 || say "gmsh -check $txt: exit $?"
  env -u DISPLAY gmsh -check "$bin" >"$W/cb$v.log" 2>&1 || say "gmsh -check $bin: exit $?"
  grep -q "Done reading '$bin'" "$W/cb$v.log" || say "gmsh did not read $bin: $(cat "$W/cb$v.log")"
  grep -q "Done checking mesh coherence" "$W/cb$v.log" || say "gmsh found $bin incoherent"
  ! grep -qi "^Error" "$W/cb$v.log" || say "gmsh errors on $bin: $(grep -i '^Error' "$W/cb$v.log")"
  [ -n "$(counts "$W/cb$v.log")" ] && [ "$(counts "$W/cb$v.log")" = "$(counts "$W/ct$v.log")" ] ||
    say "$bin: gmsh counts '$(counts "$W/cb$v.log")', text file '$(counts "$W/ct$v.log")'"
  # Gmsh's ASCII writing of what it read from the binary file, checked by tetrec
  back=$W/back$v.msh
  env -u DISPLAY gmsh "$bin" -0 -o "$back" -format msh41 >"$W/back$v.log" 2>&1 ||
    say "gmsh re-export of $bin: exit $?"
  "$T" check "$S" "$back" >"$W/tback$v.log" 2>&1 || say "tetrec check of gmsh's $back: $(cat "$W/tback$v.log")"
  grep -q "conforms exactly" "$W/tback$v.log" || say "gmsh's $back does not conform"
  # Gmsh's binary writing, read by tetrec's binary reader
  gb=$W/gmshbin$v.msh
  fmt=$([ $v = 4.1 ] && echo msh41 || echo msh22)
  env -u DISPLAY gmsh "$txt" -0 -bin -o "$gb" -format $fmt >"$W/gb$v.log" 2>&1 ||
    say "gmsh binary export of $txt: exit $?"
  head -c 20 "$gb" | grep -qa "$v 1 8" || say "gmsh did not write a binary $v file: $(head -c 20 "$gb")"
  "$T" check "$S" "$gb" >"$W/tgb$v.log" 2>&1 || say "tetrec check of gmsh's binary $gb: $(cat "$W/tgb$v.log")"
  grep -q "conforms exactly" "$W/tgb$v.log" || say "gmsh's binary $gb does not conform"
  echo "binary msh $v: gmsh reads $(counts "$W/cb$v.log")"
done
exit $((fails != 0))
