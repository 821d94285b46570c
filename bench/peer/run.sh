#!/usr/bin/env bash
# Peer benchmark (issue 7): tetrec vs `tetgen -pQ` (Debian's tetgen 1.5) on every CGAL
# sample surface (libcgal-dev's data.tar.gz, data/meshes/*.off, extracted into the build
# dir) plus the hard cases written by BUILD/tests/hard/gen_hard when that exists.
#
# Per model, in the same run, in alternating order (even models tetrec first, odd models
# tetgen first), each under bench/peer/peer_run (fork/exec, wall time by the monotonic
# clock, CPU time and peak RSS by wait4, a wall-clock timeout and an address-space limit):
#   tetrec  `tetrec mesh MODEL -o W/tetrec.node --stats W/tetrec.json`
#   tetgen  `tetgen -pQ MODEL` in W/tetgen/ (writes MODEL.1.node/.ele/.face/...; the
#           switches are TG_FLAGS, see below)
# then, untimed: `tetrec check MODEL OUT.node` on both outputs (the validator, see valid
# below), and
# `tetgen -pNEF MODEL` (same meshing, no files, statistics printed) for tetgen's counts.
#
# Steiner points (the table's): the vertices of the output .node that are not input
# vertices, coordinates compared as doubles: one definition for both programs, blind to
# their bookkeeping (both drop unused input points; tetgen jettisons duplicates). Cross-
# checks in the CSV, disagreements listed under the table: tetrec's --stats
# volume_nodes - surface_nodes and points_added_for_edges + points_added_for_facets;
# tetgen's statistics "Steiner points on segments / on facets / inside domain" (from an
# untimed `tetgen -pNEF`, the same meshing without files) and .node count - "Input points".
#
# Outcomes: ok (exit 0 and at least one tet), rejected:REASON (tetrec exits 2..7: the
# input is unreadable, invalid, open/non-manifold or self-intersecting; tetgen's outcome on
# it is still listed), FAIL:REASON (tetrec 8..11 or tetgen non-zero / no tets), timeout,
# abort (SIGABRT: tetgen's error exit), signal:N. valid: yes (links, exact orientation, exact conformity to the surface and,
# closed surfaces, the exact volume), yes* (the mesh has Steiner points written as rounded
# doubles, as both programs write them: links and exact orientation only, so e.g. a
# tetgen -pQ mesh with Steiner points that dropped input edges passes), NO (the
# validator's message is in the notes), - (not checked: no mesh, or tetrec rejected the
# surface, so the validator cannot judge it). Polygonal OFF faces: the validator checks
# conformity to tetrec's triangulation of them (with coplanar diagonals swapped), which a
# mesh conforming to the polygon need not contain; such failures are marked in the notes.
# tetgen -pQ also writes .edge and .smesh files (its defaults); they are in its time.
#
# Totals: (A) over the models where both produced a mesh; (B) over every model tetrec
# accepts, a failure or timeout counted at the wall time it took (a timeout at the limit).
#
# usage: bench/peer/run.sh [BUILD_DIR]   (default build-peer, a release build; set up if
#        missing)
#   TIMEOUT=s     per-process wall-clock limit (default 120)
#   MEM_MB=n      per-process address-space limit (default 8192)
#   ONLY=regex    run only the models whose name matches (grep -E); output to ...-only/
#   KEEP=1        keep the output meshes (default: deleted once validated)
#   NOBUILD=1     use the binaries already in BUILD_DIR (no ninja)
#   TG_FLAGS=...  tetgen's switches (default -pQ, the issue's). -pQ lets tetgen merge
#                 adjacent facets within 0.1 degree of coplanar (its facet_ang_tol, 179.9):
#                 it need not keep the input's triangle edges, and on nearly flat ones
#                 not even the enclosed volume, so the validator rejects such meshes;
#                 -p181Q makes every input edge a segment, i.e. the problem tetrec solves.
#                 Results of other flags go to BUILD/bench-peer<FLAGS>/.
#   TETGEN=path   the tetgen binary (default: tetgen on PATH), e.g. a TetGen 1.6 build
#                 made by bench/peer/build_tetgen.sh SRC_DIR OUT from its public source;
#                 machine.txt then names the version its -h prints and the path
#   TR_FLAGS=...  extra tetrec switches (e.g. --keep-surface, to compare with -pQY);
#                 results go to BUILD/bench-peer<TG_FLAGS><TR_FLAGS>/
# Output: stdout, BUILD/bench-peer/table.txt and BUILD/bench-peer/results.csv; logs of
# every process under BUILD/bench-peer/work/MODEL/.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-build-peer}
case $BUILD in /*) ;; *) BUILD=$ROOT/$BUILD ;; esac
TIMEOUT=${TIMEOUT:-120}
MEM_MB=${MEM_MB:-8192}
ONLY=${ONLY:-}
TG_FLAGS=${TG_FLAGS:--pQ}
TR_FLAGS=${TR_FLAGS:-}
KEEP=${KEEP:-0}

if [ ! -f "$BUILD/build.ninja" ]; then
  meson setup "$BUILD" "$ROOT" --buildtype=release -Dbench=true >/dev/null
fi
if [ "${NOBUILD:-0}" != 1 ]; then
  ninja -C "$BUILD" -j2 src/cli/tetrec bench/peer/peer_run >"$BUILD/bench-peer-build.log" 2>&1 || {
    tail -n 20 "$BUILD/bench-peer-build.log"; echo "build failed"; exit 1; }
fi
TR=$BUILD/src/cli/tetrec
RUN=$BUILD/bench/peer/peer_run
TG=${TETGEN:-$(command -v tetgen || true)}
[ -n "$TG" ] && [ -x "$TG" ] || { echo "tetgen not found (apt-get install tetgen; see scripts/setup.sh, or TETGEN=path)"; exit 1; }
TG_VERSION=$(dpkg-query -W -f='${Version}' tetgen 2>/dev/null || echo '(version unknown)')
if [ -n "${TETGEN:-}" ]; then
  TG_VERSION="$("$TG" -h 2>/dev/null | sed -n 's/^Version *//p' | head -n 1 || true) at $TG"
