#!/usr/bin/env bash
# Real-world benchmark (issue 50): tetrec against TetGen 1.6, and fTetWild when FTETWILD is
# set (issues 47 and 49), on the corpus of
# bench/realworld/manifest.txt (public test surfaces from STLCutters.jl, wildmeshing/data,
# TetGenTests, FastAndRobustMeshArrangements and CGAL's data meshes; fetched by
# bench/realworld/fetch.sh at pinned commits, never part of this repository), model by
# model in the same run, one process at a time.
#
# Modes (the same task for both programs):
#   plain    tetrec mesh IN -o W/tetrec.node -q                         tetgen -pQ
#   keep     ... --keep-surface                                         tetgen -pYQ
#   quality  ... --quality R (R=1.414)                                  tetgen -pqRQ
#   TetGen gets `a` too for a .poly or .smesh (its region list's volume bounds, which
#   tetrec always applies: without it TetGen meshes a coarser task)
#
# Per model (one row; "-" where there is nothing to show):
#   tris     input triangles (the manifest's count, as tetrec reads the file)
#   exit     ok, rej:N (tetrec exit 2..7: the input is invalid, open or self-
#            intersecting), exit:N (TetGen: 3 its input error, e.g. self-intersections;
#            139 a crash), t/o (the TIMEOUT), ok:0tets (TetGen: exit 0 and no tets)
#   cpu      user + system seconds of the meshing run (/usr/bin/time), output included;
#            the run a user makes, without statistics: tetrec's come from an untimed
#            second run with --stats W/tetrec.json (the same output: the runs are
#            deterministic), as TetGen's do (see steiner). TR_STATS_TIMED=1 times the
#            run with --stats instead (one run; the statistics cost about 5%)
#   steiner  points that are not input vertices: total (on edges/facets/interior).
#            tetrec: --stats steiner_on_edges, steiner_on_facets, steiner_interior (after
#            suppression: the points in the output), and "+Nr": the N more points of
#            its output (volume_nodes - surface_nodes) that refinement and sliver removal
#            added, which its stats do not split. TetGen: its own statistics "Steiner
#            points on input segments / on input facets / inside domain", from an untimed
#            second run of the same switches with N E F instead of Q (no files,
#            statistics printed); a note when they differ from its output .node count
#            minus its "Input points" (it drops duplicate and unused input points from
#            the .node). TG_DETAIL=0 skips that run: then the total only, the .node count
#            minus the vertex count of `tetrec convert IN`
#   tets     tetrahedra of the output
#   <10deg   share of tets with a dihedral angle under 10 degrees, for both outputs from
#            one measure: `tetrec check IN OUT.node --quality R` (src/refine/quality.h, on
#            the written doubles)
#   valid    that same `tetrec check`: yes (links, exact orientation, exact conformity to
#            the input surface and volume), yes* (the output has Steiner points rounded to
#            doubles: links and exact orientation only), NO (see W/*.check; e.g. TetGen
#            -p merges nearly coplanar input triangles and drops the edges between them)
#   cpu target  where both meshed: tetrec's CPU <= max(1.5 x TetGen's, TetGen's + 0.05 s):
#            ok / over
# Totals over the models both meshed: CPU, Steiner points (by where they lie), tets, the
# share under 10 degrees, and the ratios tetrec/TetGen; then the outcomes of each program
# over every model run.
#
# fTetWild (FTETWILD=path; Hu et al. 2020, built from its public source by
# bench/peer/build_ftetwild.sh, never part of this repository), run after the other two:
# `FloatTetwild_bin -i IN -o W/ft/out.mesh $FT_FLAGS` (default -e 1e-3 --max-threads 1:
# its default envelope, its boundary may lie anywhere within 1e-3 of the bounding-box
# diagonal of the input; one thread, like tetrec). It has one task in every mode, its own
# quality meshing within that envelope. It reads STL and OBJ as given, every other format
# as the OFF that `tetrec convert` writes (not timed). Its columns: exit, cpu, tets,
# <10deg (tetrec check --quality R, as above) and valid, which judges its tets but not
# their boundary against the input (that boundary moved): `tetrec check` of its .mesh
# against its own boundary faces (the faces of one tet only; every vertex of the .mesh
# is an input point, so the check is exact), written as OFF by
# bench/peer/mesh_boundary.awk: "own" = links, exact orientation, exact conformity to that
# boundary and volume hold; NO otherwise (see W/ft.check). The totals add fTetWild's over
# the models both tetrec and it meshed, with the ratios tetrec/fTetWild (issues 47 and 49:
# total CPU at most 0.25x).
#
# TetGen does not read OBJ, nor binary STL (its STL reader reads text only and stops
# with "Wrong number of vertices"): such a model is given to it as the OFF file that
# `tetrec convert IN W/tg/NAME.off` writes (vertices as %.17g, the same doubles; not
# timed). TetGen's OFF reader also aborts on '#' comment lines, so it reads an OFF copy
# without them. tetrec check measures TetGen's output against the original file.
#
# usage: TETGEN=/path/to/tetgen-1.6 bench/realworld/run.sh [BUILD_DIR] [MODE]
#   BUILD_DIR  a build of tetrec (default build; set up and built only when its
#              src/cli/tetrec is missing: an existing build is measured as it is, so a
#              tree others are editing is never rebuilt under them; run ninja first)
#   MODE       plain (default), keep or quality
#   TETGEN     the TetGen 1.6 binary (required; not part of the repository): build it
#              with bench/peer/build_tetgen.sh SRC_DIR OUT from TetGen's public source
#   CORPUS=dir the corpus (default BUILD_DIR/realworld; fetched there by fetch.sh when
#              missing, which also honours TETREC_CORPUS_MIRROR)
#   ONLY=regex only the models whose name (SOURCE/PATH) matches (grep -E)
#   NOTE=regex only the models whose manifest note matches, e.g. NOTE='^-$' leaves out
#              the self-intersecting ones
#   TIMEOUT=s  per-process wall-clock limit (default 300)
#   R=1.414    the radius-edge bound of quality mode, and of the check's figures
#   TR_FLAGS="..."  more tetrec options; TG_FLAGS="..." TetGen's switches instead of the
#              mode's
#   TOL=EPS    tetrec meshes with --surface-tolerance EPS (issue 47, docs/simplify.md)
#              and its output is checked with `tetrec check --surface-tolerance EPS`
#              (the proven two-sided bound instead of exact conformity); rows.tsv then
#              also holds the bound tetrec reports (--stats surface_tolerance_bound)
#   TG_DETAIL=0     no untimed TetGen statistics run (see steiner above)
#   FTETWILD=path   also run fTetWild (see above); FT_FLAGS="..." its options instead of
#              -e 1e-3 --max-threads 1
#   TR_FLAGS with --resolve or --resolve-internal: tetrec's output is checked with the same
#              option (against the solid of the arrangement, docs/resolve.md)
#   KEEP=1     keep the output meshes (default: deleted once measured)
#   RESULTS=dir     where the results go (default BUILD_DIR/bench-realworld-MODE, with
#              -only appended when ONLY or NOTE picks a subset)
# Output: stdout, BUILD_DIR/bench-realworld-MODE/table.txt and rows.tsv (one line per
# model, tab-separated); logs of every process under BUILD_DIR/bench-realworld-MODE/work/.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-build}
case $BUILD in /*) ;; *) BUILD=$ROOT/$BUILD ;; esac
MODE=${2:-plain}
R=${R:-1.414}
TIMEOUT=${TIMEOUT:-300}
TR_FLAGS=${TR_FLAGS:-}
TOL=${TOL:-}
tol_flags=()
[ -z "$TOL" ] || tol_flags=(--surface-tolerance "$TOL")
TG_DETAIL=${TG_DETAIL:-1}
TR_STATS_TIMED=${TR_STATS_TIMED:-0}
KEEP=${KEEP:-0}
case $MODE in
  plain) tr_mode=(); tg_mode=-pQ ;;
  keep) tr_mode=(--keep-surface); tg_mode=-pYQ ;;
  quality) tr_mode=(--quality "$R"); tg_mode=-pq${R}Q ;;
  *) echo "MODE must be plain, keep or quality, not $MODE" >&2; exit 1 ;;
esac
TG_FLAGS=${TG_FLAGS:-$tg_mode}
FTETWILD=${FTETWILD:-}
FT_FLAGS=${FT_FLAGS:--e 1e-3 --max-threads 1}
if [ -n "$FTETWILD" ]; then
  [ -x "$FTETWILD" ] ||
    { echo "FTETWILD=$FTETWILD is not executable (bench/peer/build_ftetwild.sh builds it)" >&2; exit 1; }
fi
# the check of tetrec's output is against what tetrec meshed: with --resolve, the solid
chk_flags=()
for f in $TR_FLAGS; do
  case $f in --resolve|--resolve-internal) chk_flags+=("$f") ;; esac
done
: "${TETGEN:?set TETGEN to the TetGen 1.6 binary (bench/peer/build_tetgen.sh)}"
[ -x "$TETGEN" ] || { echo "TETGEN=$TETGEN is not executable" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian package time)" >&2; exit 1; }
TETREC=$BUILD/src/cli/tetrec
if [ ! -x "$TETREC" ]; then
  [ -f "$BUILD/build.ninja" ] ||
    meson setup "$BUILD" "$ROOT" --buildtype=release -Dbench=false >/dev/null
  ninja -C "$BUILD" src/cli/tetrec >/dev/null
fi
MANIFEST=$ROOT/bench/realworld/manifest.txt
CORPUS=${CORPUS:-$BUILD/realworld}
if [ ! -d "$CORPUS" ]; then
  # a partial corpus still runs: what fetch.sh could not get is skipped below
  bash "$ROOT/bench/realworld/fetch.sh" "$CORPUS" || true
fi
OUT=${RESULTS:-$BUILD/bench-realworld-$MODE}
[ -n "${RESULTS:-}" ] || [ -z "${ONLY:-}${NOTE:-}" ] || OUT=$OUT-only # a subset never overwrites a whole run
mkdir -p "$OUT/work"

# cpu FILE: user + system seconds of the "%U %S" line /usr/bin/time wrote last in FILE
cpu() { tail -n 1 "$1" 2>/dev/null | awk 'NF == 2 { printf "%.2f", $1 + $2; ok = 1 } END { if (!ok) print "-" }'; }
# timed FILE CMD...: CMD under the timeout; FILE gets its CPU times; returns CMD's status
timed() {
  local file=$1
  shift
  timeout "$TIMEOUT" /usr/bin/time -o "$file" -f "%U %S" "$@"
}
# again CMD...: CMD, run again after a pause while it cannot be started (exit 126/127, also
# through timeout and /usr/bin/time): a shared build's tetrec may be being relinked
again() {
  local rc
  for _ in 1 2 3 4 5 6; do
    rc=0
    "$@" || rc=$?
    case $rc in 126|127) sleep 20 ;; *) return $rc ;; esac
  done
  return $rc
}
# outcome RC: the exit column's word for an exit status
outcome() {
  case $1 in
    0) echo ok ;;
    124) echo t/o ;;
    *) echo "exit:$1" ;;
  esac
}
# count FILE: the first number of the first line of a TetGen-style file (nodes, tets)
count() { [ -f "$1" ] && awk '!/^[ \t]*(#|$)/ { print $1; exit }' "$1" || true; }
# field NAME FILE: the number after "NAME": in a flat JSON file (empty if absent)
field() { sed -n "s/.*\"$1\": *\([0-9.eE+-]*\).*/\1/p" "$2" 2>/dev/null | head -n 1; }
# under10 LOG: "N TETS" of `tetrec check --quality` output: tets under 10 degrees, all tets
under10() {
  awk '/check: quality:/ {
         for (i = 1; i <= NF; i++) {
           if ($i == "quality:") t = $(i + 1)
           if ($i == "under" && $(i + 1) == "10") n = $(i - 2)
         }
         found = 1 }
       END { print found ? n " " t : "- -" }' "$1" 2>/dev/null
}
# validate IN MESH LOG WHO: "yes", "yes*" or "NO" by `tetrec check` (also writes the
# figures); why a mesh is invalid goes to the notes
validate() {
  local extra=()
  [ "$4" != tetrec ] || extra=("${tol_flags[@]}" "${chk_flags[@]}")
  if again timeout "$TIMEOUT" "$TETREC" check "$1" "$2" --quality "$R" "${extra[@]}" >"$3" 2>&1; then
    if grep -q 'rounded doubles\|surface are within' "$3"; then echo 'yes*'; else echo yes; fi
  else
    echo NO
    echo "$name: $4 output invalid: $(grep -m1 'error' "$3" | cut -c1-200)" >>"$notes"
  fi
}
# tg_stat NAME LOG: the number after "NAME:" in TetGen's statistics (0 if absent: TetGen
# prints the Steiner lines only when there are such points)
tg_stat() { awk -v k="$1" 'index($0, k ":") { sub(/.*:/, ""); n = $1 + 0 } END { print n + 0 }' "$2"; }
# binary_stl FILE: whether FILE is a binary STL (84 bytes of header and count, then 50 per
# triangle; its first bytes may still say "solid")
binary_stl() {
  local n
  n=$(od -An -tu4 -j80 -N4 "$1" | tr -d ' ')
  [ -n "$n" ] && [ "$(stat -c %s "$1")" = $((84 + 50 * n)) ]
}
pct() { awk -v n="$1" -v t="$2" 'BEGIN { if (n == "-" || t == "-" || t == 0) print "-"; else printf "%.2f%%", 100 * n / t }'; }

