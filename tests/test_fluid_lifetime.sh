#!/bin/bash
# experiments/fluid_lifetime.awk and fluid_line_after.awk on synthetic T_g series of two rows of
# Gamma: a run that stays fluid has tau inf, a fluid that nucleates coexistence has the time its
# T_g climbs back to the row's level (the geometric mean of the hottest f and the coldest fgc
# run's late T_g), a gas that condenses straight into coexistence has tau 0, and the line after
# a wait T is the mean over rows of the midpoint between the last run fluid at T and the next;
# and, on the filed fig3_4a full runs, the lifetimes and lines the README quotes.
set -u
. "$(dirname "$0")/checks.sh"
exp=$(cd "$(dirname "$0")/../experiments" && pwd)
# series: start as a gas (T = 20), fluid (T = 1) from t = 10, coexistence (T = 9) from t = jump
series() {  # run gamma estar label jump(-1: never; 0: no fluid at all)
  for t in $(seq 0 10 1000); do
    if [ "$t" -eq 0 ]; then T=20
    elif [ "$5" -eq 0 ]; then T=9
    elif [ "$5" -gt 0 ] && [ "$t" -ge "$5" ]; then T=9
    else T=1; fi
    echo "$1 $2 $3 $4 $t $T"
  done
}
{ series a 10 0.9 f -1; series b 10 1.0 fgc 400; series c 10 1.1 fgc 100; series d 10 1.2 fgc 0
  series e 20 0.9 f -1; series f 20 1.0 fgc 200; series g 20 1.1 fgc 50; } | awk -f "$exp/fluid_lifetime.awk" > "$tmp/lt.tsv"
tau() { awk -F'\t' -v g=$1 -v e=$2 '$1 == g && $2 == e { print $4 }' "$tmp/lt.tsv"; }
check "a fluid that never nucleates: tau inf" test "$(tau 10 0.9)" = inf
check "nucleation at t = 400: tau 400" test "$(tau 10 1.0)" = 400
check "nucleation at t = 50 in the other row: tau 50" test "$(tau 20 1.1)" = 50
check "no fluid ever formed: tau 0" test "$(tau 10 1.2)" = 0
check "the row's level is sqrt(1 x 9) = 3" test "$(awk -F'\t' 'NR == 2 { print $5 }' "$tmp/lt.tsv")" = 3
awk -f "$exp/fluid_line_after.awk" -v waits="20 150 300 600" -v prefix=L "$tmp/lt.tsv" > "$tmp/line.tsv"
val() { awk -F'\t' -v k=$1 '$1 == k { print $2 }' "$tmp/line.tsv"; }
near() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a - b < 1e-4 && b - a < 1e-4) }'; }
# t = 20: row 10's first coexistence is 1.2 (tau 0), row 20 has none yet (its 1.1 nucleates at 50)
check "after 20: one row, line at sqrt(1.1 x 1.2)" bash -c "[ $(val L_t20_n) = 1 ] && $(declare -f near); near $(val L_t20) $(awk 'BEGIN { print sqrt(1.32) }')"
# t = 150: both rows at sqrt(1.0 x 1.1)
check "after 150: both rows at sqrt(1.0 x 1.1), error 0" bash -c "[ $(val L_t150_n) = 2 ] && $(declare -f near); near $(val L_t150) $(awk 'BEGIN { print sqrt(1.1) }') && [ \"$(awk -F'\t' '$1 == "L_t150" { print $3 }' "$tmp/line.tsv")\" = 0 ]"
# t = 300: row 10 still at sqrt(1.1), row 20 at sqrt(0.9)
check "after 300: mean of sqrt(1.1) and sqrt(0.9)" bash -c "$(declare -f near); near $(val L_t300) $(awk 'BEGIN { print (sqrt(1.1) + sqrt(0.9)) / 2 }')"
check "after 600: both rows at sqrt(0.9 x 1.0)" bash -c "$(declare -f near); near $(val L_t600) $(awk 'BEGIN { print sqrt(0.9) }')"
# the table mode: per wait and row (rows in increasing order), the midpoint and half the step
awk -f "$exp/fluid_line_after.awk" -v table=1 -v waits="20 300" "$tmp/lt.tsv" > "$tmp/rows.tsv"
check "table: header, then after 20 only row 10, after 300 rows 10 and 20 in order" \
  test "$(cut -f1,2 "$tmp/rows.tsv" | tr '\t\n' ': ')" = "wait:row 20:10 300:10 300:20 "
