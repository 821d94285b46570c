#!/usr/bin/env bash
# Interleaved A/B of two bench_tetrec binaries (and CGAL in the same rounds): on a shared,
# loaded machine a change of a few percent only shows when the runs alternate. Prints the
# triangulation CPU time (dt_cpu) of every run, then the medians and their ratios, and
# checks that both binaries build the same store (bench_tetrec's `hash`).
#
# usage: bench/delaunay/ab.sh OLD_BENCH_TETREC NEW_BENCH_TETREC [CASE] [PAIRS]
#   CASE: random1000000 (default), random100000, sphere250000, grid100 ...; PAIRS: default 5
#   CGAL=path/to/bench_cgal to add CGAL's time (default: next to NEW, if built)
# Keep the old binary with a plain cp before rebuilding, e.g.
#   cp build-bench/bench/delaunay/bench_tetrec /tmp/bench_old
set -euo pipefail
OLD=$1
NEW=$2
CASE=${3:-random1000000}
PAIRS=${4:-5}
CG=${CGAL-$(dirname "$NEW")/bench_cgal}
[ -x "$CG" ] || CG=""
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
case $CASE in
  random*) "$NEW" gen random "${CASE#random}" "$DIR/in.bin" "$DIR/in.node" ;;
  sphere*) "$NEW" gen sphere "${CASE#sphere}" "$DIR/in.bin" "$DIR/in.node" ;;
  grid*) "$NEW" gen grid "${CASE#grid}" "$DIR/in.bin" "$DIR/in.node" ;;
  *) echo "unknown case $CASE"; exit 2 ;;
esac
ho=$("$OLD" run "$DIR/in.bin" hash | sed -n 's/^tetrec store hash //p')
hn=$("$NEW" run "$DIR/in.bin" hash | sed -n 's/^tetrec store hash //p')
echo "store hash old ${ho:-n/a} new ${hn:-n/a}$([ "$ho" = "$hn" ] && echo ' (same)')"
cpu() { "$@" | sed -n 's/.*dt_cpu=\([0-9.]*\).*/\1/p'; }
o=() w=() c=()
for i in $(seq "$PAIRS"); do
  a=$(cpu "$OLD" run "$DIR/in.bin")
  b=$(cpu "$NEW" run "$DIR/in.bin")
  g=-
  [ -n "$CG" ] && g=$(cpu "$CG" "$DIR/in.bin")
  echo "pair $i: old $a new $b cgal $g"
  o+=("$a") w+=("$b") c+=("$g")
done
med() { printf "%s\n" "$@" | sort -g | awk '{a[NR]=$1} END{print (NR%2)?a[(NR+1)/2]:(a[NR/2]+a[NR/2+1])/2}'; }
mo=$(med "${o[@]}") mn=$(med "${w[@]}") mc=-
[ -n "$CG" ] && mc=$(med "${c[@]}")
echo "median dt_cpu: old $mo new $mn cgal $mc   new/old $(awk "BEGIN{printf \"%.3f\", $mn/$mo}")" \
  "$([ -n "$CG" ] && awk "BEGIN{printf \"old/cgal %.3f new/cgal %.3f\", $mo/$mc, $mn/$mc}")"
