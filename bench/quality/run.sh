#!/usr/bin/env bash
# Quality benchmark (issue 17): tetrec `mesh --quality R` against TetGen 1.6 `-pqRQ` on every CGAL
# sample surface (libcgal-dev's data.tar.gz, data/meshes/*.off, extracted into the build
# dir), in the same run. Per model and in total: CPU time (user + system, /usr/bin/time),
# tets, minimum dihedral angle, share of tets with a dihedral angle under 10 and under 5
# degrees, and the largest radius-edge ratio. The shape figures of both outputs come from
# one measure, `tetrec check MODEL OUT.node` (src/refine/quality.h, on the written
# doubles), which also validates the output (links and exact orientation; for tetrec's
# --exact output also exact conformity and volume); a row marked (invalid) failed that
# check (its figures are shown and counted all the same), "fail" is a failed run or a
# timeout (tetrec's: fail:rejected input, fail:budget, fail:timeout). Totals are over the
# models both meshed.
#
# usage: TETGEN=/path/to/tetgen-1.6 bench/quality/run.sh [BUILD_DIR]
#   BUILD_DIR  a build of tetrec (default build; set up with meson if missing)
#   TETGEN     the TetGen 1.6 binary (required; not part of the repository)
#   R=1.414    the radius-edge bound given to both
#   TIMEOUT=s  per-process wall-clock limit (default 120)
#   ONLY=regex only the models whose name matches (grep -E)
#   TETREC_OPTS="..." more options for tetrec mesh (e.g. "-O 0": without sliver removal)
# Output: stdout and BUILD/bench-quality/table.txt; logs under BUILD/bench-quality/work/.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-build}
case $BUILD in /*) ;; *) BUILD=$ROOT/$BUILD ;; esac
R=${R:-1.414}
TIMEOUT=${TIMEOUT:-120}
: "${TETGEN:?set TETGEN to the TetGen 1.6 binary}"
[ -x "$TETGEN" ] || { echo "TETGEN=$TETGEN is not executable" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian package time)" >&2; exit 1; }
if [ ! -d "$BUILD" ]; then
  meson setup "$BUILD" "$ROOT" -Dbench=false -Dcgal=disabled >/dev/null
fi
ninja -C "$BUILD" src/cli/tetrec >/dev/null
TETREC=$BUILD/src/cli/tetrec
OUT=$BUILD/bench-quality
mkdir -p "$OUT/work"
DATA=$BUILD/cgal-data
if [ ! -d "$DATA/data/meshes" ]; then
  mkdir -p "$DATA"
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$DATA"
fi

# cpu FILE: user + system seconds recorded by /usr/bin/time -f "%U %S" in FILE's last line
cpu() { tail -n 1 "$1" | awk '{ printf "%.2f", $1 + $2 }'; }
# quality LOG: "tets min10 below10 below5 maxratio" from `tetrec check` output, or "-"
quality() {
  awk '/check: quality:/ {
         for (i = 1; i <= NF; i++) {
           if ($i == "quality:") tets = $(i + 1)
           if ($i == "min") dmin = $(i + 1)
           if ($i == "radius-edge") r = $(i + 1)
           if ($i == "under" && $(i + 1) == "5") p5 = $(i - 1)
           if ($i == "under" && $(i + 1) == "10") p10 = $(i - 1)
         }
         gsub(/[()%]/, "", p5); gsub(/[()%]/, "", p10)
         print tets, dmin, p10, p5, r; found = 1 }
       END { if (!found) print "- - - - -" }' "$1"
}

table=$OUT/table.txt
printf "%-28s | %-44s | %-44s\n" "model" "tetrec --quality $R: cpu tets mindih <10% <5% maxR" \
  "tetgen -pq${R}Q: cpu tets mindih <10% <5% maxR" | tee "$table"
tot_a_cpu=0 tot_b_cpu=0 tot_a_tets=0 tot_b_tets=0 both=0
tot_a10=0 tot_b10=0 tot_a5=0 tot_b5=0 min_a=180 min_b=180 max_a=0 max_b=0
for model in "$DATA"/data/meshes/*.off; do
  name=$(basename "$model" .off)
  if [ -n "${ONLY:-}" ] && ! echo "$name" | grep -qE "$ONLY"; then continue; fi
  w=$OUT/work/$name
  rm -rf "$w"
  mkdir -p "$w/tg"
  # tetrec
  ra=ok
  rc=0
  timeout "$TIMEOUT" /usr/bin/time -o "$w/tetrec.time" -f "%U %S" \
    "$TETREC" mesh "$model" --quality "$R" ${TETREC_OPTS:-} -o "$w/tetrec.node" --exact -q >"$w/tetrec.log" 2>&1 || rc=$?
  case $rc in
    0) ;;
    2|3|4|5|6|7) ra=fail why=rejected ;; # the input (self-intersecting, open, ...)
    8) ra=fail why=budget ;;
    124) ra=fail why=timeout ;;
    *) ra=fail why=exit$rc ;;
  esac
  a="- - - - - -"
  if [ $ra = ok ]; then
    "$TETREC" check "$model" "$w/tetrec.node" >"$w/tetrec.check" 2>&1 || ra=invalid
    a="$(cpu "$w/tetrec.time") $(quality "$w/tetrec.check")"
  fi
  # tetgen
  cp "$model" "$w/tg/$name.off"
  rb=ok
  if ! (cd "$w/tg" && timeout "$TIMEOUT" /usr/bin/time -o ../tetgen.time -f "%U %S" \
      "$TETGEN" "-pq${R}Q" "$name.off" >../tetgen.log 2>&1); then
    rb=fail
  fi
  b="- - - - - -"
  if [ $rb = ok ] && [ -f "$w/tg/$name.1.node" ]; then
    # the validator may reject it (-p merges coplanar facets, dropping input edges): the
    # shape figures are printed all the same, and the row is marked
    "$TETREC" check "$model" "$w/tg/$name.1.node" >"$w/tetgen.check" 2>&1 || rb=invalid
    b="$(cpu "$w/tetgen.time") $(quality "$w/tetgen.check")"
  else
    rb=fail
  fi
  [ $ra != fail ] || a="fail:$why"
  [ $rb != fail ] || b="$rb"
  [ $ra != invalid ] || a="$a (invalid)"
  [ $rb != invalid ] || b="$b (invalid)"
  printf "%-28s | %-44s | %-44s\n" "$name" "$a" "$b" | tee -a "$table"
  # both meshed and both measured (a mesh `check` could not even read has "-" figures)
  if [ $ra != fail ] && [ $rb != fail ] && ! echo "$a $b" | grep -q ' - - '; then
    read -r ca ta da pa10 pa5 xa _ <<<"${a% (invalid)}"
    read -r cb tb db pb10 pb5 xb _ <<<"${b% (invalid)}"
    both=$((both + 1))
    eval "$(awk -v ca="$ca" -v cb="$cb" -v ta="$ta" -v tb="$tb" -v da="$da" -v db="$db" \
        -v pa10="$pa10" -v pb10="$pb10" -v pa5="$pa5" -v pb5="$pb5" -v xa="$xa" -v xb="$xb" \
        -v A="$tot_a_cpu" -v B="$tot_b_cpu" -v TA="$tot_a_tets" -v TB="$tot_b_tets" \
        -v A10="$tot_a10" -v B10="$tot_b10" -v A5="$tot_a5" -v B5="$tot_b5" \
        -v MA="$min_a" -v MB="$min_b" -v XA="$max_a" -v XB="$max_b" 'BEGIN {
      printf "tot_a_cpu=%.2f tot_b_cpu=%.2f tot_a_tets=%d tot_b_tets=%d ", A + ca, B + cb, TA + ta, TB + tb
      printf "tot_a10=%.0f tot_b10=%.0f tot_a5=%.0f tot_b5=%.0f ", A10 + pa10 * ta / 100, B10 + pb10 * tb / 100, A5 + pa5 * ta / 100, B5 + pb5 * tb / 100
      printf "min_a=%s min_b=%s max_a=%s max_b=%s\n", (da < MA ? da : MA), (db < MB ? db : MB), (xa > XA ? xa : XA), (xb > XB ? xb : XB) }')"
  fi
done
{
  echo
  echo "total over the $both models both meshed:"
  awk -v A="$tot_a_cpu" -v B="$tot_b_cpu" -v TA="$tot_a_tets" -v TB="$tot_b_tets" \
      -v A10="$tot_a10" -v B10="$tot_b10" -v A5="$tot_a5" -v B5="$tot_b5" \
      -v MA="$min_a" -v MB="$min_b" -v XA="$max_a" -v XB="$max_b" 'BEGIN {
    printf "  tetrec: cpu %.2f s, %d tets, min dihedral %s, <10 deg %.2f%%, <5 deg %.2f%%, max radius-edge %s\n", A, TA, MA, TA ? 100 * A10 / TA : 0, TA ? 100 * A5 / TA : 0, XA
    printf "  tetgen: cpu %.2f s, %d tets, min dihedral %s, <10 deg %.2f%%, <5 deg %.2f%%, max radius-edge %s\n", B, TB, MB, TB ? 100 * B10 / TB : 0, TB ? 100 * B5 / TB : 0, XB
    if (B > 0 && TB > 0) printf "  ratios tetrec/tetgen: cpu %.2fx, tets %.2fx\n", A / B, TA / TB }'
} | tee -a "$table"
