#!/bin/bash
# wetgran-poincare (thesis Sec. 8.4): Poincare sections of per-cycle maxima, the return map and
# its fixed points, on series with known answers (tests/poincare_synth.py): logistic maps
# (r = 2.8: x* = 1 - 1/r, slope 2 - r = -0.8, stable; r = 3.7: x* = 0.7297, slope -1.7,
# unstable), a noisy limit cycle (100 periods of a sine with 10 % noise: 99 cycles, maxima 3,
# a stable point at 3), series with no cycle (white noise, a ramp: a message, exit 1), a run
# file's series, a table on stdin, bad input.
set -u
tool=${WG_BIN:?}/wetgran-poincare
. "$(dirname "$0")/checks.sh"
py=/usr/bin/python3
synth=$WG_TESTS/poincare_synth.py
col() { awk -F'\t' -v c="$1" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i } NR == 2 { print $k }' "$2"; }
near() { awk -v g="$1" -v v="$2" -v t="$3" 'BEGIN { d = g - v; if (d < 0) d = -d; exit !(g == g + 0 && d <= t) }'; }
export -f near

for x0 in 0.2 0.3 0.5 0.9; do
  $py "$synth" logistic "$tmp/l28_$x0.tsv" r=2.8 x0=$x0
  $py "$synth" logistic "$tmp/l37_$x0.tsv" r=3.7 x0=$x0 cycles=60
done
"$tool" section "$tmp/l37_0.2.tsv" > "$tmp/sec.tsv"
check "section: the cycles' maxima are the logistic iterates x_1, x_2, ... (1e-9), one per cycle after the first" \
  $py -c "
import numpy as np
rows = [l.split('\t') for l in open('$tmp/sec.tsv').read().split('\n')[1:] if l]
x, want = 0.2, []
for k in range(60): want.append(x); x = 3.7 * x * (1 - x)
got = [float(r[3]) for r in rows]
assert len(got) == 58, len(got)
assert np.allclose(got, want[1:59], rtol=0, atol=1e-9)
assert np.allclose([float(r[2]) for r in rows], [4 * k + 2 for k in range(1, 59)], atol=1e-9)"
"$tool" map "$tmp"/l37_*.tsv > "$tmp/map.tsv"
check "map: every pair on the logistic parabola x' = 3.7 x (1 - x) (1e-9), 4 x 57 pairs" \
  awk -F'\t' 'NR > 1 { n++; d = $2 - 3.7 * $1 * (1 - $1); if (d < 0) d = -d; if (d > 1e-9) bad++ }
    END { exit !(n == 228 && bad == 0) }' "$tmp/map.tsv"
"$tool" fixed "$tmp"/l28_*.tsv > "$tmp/f28.tsv"
check "fixed, r = 2.8: x* = 1 - 1/2.8 = 0.642857, slope -0.8 (1e-6), stable" \
  bash -c "[ \$(wc -l < '$tmp/f28.tsv') -eq 2 ] && near $(col x_star "$tmp/f28.tsv") 0.6428571 1e-6 && near $(col slope "$tmp/f28.tsv") -0.8 1e-6 && [ '$(col stability "$tmp/f28.tsv")' = stable ]"
"$tool" fixed "$tmp"/l37_*.tsv > "$tmp/f37.tsv"
check "fixed, r = 3.7: x* = 0.729730, slope -1.7 (1e-6), unstable" \
  bash -c "[ \$(wc -l < '$tmp/f37.tsv') -eq 2 ] && near $(col x_star "$tmp/f37.tsv") 0.7297297 1e-6 && near $(col slope "$tmp/f37.tsv") -1.7 1e-6 && [ '$(col stability "$tmp/f37.tsv")' = unstable ]"

