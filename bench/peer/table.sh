#!/usr/bin/env bash
# Formats the peer benchmark's results.csv (written by bench/peer/run.sh) as the table,
# the outcome counts, the totals and ratios, and the worst models. Separate from run.sh so
# a finished run can be re-tabulated: bench/peer/table.sh CSV [MACHINE NOTES TIMEOUT]
set -euo pipefail
CSV=$1
MACHINE=${2:-}
NOTES=${3:-}
TIMEOUT=${4:-?}
[ -n "$MACHINE" ] && [ -f "$MACHINE" ] && cat "$MACHINE"
echo "times in seconds (wall: monotonic clock around the process; cpu: user+sys), mem: peak RSS"
echo "valid: yes = links, exact orientation, exact conformity (+ exact volume if closed);"
echo "  yes* = Steiner points rounded to doubles in the file: links and exact orientation only"
echo "St: Steiner points (output vertices that are no input vertex), St.in: those on no boundary"
echo "  face; surf: yes when the boundary faces are exactly the input triangles (a polygon face:"
echo "  as \`tetrec convert\` triangulates it, which a mesh of either program need not keep; a"
echo "  triangle between two cavities is no face; tetrec's default mode swaps coplanar surface"
echo "  diagonals, --no-smooth or --keep-surface do not); ratios tetrec/tetgen"
awk -F, -v timeout="$TIMEOUT" '
function mb(kb) { return kb == "" ? "-" : sprintf("%.1f", kb / 1024) }
function nz(x) { return x == "" ? "-" : x }
function ratio(a, b) { return b > 0 ? sprintf("%.3f", a / b) : "n/a" }
function kind(o) { sub(/:.*/, "", o); return o }
function pr(a, b) { return a == "" || b == "" ? "-" : b > 0 ? sprintf("%.2f", a / b) : a > 0 ? "inf" : "=" }
NR == 1 { next }
{
  n++
  model[n] = $1; tris = $3; tro = $4; trv = $5; tgo = $6; tgv = $7
  trs = $8; tgs = $9; trt = $10; tgt = $11; trw = $12; tgw = $13; trc = $14; tgc = $15
  trm = $16; tgm = $17
  trsf = $22; trsi = $24; tgsf = $25; tgsi = $27
  if (n == 1) {
    printf "%-32s %7s %-26s %-14s %7s %7s %6s %7s %7s %5s %5s %9s %9s %8s %8s %8s %8s %6s %8s %8s\n",
      "model", "tris", "tetrec ok/valid", "tetgen ok/valid", "St.tr", "St.tg", "St r",
      "St.in tr", "St.in tg", "surf", "surf", "tets tr", "tets tg", "wall tr", "wall tg",
      "cpu tr", "cpu tg", "cpu r", "mem trMB", "mem tgMB"
    printf "%-32s %7s %-26s %-14s %7s %7s %6s %7s %7s %5s %5s\n", "", "", "", "", "", "", "",
      "", "", "tr", "tg"
  }
  printf "%-32s %7s %-26s %-14s %7s %7s %6s %7s %7s %5s %5s %9s %9s %8s %8s %8s %8s %6s %8s %8s\n",
    $1, tris, substr(tro "/" trv, 1, 26), substr(tgo "/" tgv, 1, 14), nz(trs), nz(tgs),
    tro == "ok" && tgo == "ok" ? pr(trs, tgs) : "-", nz(trsi), nz(tgsi), nz(trsf), nz(tgsf),
    nz(trt), nz(tgt), trw, tgw, trc, tgc, tro == "ok" && tgo == "ok" ? pr(trc, tgc) : "-",
    mb(trm), mb(tgm)
  if (tro == "ok") { sf_tr_n++; if (trsf == "yes") sf_tr++; si_tr_all += trsi }
  if (tgo == "ok" && kind(tro) != "rejected") { sf_tg_n++; if (tgsf == "yes") sf_tg++ }
  # outcome counts
  trk = tro; if (tro == "ok") trk = "ok, valid: " trv; cnt_tr[trk]++
  tgk = tgo; if (tgo == "ok") tgk = "ok, valid: " tgv
  if (kind(tro) == "rejected") { rej_tg[tgk]++; nrej++ } else cnt_tg[tgk]++
  # B: every model tetrec accepts, failures at the time they took
  if (kind(tro) != "rejected") {
    nb++; bw_tr += trw; bw_tg += tgw; bc_tr += trc; bc_tg += tgc
    if (tro != "ok") nb_trfail++
    if (tgo != "ok") nb_tgfail++
  }
  # A: both produced a mesh
  if (tro == "ok" && tgo == "ok") {
    na++
    if (trv == "NO") na_trinv++
    if (tgv == "NO") na_tginv++
    s_tr += trs; s_tg += tgs; t_tr += trt; t_tg += tgt; si_tr += trsi; si_tg += tgsi
    if (trsf == "yes") sfa_tr++
    if (tgsf == "yes") sfa_tg++
    w_tr += trw; w_tg += tgw; c_tr += trc; c_tg += tgc; m_tr += trm; m_tg += tgm
    if (trm > mx_tr) mx_tr = trm
    if (tgm > mx_tg) mx_tg = tgm
    if (trw + 0 < tgw + 0) fast_tr++; else if (tgw + 0 < trw + 0) fast_tg++; else fast_eq++
    if (trc + 0 < tgc + 0) cfast_tr++; else if (tgc + 0 < trc + 0) cfast_tg++; else cfast_eq++
    if (trs + 0 < tgs + 0) few_tr++; else if (tgs + 0 < trs + 0) few_tg++; else few_eq++
    if (trm + 0 < tgm + 0) mem_tr++; else if (tgm + 0 < trm + 0) mem_tg++
    if (trv != "NO" && tgv != "NO") {
      nv++; vs_tr += trs; vs_tg += tgs; vw_tr += trw; vw_tg += tgw; vc_tr += trc; vc_tg += tgc
    }
    src = $2; srcs[src] = 1; bn[src]++; bs_tr[src] += trs; bs_tg[src] += tgs
    bw_s_tr[src] += trw; bw_s_tg[src] += tgw; bc_s_tr[src] += trc; bc_s_tg[src] += tgc
    a_model[na] = $1; a_trw[na] = trw; a_tgw[na] = tgw; a_trs[na] = trs; a_tgs[na] = tgs
  }
  if (kind(tro) != "rejected") { slow[++ns] = $1; slow_w[ns] = trw; slow_o[ns] = tro }
}
END {
  printf "\n%d models. Outcomes of tetrec:\n", n
  for (k in cnt_tr) printf "  %-40s %4d\n", k, cnt_tr[k]
  printf "Outcomes of tetgen on the %d models tetrec accepts:\n", n - nrej
  for (k in cnt_tg) printf "  %-40s %4d\n", k, cnt_tg[k]
  printf "Outcomes of tetgen on the %d models tetrec rejects (validity not judged):\n", nrej
  for (k in rej_tg) printf "  %-40s %4d\n", k, rej_tg[k]

  printf "\nTotals (A) over the %d models where both produced a mesh", na
  printf " (invalid among them: tetrec %d, tetgen %d):\n", na_trinv, na_tginv
  printf "  %-22s %14s %14s %9s\n", "", "tetrec", "tetgen", "tr/tg"
  printf "  %-22s %14d %14d %9s\n", "Steiner points", s_tr, s_tg, ratio(s_tr, s_tg)
  printf "  %-22s %14d %14d %9s\n", "Steiner inside", si_tr, si_tg, ratio(si_tr, si_tg)
  printf "  %-22s %14d %14d\n", "boundary = input", sfa_tr, sfa_tg
  printf "  %-22s %14d %14d %9s\n", "tets", t_tr, t_tg, ratio(t_tr, t_tg)
  printf "  %-22s %14.2f %14.2f %9s\n", "wall time s", w_tr, w_tg, ratio(w_tr, w_tg)
  printf "  %-22s %14.2f %14.2f %9s\n", "CPU time s (user+sys)", c_tr, c_tg, ratio(c_tr, c_tg)
  printf "  %-22s %14.1f %14.1f %9s\n", "sum of peak RSS MB", m_tr / 1024, m_tg / 1024, ratio(m_tr, m_tg)
  printf "  %-22s %14.1f %14.1f %9s\n", "max peak RSS MB", mx_tr / 1024, mx_tg / 1024, ratio(mx_tr, mx_tg)
  printf "  faster (wall): tetrec %d, tetgen %d, equal %d;  faster (CPU): tetrec %d, tetgen %d, equal %d\n",
    fast_tr, fast_tg, fast_eq, cfast_tr, cfast_tg, cfast_eq
  printf "  fewer Steiner points: tetrec %d, tetgen %d, equal %d;  less memory: tetrec %d, tetgen %d\n",
    few_tr, few_tg, few_eq, mem_tr, mem_tg
  for (src in srcs)
    printf "  %s models of (A): %d; Steiner %d vs %d (%s); wall s %.2f vs %.2f (%s); CPU s %.2f vs %.2f (%s)\n",
      src, bn[src], bs_tr[src], bs_tg[src], ratio(bs_tr[src], bs_tg[src]), bw_s_tr[src],
      bw_s_tg[src], ratio(bw_s_tr[src], bw_s_tg[src]), bc_s_tr[src], bc_s_tg[src],
      ratio(bc_s_tr[src], bc_s_tg[src])
  printf "Of (A), the %d models where neither mesh fails the validator: Steiner tetrec %d, tetgen %d, ratio %s; wall s %.2f vs %.2f, ratio %s; CPU s %.2f vs %.2f, ratio %s\n",
    nv, vs_tr, vs_tg, ratio(vs_tr, vs_tg), vw_tr, vw_tg, ratio(vw_tr, vw_tg), vc_tr, vc_tg, ratio(vc_tr, vc_tg)
  printf "Totals (B) over the %d models tetrec accepts, failures and timeouts counted at the time they took (timeout %s s; tetrec failed on %d, tetgen on %d):\n",
    nb, timeout, nb_trfail, nb_tgfail
  printf "  wall time s: tetrec %.2f, tetgen %.2f, ratio %s;  CPU time s: tetrec %.2f, tetgen %.2f, ratio %s\n",
    bw_tr, bw_tg, ratio(bw_tr, bw_tg), bc_tr, bc_tg, ratio(bc_tr, bc_tg)
  printf "Boundary faces exactly the input triangles: tetrec %d of its %d meshes (%d Steiner points inside them), tetgen %d of its %d meshes of models tetrec accepts\n",
    sf_tr, sf_tr_n, si_tr_all, sf_tg, sf_tg_n
  printf "Issue 7 criteria on (A): total time tetrec <= tetgen: %s (wall), %s (CPU); Steiner tetrec <= tetgen: %s\n",
    w_tr <= w_tg ? "yes" : "NO", c_tr <= c_tg ? "yes" : "NO", s_tr <= s_tg ? "yes" : "NO"

  # worst models: tetrec slowest (any accepted model), worst time ratio and Steiner excess in A
  printf "\nSlowest for tetrec:"
  for (k = 0; k < 6; k++) {
    b = 0
    for (i = 1; i <= ns; i++) if (!(i in used) && (b == 0 || slow_w[i] + 0 > slow_w[b] + 0)) b = i
    if (b == 0) break
    used[b] = 1; printf " %s %ss%s;", slow[b], slow_w[b], slow_o[b] == "ok" ? "" : " (" slow_o[b] ")"
  }
  printf "\nWorst wall-time ratio tetrec/tetgen (A, tetgen >= 0.05 s):"
  for (k = 0; k < 6; k++) {
    b = 0
    for (i = 1; i <= na; i++)
      if (!(i in used2) && a_tgw[i] >= 0.05 && (b == 0 || a_trw[i] / a_tgw[i] > a_trw[b] / a_tgw[b])) b = i
    if (b == 0) break
    used2[b] = 1; printf " %s %.1fx;", a_model[b], a_trw[b] / a_tgw[b]
  }
  printf "\nMost Steiner points above tetgen (A):"
  for (k = 0; k < 6; k++) {
    b = 0
    for (i = 1; i <= na; i++)
      if (!(i in used3) && a_trs[i] - a_tgs[i] > 0 && (b == 0 || a_trs[i] - a_tgs[i] > a_trs[b] - a_tgs[b])) b = i
    if (b == 0) break
    used3[b] = 1; printf " %s %d vs %d;", a_model[b], a_trs[b], a_tgs[b]
  }
  printf "\n"
}' "$CSV"
if [ -n "$NOTES" ] && [ -s "$NOTES" ]; then
  echo
  echo "Notes:"
  copies=$(sed -n "s/: tetgen reads a copy without '#' comments.*//p" "$NOTES" | tr '\n' ' ')
  [ -n "$copies" ] && echo "  tetgen read copies without '#' comment lines (its OFF reader aborts on them) of: $copies"
  grep -v "tetgen reads a copy without" "$NOTES" | sed 's/^/  /'
fi
