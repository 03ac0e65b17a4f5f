#!/bin/bash
# wetgran-boundary on synthetic phase diagrams whose boundaries are known: the Delaunay-edge
# midpoints (thesis Fig. 3.3) must fall between the grid lines around the true boundary, the
# fits must recover it within half a grid spacing, and bad tables must be refused clearly.
set -u
tool=${WG_BIN:?}/wetgran-boundary
. "$(dirname "$0")/checks.sh"
# awk_ok 'condition on the file's fields' FILE: true when FILE has data rows and every data
# row (after the header) satisfies the condition
awk_ok() { awk -F'\t' -v bad=0 "NR > 1 { n++; if (!($1)) bad++ } END { exit !(n > 0 && bad == 0) }" "$2"; }
# value KEY FILE: the value column of row KEY of a key/value/error table
value() { awk -F'\t' -v k="$1" '$1 == k { print $2; f = 1 } END { exit !f }' "$2"; }
error() { awk -F'\t' -v k="$1" '$1 == k { print $3; f = 1 } END { exit !f }' "$2"; }
# near A B TOL: |A - B| <= TOL
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a == a + 0 && d <= t) }'; }
# lognear A B TOL: |log10 A - log10 B| <= TOL
lognear() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { if (!(a > 0)) exit 1; d = log(a / b) / log(10); if (d < 0) d = -d; exit !(d <= t) }'; }
export -f awk_ok near lognear
cols=(--x estar --y gamma --label phase)

check "--help explains the method, the unit-square scaling and the thesis reference" \
  bash -c "'$tool' --help > '$tmp/help' && grep -q Delaunay '$tmp/help' && grep -q 'unit square' '$tmp/help' && grep -q 'Roeller' '$tmp/help' && grep -q 'Fig. 3.3' '$tmp/help'"

# (1) 9 x 7 grid, E* = 10^(-1 + i/4) (0.1 ... 10, 1/4 decade apart), Gamma = 1 ... 7;
# f for E* < 1.02, else fgc.  The boundary lies between the columns E* = 1 and 10^0.25.
awk 'BEGIN { OFS = "\t"; print "estar", "gamma", "phase"; print "# a comment line, skipped"
  for (i = 0; i < 9; i++) for (j = 0; j < 7; j++) {
    e = exp((-1 + i / 4) * log(10)); printf "%.12g\t%d\t%s\n", e, 1 + j, (e < 1.02 ? "f" : "fgc") } }' \
  > "$tmp/grid.tsv"
"$tool" "${cols[@]}" --logx "$tmp/grid.tsv" > "$tmp/grid.out" 2> "$tmp/grid.err"; rc=$?
check "grid: exit 0, nothing on stderr" bash -c "[ $rc -eq 0 ] && [ ! -s '$tmp/grid.err' ]"
check "grid: header x y phase_a phase_b" test "$(head -n 1 "$tmp/grid.out")" = $'x\ty\tphase_a\tphase_b'
check "grid: every midpoint joins f and fgc" awk_ok '$3 == "f" && $4 == "fgc"' "$tmp/grid.out"
check "grid: every midpoint lies between the columns E* = 1 and 10^0.25" \
  awk_ok '$1 > 1 && $1 < 1.7782794' "$tmp/grid.out"
check "grid: --logx puts midpoints at the geometric mean 10^0.125 of the two columns" \
  awk_ok '$1 > 1.33352 && $1 < 1.33353' "$tmp/grid.out"
check "grid: at least one crossing edge per row (7), Gamma spans 1..7" \
  bash -c "[ \$(awk 'NR > 1' '$tmp/grid.out' | wc -l) -ge 7 ] && awk -F'\t' 'NR > 1 { if (\$2 == 1) a = 1; if (\$2 == 7) b = 1 } END { exit !(a && b) }' '$tmp/grid.out'"
"$tool" "${cols[@]}" "$tmp/grid.tsv" > "$tmp/grid_lin.out"
check "grid: without --logx the midpoint is the arithmetic mean (1 + 10^0.25)/2" \
  awk_ok '$1 > 1.38913 && $1 < 1.38914' "$tmp/grid_lin.out"
"$tool" "${cols[@]}" --logx --fit-vertical f:fgc "$tmp/grid.tsv" > "$tmp/grid.fit"; rc=$?
v=$(value vertical_f_fgc "$tmp/grid.fit")
check "grid: --fit-vertical f:fgc header key value error" test "$(head -n 1 "$tmp/grid.fit")" = $'key\tvalue\terror'
check "grid: --fit-vertical f:fgc = $v, within half a spacing (1/8 decade) of 1.02" \
  bash -c "[ $rc -eq 0 ] && lognear '$v' 1.02 0.125"
