#!/bin/bash
# wetgran-orderparam on real runs: Eq. 3.3 contrasts agree with the profiles they come from,
# a cold bound state is labelled fluid and a hot one gas, a window that has not settled is
# flagged with where the warm-up ends (or that it never does), and --calibrate finds the
# fluid/gas cut between the two.
set -u
bin=${WG_BIN:?}
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"
small="n=300 lx=100 t_end=300 profile_start=150 profile_bins=25 dt_series=1 dt_checkpoint=0"
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=0.5 -q -o "$tmp/cold.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=2.5 -q -o "$tmp/hot.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=0.5 profile_start=0 tg_init=400 -q -o "$tmp/settling.h5" 2>/dev/null

"$bin/wetgran-orderparam" "$tmp/cold.h5" "$tmp/hot.h5" > "$tmp/op.tsv" 2> "$tmp/op.err"
col() { awk -F'\t' -v f="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) k[$i] = i; next } $1 ~ f { print $k[c] }' "$tmp/op.tsv"; }
check "header and one row per run" test "$(wc -l < "$tmp/op.tsv")" -eq 3
check "cold bound state (E* = 0.5) is a fluid: T_g/E_cb = $(col cold tg_ecb)" test "$(col cold label)" = f
check "hot state (E* = 2.5) is a gas: T_g/E_cb = $(col hot tg_ecb)" test "$(col hot label)" = g
check "the gas is more than ten times hotter" awk -v a="$(col cold tg_ecb)" -v b="$(col hot tg_ecb)" 'BEGIN { exit !(b > 10 * a) }'
"$bin/wetgran-profiles" "$tmp/cold.h5" > "$tmp/prof.tsv"
dn=$(awk -F'\t' 'NR > 1 { if (min == "" || $6 < min) min = $6; if ($6 > max) max = $6 } END { print max - min }' "$tmp/prof.tsv")
check "dn_cb is max - min of the bridge-density profile (Eq. 3.3): $(col cold dn_cb) vs $dn" \
  awk -v a="$(col cold dn_cb)" -v b="$dn" 'BEGIN { d = a - b; exit !(d < 1e-4 && d > -1e-4) }'
tg=$("$bin/wetgran-series" "$tmp/cold.h5" temperature | awk -F'\t' 'NR > 1 && $1 >= 150 { s += $2; n++ } END { print s / n / 0.2844 }')
check "tg is the window mean of the temperature series over E_cb: $(col cold tg_ecb) vs $tg" \
  awk -v a="$(col cold tg_ecb)" -v b="$tg" 'BEGIN { exit !(a / b - 1 < 1e-4 && b / a - 1 < 1e-4) }'

"$bin/wetgran-orderparam" "$tmp/settling.h5" > "$tmp/op2.tsv" 2> "$tmp/op2.err"
check "a window that starts in the hot initial state is flagged as not stationary" \
  bash -c "awk -F'\t' 'NR == 2 { exit !(\$9 == 0) }' '$tmp/op2.tsv' && grep -q -E 'not stationary|never became stationary' '$tmp/op2.err'"
check "settled runs are not flagged" bash -c "! grep -q -E 'not stationary|never became stationary' '$tmp/op.err'"
# where the warm-up ends (MSER-5): a gas started at 400 E_cb cools into a fluid of ~1 E_cb
long="n=300 lx=100 t_end=600 profile_bins=25 dt_series=1 dt_checkpoint=0 estar=0.5 tg_init=400"
"$bin/wetgran-run" "$scenes/shake2d.ini" $long profile_start=0 -q -o "$tmp/settle0.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d.ini" $long profile_start=300 -q -o "$tmp/settle300.h5" 2>/dev/null
"$bin/wetgran-orderparam" --h5 "$tmp/st.h5" "$tmp/settle0.h5" "$tmp/settle300.h5" > "$tmp/op3.tsv" 2> "$tmp/op3.err"
ts=$(sed -n 's/.*settle0.h5: not stationary in \[0, 600\]: T_g settles only at t = \([0-9.]*\).*/\1/p' "$tmp/op3.err")
check "a window from t = 0 is flagged with the end of the warm-up (t = ${ts:-none})" test -n "$ts"
"$bin/wetgran-series" "$tmp/settle0.h5" temperature > "$tmp/ser.tsv"
check "before that end T_g is more than 3 times its later mean, after it within 20 % of it" \
  awk -F'\t' -v ts="${ts:-0}" 'NR > 1 { if ($1 < ts) { a += $2; na++ } else { b += $2; nb++; v[nb] = $2 } }
    END { m = b / nb; late = 0; for (i = 1; i <= 10; i++) late += v[i]; late /= 10
          exit !(na > 0 && a / na > 3 * m && late < 1.2 * m && late > 0.8 * m) }' "$tmp/ser.tsv"
check "the same run averaged from t = 300, after the warm-up, is stationary" \
  bash -c "! grep -q settle300 '$tmp/op3.err' && awk -F'\t' '\$1 ~ /settle300/ { exit !(\$9 == 1) }' '$tmp/op3.tsv'"
h5dump -d /orderparam/t_settle -y -o "$tmp/ts.txt" "$tmp/st.h5" > /dev/null 2>&1
check "--h5 gives every run's end of warm-up (/orderparam/t_settle: $(tr -s ', \n' '  ' < "$tmp/ts.txt"))" \
  bash -c "[ \"\$(tr -s ', \n' '  ' < '$tmp/ts.txt' | awk '{ print \$1, \$2 }')\" = '$ts $ts' ]"
"$bin/wetgran-run" "$scenes/shake2d.ini" n=300 lx=100 t_end=8 profile_start=0 profile_bins=25 dt_series=0.05 \
  dt_checkpoint=0 estar=0.5 tg_init=400 -q -o "$tmp/short.h5" 2>/dev/null
"$bin/wetgran-orderparam" "$tmp/short.h5" > /dev/null 2> "$tmp/op4.err"
check "a run still cooling at its end (8 t.u. from 400 E_cb) never became stationary" \
  grep -q 'short.h5: never became stationary' "$tmp/op4.err"

"$bin/wetgran-orderparam" --calibrate "$tmp/cold.h5" "$tmp/hot.h5" > "$tmp/cal.tsv" 2> "$tmp/cal.err"
tfg=$(awk -F"\t" "NR == 1 { print \$4 }" "$tmp/cal.tsv")
check "--calibrate puts the fluid/gas cut between the two runs' temperatures ($tfg)" \
  awk -v c="$tfg" -v a="$(col cold tg_ecb)" -v b="$(col hot tg_ecb)" 'BEGIN { exit !(c > a && c < b) }'
"$bin/wetgran-orderparam" --calibrate --t-fg 1e6 "$tmp/cold.h5" "$tmp/hot.h5" > "$tmp/cal2.tsv" 2> /dev/null
check "--calibrate keeps a threshold given on the command line (t_fg = 1e6: no gas)" \
  bash -c "awk -F'\t' 'NR == 1 { exit !(\$4 == 1e+06) }' '$tmp/cal2.tsv' && [ \$(grep -c \"\tg\$\" '$tmp/cal2.tsv') -eq 0 ]"
"$bin/wetgran-orderparam" --h5 "$tmp/op.h5" "$tmp/cold.h5" "$tmp/hot.h5" > /dev/null 2>&1
h5dump -d /orderparam/tg_ecb -y -o "$tmp/tg.txt" "$tmp/op.h5" > /dev/null 2>&1
check "--h5 writes the same T_g/E_cb as the table" \
  awk -v a="$(col cold tg_ecb)" -v b="$(tr -s ', \n' '  ' < "$tmp/tg.txt" | awk '{ print $1 }')" 'BEGIN { exit !(a > 0 && (a - b) / a < 1e-5 && (b - a) / a < 1e-5) }'
"$bin/wetgran-orderparam" --inflection "$tmp/cold.h5" "$tmp/hot.h5" > "$tmp/inf.tsv"
check "--inflection of a two-run scan: the geometric middle sqrt(0.5 * 2.5) +- 1" \
  awk -F'\t' '$1 == "inflection_estar" { d = $2 - sqrt(1.25); ok = (d < 1e-4 && d > -1e-4 && $3 == 1) } END { exit !ok }' "$tmp/inf.tsv"
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=0.5 gamma=30 -q -o "$tmp/cold30.h5" 2>/dev/null
"$bin/wetgran-orderparam" --inflection --along gamma "$tmp/cold30.h5" "$tmp/cold.h5" > "$tmp/infg.tsv"
check "--inflection --along gamma of a two-run scan in Gamma: sqrt(15 * 30) +- 7.5" \
  awk -F'\t' '$1 == "inflection_gamma" { d = $2 - sqrt(450); ok = (d < 1e-4 && d > -1e-4 && $3 == 7.5) } END { exit !ok }' "$tmp/infg.tsv"
# The contrast cut recomputed from a table's column: Otsu's two-class cut of the sorted
# values, moved to the widest gap between neighbours that lies between the two classes' means.
natural_cut='function natural_cut(x, n,   i, j, t, tot, left, best, k, m1, m2, b, cut, lo, hi, nl, g) {
    for (i = 0; i < n; i++) for (j = i + 1; j < n; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
    for (i = 0; i < n; i++) tot += x[i]; best = -1
    for (k = 1; k < n; k++) { left += x[k - 1]; m1 = left / k; m2 = (tot - left) / (n - k)
      b = k * (n - k) * (m1 - m2) ^ 2; if (b > best && x[k] > x[k - 1]) { best = b; cut = (x[k - 1] + x[k]) / 2 } }
    for (i = 0; i < n; i++) if (x[i] < cut) { lo += x[i]; nl++ } else hi += x[i]
    lo /= nl; hi /= n - nl
    for (i = 0; i < n && x[i] < cut; i++); g = x[i] - x[i - 1]
    for (i = 0; i + 1 < n; i++) if (x[i] >= lo && x[i + 1] <= hi && x[i + 1] - x[i] > g) { g = x[i + 1] - x[i]; cut = (x[i] + x[i + 1]) / 2 }
    return cut }'
# --log-contrast: the dn cut is that cut of log10 of the runs' contrasts, recomputed here from
# the table's dn_cb column
four="$tmp/cold.h5 $tmp/hot.h5 $tmp/settling.h5 $tmp/cold30.h5"
"$bin/wetgran-orderparam" --calibrate --log-contrast $four > "$tmp/log.tsv" 2> /dev/null
want=$(awk -F'\t' "$natural_cut"' !/^#/ && $1 != "file" && $15 > 0 { x[n++] = log($15) / log(10) }
  END { printf "%.6g", 10 ^ natural_cut(x, n) }' "$tmp/log.tsv")
got=$(awk -F'\t' 'NR == 1 { print $6 }' "$tmp/log.tsv")
check "--log-contrast: dn = 10^(cut of log10 dn_cb) = $want (got $got)" \
  awk -v a="$got" -v b="$want" 'BEGIN { exit !(b > 0 && (a - b) / b < 1e-5 && (b - a) / b < 1e-5) }'
# --relative-contrast: rel_contrast is dn_area over the largest packing fraction of the
# profile.  A cold inelastic bed at Gamma = 1.2 keeps a bridge-density profile varying by
# ~2.7 per bin from its structure alone, more than a run in fluid-gas coexistence
# (Gamma = 15, E* = 1.2: dense part ~4, dilute part ~15 E_cb) shows; its packing fraction
# varies by a quarter, while the coexisting run's dilute part is half as dense as the dense one.
"$bin/wetgran-run" "$scenes/shake2d.ini" $small eps=0.96 gamma=1.2 estar=1 -q -o "$tmp/bed.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=1.2 -q -o "$tmp/coex.h5" 2>/dev/null
"$bin/wetgran-orderparam" --relative-contrast --dn 0.4 --t-fg 10 "$tmp/bed.h5" "$tmp/coex.h5" > "$tmp/rel.tsv" 2> /dev/null
rcol() { awk -F'\t' -v f="$1" -v c="$2" '$1 == "file" { for (i = 1; i <= NF; i++) k[$i] = i; next } $1 ~ f { print $k[c] }' "$tmp/rel.tsv"; }
"$bin/wetgran-profiles" "$tmp/coex.h5" > "$tmp/coexprof.tsv"
want=$(awk -F'\t' 'NR > 1 { if (min == "" || $3 < min) min = $3; if ($3 > max) max = $3 } END { printf "%.6g", (max - min) / max }' "$tmp/coexprof.tsv")
check "rel_contrast is (max - min) / max of the packing-fraction profile: $(rcol coex rel_contrast) vs $want" \
  awk -v a="$(rcol coex rel_contrast)" -v b="$want" 'BEGIN { d = a - b; exit !(b > 0 && d < 1e-3 && d > -1e-3) }'
check "the bed's dn_cb ($(rcol bed dn_cb)) exceeds the coexisting run's ($(rcol coex dn_cb))" \
  awk -v a="$(rcol bed dn_cb)" -v b="$(rcol coex dn_cb)" 'BEGIN { exit !(a > b) }'
check "... but its rel_contrast ($(rcol bed rel_contrast)) lies below 0.35 and the coexisting run's ($(rcol coex rel_contrast)) above 0.45" \
  awk -v a="$(rcol bed rel_contrast)" -v b="$(rcol coex rel_contrast)" 'BEGIN { exit !(a < 0.35 && b > 0.45) }'
check "--relative-contrast (cut 0.4, t_fg 10): the bed is homogeneous ($(rcol bed label)), the coexisting run fgc ($(rcol coex label))" \
  test "$(rcol bed label) $(rcol coex label)" = "f fgc"
"$bin/wetgran-orderparam" --calibrate --relative-contrast $four "$tmp/bed.h5" "$tmp/coex.h5" > "$tmp/relcal.tsv" 2> /dev/null
# the relative contrast's cut recomputed from a table: the middle of the empty interval of
# rel_contrast values around 1/2 (0 and 1 bound it where no value lies below or above)
relcut() { awk -F'\t' '$1 == "file" { for (i = 1; i <= NF; i++) k[$i] = i; next }
  !/^#/ { x = $k["rel_contrast"]; if (x <= 0.5 && x > lo) lo = x; if (x > 0.5 && (hi == "" || x < hi)) hi = x }
  END { if (hi == "") hi = 1; printf "%.6g", (lo + hi) / 2 }' "$1"; }
want=$(relcut "$tmp/relcal.tsv")
got=$(awk -F'\t' 'NR == 1 { print $6 " " $8 }' "$tmp/relcal.tsv")
check "--calibrate --relative-contrast: dn = middle of the empty interval around 1/2 = $want, reported as relative (got $got)" \
  awk -v a="${got% *}" -v b="$want" -v m="${got#* }" 'BEGIN { exit !(m == "relative" && b > 0 && (a - b) / b < 1e-4 && (b - a) / b < 1e-4) }'
# On the 117 filed runs of the full fig3_9 sweep (eps = 0.96, 20 000 t.u., data/records).  Their
# rel_contrast lies below 0.18 (homogeneous) or above 0.55 (coexisting) but for a sparse tail
# at 0.27-0.47: fluids just before the f-fgc line with a somewhat hotter dilute part (Gamma = 8,
# E* = 1.7: 9 against 3.3 E_cb).  Otsu's cut (0.41) and the widest gap between the class means
# (0.23) fall on either side of that tail; the cut around 1/2 lies in 0.47-0.55.
filed=$(cd "$(dirname "$0")/../data/records/fig3_9/full" && pwd)
"$bin/wetgran-orderparam" --calibrate --per-scan --relative-contrast "$filed"/G*.h5 > "$tmp/f39.tsv" 2> "$tmp/f39.err"
want=$(relcut "$tmp/f39.tsv")
got=$(awk -F'\t' 'NR == 1 { print $6 }' "$tmp/f39.tsv")
check "filed fig3_9 runs ($(($(wc -l < "$tmp/f39.tsv") - 2)) of them): dn = $got, the cut around 1/2 ($want), between 0.47 and 0.55" \
  awk -v a="$got" -v b="$want" 'BEGIN { exit !(a > 0.47 && a < 0.55 && (a - b) / b < 1e-4 && (b - a) / b < 1e-4) }'
lab() { awk -F'\t' -v g="$1" -v e="$2" '$2 == g && $3 == e { print $NF }' "$tmp/f39.tsv"; }
labels=$(for g in 8 15 30; do printf '%s:%s:%s ' $g "$(lab $g 1.7)" "$(lab $g 1.8)"; done)
check "filed fig3_9 runs: Gamma = 8, 15, 30 are fluid at E* = 1.7 and coexisting at 1.8 ($labels)" \
  test "$labels" = "8:f:fgc 15:f:fgc 30:f:fgc "
# --per-scan: the coexisting runs' dense parts lie below their scan's cut and their dilute parts
# above it.  At Gamma = 8 the gas of E* = 4.5 is coexisting by contrast, its dense part at 26 E_cb
# hotter than the dilute parts of the coexistence at E* = 1.8-2.7 (20-27); it is left out of
# that interval (its parts differ least in T_g).  Between the coexistence's hottest dense part
# (4.4) and its coldest dilute part (20.5) the widest gap, 4.8 to 11.5 E_cb (E* = 1.7 and 3), is
# 0.38 decades: no jump, as a fluid warms by 0.33 decades from E* = 1.7 to 3 (T_g ~ E*^1.34 at
# E* = 1-1.4), so the scan takes
# the cut of Gamma = 5 (20.2) and E* = 3 and 3.5 (11.5, 13.7 E_cb) are hot fluids between the
# coexistence and the gas (the inflection of T_g along the scan lies at E* = 4).  The gases
# next to the coexistence at Gamma = 15 (E* = 3.5: 17.7 E_cb) and Gamma = 3 (E* = 6: 19.8), below
# that cut, were fluids when the dilute parts of weak contrasts (0.27-0.47) entered their scans.
cut5=$(sed -n 's/.*scan Gamma = 5,.*t_fg = \([^ ]*\) (its own jump;.*/\1/p' "$tmp/f39.err")
check "filed fig3_9 runs: the Gamma = 8 scan takes the cut of Gamma = 5 ($cut5)" \
  grep -q "scan Gamma = 8,.*t_fg = $cut5 (nearest scan's; its cut lies in a gap of 0.38 decades)" "$tmp/f39.err"
check "filed fig3_9 runs: Gamma = 8 is coexisting at E* = 2.7, fluid at 3 and 3.5 ($(lab 8 2.7) $(lab 8 3) $(lab 8 3.5))" \
  test "$(lab 8 2.7) $(lab 8 3) $(lab 8 3.5)" = "fgc f f"
labels="$(lab 8 4.5) $(lab 15 3.5) $(lab 3 6) $(lab 3 2.2)"
check "filed fig3_9 runs: the gases at Gamma = 8, E* = 4.5 (coexisting by contrast), 15, 3.5, 3, 6 and 3, 2.2 are g ($labels)" \
  test "$labels" = "g g g g"
check "filed fig3_9 runs: Gamma = 1.2 is solid at E* = 0.3 and 6 and in fluid-gas coexistence at 1.8 ($(lab 1.2 0.3) $(lab 1.2 6) $(lab 1.2 1.8))" \
  test "$(lab 1.2 0.3) $(lab 1.2 6) $(lab 1.2 1.8)" = "s s fgc"
# --per-scan chains: at Gamma = 5 of the filed fig3_4b runs (F_B = 16 mg) the gases right of
# the coexistence cool steadily as E* grows, from 12.5 E_cb at E* = 1.3 to 7.4 at E* = 5 (steps
# of at most 0.1 decades).  The row has no jump of its own (0.38 decades), takes the cut of
# Gamma = 3 (8.9), and that cut falls inside the chain: E* = 5 alone would be fluid.  A phase
# changes only where T_g jumps, so the chain is one phase, labelled by its median (10.4): gas.
# At Gamma = 3 the homogeneous runs at E* = 1-5 (4.9-2.9 E_cb) lie below the row's own cut.
filed=$(cd "$(dirname "$0")/../data/records/fig3_4b/full" && pwd)
"$bin/wetgran-orderparam" --calibrate --per-scan --relative-contrast --h5 "$tmp/f34b.h5" "$filed"/G*.h5 \
  > "$tmp/f34b.tsv" 2> "$tmp/f34b.err"
labb() { awk -F'\t' -v g="$1" -v e="$2" '$2 == g && $3 == e { print $NF }' "$tmp/f34b.tsv"; }
cut3=$(sed -n 's/.*scan Gamma = 3,.*t_fg = \([^ ]*\) (its own jump;.*/\1/p' "$tmp/f34b.err")
check "filed fig3_4b runs: the Gamma = 5 row takes the cut of Gamma = 3 ($cut3), above the T_g of its gas at E* = 5 ($(awk -F'\t' '$2 == 5 && $3 == 5 { print $11 }' "$tmp/f34b.tsv"))" \
  bash -c "grep -q 'scan Gamma = 5,.*t_fg = $cut3 (nearest scan' '$tmp/f34b.err' && awk -F'\t' -v c='$cut3' '\$2 == 5 && \$3 == 5 { exit !(\$11 < c) }' '$tmp/f34b.tsv'"
labels=$(for e in 1 1.3 1.7 2.2 3 5; do printf '%s ' "$(labb 5 $e)"; done)
check "filed fig3_4b runs: Gamma = 5 is coexisting at E* = 1 and gas at 1.3-5 ($labels)" \
  test "$labels" = "fgc g g g g g "
labels=$(for e in 0.8 1 1.7 5; do printf '%s ' "$(labb 3 $e)"; done)
check "filed fig3_4b runs: Gamma = 3 is coexisting at E* = 0.8 and fluid at 1-5 ($labels)" \
  test "$labels" = "fgc f f f "
# An order parameter the labels do not use agrees: bridges per particle (2 n_cb / n from the
# profiles) at Gamma = 5 are 2.3-3.1 for the fluids (E* <= 0.45), 0.24-0.30 for the gases
# at E* = 1.3-3, and 0.38 at E* = 5: a gas, by a factor 5 from the fluids.
bpp() { "$bin/wetgran-profiles" "$filed/G5_E$1.h5" | awk -F'\t' 'NR > 1 { n += $2; b += $6 } END { print 2 * b / n }'; }
b5=$(bpp 5); bf=$(bpp 0.45); bg=$(bpp 3)
check "filed fig3_4b runs: Gamma = 5, E* = 5 has $b5 bridges per particle, nearer in log to the gas at E* = 3 ($bg) than to the fluid at 0.45 ($bf)" \
  awk -v x="$b5" -v f="$bf" -v g="$bg" 'BEGIN { exit !(log(x / g) ^ 2 < log(f / x) ^ 2 && g < f) }'
# --h5 holds each run's chain median: at Gamma = 5 the median of the five gases' T_g (E* = 2.2)
h5dump -d /orderparam/tg_chain -y -o "$tmp/chain.txt" "$tmp/f34b.h5" > /dev/null 2>&1
chain=$(tr -s ', \n' '\n\n\n' < "$tmp/chain.txt" | grep -v '^$' | paste - <(awk -F'\t' '!/^#/ && $1 != "file" { print $2, $3, $11 }' "$tmp/f34b.tsv"))
check "--h5: /orderparam/tg_chain of Gamma = 5, E* = 1.3-5 is the T_g of E* = 2.2 ($(echo "$chain" | awk '$2 == 5 && $3 >= 1.3 { printf "%.4g ", $1 }'))" \
  bash -c "echo '$chain' | awk '\$2 == 5 && \$3 == 2.2 { m = \$4 } \$2 == 5 && \$3 >= 1.3 { v[++n] = \$1 }
    END { for (i = 1; i <= n; i++) if (v[i] != v[1] || (v[i] - m) / m > 1e-5 || (m - v[i]) / m > 1e-5) exit 1; exit n != 5 }'"
# --per-scan: at Gamma = 80 the gas is hotter than at 15 (T_g/E_cb ~ 1400 and 2400 against
# ~1300), so one Otsu cut over the sweep would fall between the gases; each scan's own jump
# (Gamma = 15: fluid ~ 1, gas ~ 1300) must label every gas g, and the Gamma = 80 scan, which
# has no fluid and so no jump, takes the Gamma = 15 scan's cut.
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=2 gamma=80 -q -o "$tmp/hot80a.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=2.5 gamma=80 -q -o "$tmp/hot80b.h5" 2>/dev/null
sweep="$tmp/cold.h5 $tmp/hot.h5 $tmp/hot80a.h5 $tmp/hot80b.h5"
"$bin/wetgran-orderparam" --calibrate --per-scan $sweep > "$tmp/ps.tsv" 2> "$tmp/ps.err"
labels=$(awk -F'\t' '!/^#/ && $1 != "file" { sub(/.*\//, "", $1); printf "%s:%s ", $1, $NF }' "$tmp/ps.tsv")
check "--per-scan: the fluid is f and the three gases g ($labels)" \
  test "$labels" = "cold.h5:f hot.h5:g hot80a.h5:g hot80b.h5:g "
cut15=$(sed -n 's/.*scan Gamma = 15,.*t_fg = \([^ ]*\) (its own jump;.*/\1/p' "$tmp/ps.err")
check "--per-scan: the Gamma = 15 scan's cut ($cut15) lies between its fluid and its gas" \
  awk -v c="$cut15" -v a="$(col cold tg_ecb)" -v b="$(col hot tg_ecb)" 'BEGIN { exit !(c > a && c < b) }'
check "--per-scan: the Gamma = 80 scan, all gas, takes the nearest scan's cut" \
  grep -q "scan Gamma = 80,.*t_fg = $cut15 (nearest scan's;" "$tmp/ps.err"
# --per-scan with a cool gas: at Gamma = 2 the gas has T_g/E_cb ~ 16, below the sweep's global
# cut (~165, set by the hot gases), so the global colder class holds fluids (~1.4) and that gas
# more than a decade apart, and its split would call the fluids solid (the full fig3_4a sweep
# did this at 125 runs).  The solid cut must come from the runs below their own scan's cut.
# (--dn 1: all six homogeneous, as the small fluids' contrasts are near the sweep's cut.)
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=0.5 gamma=2 -q -o "$tmp/cool2f.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=5 gamma=2 -q -o "$tmp/cool2g.h5" 2>/dev/null
"$bin/wetgran-orderparam" --calibrate --per-scan --dn 1 $sweep "$tmp/cool2f.h5" "$tmp/cool2g.h5" \
  > "$tmp/ps2.tsv" 2> "$tmp/ps2.err"
labels=$(awk -F'\t' '!/^#/ && $1 != "file" { sub(/.*\//, "", $1); printf "%s:%s ", $1, $NF }' "$tmp/ps2.tsv")
check "--per-scan with a cool gas at Gamma = 2: fluids f, every gas g, no solid ($labels)" \
  test "$labels" = "cold.h5:f hot.h5:g hot80a.h5:g hot80b.h5:g cool2f.h5:f cool2g.h5:g "
"$bin/wetgran-orderparam" --inflection --along gamma "$tmp/cold.h5" "$tmp/hot.h5" > /dev/null 2> "$tmp/err"; rc=$?
check "--along gamma over runs of one Gamma: an error naming gamma" bash -c "[ $rc -ne 0 ] && grep -q gamma '$tmp/err'"
"$bin/wetgran-orderparam" "$tmp/none.h5" > /dev/null 2> "$tmp/err"; rc=$?
check "missing run file: non-zero exit, file named" bash -c "[ $rc -ne 0 ] && grep -q none.h5 '$tmp/err'"
summary
