#!/bin/sh
# Which path recovers the missing facets, per recovery mode, on CGAL's sample surfaces and
# the hard cases: for each input meshed by every mode (tetrec mesh --recovery MODE), the
# missing facets, those recovered by swaps/flips and by cavity retriangulation (no Steiner
# point), the Steiner points on facets and on edges, and the CPU time of the run (user +
# system, /usr/bin/time); rows for inputs with missing facets, then totals per mode over
# the inputs every mode meshed.
# usage: bench/models/paths.sh [BUILD_DIR] [MODE...]   (modes: default paper
#        no-facet-flips; default: default no-facet-flips)
set -e
build=${1:-build}
[ $# -gt 0 ] && shift
modes=${*:-default no-facet-flips}
root=$(cd "$(dirname "$0")/../.." && pwd)
tetrec="$root/$build/src/cli/tetrec"
gen="$root/$build/tests/hard/gen_hard"
[ -x "$tetrec" ] && [ -x "$gen" ] || { echo "build $tetrec and $gen first"; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian package time)"; exit 1; }
out="$root/$build/bench-paths"
mkdir -p "$out/hard"
if [ ! -d "$out/data/meshes" ]; then
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$out" --wildcards 'data/meshes/*.off'
fi
"$gen" "$out/hard" >/dev/null
rows="$out/rows.txt"
: >"$rows"
for f in "$out"/data/meshes/*.off "$out"/hard/*.off; do
  b=$(basename "$f" .off)
  for m in $modes; do
    s="$out/$b.$m.json"
    rm -f "$s"
    if /usr/bin/time -f "%U %S" -o "$out/cpu" timeout 600 "$tetrec" mesh "$f" \
         -o "$out/last.mesh" --recovery "$m" --stats "$s" -q >/dev/null 2>&1; then
      cpu=$(awk 'END { print $1 + $2 }' "$out/cpu")
      awk -v b="$b" -v m="$m" -v cpu="$cpu" -F'[:,]' '
        { gsub(/[" ]/, "", $1); v[$1] = $2 + 0 }
        END { print b, m, v["missing_facets"] + 0, v["facets_recovered_by_swap"] + 0,
                    v["facets_recovered_by_cavity"] + 0, v["points_added_for_facets"] + 0,
                    v["points_added_for_edges"] + 0, cpu }' "$s" >>"$rows"
    else
      echo "$b $m FAIL" >>"$rows"
    fi
  done
done
nmodes=$(echo $modes | wc -w)
awk -v n="$nmodes" '
  $3 == "FAIL" { bad[$1] = 1; printf "1 %s %s failed\n", $1, $2; next }
  { r[$1] = r[$1] sprintf("  %s: missing %d swap %d cavity %d facet pts %d edge pts %d cpu %.2f s",
                          $2, $3, $4, $5, $6, $7, $8); cnt[$1]++; any[$1] += $3
    line[NR] = $0 }
  END {
    printf "0 %-28s per mode: missing facets, by swaps/flips, by cavity, Steiner points on facets, on edges, CPU\n", "input"
    for (k in r) if (any[k] > 0 && !bad[k] && cnt[k] == n) printf "2 %-28s%s\n", k, r[k]
    for (i in line) { split(line[i], f, " ")
      if (bad[f[1]] || cnt[f[1]] != n) continue
      tm[f[2]]++; tmi[f[2]] += f[3]; tsw[f[2]] += f[4]; tcv[f[2]] += f[5]; tfp[f[2]] += f[6]
      tep[f[2]] += f[7]; tt[f[2]] += f[8] }
    for (m in tm)
      printf "3 TOTAL %s over %d inputs: missing facets %d, by swaps/flips %d, by cavity %d, Steiner points on facets %d, on edges %d, CPU %.2f s\n", m, tm[m], tmi[m], tsw[m], tcv[m], tfp[m], tep[m], tt[m]
  }' "$rows" | sort -k1,1n -k2,2 | cut -d' ' -f2-