check "table: after 300, row 20 at sqrt(0.9 x 1.0), error half the step (0.05)" \
  bash -c "$(declare -f near); near $(awk -F'\t' '$1 == 300 && $2 == 20 { print $3 }' "$tmp/rows.tsv") $(awk 'BEGIN { print sqrt(0.9) }') && [ $(awk -F'\t' '$1 == 300 && $2 == 20 { print $4 }' "$tmp/rows.tsv") = 0.05 ]"
# The fgc-g line from the bridge count (-v lower=fgc -v upper=g -v falling=1): a coexistence has
# many bridges (500), a gas few (70).  Row 30: u coexists only from t = 600 (formed 600), p from
# t = 10 on, q from 10 until it evaporates at 800 (tau 800), r is a gas throughout (tau 0).
bseries() {  # run estar label from until(-1: never ends)
  for t in $(seq 0 10 1000); do
    if [ "$t" -ge "$4" ] && { [ "$5" -lt 0 ] || [ "$t" -lt "$5" ]; }; then B=500; else B=70; fi
    echo "$1 30 $2 $3 $t $B"
  done
}
{ bseries u 0.9 fgc 600 -1; bseries p 1.0 fgc 10 -1; bseries q 1.1 g 10 800; bseries r 1.2 g 2000 -1; } > "$tmp/bs.txt"
awk -v lower=fgc -v upper=g -v falling=1 -v late=0.1 -f "$exp/fluid_lifetime.awk" "$tmp/bs.txt" > "$tmp/blt.tsv"
near_rel() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a - b < 1e-3 * b && b - a < 1e-3 * b) }'; }
bcol() { awk -F'\t' -v e=$1 -v c=$2 '$2 == e { print $c }' "$tmp/blt.tsv"; }
check "falling: coexistence from 600 (formed $(bcol 0.9 6), tau $(bcol 0.9 4)), evaporating at 800 (tau $(bcol 1.1 4)), a gas throughout (tau $(bcol 1.2 4))" \
  test "$(bcol 0.9 6) $(bcol 0.9 4) $(bcol 1.0 6) $(bcol 1.1 4) $(bcol 1.2 4)" = "600 inf 10 800 0"
check "late=0.1: the level between the phases' last tenths, sqrt(500 x 70) ($(bcol 1.0 5))" \
  near_rel "$(bcol 1.0 5)" "$(awk 'BEGIN { print sqrt(35000) }')"
awk -v lower=fgc -v upper=g -v falling=1 -f "$exp/fluid_lifetime.awk" "$tmp/bs.txt" > "$tmp/blt2.tsv"
# (the second half is t = 500-1000, 51 samples: u coexists in 41 of them, q in 30)
check "late=0.5 (default): the second halves, partly of the other phase, put the level at sqrt(416 x 323) ($(awk -F'\t' 'NR == 2 { print $5 }' "$tmp/blt2.tsv"))" \
  near_rel "$(awk -F'\t' 'NR == 2 { print $5 }' "$tmp/blt2.tsv")" "$(awk 'BEGIN { print sqrt((10 * 70 + 41 * 500) / 51 * (30 * 500 + 21 * 70) / 51) }')"
awk -f "$exp/fluid_line_after.awk" -v table=1 -v waits="300 700 900" "$tmp/blt.tsv" > "$tmp/brows.tsv"
check "after 300 no line (u not yet formed), after 700 sqrt(1.1 x 1.2) (q coexists until 800), after 900 sqrt(1.0 x 1.1)" \
  test "$(tail -n +2 "$tmp/brows.tsv" | cut -f1,3 | tr '\t\n' ': ')" = "700:$(awk 'BEGIN { printf "%.6g", sqrt(1.1 * 1.2) }') 900:$(awk 'BEGIN { printf "%.6g", sqrt(1.1) }') "
