#!/bin/sh
# `--threads N` changes nothing in what tetrec writes: the outputs of `tetrec mesh` on a
# few corpus surfaces and of `tetrec delaunay` on 40,000 generated points (enough for the
# threads to do most of the work: the serial prefix is 4,096 points per thread) are byte
# for byte the same with 1, 2 and 3 threads, and `tetrec check` accepts the meshes.
# Bad values are refused. usage: cli_threads.sh TETREC DATA_DIR WORKDIR
set -u
tetrec=$1
data=$2
work=$3
mkdir -p "$work"
fail=0
say() { echo "FAIL: $*" >&2; fail=1; }

for f in two_cubes.off cavity.off star_rounding_budget.off \
         regressions/star_steiner_cluster_s3_1477.off; do
  b=$(basename "$f" .off)
  for n in 1 2 3; do
    "$tetrec" mesh "$data/$f" -q --threads $n -o "$work/$b.$n.mesh" ||
      say "$f: mesh --threads $n exited $?"
  done
  cmp -s "$work/$b.1.mesh" "$work/$b.2.mesh" || say "$f: --threads 1 and 2 differ"
  cmp -s "$work/$b.1.mesh" "$work/$b.3.mesh" || say "$f: --threads 1 and 3 differ"
  "$tetrec" check "$data/$f" "$work/$b.2.mesh" -q || say "$f: check of the 2-thread mesh failed"
done

# 40,000 points of a fixed linear congruential sequence, as a TetGen .node
awk 'BEGIN { s = 12345; print 40000, 3, 0, 0;
  for (i = 0; i < 40000; i++) { printf "%d", i;
    for (c = 0; c < 3; c++) { s = (s * 1103515245 + 12345) % 2147483648; printf " %.17g", s / 2147483648 }
    printf "\n" } }' > "$work/points.node"
for n in 1 2 3; do
  "$tetrec" delaunay "$work/points.node" -q -j $n -o "$work/points.$n.node" ||
    say "delaunay -j $n exited $?"
done
for e in node ele; do
  cmp -s "$work/points.1.$e" "$work/points.2.$e" || say "delaunay .$e: -j 1 and 2 differ"
  cmp -s "$work/points.1.$e" "$work/points.3.$e" || say "delaunay .$e: -j 1 and 3 differ"
done
[ -s "$work/points.1.ele" ] || say "delaunay wrote no tets"

for bad in -1 x 2.5 ""; do
  if "$tetrec" mesh "$data/two_cubes.off" -q --threads "$bad" -o "$work/bad.mesh" 2>/dev/null; then
    say "--threads '$bad' accepted"
  fi
done
[ $fail -eq 0 ] && echo "threads: same outputs for 1, 2, 3 threads; bad values refused"
exit $fail
