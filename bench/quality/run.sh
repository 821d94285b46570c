#!/usr/bin/env bash
# Quality benchmark (issue 17): tetrec `mesh --quality R` against TetGen 1.6 `-pqRQ` on every CGAL
# sample surface (libcgal-dev's data.tar.gz, data/meshes/*.off, extracted into the build
# dir), in the same run. Per model and in total: CPU time (user + system, /usr/bin/time),
# tets, minimum dihedral angle, share of tets with a dihedral angle under 10 and under 5
# degrees, the largest radius-edge ratio and the share of tets over R (the bound both were
# given; TetGen's insertion rules meet it on more tets, docs/benchmarks.md). The shape figures of both
# outputs come from one measure, `tetrec check MODEL OUT.node --quality R`
# (src/refine/quality.h, on the written doubles), which also validates the output (links
# and exact orientation; for tetrec's --exact output also exact conformity and volume); a
# row marked (invalid) failed that
# check (its figures are shown and counted all the same), "fail" is a failed run or a
# timeout (tetrec's: fail:rejected input, fail:budget, fail:timeout). Totals are over the
# models both meshed.
#
# Three more columns per model:
# - "targets": issue 17's per-model targets, on the models both meshed: tetrec's share of
#   tets under 10 degrees at most half of TetGen's (compared on the tet counts) and its
#   minimum dihedral angle at least TetGen's (as printed, 3 decimals); "yes", or "no:"
#   and the ones missed (<10, min). The total says on how many models both hold, with the
#   CPU ratio (target <= 1) and the tet ratio (target <= 1.2).
# - "TetGen surface": TetGen -p merges adjacent input triangles within 0.1 degree of flat
#   into one facet and drops the edge between them; where they are not exactly coplanar
#   its output no longer has the input surface (tetrec keeps every input edge and
#   triangle). bench/quality/tg_surface.py counts, on TetGen's boundary faces (.face), the
#   input edges that are not a chain of their edges (N of the E input edges: "drops N/E")
#   and of those the ones between two faces that are not exactly coplanar (M: "M
#   non-copl."; exact orient3d of the input doubles); "keeps" when N = 0; and the OFF
#   polygons whose vertices are not exactly coplanar (P: "P non-planar polygons"), where
#   tetrec keeps its splitting diagonals as constraints and TetGen takes the polygon as
#   one facet and picks its own. The models both meshed where M = 0 and P = 0 (TetGen
#   keeps the input surface, up to exactly flat merges) are totalled again as the
#   like-for-like comparison.
# - "tetrec <10 on thin input": of tetrec's tets under 10 degrees, those that stand on an
#   input triangle with a corner under 10 degrees (an edge on a boundary face inside one,
#   `--stats` tets_dihedral_below_10_on_thin_input, src/refine/thin.c), "N on T
#   triangles": tetrec keeps every input triangle, and the boundary faces inside a thin
#   one are thin too. The total says how many of the tets under 10 degrees of the models
#   that miss the targets stand so.
#
# With FTETWILD=path, fTetWild (Hu et al. 2020; bench/peer/build_ftetwild.sh builds it from
# its public source, never part of this repository) meshes each model too: `FloatTetwild_bin
# -i IN.off -o OUT.mesh $FT_FLAGS` (default -e 1e-3 --max-threads 1: its default envelope,
# its boundary may lie anywhere within 1e-3 of the bounding-box diagonal, on one thread;
# the model as the OFF `tetrec convert` writes, not timed). Its column: cpu, tets, min dihedral, share under 10 degrees
# by the same `tetrec check --quality R`, and whether that check finds its tets valid
# against their own boundary (links, exact orientation, exact conformity and volume; the
# boundary moved, so it is not checked against the input): "own", or "(invalid)". The
# totals add it over the models tetrec and fTetWild both meshed, with the ratios
# tetrec/fTetWild (issue 47: CPU at most 0.25x).
#
# usage: TETGEN=/path/to/tetgen-1.6 bench/quality/run.sh [BUILD_DIR]
#   BUILD_DIR  a build of tetrec (default build; set up with meson if missing)
#   TETGEN     the TetGen 1.6 binary (required; not part of the repository). Build it with
#              bench/peer/build_tetgen.sh (all of it at -O3): TetGen's own makefile builds
#              predicates.cxx at -O0, which makes it about 40% slower on cheese, and the
#              CPU ratio is only comparable between runs against the same build
#   R=1.414    the radius-edge bound given to both
#   TIMEOUT=s  per-process wall-clock limit (default 120)
#   REPEAT=n   run each program n times per model and keep its fastest run (default 1).
#              TetGen's CPU time varies from run to run far more than tetrec's: anchor
#              took 3.97 s in one bench and 5.5 to 6.1 s in three later runs on the same
#              machine, and its total over the 74 models went from 41 to 53 s between
#              benches, while tetrec's stayed within 48.5 to 52.5 s
#   ONLY=regex only the models whose name matches (grep -E)
#   TETREC_OPTS="..." more options for tetrec mesh (e.g. "-O 0": without sliver removal)
#   TOL=EPS    tetrec meshes with --surface-tolerance EPS (docs/simplify.md) and its
#              output is checked with `tetrec check --surface-tolerance EPS` (the proven
#              two-sided bound instead of exact conformity)
#   FTETWILD=path     also fTetWild (above); FT_FLAGS="..." its options instead of
#              -e 1e-3 --max-threads 1
#   TG_FLAGS="..."    TetGen's switches instead of -pq${R}Q, e.g. -p180//0q1.414Q: no facet
#              merging (-p180) and no removal of near-flat edges at small angles (//0);
#              plain -p180 still drops edges under 5 degrees from flat at angles under 15;
#              -p180//0 still drops those whose two triangles' normals are parallel in
#              doubles (pinion: 17 of 1950, all non-coplanar) and costs TetGen far more
# Output: stdout and BUILD/bench-quality/table.txt; logs under BUILD/bench-quality/work/.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-build}
case $BUILD in /*) ;; *) BUILD=$ROOT/$BUILD ;; esac
R=${R:-1.414}
TIMEOUT=${TIMEOUT:-120}
TG_FLAGS=${TG_FLAGS:--pq${R}Q}
FTETWILD=${FTETWILD:-}
FT_FLAGS=${FT_FLAGS:--e 1e-3 --max-threads 1}
if [ -n "$FTETWILD" ] && [ ! -x "$FTETWILD" ]; then
  echo "FTETWILD=$FTETWILD is not executable (bench/peer/build_ftetwild.sh builds it)" >&2
  exit 1
fi
: "${TETGEN:?set TETGEN to the TetGen 1.6 binary}"
[ -x "$TETGEN" ] || { echo "TETGEN=$TETGEN is not executable" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian package time)" >&2; exit 1; }
command -v python3 >/dev/null || { echo "needs python3 (bench/quality/tg_surface.py)" >&2; exit 1; }
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
# timed FILE CMD...: CMD under the timeout, REPEAT times; FILE gets the "%U %S" line of
# the fastest run. Returns the exit status of the first run that fails (then no more runs).
timed() {
  local file=$1 i rc
  shift
  rm -f "$file"
  for ((i = 0; i < ${REPEAT:-1}; i++)); do
    rc=0
    timeout "$TIMEOUT" /usr/bin/time -o "$file.run" -f "%U %S" "$@" || rc=$?
    [ $rc = 0 ] || { mv "$file.run" "$file" 2>/dev/null || true; return $rc; }
    if [ ! -f "$file" ] ||
        awk -v a="$(cpu "$file.run")" -v b="$(cpu "$file")" 'BEGIN { exit !(a + 0 < b + 0) }'; then
      mv "$file.run" "$file"
    else
      rm -f "$file.run"
    fi
  done
}
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
# overr LOG: "N (x%)" of `tetrec check --quality R`'s bounds line: the tets over R, or "- -"
overr() {
  awk '/check: bounds:/ {
         for (i = 1; i <= NF; i++)
           if ($i == "over" && $(i + 1) == "radius-edge") { n = $(i - 2); p = $(i - 1) }
         gsub(/[()%]/, "", p); found = 1 }
       END { print found ? n " " p : "- -" }' "$1"
}
# thin JSON: "N T" of tetrec's --stats: its tets under 10 degrees that stand on input
# triangles with a corner under 10 degrees (src/refine/thin.c), and those triangles
thin() {
  python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
print(d.get("tets_dihedral_below_10_on_thin_input", "-"), d.get("thin_input_triangles", "-"))' "$1" \
    2>/dev/null || echo "- -"
}
# under LOG: "N10 N5", the numbers of tets with a dihedral angle under 10 and under 5 degrees
under() {
  awk '/check: quality:/ {
         for (i = 1; i <= NF; i++) {
           if ($i == "under" && $(i + 1) == "10") n10 = $(i - 2)
           if ($i == "under" && $(i + 1) == "5") n5 = $(i - 2)
         }
         found = 1 }
       END { print found ? n10 " " n5 : "- -" }' "$1"
}

table=$OUT/table.txt
rows=$OUT/work/rows.txt
ftrows=$OUT/work/ftrows.txt
: >"$rows"
: >"$ftrows"
ft_head=
[ -z "$FTETWILD" ] || ft_head=" | ftetwild ${FT_FLAGS}: cpu tets mindih <10% valid"
printf "%-28s | %-50s | %-50s | %-13s | %-36s | %s%s\n" "model" "tetrec --quality $R: cpu tets mindih <10% <5% maxR >R%" \
  "tetgen ${TG_FLAGS}: cpu tets mindih <10% <5% maxR >R%" "targets" "TetGen surface" \
  "tetrec <10 on thin input" "$ft_head" | tee "$table"
for model in "$DATA"/data/meshes/*.off; do
  name=$(basename "$model" .off)
  if [ -n "${ONLY:-}" ] && ! echo "$name" | grep -qE "$ONLY"; then continue; fi
  w=$OUT/work/$name
  rm -rf "$w"
  mkdir -p "$w/tg"
  # tetrec
  ra=ok
  rc=0
  # shellcheck disable=SC2086
  timed "$w/tetrec.time" \
    "$TETREC" mesh "$model" --quality "$R" ${TOL:+--surface-tolerance "$TOL"} ${TETREC_OPTS:-} -o "$w/tetrec.node" --exact -q \
      --stats "$w/tetrec.json" >"$w/tetrec.log" 2>&1 || rc=$?
  case $rc in
    0) ;;
    2|3|4|5|6|7) ra=fail why=rejected ;; # the input (self-intersecting, open, ...)
    8) ra=fail why=budget ;;
    124) ra=fail why=timeout ;;
    *) ra=fail why=exit$rc ;;
  esac
  a="- - - - - - -"
  thin="- -"
  if [ $ra = ok ]; then
    thin=$(thin "$w/tetrec.json")
    "$TETREC" check "$model" "$w/tetrec.node" --quality "$R" ${TOL:+--surface-tolerance "$TOL"} >"$w/tetrec.check" 2>&1 || ra=invalid
    a="$(cpu "$w/tetrec.time") $(quality "$w/tetrec.check") $(overr "$w/tetrec.check" | cut -d' ' -f2)"
  fi
  # tetgen
  cp "$model" "$w/tg/$name.off"
  rb=ok
  # shellcheck disable=SC2086
  if ! (cd "$w/tg" && timed ../tetgen.time "$TETGEN" $TG_FLAGS "$name.off" >../tetgen.log 2>&1); then
    rb=fail
  fi
  b="- - - - - - -"
  surf=- edges=- dropped=- noncopl=- nonplanar=-
  if [ $rb = ok ] && [ -f "$w/tg/$name.1.node" ]; then
    # the validator may reject it (-p merges coplanar facets, dropping input edges): the
    # shape figures are printed all the same, and the row is marked
    "$TETREC" check "$model" "$w/tg/$name.1.node" --quality "$R" >"$w/tetgen.check" 2>&1 || rb=invalid
    b="$(cpu "$w/tetgen.time") $(quality "$w/tetgen.check") $(overr "$w/tetgen.check" | cut -d' ' -f2)"
    if [ ! -f "$w/tg/$name.1.face" ]; then
      surf="- (no .face)"
    elif python3 "$ROOT/bench/quality/tg_surface.py" "$model" "$w/tg/$name.1" -v \
        >"$w/tetgen.surface" 2>&1; then
      read -r edges dropped noncopl nonplanar <<<"$(tail -n 1 "$w/tetgen.surface")"
      if [ "$dropped" = 0 ]; then surf="keeps all $edges"
      else surf="drops $dropped/$edges, $noncopl non-copl."; fi
      [ "$nonplanar" = 0 ] || surf="$surf; $nonplanar non-planar polygons"
    else
      surf="? (see work/$name/tetgen.surface)"
    fi
  else
    rb=fail
  fi
  [ $ra != fail ] || a="fail:$why"
  [ $rb != fail ] || b="$rb"
  [ $ra != invalid ] || a="$a (invalid)"
  [ $rb != invalid ] || b="$b (invalid)"
  # both meshed and both measured (a mesh `check` could not even read has "-" figures)
  target=-
  if [ $ra != fail ] && [ $rb != fail ] && ! echo "$a $b" | grep -q ' - - '; then
    read -r ca ta da _ _ xa _ <<<"${a% (invalid)}"
    read -r cb tb db _ _ xb _ <<<"${b% (invalid)}"
    read -r na na5 <<<"$(under "$w/tetrec.check")"
    read -r nb nb5 <<<"$(under "$w/tetgen.check")"
    read -r ova _ <<<"$(overr "$w/tetrec.check")"
    read -r ovb _ <<<"$(overr "$w/tetgen.check")"
    target=$(awk -v na="$na" -v ta="$ta" -v nb="$nb" -v tb="$tb" -v da="$da" -v db="$db" 'BEGIN {
      m = ""
      if (2 * na * tb > nb * ta) m = "<10"
      if (da + 0 < db + 0) m = m (m == "" ? "" : ",") "min"
      print m == "" ? "yes" : "no:" m }')
    echo "$name $ca $ta $da $na $na5 $xa $cb $tb $db $nb $nb5 $xb $target $dropped $noncopl $nonplanar $ova $ovb $thin" >>"$rows"
  elif [ "$edges" != - ]; then
    # TetGen's surface is still counted on the models only TetGen meshed
    echo "$name - - - - - - - - - - - - - $dropped $noncopl $nonplanar" >>"$rows"
  fi
  read -r thin_n thin_t <<<"$thin"
  thin_col=-
  [ "$thin_n" = - ] || thin_col="$thin_n on $thin_t triangles"
  ft_col=
  if [ -n "$FTETWILD" ]; then
    mkdir -p "$w/ft"
    # shellcheck disable=SC2086
    if ! "$TETREC" convert "$model" "$w/ft/in.off" -q >"$w/ft/convert.log" 2>&1; then
      c=fail:convert
    elif timed "$w/ftetwild.time" "$FTETWILD" -i "$w/ft/in.off" -o "$w/ft/out.mesh" $FT_FLAGS \
        >"$w/ftetwild.log" 2>&1 </dev/null && [ -s "$w/ft/out.mesh" ]; then
      awk -f "$ROOT/bench/peer/mesh_boundary.awk" "$w/ft/out.mesh" >"$w/ft/boundary.off"
      cv=own
      "$TETREC" check "$w/ft/boundary.off" "$w/ft/out.mesh" --quality "$R" >"$w/ftetwild.check" 2>&1 ||
        cv="(invalid)"
      read -r tc dc pc _ _ <<<"$(quality "$w/ftetwild.check")"
      read -r nc _ <<<"$(under "$w/ftetwild.check")"
      c="$(cpu "$w/ftetwild.time") $tc $dc $pc $cv"
      # with tetrec's figures where it meshed: cpu tets min n10, fTetWild's the same
      if [ $ra != fail ] && [ "$tc" != - ]; then
        read -r ca ta da _ _ _ _ <<<"${a% (invalid)}"
        read -r na _ <<<"$(under "$w/tetrec.check")"
        echo "$name $ca $ta $da $na $(cpu "$w/ftetwild.time") $tc $dc $nc" >>"$ftrows"
      fi
    else
      c=fail
    fi
    rm -f "$w/ft/out.mesh" "$w/ft/out.mesh"_* "$w/ft/boundary.off"
    ft_col=" | $c"
  fi
  printf "%-28s | %-50s | %-50s | %-13s | %-36s | %s%s\n" "$name" "$a" "$b" "$target" "$surf" \
    "$thin_col" "$ft_col" | tee -a "$table"
done
# totals: the first four lines as before the targets and surface columns came (others read them)
# rows: name, tetrec's cpu tets min n10 n5 maxR, TetGen's the same, target, dropped,
# non-coplanar, non-planar polygons, tets over R of tetrec and of TetGen
awk '
  function add(k) {
    n[k]++; A[k] += $2; TA[k] += $3; NA[k] += $5; NA5[k] += $6
    B[k] += $8; TB[k] += $9; NB[k] += $11; NB5[k] += $12; RA[k] += $18; RB[k] += $19
    if (!(k in MA) || $4 + 0 < MA[k] + 0) MA[k] = $4
    if (!(k in XA) || $7 + 0 > XA[k] + 0) XA[k] = $7
    if (!(k in MB) || $10 + 0 < MB[k] + 0) MB[k] = $10
    if (!(k in XB) || $13 + 0 > XB[k] + 0) XB[k] = $13
    if ($14 == "yes") met[k]++
    if ($20 != "" && $20 != "-") { TH[k] += $20; if ($14 != "yes") THM[k] += $20 }
    if ($14 != "yes") { miss[k]++; NAM[k] += $5 }
  }
  function line(who, c, t, n10, n5, mn, mx, nr) {
    printf "  %s: cpu %.2f s, %d tets, min dihedral %s, <10 deg %.2f%%, <5 deg %.2f%%, max radius-edge %s, over R %.2f%%\n", who, c, t, mn, t ? 100 * n10 / t : 0, t ? 100 * n5 / t : 0, mx, t ? 100 * nr / t : 0
  }
  function totals(k) {
    line("tetrec", A[k], TA[k], NA[k], NA5[k], k in MA ? MA[k] : 180, k in XA ? XA[k] : 0, RA[k])
    line("tetgen", B[k], TB[k], NB[k], NB5[k], k in MB ? MB[k] : 180, k in XB ? XB[k] : 0, RB[k])
    if (B[k] > 0 && TB[k] > 0) printf "  ratios tetrec/tetgen: cpu %.2fx, tets %.2fx\n", A[k] / B[k], TA[k] / TB[k]
  }
  {
    if ($15 != "-") { tg++; if ($15 > 0) tgd++; if ($16 > 0) tgn++; if ($17 > 0) tgp++; if ($16 == 0 && $17 == 0) tgk++ }
    if ($2 == "-") next
    add("all")
    if ($15 != "-") {
      ed += $15; em += $16
      if ($16 == 0 && $17 == 0) add("lfl")
      if ($15 == 0 && $17 == 0) add("same")
    }
  }
  END {
    printf "\ntotal over the %d models both meshed:\n", n["all"]
    totals("all")
    printf "  issue 17 targets (per model: share under 10 deg at most half of TetGen'"'"'s, min dihedral at least TetGen'"'"'s): met on %d of %d models", met["all"], n["all"]
    if (B["all"] > 0 && TB["all"] > 0) printf "; cpu %.2fx (target <= 1), tets %.2fx (target <= 1.2)", A["all"] / B["all"], TA["all"] / TB["all"]
    printf "\n  tetrec'"'"'s tets under 10 deg standing on input triangles with a corner under 10 deg (an edge on a boundary face inside one; src/refine/thin.c): %d of %d; on the %d models that miss the targets, %d of %d\n", TH["all"], NA["all"], miss["all"], THM["all"], NAM["all"]
    printf "\nTetGen'"'"'s surface (%d models TetGen meshed): it drops input edges on %d, edges between non-coplanar faces on %d; %d have non-planar polygons; it keeps the input surface (drops no edge between non-coplanar faces, no non-planar polygon) on %d\n", tg, tgd, tgn + 0, tgp + 0, tgk
    printf "  over the %d models both meshed: %d input edges dropped, %d of them between non-coplanar faces\n", n["all"], ed, em
    printf "like-for-like: the %d models both meshed where TetGen keeps the input surface:\n", n["lfl"]
    totals("lfl")
    printf "  issue 17 targets met on %d of %d models\n", met["lfl"], n["lfl"]
    printf "  of those, the %d where TetGen keeps every input edge: targets met on %d", n["same"], met["same"]
    if (B["same"] > 0 && TB["same"] > 0) printf "; cpu %.2fx, tets %.2fx", A["same"] / B["same"], TA["same"] / TB["same"]
    printf "\n"
  }' "$rows" | tee -a "$table"
if [ -n "$FTETWILD" ]; then
  # ftrows: name, tetrec's cpu tets min n10, fTetWild's the same
  awk '
    { n++; ca += $2; ta += $3; na += $5; cb += $6; tb += $7; nb += $9
      if (n == 1 || $4 + 0 < ma) ma = $4 + 0
      if (n == 1 || $8 + 0 < mb) mb = $8 + 0
      if ($4 + 0 >= $8 + 0) ge++ }
    END {
      printf "\nfTetWild: total over the %d models tetrec and fTetWild both meshed:\n", n
      if (!n) exit
      printf "  tetrec:   cpu %.2f s, %d tets, min dihedral %s, <10 deg %.2f%%\n", ca, ta, ma, ta ? 100 * na / ta : 0
      printf "  ftetwild: cpu %.2f s, %d tets, min dihedral %s, <10 deg %.2f%%\n", cb, tb, mb, tb ? 100 * nb / tb : 0
      printf "  ratios tetrec/ftetwild: cpu %.2fx (issue 47: <= 0.25x), tets %.2fx; tetrec'"'"'s min dihedral >= fTetWild'"'"'s on %d of %d\n", cb ? ca / cb : 0, tb ? ta / tb : 0, ge, n
    }' "$ftrows" | tee -a "$table"
fi