# On the 129 filed runs of the full fig3_4a sweep (elastic, 20 000 t.u., data/records), labelled
# as experiments/phase_diagram.mk labels them: the late nucleation at E* = 0.9 (Gamma = 15, 50)
# and the fluid that lasts (Gamma = 8, 30), and the line after 300 t.u. (every row between 1
# and 1.05) and after the whole run (the Delaunay fit's 0.90).
if [ -n "${WG_BIN:-}" ]; then
  filed=$(cd "$(dirname "$0")/../data/records/fig3_4a/full" && pwd)
  "$WG_BIN/wetgran-orderparam" --calibrate --per-scan --relative-contrast "$filed"/G*.h5 2> /dev/null |
    awk -F'\t' '$1 !~ /^#/ && $1 != "file" && $2 >= 8 && ($NF == "f" || $NF == "fgc") { print $1, $2, $3, $NF }' |
    while read -r run g e l; do
      "$WG_BIN/wetgran-series" "$run" temperature | awk -v r="$run" -v g=$g -v e=$e -v l=$l 'NR > 1 { print r, g, e, l, $1, $2 }'
    done | awk -f "$exp/fluid_lifetime.awk" > "$tmp/lt4a.tsv"
  t4a() { awk -F'\t' -v g=$1 -v e=$2 '$1 == g && $2 == e { print $4 }' "$tmp/lt4a.tsv"; }
  check "fig3_4a full, E* = 0.9: coexistence nucleates late at Gamma = 15 and 50 ($(t4a 15 0.9), $(t4a 50 0.9) t.u.), never at 8 and 30 ($(t4a 8 0.9), $(t4a 30 0.9))" \
    bash -c "[ '$(t4a 8 0.9)' = inf ] && [ '$(t4a 30 0.9)' = inf ] && awk 'BEGIN { exit !($(t4a 15 0.9) > 3000 && $(t4a 15 0.9) < 5000 && $(t4a 50 0.9) > 5000 && $(t4a 50 0.9) < 7000) }'"
  check "fig3_4a full, E* = 0.95: nucleation within 300-700 t.u. in every row ($(for g in 8 15 30 50; do printf '%s ' "$(t4a $g 0.95)"; done))" \
    bash -c "for g in 8 15 30 50; do awk -v t=\$(awk -F'\t' -v g=\$g '\$1 == g && \$2 == 0.95 { print \$4 }' '$tmp/lt4a.tsv') 'BEGIN { exit !(t >= 300 && t <= 700) }' || exit 1; done"
  awk -f "$exp/fluid_line_after.awk" -v waits="300 20000" -v prefix=L "$tmp/lt4a.tsv" > "$tmp/l4a.tsv"
  check "fig3_4a full: the line after 300 t.u. is sqrt(1 x 1.05) in all 4 rows ($(awk -F'\t' '$1 == "L_t300" { print $2 }' "$tmp/l4a.tsv") over $(awk -F'\t' '$1 == "L_t300_n" { print $2 }' "$tmp/l4a.tsv"))" \
    bash -c "[ $(awk -F'\t' '$1 == "L_t300_n" { print $2 }' "$tmp/l4a.tsv") = 4 ] && $(declare -f near); near $(awk -F'\t' '$1 == "L_t300" { print $2 }' "$tmp/l4a.tsv") $(awk 'BEGIN { print sqrt(1.05) }')"
  check "fig3_4a full: after 20 000 t.u. it is 0.90 +- 0.01, the Delaunay fit's ($(awk -F'\t' '$1 == "L_t20000" { print $2 }' "$tmp/l4a.tsv"))" \
    awk -F'\t' '$1 == "L_t20000" { exit !($2 > 0.89 && $2 < 0.91) }' "$tmp/l4a.tsv"
  # The 33 runs of the full fig3_5 sweep filed first (F_B = 1, 2, 8, 16 m g at Gamma = 30, a row
  # per E_cb), labelled as its Makefile labels them: runs stopped at 300 t.u. put the line at
  # sqrt(1 x 1.05) for the two weak bridges, as fig3_4a's rows, but lower for the strong ones
  # (F_B = 8: 0.85 fluid for 320 t.u., 0.9 coexisting at once; F_B = 16: 0.65 for 540, 0.7 for
  # 280), so short runs do not restore the thesis's E* = 1 at large E_cb; after 20 000 t.u. the
  # lines are the ones wetgran-transitions cuts from the labels.
  filed=$(cd "$(dirname "$0")/../data/records/fig3_5/full" && pwd)
  runs5=$(for e in 0.7 0.8 0.85 0.9 0.95 1 1.05 1.1 1.15 1.2 1.3 1.4 1.5 1.6; do printf '%s ' "$filed/F1_E$e.h5"; done
          for e in 0.7 0.8 0.85 0.9 0.95 1 1.05 1.1 1.3 1.4; do printf '%s ' "$filed/F2_E$e.h5"; done
          for e in 0.7 0.75 0.8 0.85 0.9; do printf '%s ' "$filed/F8_E$e.h5"; done
          for e in 0.55 0.6 0.65 0.7; do printf '%s ' "$filed/F16_E$e.h5"; done)
  "$WG_BIN/wetgran-orderparam" --calibrate --per-scan --relative-contrast $runs5 2> /dev/null > "$tmp/op5.tsv"
  awk -F'\t' '$1 !~ /^#/ && $1 != "file" && ($NF == "f" || $NF == "fgc") { print $1, $5, $3, $NF }' "$tmp/op5.tsv" |
    while read -r run ecb e l; do
      "$WG_BIN/wetgran-series" "$run" temperature | awk -v r="$run" -v g=$ecb -v e=$e -v l=$l 'NR > 1 { print r, g, e, l, $1, $2 }'
    done | awk -f "$exp/fluid_lifetime.awk" > "$tmp/lt5.tsv"
  awk -f "$exp/fluid_line_after.awk" -v table=1 -v waits="300 20000" "$tmp/lt5.tsv" > "$tmp/rows5.tsv"
  line5() { awk -F'\t' -v w=$1 -v r=$2 '$1 == w && $2 == r { print $3 }' "$tmp/rows5.tsv"; }
  check "fig3_5 full, after 300 t.u.: F_B = 1, 2 m g at sqrt(1.05) ($(line5 300 0.0711), $(line5 300 0.1422)), 8 at sqrt(0.85 x 0.9) ($(line5 300 0.5688)), 16 at sqrt(0.65 x 0.7) ($(line5 300 1.1376))" \
    bash -c "$(declare -f near); near $(line5 300 0.0711) $(awk 'BEGIN { print sqrt(1.05) }') && near $(line5 300 0.1422) $(awk 'BEGIN { print sqrt(1.05) }') && near $(line5 300 0.5688) $(awk 'BEGIN { print sqrt(0.765) }') && near $(line5 300 1.1376) $(awk 'BEGIN { print sqrt(0.455) }')"
  "$WG_BIN/wetgran-transitions" --x estar --group e_cb --pair f:fgc --logx "$tmp/op5.tsv" 2> /dev/null > "$tmp/tr5.tsv"
  check "fig3_5 full, after 20 000 t.u.: every row's line is wetgran-transitions' f-fgc cut ($(cut -f3 "$tmp/tr5.tsv" | tail -n +2 | tr '\n' ' '))" \
    bash -c "[ \$(tail -n +2 '$tmp/tr5.tsv' | wc -l) = 4 ] && tail -n +2 '$tmp/tr5.tsv' | while IFS=\$'\t' read -r g pair e err; do \
      awk -v a=\$e -v b=\$(awk -F'\t' -v r=\$g '\$1 == 20000 && \$2 == r { print \$3 }' '$tmp/rows5.tsv') 'BEGIN { exit !(b != \"\" && a - b < 1e-4 && b - a < 1e-4) }' || exit 1; done"
  # The fgc-g line from the bridge count, on the filed rows F_B = 2 and 16 m g of fig3_5 full:
  # at F_B = 2, E* = 1.4 coexists from t = 300 and evaporates at about 1200; at F_B = 16, E* = 1
  # coexists until about 16 400 of its 20 000 t.u., E* = 1.2 until about 400 and 1.3 until about
  # 250, so after 300 t.u. that row's line lies at sqrt(1.2 x 1.3).  After the whole run every
  # row's line is wetgran-transitions' fgc-g cut.
  "$WG_BIN/wetgran-orderparam" --calibrate --per-scan --relative-contrast "$filed"/F2_E*.h5 "$filed"/F16_E*.h5 \
    2> /dev/null > "$tmp/op5g.tsv"
  awk -F'\t' '$1 !~ /^#/ && $1 != "file" && ($NF == "fgc" || $NF == "g") { print $1, $5, $3, $NF }' "$tmp/op5g.tsv" |
    while read -r run ecb e l; do
      "$WG_BIN/wetgran-series" "$run" bridges | awk -v r="$run" -v g=$ecb -v e=$e -v l=$l 'NR > 1 { print r, g, e, l, $1, $2 }'
    done | awk -v lower=fgc -v upper=g -v falling=1 -v late=0.1 -f "$exp/fluid_lifetime.awk" > "$tmp/ltg.tsv"
  tg5() { awk -F'\t' -v g=$1 -v e=$2 -v c=$3 '$1 == g && $2 == e { print $c }' "$tmp/ltg.tsv"; }
  check "fig3_5 full, bridges: F_B = 2 mg, E* = 1.4 coexists from $(tg5 0.1422 1.4 6) to $(tg5 0.1422 1.4 4); 16 mg, E* = 1 until $(tg5 1.1376 1 4), 1.2 until $(tg5 1.1376 1.2 4)" \
    awk -v f="$(tg5 0.1422 1.4 6)" -v a="$(tg5 0.1422 1.4 4)" -v b="$(tg5 1.1376 1 4)" -v c="$(tg5 1.1376 1.2 4)" \
      'BEGIN { exit !(f >= 200 && f <= 400 && a >= 1000 && a <= 1400 && b >= 15000 && b <= 18000 && c > 300 && c <= 500) }'
  awk -f "$exp/fluid_line_after.awk" -v table=1 -v waits="300 20000" "$tmp/ltg.tsv" > "$tmp/rowsg.tsv"
  "$WG_BIN/wetgran-transitions" --x estar --group e_cb --pair fgc:g --logx "$tmp/op5g.tsv" 2> /dev/null > "$tmp/trg.tsv"
  check "fig3_5 full, bridges: after 300 t.u. F_B = 2 mg at sqrt(1.4 x 1.5), 16 mg at sqrt(1.2 x 1.3) ($(awk -F'\t' '$1 == 300 { printf "%s:%s ", $2, $3 }' "$tmp/rowsg.tsv"))" \
    bash -c "$(declare -f near); [ \$(awk -F'\t' '\$1 == 300' '$tmp/rowsg.tsv' | wc -l) = 2 ] && near \$(awk -F'\t' '\$1 == 300 && \$2 == 0.1422 { print \$3 }' '$tmp/rowsg.tsv') $(awk 'BEGIN { print sqrt(2.1) }') && near \$(awk -F'\t' '\$1 == 300 && \$2 == 1.1376 { print \$3 }' '$tmp/rowsg.tsv') $(awk 'BEGIN { print sqrt(1.56) }')"
  check "fig3_5 full, bridges: after 20 000 t.u. both rows' lines are wetgran-transitions' fgc-g cuts ($(cut -f3 "$tmp/trg.tsv" | tail -n +2 | tr '\n' ' '))" \
    bash -c "[ \$(tail -n +2 '$tmp/trg.tsv' | wc -l) = 2 ] && tail -n +2 '$tmp/trg.tsv' | while IFS=\$'\t' read -r g pair e err; do \
      awk -v a=\$e -v b=\$(awk -F'\t' -v r=\$g '\$1 == 20000 && \$2 == r { print \$3 }' '$tmp/rowsg.tsv') 'BEGIN { exit !(b != \"\" && a - b < 1e-4 && b - a < 1e-4) }' || exit 1; done"
fi
summary