n=$(value vertical_f_fgc_n "$tmp/grid.fit")
check "grid: vertical_f_fgc_n ($n) counts the midpoints" \
  test "$n" = "$(awk 'NR > 1' "$tmp/grid.out" | wc -l)"
check "grid: the pair may be given in either order" \
  bash -c "[ \"\$('$tool' ${cols[*]} --logx --fit-vertical fgc:f '$tmp/grid.tsv' | awk -F'\t' '\$1 == \"vertical_fgc_f\" { print \$2 }')\" = '$v' ]"
# (1b) the same grid with the fluid back at E* >= 10^0.75 (as at Gamma = 1.2 in Fig. 3.4a):
# f:fgc also averages that second boundary (10^0.625), f<fgc only the edges with f at the
# smaller E* (10^0.125), and fgc<f only the others.
awk -F'\t' -v OFS='\t' 'NR > 2 && $1 > 5 { $3 = "f" } { print }' "$tmp/grid.tsv" > "$tmp/back.tsv"
"$tool" "${cols[@]}" --logx --fit-vertical f:fgc --fit-vertical "f<fgc" --fit-vertical "fgc<f" "$tmp/back.tsv" > "$tmp/back.fit"
vals=$(awk -F'\t' 'NR > 1 && $1 !~ /_n$/ { printf "%s ", $2 }' "$tmp/back.fit")
set -- $vals
check "returning fluid: f:fgc mixes both boundaries ($1, between 10^0.125 and 10^0.625)" \
  awk -v a="$1" 'BEGIN { exit !(a > 1.4 && a < 4.1) }'
check "returning fluid: f<fgc = $2 is the left boundary 10^0.125" lognear "$2" 1.3335214 1e-6
check "returning fluid: fgc<f = $3 is the right boundary 10^0.625" lognear "$3" 4.2169650 1e-6
check "returning fluid: f<fgc keeps the key vertical_f_fgc" \
  test "$(awk -F'\t' 'NR == 4 { print $1 }' "$tmp/back.fit")" = vertical_f_fgc
check "grid: same output from stdin" \
  bash -c "'$tool' ${cols[*]} --logx < '$tmp/grid.tsv' | cmp -s - '$tmp/grid.out'"

# the triangulation is done in the unit square: A = (0, 500) f and B = (1, 500) g are 1 apart,
# C = (0.5, 350) and D = (0.5, 650) 300 apart.  Unscaled, AB is a Delaunay edge (f|g midpoint);
# in the unit square CD is the edge, and A, B are not joined.
printf 'x\ty\tlabel\n0\t500\tf\n1\t500\tg\n0.5\t350\ts\n0.5\t650\ts\n0\t0\ts\n1\t0\ts\n0\t1000\ts\n1\t1000\ts\n' \
  > "$tmp/scale.tsv"
"$tool" "$tmp/scale.tsv" > "$tmp/scale.out"; rc=$?
check "scaling: f and g are not joined in unit-square coordinates (no f|g midpoint)" \
  bash -c "[ $rc -eq 0 ] && ! awk -F'\t' '\$3 == \"f\" && \$4 == \"g\"' '$tmp/scale.out' | grep -q . && awk -F'\t' '\$3 == \"f\" && \$4 == \"s\"' '$tmp/scale.out' | grep -q ."

# (2) horizontal boundary Gamma = 1.5, Gamma = 0.6, 1.0, ..., 4.2 (0.4 apart): s below, f above
awk 'BEGIN { OFS = "\t"; print "estar", "gamma", "phase"
  for (i = 0; i < 9; i++) for (j = 0; j < 10; j++) {
    e = exp((-1 + i / 4) * log(10)); g = 0.6 + 0.4 * j; printf "%.12g\t%.12g\t%s\n", e, g, (g < 1.5 ? "s" : "f") } }' \
  > "$tmp/horiz.tsv"
"$tool" "${cols[@]}" --logx --fit-horizontal s:f "$tmp/horiz.tsv" > "$tmp/horiz.fit"; rc=$?
v=$(value horizontal_s_f "$tmp/horiz.fit")
check "horizontal: --fit-horizontal s:f = $v, within half a spacing (0.2) of 1.5" \
  bash -c "[ $rc -eq 0 ] && near '$v' 1.5 0.2"
