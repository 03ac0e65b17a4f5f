#!/bin/bash
# experiments/fgc_g_bulge.awk on synthetic orderparam tables: per row of Gamma the fgc-g line is
# the midpoint between the last fgc that a g follows and that g; the bulge is the interior
# local maximum of that line along Gamma (a plateau counts once, at its geometric-mean Gamma),
# with A / s_crit = 2 E* E_cb / (Gamma s_crit); a maximum at the first or last row is not a
# bulge; and, on the filed fig3_4a and fig3_4b full runs, the bulges the README quotes.
set -u
. "$(dirname "$0")/checks.sh"
exp=$(cd "$(dirname "$0")/../experiments" && pwd)
table() {  # "gamma:estar:label ..." -> an orderparam table (gamma, estar, ..., label last)
  printf '# thresholds\nfile\tgamma\testar\tlabel\n'
  for p in "$@"; do IFS=: read -r g e l <<< "$p"; printf 'run\t%s\t%s\t%s\n' "$g" "$e" "$l"; done
}
near() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a - b < 1e-4 && b - a < 1e-4) }'; }
val() { awk -F'\t' -v k=$1 '$1 == k { print $2 }' "$2"; }
# rows 5 (line sqrt(1 x 1.2)), 10 (sqrt(1.6 x 2), listed out of order), 20 (f straight to g: no
# line), 40 (sqrt(1.2 x 1.4)); a g below the last fgc (row 10, E* = 0.9) does not count
table 5:0.8:f 5:1:fgc 5:1.2:g 10:2:g 10:0.9:g 10:1.6:fgc 10:1:fgc 10:0.7:f \
      20:1:f 20:1.2:g 40:1:f 40:1.2:fgc 40:1.4:g > "$tmp/a.tsv"
awk -f "$exp/fgc_g_bulge.awk" -v ecb=0.5 -v scrit=0.1 "$tmp/a.tsv" > "$tmp/a.out"
check "bulge at Gamma = 10, E* = sqrt(1.6 x 2), error half the step" \
  bash -c "$(declare -f near); near $(val fgc_g_bulge_estar "$tmp/a.out") $(awk 'BEGIN { print sqrt(3.2) }') && [ $(val fgc_g_bulge_gamma "$tmp/a.out") = 10 ] && [ \"\$(awk -F'\t' '\$1 == \"fgc_g_bulge_estar\" { print \$3 }' '$tmp/a.out')\" = 0.2 ]"
# A / s_crit = 2 x 1.78885 x 0.5 / (10 x 0.1); error: rel. E* 0.2 / 1.78885 and ln(40 / 5) / 4
check "A / s_crit = 2 E* E_cb / (Gamma s_crit), error from the E* step and the rows 5 and 40" \
  bash -c "$(declare -f near); near $(val fgc_g_bulge_a_over_scrit "$tmp/a.out") $(awk 'BEGIN { print sqrt(3.2) }') && \
    near \$(awk -F'\t' '\$1 == \"fgc_g_bulge_a_over_scrit\" { print \$3 }' '$tmp/a.out') \$(awk 'BEGIN { a = sqrt(3.2); r = 0.2 / a; q = log(8) / 4; printf \"%.3g\", a * sqrt(r * r + q * q) }')"
awk -f "$exp/fgc_g_bulge.awk" -v table=1 -v ecb=0.5 -v scrit=0.1 "$tmp/a.tsv" > "$tmp/a.tab"
check "table: the rows with a line (5, 10, 40; not 20) in increasing Gamma" \
  test "$(tail -n +2 "$tmp/a.tab" | cut -f1 | tr '\n' ' ')" = "5 10 40 "
# a plateau over rows 10 and 40 between lower rows 5 and 80: one bulge at Gamma = 20
table 5:1:fgc 5:1.2:g 10:1.6:fgc 10:2:g 40:1.6:fgc 40:2:g 80:1:fgc 80:1.2:g > "$tmp/p.tsv"
awk -f "$exp/fgc_g_bulge.awk" -v ecb=0.5 -v scrit=0.1 "$tmp/p.tsv" > "$tmp/p.out"
check "a plateau of two rows is one bulge at their geometric-mean Gamma (20)" \
  bash -c "$(declare -f near); near $(val fgc_g_bulge_gamma "$tmp/p.out") 20"