TR_VERSION=$("$TETREC" --version 2>/dev/null | head -n 1 || true)
TG_VERSION=$("$TETGEN" -h 2>/dev/null | sed -n 's/^Version *//p' | head -n 1 || true)
table=$OUT/table.txt
rows=$OUT/rows.tsv
notes=$OUT/notes.txt
: >"$notes"
: >"$rows"
{
  echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); timeout ${TIMEOUT}s; mode $MODE"
  if [ "$TR_STATS_TIMED" = 1 ]; then st_note="--stats S.json "; else st_note=""; fi
  echo "tetrec ($TR_VERSION): mesh IN -o OUT.node ${st_note}-q ${tr_mode[*]} ${tol_flags[*]} $TR_FLAGS" \
    "(timed; statistics from an untimed run with --stats unless TR_STATS_TIMED=1)"
  echo "tetgen ${TG_VERSION:-(version unknown)} $TG_FLAGS; corpus $CORPUS"
  [ -z "$FTETWILD" ] ||
    echo "ftetwild: FloatTetwild_bin -i IN -o OUT.mesh $FT_FLAGS; valid: against its own boundary (it moves the input's), see the header"
  echo "steiner: total (on edges/facets/interior); <10deg: share of tets with a dihedral angle under 10 degrees (tetrec check --quality $R on both)"
  if [ -n "$FTETWILD" ]; then
    printf '%-46s %6s | %-8s %6s %-26s %8s %7s %-4s | %-8s %6s %-26s %8s %7s %-4s | %-10s | %-8s %6s %8s %7s %s\n' \
      model tris "tetrec" cpu steiner tets "<10deg" valid "tetgen" cpu steiner tets "<10deg" valid \
      "cpu target" ftetwild cpu tets "<10deg" valid
  else
    printf '%-46s %6s | %-8s %6s %-26s %8s %7s %-4s | %-8s %6s %-26s %8s %7s %-4s | %s\n' \
      model tris "tetrec" cpu steiner tets "<10deg" valid "tetgen" cpu steiner tets "<10deg" valid \
      "cpu target"
  fi
} | tee "$table"