$py "$synth" noisy "$tmp/noisy.tsv"
"$tool" section --smooth 11 "$tmp/noisy.tsv" > "$tmp/nsec.tsv"
check "noisy limit cycle, --smooth 11: 99 cycles (100 periods, the first without its minimum), maxima 3 (+- 0.05)" \
  awk -F'\t' 'NR > 1 { n++; s += $4 } END { m = s / n; exit !(n == 99 && m > 2.95 && m < 3.05) }' "$tmp/nsec.tsv"
"$tool" section "$tmp/noisy.tsv" > "$tmp/nsec1.tsv"
check "noisy limit cycle unsmoothed: the noise-scaled prominence still finds 100 +- 1 cycles" \
  bash -c "n=\$((\$(wc -l < '$tmp/nsec1.tsv') - 1)); [ \$n -ge 99 ] && [ \$n -le 101 ]"
"$tool" fixed --smooth 11 "$tmp/noisy.tsv" > "$tmp/nfix.tsv"
check "noisy limit cycle: one fixed point at 3 (+- 0.05), stable, slope 0 within 0.8" \
  bash -c "[ \$(wc -l < '$tmp/nfix.tsv') -eq 2 ] && near $(col x_star "$tmp/nfix.tsv") 3 0.05 && near $(col slope "$tmp/nfix.tsv") 0 0.8 && [ '$(col stability "$tmp/nfix.tsv")' = stable ]"

for k in white ramp; do
  $py "$synth" $k "$tmp/$k.tsv"
  "$tool" fixed --smooth 11 "$tmp/$k.tsv" > "$tmp/$k.out" 2> "$tmp/$k.err"; rc=$?
  check "no cycle in $k: exit 1, 'no limit cycle' on stderr, no fixed point printed" \
    bash -c "[ $rc -eq 1 ] && grep -q 'no limit cycle' '$tmp/$k.err' && [ ! -s '$tmp/$k.out' ]"
done

$py "$synth" h5 "$tmp/run.h5" r=2.8
"$tool" section "$tmp/run.h5" > "$tmp/h5sec.tsv"
"$tool" section "$tmp/l28_0.2.tsv" > "$tmp/tsec.tsv"
check "a run file's /observables/e_perp gives the same section as its table" \
  bash -c "diff <(cut -f2- '$tmp/h5sec.tsv') <(cut -f2- '$tmp/tsec.tsv') > /dev/null"
"$tool" section - < "$tmp/l28_0.2.tsv" > "$tmp/stdin.tsv"
check "a table on stdin ('-') as from a file" bash -c "diff <(cut -f2- '$tmp/stdin.tsv') <(cut -f2- '$tmp/tsec.tsv') > /dev/null"
"$tool" section --column e_par "$tmp/run.h5" > /dev/null 2> "$tmp/nocol.err"; rc=$?
check "a series the run lacks: exit 1, named" bash -c "[ $rc -eq 1 ] && grep -q \"'e_par'\" '$tmp/nocol.err'"
"$tool" section --column e_par "$tmp/l28_0.2.tsv" > /dev/null 2> "$tmp/nocol2.err"; rc=$?
check "a column the table lacks: exit 1, file, line and column named" \
  bash -c "[ $rc -eq 1 ] && grep -q \"l28_0.2.tsv:1: no column 'e_par'\" '$tmp/nocol2.err'"
"$tool" section --smooth 4 "$tmp/l28_0.2.tsv" > /dev/null 2>&1; rc=$?
check "an even --smooth is refused (exit 2)" test "$rc" -eq 2
"$tool" orbit "$tmp/l28_0.2.tsv" > /dev/null 2>&1; rc=$?
check "an unknown mode is refused (exit 2)" test "$rc" -eq 2
"$tool" section "$tmp/missing.tsv" > /dev/null 2> "$tmp/miss.err"; rc=$?
check "a missing file: exit 1, one line naming it" bash -c "[ $rc -eq 1 ] && [ \$(wc -l < '$tmp/miss.err') -eq 1 ] && grep -q missing.tsv '$tmp/miss.err'"

summary