fi

OUT=$BUILD/bench-peer
[ "$TG_FLAGS" = -pQ ] && [ -z "$TR_FLAGS" ] || OUT=$BUILD/bench-peer$TG_FLAGS${TR_FLAGS// /}
[ -z "$ONLY" ] || OUT=$OUT-only # a subset never overwrites the whole run's results
WORK=$OUT/work
mkdir -p "$OUT" "$WORK"
notes=()
DATA=$BUILD/bench-peer
mkdir -p "$DATA"
if [ ! -d "$DATA/data/meshes" ]; then
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$DATA" --wildcards 'data/meshes/*.off'
fi
models=()
for f in "$DATA"/data/meshes/*.off; do models+=("cgal:$f"); done
if [ "${NOBUILD:-0}" != 1 ] &&
   ninja -C "$BUILD" -t targets all 2>/dev/null | grep -q '^tests/hard/gen_hard:'; then
  ninja -C "$BUILD" -j2 tests/hard/gen_hard >/dev/null 2>&1 || true
fi
if [ -x "$BUILD/tests/hard/gen_hard" ]; then
  rm -rf "$DATA/hard"
  mkdir -p "$DATA/hard"
  if "$BUILD/tests/hard/gen_hard" "$DATA/hard" >"$DATA/hard.log" 2>&1; then
    for f in "$DATA"/hard/*; do
      case $f in *.off|*.poly|*.smesh|*.stl|*.ply|*.mesh) models+=("hard:$f") ;; esac
    done
  else
    notes+=("hard cases skipped: gen_hard failed (see $DATA/hard.log)")
  fi
else
  notes+=("hard cases skipped: tests/hard/gen_hard is not built in this tree")
fi

# field NAME FILE: the number after `"NAME":` in a flat JSON file (empty if absent)
field() { sed -n "s/.*\"$1\": *\([0-9.eE+-]*\).*/\1/p" "$2" 2>/dev/null | head -1; }
# rec KEY LINE: value of KEY=... in a peer_run line
rec() { printf '%s\n' "$2" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
# first number on the first line of a TetGen-style file (count of nodes / tets)
count() { [ -f "$1" ] && awk '!/^[ \t]*(#|$)/ { print $1; exit }' "$1" || true; }
# the tr_status name tetrec printed last ("tetrec: error: ... [TR_ERR_OPEN]") as a short
# word ("open")
reason() {
  sed -n 's/.*\[TR_ERR_\([A-Z_]*\)\][^[]*$/\1/p' "$1" 2>/dev/null | tail -1 |
    tr 'A-Z_' 'a-z-' | cut -c1-16
}

CSV=$OUT/results.csv
echo "model,source,tris,tr_outcome,tr_valid,tg_outcome,tg_valid,tr_steiner,tg_steiner,tr_tets,tg_tets,tr_wall_s,tg_wall_s,tr_cpu_s,tg_cpu_s,tr_rss_kb,tg_rss_kb,tr_steiner_json,tr_steiner_added,tg_steiner_stats,tg_steiner_nodes,tr_surface,tr_steiner_boundary,tr_steiner_interior,tg_surface,tg_steiner_boundary,tg_steiner_interior" >"$CSV"
NOTES=$OUT/notes.txt
: >"$NOTES"
for n in "${notes[@]}"; do echo "$n" >>"$NOTES"; done

run_tetrec() {
  local line
  line=$("$RUN" "$TIMEOUT" "$MEM_MB" "$w/tetrec.out" "$w/tetrec.err" \
         "$TR" mesh "$model" -o "$w/tetrec.node" --stats "$w/tetrec.json" $TR_FLAGS)
  tr_status=$(rec status "$line"); tr_wall=$(rec wall "$line"); tr_rss=$(rec rss_kb "$line")
  tr_cpu=$(awk -v u="$(rec user "$line")" -v s="$(rec sys "$line")" 'BEGIN{printf "%.3f", u+s}')
}
run_tetgen() {
  local line
  line=$(cd "$w/tetgen" && "$RUN" "$TIMEOUT" "$MEM_MB" "$w/tetgen.out" "$w/tetgen.err" \
         "$TG" $TG_FLAGS "$base")
  tg_status=$(rec status "$line"); tg_wall=$(rec wall "$line"); tg_rss=$(rec rss_kb "$line")
  tg_cpu=$(awk -v u="$(rec user "$line")" -v s="$(rec sys "$line")" 'BEGIN{printf "%.3f", u+s}')
}
# steiner OUTNODE: vertices of the .node file OUTNODE that are not input vertices (all
# coordinates compared as doubles; W/input.node holds the input's points as `tetrec
# convert` reads them), the same definition for both programs and for any bookkeeping.
steiner() {
  [ -s "$w/input.node" ] && [ -f "$1" ] || return 0
  awk 'FILENAME != cur { cur = FILENAME; f++; head = 0 }
       { sub(/#.*/, "") } NF == 0 { next }
       !head { head = 1; next }
       { k = sprintf("%.17g %.17g %.17g", $2 + 0, $3 + 0, $4 + 0) }
       f == 1 { inp[k] = 1; next }
       !(k in inp) { s++ }
       END { print s + 0 }' "$w/input.node" "$1"
}
# boundary OUTNODE OUTELE: "SURFACE ON_BOUNDARY INTERIOR" (bench/peer/boundary.sh): SURFACE
# yes when the boundary faces are exactly the input triangles (as `tetrec convert` writes
# them to W/input.face), else NO; the Steiner points on a boundary face and the others
boundary() {
  [ -s "$w/input.node" ] && [ -s "$w/input.face" ] && [ -f "$1" ] && [ -f "$2" ] || {
    echo "- - -"; return 0; }
  bash "$ROOT/bench/peer/boundary.sh" "$w/input.node" "$w/input.face" "$1" "$2" |
    awk '{ print $1, $4, $5 }'
}
# check OUTNODE LOG WHO: the validator on a mesh; sets chk to yes / yes* / NO
check() {
  local line
  line=$("$RUN" "$TIMEOUT" "$MEM_MB" /dev/null "$2" "$TR" check "$model" "$1")
  if [ "$(rec status "$line")" = "exit:0" ]; then
    chk=yes
    if grep -q 'rounded doubles' "$2"; then chk='yes*'; fi
  else
    chk=NO
    local why
    why=$(grep -m1 'error' "$2" | cut -c1-150)
    if [ "$polys" -gt 0 ] && printf '%s' "$why" | grep -q 'conformity'; then
      why="$why ... (the input has $polys polygon faces: conformity is checked against tetrec's triangulation of them)"
    fi
    echo "$name: $3 invalid ($(rec status "$line")): $why" >>"$NOTES"
  fi
}
# polygons MODEL: number of faces with more than 3 vertices of an OFF file (0 otherwise)
polygons() {
  case $1 in *.off) ;; *) echo 0; return ;; esac
  awk '{ sub(/#.*/, "") } NF == 0 { next }
       st == 0 { st = 1; if ($1 ~ /OFF$/) { if (NF >= 3) { nv = $2; nf = $3; st = 2 }; next } }
       st == 1 { nv = $1; nf = $2; st = 2; next }
       st == 2 { if (++k > nv && k <= nv + nf && $1 > 3) p++ }
       END { print p + 0 }' "$1"
}

echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); timeout ${TIMEOUT}s, limit ${MEM_MB} MB; tetgen $TG_VERSION $TG_FLAGS; tetrec $("$TR" --version | cut -d' ' -f2) $TR_FLAGS" >"$OUT/machine.txt"
idx=0
for m in "${models[@]}"; do
  src=${m%%:*}
  model=${m#*:}
  base=$(basename "$model")
  name=${base%.*}
  [ "$src" = hard ] && name=hard/$name
  if [ -n "$ONLY" ] && ! printf '%s\n' "$name" | grep -qE "$ONLY"; then continue; fi
  w=$WORK/${name//\//_}
  rm -rf "$w"
  mkdir -p "$w/tetgen"
  # tetgen's OFF reader aborts on '#' comment lines (which tetrec's and CGAL's accept), so
  # it reads a copy without them: the same surface, and that failure is not the subject.
  if [ "${model##*.}" = off ] && grep -q '#' "$model"; then
    sed 's/#.*//' "$model" | grep -v '^[[:space:]]*$' >"$w/tetgen/$base"
    echo "$name: tetgen reads a copy without '#' comments (its OFF reader aborts on them)" >>"$NOTES"
  else
    ln -s "$model" "$w/tetgen/$base"
  fi
  # same files for tetgen's .poly/.smesh companions (a .poly may name a .node)
  for c in "${model%.*}".node; do [ -f "$c" ] && ln -sf "$c" "$w/tetgen/"; done
  polys=$(polygons "$model")
  "$TR" convert "$model" "$w/input.node" >/dev/null 2>&1 || rm -f "$w/input.node" "$w/input.face"
  if [ $((idx % 2)) -eq 0 ]; then run_tetrec; run_tetgen; else run_tetgen; run_tetrec; fi
  idx=$((idx + 1))

  # tetrec's outcome
  tr_code=${tr_status#exit:}
  tr_ok=0
  tr_steiner=""; tr_json=""; tr_tets=""; tr_added=""; tr_valid="-"; tris=""
  tr_surf=-; tr_sbnd=""; tr_sint=""; tg_surf=-; tg_sbnd=""; tg_sint=""
  if [ -f "$w/tetrec.json" ]; then
    tris=$(field surface_facets "$w/tetrec.json")
  fi
  case $tr_status in
    exit:0)
      tr_tets=$(field volume_elements "$w/tetrec.json")
      tr_json=$(( $(field volume_nodes "$w/tetrec.json") - $(field surface_nodes "$w/tetrec.json") ))
      tr_steiner=$(steiner "$w/tetrec.node")
      tr_added=$(( $(field points_added_for_edges "$w/tetrec.json") + $(field points_added_for_facets "$w/tetrec.json") ))
      tr_out=ok; tr_ok=1
      read -r tr_surf tr_sbnd tr_sint < <(boundary "$w/tetrec.node" "$w/tetrec.ele") || true
      check "$w/tetrec.node" "$w/tetrec.check" tetrec; tr_valid=$chk ;;
    exit:[2-7]) tr_out="rejected:$(reason "$w/tetrec.err")" ;;
    exit:*) tr_out="FAIL:$(reason "$w/tetrec.err")"
      echo "$name: tetrec $tr_status: $(grep -m1 'error' "$w/tetrec.err" | cut -c1-150)" >>"$NOTES" ;;
    *) tr_out=$tr_status
      echo "$name: tetrec $tr_status after ${tr_wall}s" >>"$NOTES" ;;
  esac
  tr_rejected=0
  case $tr_out in rejected:*) tr_rejected=1 ;; esac

  # tetgen's outcome
  tg_node=$w/tetgen/${base%.*}.1.node
  tg_ele=$w/tetgen/${base%.*}.1.ele
  tg_steiner=""; tg_stats=""; tg_tets=""; tg_nodes_steiner=""; tg_valid="-"; tg_ok=0
  tg_tets=$(count "$tg_ele")
  if [ "$tg_status" = exit:0 ] && [ -n "$tg_tets" ] && [ "$tg_tets" -gt 0 ]; then
    tg_out=ok; tg_ok=1
  elif [ "$tg_status" = exit:0 ]; then
    tg_out="FAIL:no-tets"
  else
    case $tg_status in
      exit:*) tg_out="FAIL:${tg_status#exit:}" ;;
      signal:6) tg_out=abort ;;
      *) tg_out=$tg_status ;;
    esac
    echo "$name: tetgen $tg_status after ${tg_wall}s: $(tail -n 2 "$w/tetgen.err" "$w/tetgen.out" 2>/dev/null | grep -v '^==>' | grep -v '^$' | tail -1 | cut -c1-120)" >>"$NOTES"
  fi
  if [ $tg_ok = 1 ]; then
    # statistics from an untimed run of the same meshing (deterministic), no files
    (cd "$w/tetgen" && "$RUN" "$TIMEOUT" "$MEM_MB" "$w/tetgen.stats" /dev/null "$TG" "${TG_FLAGS//Q/}NEF" "$base" >/dev/null)
    if grep -q '^  Input points:' "$w/tetgen.stats"; then
      tg_stats=$(awk -F: '/^  Steiner points (on|inside)/ { s += $2 } END { print s + 0 }' "$w/tetgen.stats")
      tg_input=$(awk -F: '/^  Input points:/ { print $2 + 0 }' "$w/tetgen.stats")
      tg_nodes_steiner=$(( $(count "$tg_node") - tg_input ))
      [ -z "$tris" ] && tris=$(awk -F: '/^  Input facets:/ { print $2 + 0 }' "$w/tetgen.stats")
    fi
    tg_steiner=$(steiner "$tg_node")
    read -r tg_surf tg_sbnd tg_sint < <(boundary "$tg_node" "$tg_ele") || true
    if [ $tr_rejected = 0 ]; then
      check "$tg_node" "$w/tetgen.check" tetgen; tg_valid=$chk
    fi
  fi
  if [ -z "$tris" ]; then
    tris=$(awk '!/^[ \t]*(#|$)/ { if (++k == 2) { print $2; exit } }' "$model" 2>/dev/null || true)
  fi
  # points_added (CSV) also counts points removed later, so only a disagreement with the
  # counts of the output is noted
  if [ -n "$tr_json" ] && [ "$tr_steiner" != "$tr_json" ]; then
    echo "$name: tetrec Steiner: new vertices in the output = $tr_steiner, stats volume_nodes - surface_nodes = $tr_json, points_added = $tr_added" >>"$NOTES"
  fi
  if [ -n "$tg_stats$tg_steiner" ] && [ "$tg_steiner" != "$tg_stats" ]; then
    echo "$name: tetgen Steiner: new vertices in the output = $tg_steiner, its statistics = $tg_stats, nodes - input points = $tg_nodes_steiner" >>"$NOTES"
  fi
  echo "$name,$src,$tris,$tr_out,$tr_valid,$tg_out,$tg_valid,$tr_steiner,$tg_steiner,$tr_tets,$tg_tets,$tr_wall,$tg_wall,$tr_cpu,$tg_cpu,$tr_rss,$tg_rss,$tr_json,$tr_added,$tg_stats,$tg_nodes_steiner,$tr_surf,${tr_sbnd/-/},${tr_sint/-/},$tg_surf,${tg_sbnd/-/},${tg_sint/-/}" >>"$CSV"
  printf '%-34s tetrec %-22s %8ss   tetgen %-18s %8ss\n' "$name" "$tr_out/$tr_valid" "$tr_wall" "$tg_out/$tg_valid" "$tg_wall" >&2
  if [ "$KEEP" != 1 ]; then
    rm -f "$w"/tetrec.node "$w"/tetrec.ele "$w"/tetrec.face "$w"/tetgen/*.1.*
  fi
done

bash "$ROOT/bench/peer/table.sh" "$CSV" "$OUT/machine.txt" "$NOTES" "$TIMEOUT" | tee "$OUT/table.txt"
