#!/bin/bash
# wetgran-fit recovers known parameters from noisy synthetic data (the critical power law of
# Fig. 3.31, the straight line of Fig. 3.5 and the logarithmic fluidization depth of Fig. 4.4)
# within three of its own error bars, and refuses bad tables.
set -u
fit=${WG_BIN:?}/wetgran-fit
. "$(dirname "$0")/checks.sh"
within() { awk -v v="$1" -v e="$2" -v t="$3" 'BEGIN { d = v - t; if (d < 0) d = -d; exit !(e > 0 && d <= 3 * e) }'; }
get() { awk -F'\t' -v k="$1" '$1 == k { print $2 "\t" $3 }' "$2"; }
awk 'BEGIN { srand(3); print "estar\tdn"; for (i = 0; i < 20; i++) { x = 1 + i * 0.045;
  print x "\t" 0.7 * (1.97 - x)^0.37 * (1 + 0.02 * (rand() - 0.5)) }
  for (i = 0; i < 4; i++) print 2.0 + 0.1 * i "\t0" }' > "$tmp/crit.tsv"
"$fit" --model critical --x estar --y dn --prefix c "$tmp/crit.tsv" > "$tmp/c.out"
read -r v e < <(get c_beta "$tmp/c.out")
check "critical exponent 0.37 recovered: $v +- $e" within "$v" "$e" 0.37
read -r v e < <(get c_xc "$tmp/c.out")
check "critical point 1.97 recovered: $v +- $e" within "$v" "$e" 1.97
check "points counted (24)" test "$(get c_n "$tmp/c.out" | cut -f1)" = 24
"$fit" --model critical --x estar --y dn --xmax 1.5 --prefix c "$tmp/crit.tsv" > "$tmp/c2.out"
check "--xmax keeps only x <= 1.5 (12 points)" test "$(get c_n "$tmp/c2.out" | cut -f1)" = 12
awk 'BEGIN { srand(5); print "e\tt"; for (i = 1; i <= 12; i++) print 0.1 * i "\t" 0.2 + 1.5 * 0.1 * i + 0.01 * (rand() - 0.5) }' > "$tmp/line.tsv"
"$fit" --model line --x e --y t --prefix l "$tmp/line.tsv" > "$tmp/l.out"
read -r v e < <(get l_b "$tmp/l.out")
check "slope 1.5 recovered: $v +- $e" within "$v" "$e" 1.5
"$fit" --model line --x e --y nope "$tmp/line.tsv" > /dev/null 2> "$tmp/err"; rc=$?
check "missing column: non-zero exit naming it" bash -c "[ $rc -ne 0 ] && grep -q \"'nope'\" '$tmp/err'"
printf 'x\ty\n1\t2\n2\tabc\n' > "$tmp/bad.tsv"
"$fit" --model line --x x --y y "$tmp/bad.tsv" > /dev/null 2> "$tmp/err"; rc=$?
check "non-number: non-zero exit naming file and line 3" bash -c "[ $rc -ne 0 ] && grep -q 'bad.tsv:3' '$tmp/err'"
awk 'BEGIN { srand(5); print "ecb\tekin"; for (i = 1; i <= 6; i++) print i "\t" 1.52 * i * (1 + 0.03 * (rand() - 0.5)) }' > "$tmp/prop.tsv"
"$fit" --model prop --x ecb --y ekin --prefix p "$tmp/prop.tsv" > "$tmp/p.out"
read -r v e < <(get p_b "$tmp/p.out")
check "slope through the origin 1.52 recovered: $v +- $e" within "$v" "$e" 1.52
check "the slope's error shrinks with the scatter (< 0.02)" awk -v e="$e" 'BEGIN { exit !(e > 0 && e < 0.02) }'
# Fig. 4.4: l_s = l0 ln(1/(1 - (G - G_M)/(G_C - G_M))), 0 below G_M, at most M = 6 layers
awk 'BEGIN { srand(7); print "gamma\tls"; for (i = 0; i <= 46; i++) { x = 0.9 + 0.05 * i;
  y = x <= 1.16 ? 0 : (x >= 2.65 ? 6 : 1.27 * log(1 / (1 - (x - 1.16) / (2.65 - 1.16)))); if (y > 6) y = 6;
  print x "\t" y + 0.05 * (rand() - 0.5) } }' > "$tmp/melt.tsv"
"$fit" --model melt --cap 6 --x gamma --y ls --prefix m "$tmp/melt.tsv" > "$tmp/m.out"
for k in l0:1.27 xm:1.16 xc:2.65; do
  read -r v e < <(get "m_${k%%:*}" "$tmp/m.out")
  check "melt: ${k%%:*} = ${k#*:} recovered: $v +- $e" within "$v" "$e" "${k#*:}"
done
awk -F'\t' 'NR == 1 || $1 < 2.6' "$tmp/melt.tsv" > "$tmp/melt2.tsv"
"$fit" --model melt --cap 6 --x gamma --y ls --prefix m "$tmp/melt2.tsv" > "$tmp/m2.out"
read -r v e < <(get m_xc "$tmp/m2.out")
check "melt: xc = 2.65 found beyond the last point (2.55): $v +- $e" within "$v" "$e" 2.65
"$fit" --model melt --x gamma --y ls --prefix m "$tmp/melt.tsv" > "$tmp/m3.out"
check "melt: the cap defaults to the largest y (same l0 as --cap at that value)" test \
  "$(get m_l0 "$tmp/m3.out")" = "$("$fit" --model melt --cap "$(awk -F'\t' 'NR > 1 && $2 > m { m = $2 } END { print m }' "$tmp/melt.tsv")" \
     --x gamma --y ls --prefix m "$tmp/melt.tsv" | awk -F'\t' '$1 == "m_l0" { print $2 "\t" $3 }')"
summary