absent=0
idx=0
# the manifest comes on fd 3, so that no program run in the loop can read it from stdin
while read -r _ src path _ tris note <&3; do
  name=$src/$path
  if [ -n "${ONLY:-}" ] && ! printf '%s\n' "$name" | grep -qE "$ONLY"; then continue; fi
  if [ -n "${NOTE:-}" ] && ! printf '%s\n' "$note" | grep -qE "$NOTE"; then continue; fi
  model=$CORPUS/$src/$path
  if [ ! -f "$model" ]; then
    echo "$name: not in the corpus (fetch.sh could not get it): skipped" >>"$notes"
    absent=$((absent + 1))
    continue
  fi
  w=$OUT/work/${name//\//_}
  rm -rf "$w"
  mkdir -p "$w/tg"
  base=$(basename "$path")
  ext=${base##*.}
  # TetGen names its output after its input with the last dot-part taken as an iteration
  # number (ellipe0.003.off -> ellipe0.4.node), so its copy of every model is called in.EXT
  stem=in
  # TetGen's input: the same surface in a file it reads (see the header)
  kind=$ext
  [ "$ext" != stl ] || ! binary_stl "$model" || kind=binary-stl
  case $kind in
    obj|binary-stl)
      tg_in=$stem.off
      again "$TETREC" convert "$model" "$w/tg/$tg_in" -q >"$w/convert.log" 2>&1 || tg_in=
      echo "$name: TetGen reads ${tg_in:-nothing (tetrec convert failed)} written by tetrec convert (TetGen reads no OBJ or binary STL)" >>"$notes" ;;
    off)
      tg_in=$stem.off
      if grep -q '#' "$model"; then
        sed 's/#.*//' "$model" | grep -v '^[[:space:]]*$' >"$w/tg/$tg_in"
        echo "$name: TetGen reads a copy without '#' comments" >>"$notes"
      else
        ln -s "$model" "$w/tg/$tg_in"
      fi ;;
    *)
      tg_in=$stem.$ext
      ln -s "$model" "$w/tg/$tg_in"
      # a .poly or .smesh may take its points from the .node of the same name
      [ ! -f "${model%.*}.node" ] || ln -s "${model%.*}.node" "$w/tg/$stem.node" ;;
  esac

  tg_flags=$TG_FLAGS
  case $ext in poly|smesh) [[ $tg_flags == *a* ]] || tg_flags=${tg_flags}a ;; esac

  run_tetrec() {
    tr_rc=0
    local stats=(--stats "$w/tetrec.json")
    [ "$TR_STATS_TIMED" = 1 ] || stats=()
    # shellcheck disable=SC2086
    again timed "$w/tetrec.time" "$TETREC" mesh "$model" -o "$w/tetrec.node" \
      "${stats[@]}" -q "${tr_mode[@]}" "${tol_flags[@]}" $TR_FLAGS >"$w/tetrec.log" 2>&1 || tr_rc=$?
    if [ "$TR_STATS_TIMED" != 1 ] && [ "$tr_rc" != 124 ]; then
      # the statistics, untimed, from the same command (its output goes elsewhere)
      mkdir -p "$w/stats"
      # shellcheck disable=SC2086
      again timeout "$TIMEOUT" "$TETREC" mesh "$model" -o "$w/stats/tetrec.node" \
        --stats "$w/tetrec.json" -q "${tr_mode[@]}" "${tol_flags[@]}" $TR_FLAGS \
        >"$w/stats/tetrec.log" 2>&1 || true
      rm -rf "$w/stats"
    fi
  }
  run_tetgen() {
    tg_rc=0
    if [ -z "$tg_in" ]; then tg_rc=conv; return; fi
    # shellcheck disable=SC2086
    (cd "$w/tg" && timed ../tetgen.time "$TETGEN" $tg_flags "$tg_in" >../tetgen.log 2>&1) || tg_rc=$?
  }
  # alternate which program runs first, so that neither always finds the caches warm
  if [ $((idx % 2)) -eq 0 ]; then run_tetrec; run_tetgen; else run_tetgen; run_tetrec; fi
  idx=$((idx + 1))
  # fTetWild: its input as for TetGen, but it reads binary STL and OBJ too
  c_out=- c_cpu=- c_tets=- c_n10=- c_valid=- c_min=-
  if [ -n "$FTETWILD" ]; then
    mkdir -p "$w/ft"
    case $ext in
      stl|obj) ft_in=$model ;;
      *)
        ft_in=$w/ft/in.off
        again "$TETREC" convert "$model" "$ft_in" -q >"$w/ft/convert.log" 2>&1 || ft_in= ;;
    esac
    ft_rc=0
    if [ -z "$ft_in" ]; then
      c_out=conv
    else
      # shellcheck disable=SC2086
      timed "$w/ftetwild.time" "$FTETWILD" -i "$ft_in" -o "$w/ft/out.mesh" $FT_FLAGS \
        >"$w/ftetwild.log" 2>&1 </dev/null || ft_rc=$?
      c_out=$(outcome "$ft_rc")
      [ "$ft_rc" = 124 ] || c_cpu=$(cpu "$w/ftetwild.time")
      if [ "$ft_rc" = 0 ]; then
        c_tets=$(awk '$1 == "Tetrahedra" { getline; print $1; exit }' "$w/ft/out.mesh" 2>/dev/null || true)
        if [ -z "$c_tets" ] || [ "$c_tets" = 0 ]; then
          c_out="ok:0tets"
          c_tets=-
        fi
      fi
    fi
    if [ "$c_out" = ok ]; then
      awk -f "$ROOT/bench/peer/mesh_boundary.awk" "$w/ft/out.mesh" >"$w/ft/boundary.off"
      if again timeout "$TIMEOUT" "$TETREC" check "$w/ft/boundary.off" "$w/ft/out.mesh" \
          --quality "$R" >"$w/ft.check" 2>&1; then
        c_valid=own
      else
        c_valid=NO
        echo "$name: ftetwild output invalid against its own boundary: $(grep -m1 'error' "$w/ft.check" | cut -c1-200)" >>"$notes"
      fi
      read -r c_n10 _ <<<"$(under10 "$w/ft.check")"
      c_min=$(sed -n 's/.*dihedral min \([0-9.e+-]*\).*/\1/p' "$w/ft.check" | head -n 1 || true)
    fi
  fi

  # tetrec
  a_out=$(outcome "$tr_rc")
  case $tr_rc in [2-7]) a_out=rej:$tr_rc ;; esac
  a_cpu=- a_st=- a_e=- a_f=- a_i=- a_r=- a_tets=- a_n10=- a_valid=-
  [ "$tr_rc" = 124 ] || a_cpu=$(cpu "$w/tetrec.time")
  if [ "$tr_rc" = 0 ]; then
    a_e=$(field steiner_on_edges "$w/tetrec.json")
    a_f=$(field steiner_on_facets "$w/tetrec.json")
    a_i=$(field steiner_interior "$w/tetrec.json")
    # every point of the output that is not an input vertex: the recovery's (split by
    # where they lie) and, with --quality, refinement's and sliver removal's, which the
    # stats do not split
    a_st=$(($(field volume_nodes "$w/tetrec.json") - $(field surface_nodes "$w/tetrec.json")))
    if [ -n "$a_e" ] && [ -n "$a_f" ] && [ -n "$a_i" ]; then
      a_r=$((a_st - a_e - a_f - a_i))
    else
      a_e=- a_f=- a_i=- # a build from before the split: the total only
    fi
    a_tets=$(field volume_elements "$w/tetrec.json")
    a_valid=$(validate "$model" "$w/tetrec.node" "$w/tetrec.check" tetrec)
    read -r a_n10 _ <<<"$(under10 "$w/tetrec.check")"
  fi

  # TetGen
  b_out=$(outcome "$tg_rc")
  [ "$tg_rc" != conv ] || b_out=conv
  b_cpu=- b_st=- b_e=- b_f=- b_i=- b_tets=- b_n10=- b_valid=-
  [ "$tg_rc" = 124 ] || [ "$tg_rc" = conv ] || b_cpu=$(cpu "$w/tetgen.time")
  tg_node=$w/tg/$stem.1.node
  if [ "$tg_rc" = 0 ]; then
    b_tets=$(count "$w/tg/$stem.1.ele")
    if [ -z "$b_tets" ] || [ "$b_tets" = 0 ]; then
      b_out="ok:0tets"
      b_tets=-
    fi
  fi
  if [ "$b_out" = ok ]; then
    nodes=$(count "$tg_node")
    inputs=
    if [ "$TG_DETAIL" = 1 ]; then
      # the same meshing, untimed, without files and with statistics
      (cd "$w/tg" && timeout "$TIMEOUT" "$TETGEN" "${tg_flags//Q/}NEF" "$tg_in" >../tetgen.stats 2>&1) || true
      if grep -q 'Input points:' "$w/tetgen.stats"; then
        inputs=$(tg_stat 'Input points' "$w/tetgen.stats")
        b_e=$(tg_stat 'Steiner points on input segments' "$w/tetgen.stats")
        b_f=$(tg_stat 'Steiner points on input facets' "$w/tetgen.stats")
        b_i=$(tg_stat 'Steiner points inside domain' "$w/tetgen.stats")
        if [ $((b_e + b_f + b_i)) != $((nodes - inputs)) ]; then
          echo "$name: TetGen's statistics say $((b_e + b_f + b_i)) Steiner points; its .node count minus its input points: $((nodes - inputs)) (it drops duplicate and unused input points)" >>"$notes"
        fi
      fi
    fi
    if [ -z "$inputs" ]; then
      again "$TETREC" convert "$model" "$w/input.node" -q >/dev/null 2>&1 &&
        inputs=$(count "$w/input.node") || true
    fi
    # TetGen's own count where there is one: its .node leaves out the duplicate and
    # unused input points it drops (boeing: 1477 fewer points than its input)
    if [ "$b_e" != - ]; then
      b_st=$((b_e + b_f + b_i))
    elif [ -n "$inputs" ]; then
      b_st=$((nodes - inputs))
    fi
    b_valid=$(validate "$model" "$tg_node" "$w/tetgen.check" tetgen)
    read -r b_n10 _ <<<"$(under10 "$w/tetgen.check")"
  fi

  target=-
  if [ "$a_out" = ok ] && [ "$b_out" = ok ]; then
    target=$(awk -v a="$a_cpu" -v b="$b_cpu" 'BEGIN {
      lim = 1.5 * b; if (b + 0.05 > lim) lim = b + 0.05
      print (a + 0 <= lim + 1e-9) ? "ok" : "over" }')
  fi
  # steiner_col TOTAL E F I [R]: "TOTAL (E/F/I)", "+Rr" for R points added by refinement
  steiner_col() {
    if [ "$1" = - ]; then echo -
    elif [ "$2" = - ]; then echo "$1"
    elif [ "${5:--}" = - ] || [ "$5" = 0 ]; then echo "$1 ($2/$3/$4)"
    else echo "$1 ($2/$3/$4 +${5}r)"; fi
  }
  {
    if [ -n "$FTETWILD" ]; then
      printf '%-46s %6s | %-8s %6s %-26s %8s %7s %-4s | %-8s %6s %-26s %8s %7s %-4s | %-10s | %-8s %6s %8s %7s %s\n' \
        "$name" "$tris" "$a_out" "$a_cpu" "$(steiner_col "$a_st" "$a_e" "$a_f" "$a_i" "$a_r")" "$a_tets" \
        "$(pct "$a_n10" "$a_tets")" "$a_valid" \
        "$b_out" "$b_cpu" "$(steiner_col "$b_st" "$b_e" "$b_f" "$b_i")" "$b_tets" \
        "$(pct "$b_n10" "$b_tets")" "$b_valid" "$target" \
        "$c_out" "$c_cpu" "$c_tets" "$(pct "$c_n10" "$c_tets")" "$c_valid"
    else
      printf '%-46s %6s | %-8s %6s %-26s %8s %7s %-4s | %-8s %6s %-26s %8s %7s %-4s | %s\n' \
        "$name" "$tris" "$a_out" "$a_cpu" "$(steiner_col "$a_st" "$a_e" "$a_f" "$a_i" "$a_r")" "$a_tets" \
        "$(pct "$a_n10" "$a_tets")" "$a_valid" \
        "$b_out" "$b_cpu" "$(steiner_col "$b_st" "$b_e" "$b_f" "$b_i")" "$b_tets" \
        "$(pct "$b_n10" "$b_tets")" "$b_valid" "$target"
    fi
  } | tee -a "$table"
  printf '%s\t' "$name" "$tris" "$note" "$a_out" "$a_cpu" "$a_st" "$a_e" "$a_f" "$a_i" "$a_tets" \
    "$a_n10" "$a_valid" "$b_out" "$b_cpu" "$b_st" "$b_e" "$b_f" "$b_i" "$b_tets" "$b_n10" \
    "$b_valid" "$target" >>"$rows"
  a_min=$(sed -n 's/.*dihedral min \([0-9.e+-]*\).*/\1/p' "$w/tetrec.check" 2>/dev/null | head -n 1 || true)
  b_min=$(sed -n 's/.*dihedral min \([0-9.e+-]*\).*/\1/p' "$w/tetgen.check" 2>/dev/null | head -n 1 || true)
  a_bound=$(field surface_tolerance_bound "$w/tetrec.json" || true)
  printf '%s\t' "$a_r" "${a_min:--}" "${b_min:--}" >>"$rows"
  printf '%s\t' "${a_bound:--}" "$c_out" "$c_cpu" "$c_tets" "$c_n10" "$c_valid" >>"$rows"
  printf '%s\n' "${c_min:--}" >>"$rows"
  if [ "$KEEP" != 1 ]; then
    rm -f "$w"/tetrec.node "$w"/tetrec.ele "$w"/tetrec.face "$w"/tg/*.1.* "$w"/input.*
    rm -rf "$w/ft"
  fi
done 3< <(awk '$1 == "file"' "$MANIFEST")

# rows: 1 name 2 tris 3 note, tetrec 4 out 5 cpu 6 steiner 7 e 8 f 9 i 10 tets 11 n10
# 12 valid, TetGen 13 out 14 cpu 15 steiner 16 e 17 f 18 i 19 tets 20 n10 21 valid, 22 target,
# 23 tetrec's points added by refinement, 24 tetrec's and 25 TetGen's smallest dihedral
# angle (tetrec check), 26 the surface bound tetrec reports (TOL), fTetWild 27 out 28 cpu
# 29 tets 30 n10 31 valid 32 smallest dihedral angle ("-" without FTETWILD)
awk -F'\t' -v absent="$absent" -v ft="${FTETWILD:+1}" '
  function sh(n, t) { return t > 0 ? sprintf("%.2f%%", 100 * n / t) : "-" }
  function ratio(a, b) { return b > 0 ? sprintf("%.2fx", a / b) : "-" }
  {
    models++
    ao[$4 ~ /^rej/ ? "rejected" : $4]++; bo[$13]++
    if ($12 != "-") av[$12]++
    if ($21 != "-") bv[$21]++
    if (ft) {
      co[$27]++
      if ($31 != "-") cv[$31]++
      if ($4 == "ok" && $27 == "ok") {
        cn++; cac += $5; cat += $10; can += $11; ccc += $28; cct += $29; ccn += $30
        if ($24 != "-" && $32 != "-" && $24 + 0 >= $32 + 0) cmin++
      }
    }
    if ($4 != "ok" || $13 != "ok") next
    n++; ac += $5; bc += $14; as += $6; ae += $7; af += $8; ai += $9; ar += $23; at += $10; an += $11
    if ($15 != "-") { bs += $15; bst++ }
    be += ($16 == "-" ? 0 : $16); bf += ($17 == "-" ? 0 : $17); bi += ($18 == "-" ? 0 : $18)
    bt += $19; bn += $20
    if ($22 == "ok") met++
    if ($24 != "-" && $25 != "-" && $24 + 0 >= ($25 + 0 > 10 ? $25 + 0 : 10)) mindih++
    if ($19 > 0 && $10 > 0 && $11 / $10 <= 0.5 * $20 / $19) half++
    if ($26 != "-" && $26 + 0 > bound) bound = $26 + 0
  }
  function outcomes(o,   k, s) { s = ""; for (k in o) s = s (s == "" ? "" : ", ") o[k] " " k; return s }
  END {
    printf "\ntotal over the %d models both meshed:\n", n
    printf "  tetrec: cpu %.2f s, steiner %d (%d/%d/%d%s), %d tets, <10deg %s\n", ac, as, ae, af, ai, ar ? sprintf(" +%dr", ar) : "", at, sh(an, at)
    printf "  tetgen: cpu %.2f s, steiner %d (%d/%d/%d), %d tets, <10deg %s\n", bc, bs, be, bf, bi, bt, sh(bn, bt)
    printf "  ratios tetrec/tetgen: cpu %s, steiner %s, tets %s\n", ratio(ac, bc), ratio(as, bs), ratio(at, bt)
    printf "  cpu target (tetrec <= max(1.5x TetGen, TetGen + 0.05 s)) met on %d of %d\n", met, n
    printf "  smallest dihedral >= max(TetGen'"'"'s, 10 deg) on %d of %d; share <10deg <= half TetGen'"'"'s on %d of %d\n", mindih, n, half, n
    if (bound > 0) printf "  largest surface bound tetrec reported: %.6g of the diagonal\n", bound
    printf "outcomes over the %d models run:\n  tetrec: %s; valid: %s\n  tetgen: %s; valid: %s\n", models, outcomes(ao), outcomes(av), outcomes(bo), outcomes(bv)
    if (ft) {
      printf "total over the %d models tetrec and fTetWild both meshed:\n", cn
      printf "  tetrec:   cpu %.2f s, %d tets, <10deg %s\n", cac, cat, sh(can, cat)
      printf "  ftetwild: cpu %.2f s, %d tets, <10deg %s\n", ccc, cct, sh(ccn, cct)
      printf "  ratios tetrec/ftetwild: cpu %s (issues 47, 49: <= 0.25x), tets %s; smallest dihedral >= fTetWild'"'"'s on %d of %d\n", ratio(cac, ccc), ratio(cat, cct), cmin, cn
      printf "  ftetwild: %s; valid against its own boundary: %s\n", outcomes(co), outcomes(cv)
    }
    if (absent) printf "%d models of the manifest are not in the corpus (notes.txt)\n", absent
  }' "$rows" | tee -a "$table"
[ ! -s "$notes" ] || echo "notes: $notes" | tee -a "$table"