"$tool" "${cols[@]}" --logx "$tmp/horiz.tsv" > "$tmp/horiz.out"
check "horizontal: every midpoint lies between the rows Gamma = 1.4 and 1.8" \
  awk_ok '$2 > 1.4 && $2 < 1.8 && $3 == "f" && $4 == "s"' "$tmp/horiz.out"

# (3) three phases: s below Gamma 1.5, above it f left of E* = 1 and fgc right of it
awk 'BEGIN { OFS = "\t"; print "phase", "gamma", "estar"
  for (i = 0; i < 9; i++) for (j = 0; j < 10; j++) {
    e = exp((-0.9 + i / 4) * log(10)); g = 0.6 + 0.4 * j
    printf "%s\t%.12g\t%.12g\n", (g < 1.5 ? "s" : e < 1 ? "f" : "fgc"), g, e } }' > "$tmp/three.tsv"
"$tool" "${cols[@]}" --logx "$tmp/three.tsv" > "$tmp/three.out"; rc=$?
check "three phases: exit 0 (columns found by name in another order)" test "$rc" -eq 0
check "three phases: the pairs are exactly f|fgc, f|s, fgc|s, in this order" \
  test "$(awk -F'\t' 'NR > 1 { print $3 "|" $4 }' "$tmp/three.out" | uniq | tr '\n' ' ')" = "f|fgc f|s fgc|s "
check "three phases: no midpoint of a same-phase edge, phase_a < phase_b" \
  awk_ok '$3 < $4' "$tmp/three.out"
check "three phases: f|fgc midpoints lie above Gamma 1.4 and between E* = 10^-0.15 and 10^0.1" \
  bash -c "awk -F'\t' '\$3 == \"f\" && \$4 == \"fgc\"' '$tmp/three.out' | awk -F'\t' '{ n++; if (!(\$2 > 1.4 && \$1 > 0.70794 && \$1 < 1.25893)) bad++ } END { exit !(n > 0 && !bad) }'"
check "three phases: f|s and fgc|s midpoints lie between Gamma 1.4 and 1.8" \
  bash -c "awk -F'\t' '\$4 == \"s\"' '$tmp/three.out' | awk -F'\t' '{ n++; if (!(\$2 > 1.4 && \$2 < 1.8)) bad++ } END { exit !(n > 0 && !bad) }'"
check "three phases: sorted by phase pair, then x, then y" \
  bash -c "(head -n 1 '$tmp/three.out'; tail -n +2 '$tmp/three.out' | LC_ALL=C sort -t$'\t' -k3,3 -k4,4 -k1,1g -k2,2g) | cmp -s - '$tmp/three.out'"
check "three phases: a second run gives identical bytes" \
  bash -c "'$tool' ${cols[*]} --logx '$tmp/three.tsv' | cmp -s - '$tmp/three.out'"

# (4) jittered grid: 15 x 12 points in (log10 E*, Gamma), each moved by up to +-0.3 spacing
awk 'BEGIN { srand(42); print "estar\tgamma\tphase"; nx = 15; ny = 12
  for (i = 0; i < nx; i++) for (j = 0; j < ny; j++) {
    le = -1 + 2 * (i + 0.6 * (rand() - 0.5)) / (nx - 1); g = 1 + 11 * (j + 0.6 * (rand() - 0.5)) / (ny - 1)
    e = exp(le * log(10)); printf "%.12g\t%.12g\t%s\n", e, g, (e < 1.02 ? "f" : "fgc") } }' > "$tmp/jit.tsv"
"$tool" "${cols[@]}" --logx --fit-vertical f:fgc --fit-horizontal f:fgc "$tmp/jit.tsv" > "$tmp/jit.fit"; rc=$?
"$tool" "${cols[@]}" --logx "$tmp/jit.tsv" > "$tmp/jit.out"
v=$(value vertical_f_fgc "$tmp/jit.fit"); e=$(error vertical_f_fgc "$tmp/jit.fit")
check "jittered: --fit-vertical f:fgc = $v +- $e, within half a spacing (1/14 decade) of 1.02" \
  bash -c "[ $rc -eq 0 ] && lognear '$v' 1.02 0.0714"