# two local maxima (rows 10 and 40) between lower rows: the larger, 10, is the bulge
table 5:1:fgc 5:1.2:g 10:2:fgc 10:2.5:g 20:1.2:fgc 20:1.4:g 40:1.6:fgc 40:2:g 80:1:fgc 80:1.2:g > "$tmp/m.tsv"
awk -f "$exp/fgc_g_bulge.awk" -v ecb=0.5 -v scrit=0.1 "$tmp/m.tsv" > "$tmp/m.out"
check "of two local maxima the larger is the bulge (Gamma = 10, not 40)" test "$(val fgc_g_bulge_gamma "$tmp/m.out")" = 10
# the line rises to the last row: no bracketed maximum, no keys, a message
table 5:1:fgc 5:1.2:g 10:1.2:fgc 10:1.4:g 20:1.6:fgc 20:2:g > "$tmp/e.tsv"
awk -f "$exp/fgc_g_bulge.awk" -v ecb=0.5 -v scrit=0.1 "$tmp/e.tsv" > "$tmp/e.out" 2> "$tmp/e.err"
check "a maximum at the last row is no bulge: no keys, a message naming why" \
  bash -c "[ ! -s '$tmp/e.out' ] && grep -q 'no bracketed maximum' '$tmp/e.err'"
# On the 129 filed runs of the full fig3_4a sweep, labelled as experiments/phase_diagram.mk
# labels them: the fgc-g line at E* = 1.05-1.08 for Gamma = 2 and 8, 1.55 at 15, 1.30 at 30
# and 50: the bulge at Gamma = 15, A = 0.83 s_crit.
if [ -n "${WG_BIN:-}" ]; then
  filed=$(cd "$(dirname "$0")/../data/records/fig3_4a/full" && pwd)
  "$WG_BIN/wetgran-orderparam" --calibrate --per-scan --relative-contrast "$filed"/G*.h5 2> /dev/null > "$tmp/op4a.tsv"
  awk -f "$exp/fgc_g_bulge.awk" -v ecb=0.2844 -v scrit=0.0711 "$tmp/op4a.tsv" > "$tmp/b4a.out"
  check "fig3_4a full: the bulge at Gamma = 15, E* = sqrt(1.5 x 1.6), A / s_crit = 0.826 ($(val fgc_g_bulge_gamma "$tmp/b4a.out"), $(val fgc_g_bulge_estar "$tmp/b4a.out"), $(val fgc_g_bulge_a_over_scrit "$tmp/b4a.out"))" \
    bash -c "[ '$(val fgc_g_bulge_gamma "$tmp/b4a.out")' = 15 ] && $(declare -f near); near $(val fgc_g_bulge_estar "$tmp/b4a.out") $(awk 'BEGIN { print sqrt(2.4) }') && near $(val fgc_g_bulge_a_over_scrit "$tmp/b4a.out") 0.826236"
  # fig3_4b's filed runs (E_cb four times larger, all 140 of its runs; the last 5 lie away from
  # the fgc-g line): the bulge moves to Gamma = 70 and stays near A = s_crit (0.78 against 0.83)
  filed=$(cd "$(dirname "$0")/../data/records/fig3_4b/full" && pwd)
  "$WG_BIN/wetgran-orderparam" --calibrate --per-scan --relative-contrast "$filed"/G*.h5 2> /dev/null > "$tmp/op4b.tsv"
  awk -f "$exp/fgc_g_bulge.awk" -v ecb=1.1376 -v scrit=0.0711 "$tmp/op4b.tsv" > "$tmp/b4b.out"
  check "fig3_4b full: the bulge moves with E_cb to Gamma = 70, E* = sqrt(1.6 x 1.8), at A / s_crit = 0.776 ($(val fgc_g_bulge_gamma "$tmp/b4b.out"), $(val fgc_g_bulge_estar "$tmp/b4b.out"), $(val fgc_g_bulge_a_over_scrit "$tmp/b4b.out"))" \
    bash -c "[ '$(val fgc_g_bulge_gamma "$tmp/b4b.out")' = 70 ] && $(declare -f near); near $(val fgc_g_bulge_estar "$tmp/b4b.out") $(awk 'BEGIN { print sqrt(2.88) }') && near $(val fgc_g_bulge_a_over_scrit "$tmp/b4b.out") 0.775797"
fi
summary