# the fit recomputed from the midpoint list: geometric mean of x, error value*ln10*stderr(log10 x)
read -r gm gerr am aerr < <(awk -F'\t' 'NR > 1 { n++; l = log($1) / log(10); s += l; ss += l * l; t += $2; tt += $2 * $2 }
  END { m = s / n; se = sqrt((ss - n * m * m) / (n - 1) / n); v = exp(m * log(10))
        a = t / n; ae = sqrt((tt - n * a * a) / (n - 1) / n); printf "%.12g %.12g %.12g %.12g\n", v, v * log(10) * se, a, ae }' "$tmp/jit.out")
check "jittered: vertical value is the geometric mean of the midpoints' x ($gm)" near "$v" "$gm" 1e-8
# the error adds the grid's resolution to the scatter: sqrt(err^2 - stderr^2) lies between 0
# and the half-extent of a long edge over sqrt 3 (an edge of the jittered grid spans at most
# about 3.2 spacings: x spacing 2/14 decade, in log10 times value ln 10; y spacing 1)
res_between() { awk -v e="$1" -v s="$2" -v hi="$3" 'BEGIN { r = e * e - s * s; exit !(r > 0 && sqrt(r) <= hi) }'; }
export -f res_between
check "jittered: vertical error = stderr of log10 x (times value ln 10) plus resolution ($gerr < $e)" \
  res_between "$e" "$gerr" "$(awk -v v="$v" 'BEGIN { print v * log(10) * 1.6 * 2 / 14 / sqrt(3) }')"
check "jittered: horizontal value is the plain mean of y ($am), its error stderr plus resolution" \
  bash -c "near '$(value horizontal_f_fgc "$tmp/jit.fit")' '$am' 1e-7 && res_between '$(error horizontal_f_fgc "$tmp/jit.fit")' '$aerr' $(awk 'BEGIN { print 1.6 / sqrt(3) }')"
check "jittered: the error is a real number, not nan" awk -v e="$e" 'BEGIN { exit !(e > 0 && e < 0.2) }'
# points in general position have one Delaunay triangulation: the order of the rows is irrelevant
awk 'BEGIN { srand(7) } NR == 1 { print; next } { printf "%.17f\t%s\n", rand(), $0 }' "$tmp/jit.tsv" \
  | { IFS= read -r h; echo "$h"; LC_ALL=C sort -t$'\t' -k1,1 | cut -f2-; } > "$tmp/shuf.tsv"
"$tool" "${cols[@]}" --logx "$tmp/shuf.tsv" > "$tmp/shuf.out"
check "jittered: shuffled rows give the same bytes (rows sorted by pair, x, y)" \
  bash -c "! cmp -s '$tmp/jit.tsv' '$tmp/shuf.tsv' && cmp -s '$tmp/jit.out' '$tmp/shuf.out'"
check "jittered: sorted by phase pair, then x, then y" \
  bash -c "(head -n 1 '$tmp/shuf.out'; tail -n +2 '$tmp/shuf.out' | LC_ALL=C sort -t$'\t' -k3,3 -k4,4 -k1,1g -k2,2g) | cmp -s - '$tmp/shuf.out'"

# duplicates: a repeated point is dropped with a warning naming its line; output unchanged
{ cat "$tmp/grid.tsv"; sed -n 12p "$tmp/grid.tsv" | awk -F'\t' -v OFS='\t' '{ $3 = "fgc"; print }'; } > "$tmp/dup.tsv"
dupline=$(wc -l < "$tmp/dup.tsv")
"$tool" "${cols[@]}" --logx "$tmp/dup.tsv" > "$tmp/dup.out" 2> "$tmp/dup.err"; rc=$?
check "duplicate: exit 0, same midpoints as without it" bash -c "[ $rc -eq 0 ] && cmp -s '$tmp/dup.out' '$tmp/grid.out'"
check "duplicate: warning names line $dupline and the kept line 12" grep -q "dup.tsv:$dupline: .*repeats line 12" "$tmp/dup.err"

# fewer than 2 midpoints: nan error and a warning
"$tool" "${cols[@]}" --logx --fit-vertical f:s "$tmp/grid.tsv" > "$tmp/none.fit" 2> "$tmp/none.err"; rc=$?
check "no midpoints: value nan, error nan, n 0, warning on stderr" \
  bash -c "[ $rc -eq 0 ] && grep -qx $'vertical_f_s\tnan\tnan' '$tmp/none.fit' && grep -q $'^vertical_f_s_n\t0\t' '$tmp/none.fit' && grep -q '0 midpoints' '$tmp/none.err'"

# (4b) a grid is not in general position (each rectangle's corners are cocircular): the
# diagonals must not depend on qhull's order of insertion.  Four rows whose last fluid
# alternates (0.9, 0.85, 0.9, 0.85); adding one gas point far to the right must leave every
# midpoint left of E* = 1.3, and the vertical fit, unchanged.
{ printf 'estar\tgamma\tphase\n'
  for row in "8 0.9" "15 0.85" "30 0.9" "50 0.85"; do set -- $row
    for x in 0.4 0.6 0.8 0.85 0.9 0.95 1 1.05 1.1 1.2 1.4 1.6 2; do
      awk -v x=$x -v y=$1 -v t=$2 'BEGIN { printf "%s\t%s\t%s\n", x, y, (x <= t ? "f" : x <= 1.2 ? "fgc" : "g") }'
    done
  done; } > "$tmp/rows.tsv"
{ cat "$tmp/rows.tsv"; printf '2.5\t50\tg\n'; } > "$tmp/rows_far.tsv"
for f in rows rows_far; do
  "$tool" "${cols[@]}" --logx "$tmp/$f.tsv" | awk -F'\t' 'NR == 1 || $1 < 1.3' > "$tmp/$f.near"
  "$tool" "${cols[@]}" --logx --fit-vertical f:fgc "$tmp/$f.tsv" > "$tmp/$f.fit"
done
check "general position: a far point leaves the midpoints near the f-fgc line unchanged" \
  bash -c "[ \$(wc -l < '$tmp/rows.near') -gt 8 ] && cmp -s '$tmp/rows.near' '$tmp/rows_far.near'"
check "general position: ... and the vertical fit" cmp -s "$tmp/rows.fit" "$tmp/rows_far.fit"
check "general position: each rectangle is split lower right to upper left (no f-fgc edge (0.85, 8)-(0.9, 15))" \
  bash -c "! grep -q \$'^0.87[0-9]*\t11.5\tf\tfgc' '$tmp/rows.near'"

# (5) errors
"$tool" --x estr --y gamma --label phase "$tmp/grid.tsv" > "$tmp/e1.out" 2> "$tmp/e1.err"; rc=$?
check "missing column: non-zero exit, message names the column 'estr' and the file" \
  bash -c "[ $rc -ne 0 ] && grep -q \"grid.tsv:1: no column 'estr'\" '$tmp/e1.err' && [ ! -s '$tmp/e1.out' ]"
sed '5s/^[^\t]*/1.2.3/' "$tmp/grid.tsv" > "$tmp/nan.tsv"
"$tool" "${cols[@]}" "$tmp/nan.tsv" > /dev/null 2> "$tmp/e2.err"; rc=$?
check "non-number: non-zero exit, message names file, line 5 and the value" \
  bash -c "[ $rc -ne 0 ] && grep -q \"nan.tsv:5: column 'estar': '1.2.3' is not a finite number\" '$tmp/e2.err'"
printf 'x\ty\tlabel\n1\t1\tf\n2\t2\tg\n' > "$tmp/two.tsv"
"$tool" "$tmp/two.tsv" > /dev/null 2> "$tmp/e3.err"; rc=$?
check "2 points: non-zero exit, says a triangulation needs 3" bash -c "[ $rc -ne 0 ] && grep -q 'at least 3' '$tmp/e3.err'"
printf 'x\ty\tlabel\n1\t1\tf\n2\t2\tg\n3\t3\tf\n4\t4\tg\n' > "$tmp/line.tsv"
"$tool" "$tmp/line.tsv" > /dev/null 2> "$tmp/e4.err"; rc=$?
check "collinear points: non-zero exit, says they lie on one line" bash -c "[ $rc -ne 0 ] && grep -q 'one line' '$tmp/e4.err'"
printf 'x\ty\tlabel\n1\t1\tf\n0\t2\tg\n3\t3\tf\n' > "$tmp/zero.tsv"
"$tool" --logx "$tmp/zero.tsv" > /dev/null 2> "$tmp/e5.err"; rc=$?
check "--logx with x = 0: non-zero exit, message names line 3" bash -c "[ $rc -ne 0 ] && grep -q 'zero.tsv:3:' '$tmp/e5.err'"
"$tool" --bogus "$tmp/grid.tsv" > /dev/null 2>&1; rc=$?
check "unknown option: exit 2" test "$rc" -eq 2
"$tool" --fit-vertical f "$tmp/grid.tsv" > /dev/null 2>&1; rc=$?
check "--fit-vertical without A:B: exit 2" test "$rc" -eq 2

summary
