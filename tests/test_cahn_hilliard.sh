#!/bin/bash
# wetgran-cahn-hilliard (the layering paper's Eq. 1-4): mass conserved to round-off with shear;
# one step multiplies a small mode by the scheme's own gain; small modes grow at the analytic
# rate M k^2 (K c_o (1 - c_o) - kappa k^2) and change sign at k_c = sqrt(K / (4 kappa)); the
# free energy never rises without shear; a single well (K < 0) smooths any noise away; the
# shear advects a mode as the exact solution cos(x - (z - lz/2) t) says; same arguments, same
# bytes; bad arguments refused.
set -u
ch=${WG_BIN:?}/wetgran-cahn-hilliard
. "$(dirname "$0")/checks.sh"
pi=3.14159265358979
# col FILE NAME: the series column NAME, one value per line
col() { "$ch" series "$1" | awk -F'\t' -v k="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == k) c = i; next } { print $c }'; }

check "--help names the equation and the modes" bash -c "'$ch' --help | grep -q 'kappa lap c' && '$ch' --help | grep -q profile"
"$ch" run kapa=1 -o "$tmp/x.h5" 2> "$tmp/e1"; rc=$?
check "unknown key refused (exit $rc), named" bash -c "[ $rc -eq 2 ] && grep -q kapa '$tmp/e1' && [ ! -e '$tmp/x.h5' ]"
"$ch" run nz=20.5 -o "$tmp/x.h5" 2> "$tmp/e2"; rc=$?
check "non-integer grid refused (exit $rc)" bash -c "[ $rc -eq 2 ] && grep -q 'whole number' '$tmp/e2'"
"$ch" run t_end=1 2> "$tmp/e3"; rc=$?
check "no output file refused (exit $rc)" bash -c "[ $rc -eq 2 ] && grep -q -- '-o' '$tmp/e3'"
"$ch" series "$tmp/none.h5" 2> "$tmp/e4"; rc=$?
check "series of a missing file: non-zero exit, file named" bash -c "[ $rc -ne 0 ] && grep -q none.h5 '$tmp/e4'"

# mass, 2D with the paper's shear, from noise; the layers form
"$ch" run nx=32 nz=32 t_end=8 dt=2e-3 -q -o "$tmp/m.h5" > "$tmp/m.out"
d=$(grep -o 'mass_drift=[^ ]*' "$tmp/m.out" | cut -d= -f2)
check "2D with shear: mean c conserved to round-off (drift $d over 4000 steps)" awk -v d="$d" 'BEGIN { if (d < 0) d = -d; exit !(d != "" && d < 1e-12) }'
g=$(col "$tmp/m.h5" grad2 | awk 'NR == 1 { a = $1 } { b = $1 } END { print b / a }')
l=$(col "$tmp/m.h5" layers | tail -1)
check "2D with shear: <|grad c|^2> grows $g-fold from the noise (> 20) as $l layers form (k_c = 2.99)" \
  awk -v g="$g" -v l="$l" 'BEGIN { exit !(g > 20 && l >= 2 && l <= 4) }'

# one step's gain of a small mode against the scheme's formula (K = 25, kappa = 0.7, S = 50, M = 1)
for m in 4 8; do
  "$ch" run init=1 amp=1e-8 mode_z=$m mobility=1 t_end=1e-3 dt=1e-3 dt_series=1e-3 -q -o "$tmp/g.h5" > /dev/null
  r=$(col "$tmp/g.h5" amplitude | awk 'NR == 1 { a = $1 } NR == 2 { printf "%.12f", $1 / a }')
  f=$(awk -v m=$m 'BEGIN { K = 25; ka = 0.7; S = 50; dt = 1e-3; k2 = (m / 2) ^ 2; fpp = -K / 4
    printf "%.12f", (1 + dt * k2 * (S - fpp)) / (1 + dt * k2 * (S + ka * k2)) }')
  check "mode k = $((m / 2)): one step's gain $r = the scheme's $f (1e-8)" awk -v a="$r" -v b="$f" 'BEGIN { d = a - b; exit !(d < 1e-8 && d > -1e-8) }'
done
# the growth rate of the equation itself (dt 1e-6: the scheme's error below 1e-3)
for m in 2 4 5 6 8; do
  "$ch" run init=1 amp=1e-8 mode_z=$m mobility=1 t_end=2e-3 dt=1e-6 dt_series=2e-3 -q -o "$tmp/s.h5" > /dev/null
  s=$(col "$tmp/s.h5" amplitude | awk 'NR == 1 { a = $1 } END { printf "%.6f", log($1 / a) / 2e-3 }')
  e=$(awk -v m=$m 'BEGIN { k2 = (m / 2) ^ 2; printf "%.6f", k2 * (25 / 4 - 0.7 * k2) }')
  check "k = $(awk -v m=$m 'BEGIN { print m / 2 }'): growth rate $s against M k^2 (K/4 - kappa k^2) = $e (2e-3)" \
    awk -v a="$s" -v b="$e" 'BEGIN { d = a - b; if (d < 0) d = -d; s = b < 0 ? -b : b; exit !(d <= 2e-3 * s + 1e-9) }'
done
# k_c = sqrt(K / (4 kappa)): k = 3 grows for kappa = 0.69 (k_c = 3.01), decays for 0.70 (2.99)
for ka in 0.69 0.70; do
  "$ch" run init=1 amp=1e-8 mode_z=6 kappa=$ka mobility=1 t_end=0.5 dt=1e-4 dt_series=0.5 -q -o "$tmp/k$ka.h5" > /dev/null
done
u=$(col "$tmp/k0.69.h5" amplitude | tail -1); v=$(col "$tmp/k0.70.h5" amplitude | tail -1)
check "k = 3 grows at k_c = 3.01 ($u > 1e-8) and decays at k_c = 2.99 ($v < 1e-8)" \
  awk -v u="$u" -v v="$v" 'BEGIN { exit !(u > 1e-8 && v < 1e-8) }'

# no shear: the free energy never rises (2D, from noise; S = 2 K by default)
"$ch" run nx=32 nz=32 shear=0 amp=0.2 t_end=5 dt=2e-3 dt_series=2e-3 -q -o "$tmp/f.h5" > /dev/null
r=$(col "$tmp/f.h5" free_energy | awk 'NR > 1 && $1 > prev + 1e-13 { up++ } { prev = $1 } END { print up + 0, NR }')
check "without shear the free energy never rises (rises, samples: $r)" bash -c "[ '${r%% *}' = 0 ]"
# a single well (K < 0): noise decays
"$ch" run nz=64 K=-5 amp=0.1 mobility=1 t_end=5 dt=1e-3 -q -o "$tmp/w.h5" > /dev/null
g=$(col "$tmp/w.h5" grad2 | awk 'NR == 1 { a = $1 } { b = $1 } END { print b / a }')
check "K < 0 (one well): <|grad c|^2> falls to $g of the noise's (< 1e-6)" awk -v g="$g" 'BEGIN { exit !(g < 1e-6) }'

# advection: with M -> 0 the mode cos(x) becomes cos(x - (z - pi) t), whose (1, 0) amplitude is
# sin(pi t)/(pi t)
"$ch" run nx=64 nz=64 init=1 amp=1 mode_x=1 mode_z=0 mobility=1e-9 K=1 kappa=1 S=0 t_end=0.5 dt=1e-4 \
  dt_series=0.5 -q -o "$tmp/a.h5" > /dev/null
a=$(col "$tmp/a.h5" amplitude | tail -1)
check "shear alone: amplitude $a at strain 0.5 against sin(pi t)/(pi t) = 2/pi (first order in dt: 2e-4)" \
  awk -v a="$a" -v p=$pi 'BEGIN { d = a - 2 / p; if (d < 0) d = -d; exit !(d < 2e-4) }'

# reproducible: the same arguments give the same file
"$ch" run nx=16 nz=32 t_end=1 seed=3 -q -o "$tmp/r1.h5" > /dev/null
"$ch" run nx=16 nz=32 t_end=1 seed=3 -q -o "$tmp/r2.h5" > /dev/null
check "same arguments, same bytes" cmp -s "$tmp/r1.h5" "$tmp/r2.h5"
"$ch" profile "$tmp/r1.h5" > "$tmp/p"
check "profile: 32 rows of z and c, z = (iz + 1/2) lz / nz" bash -c "[ \$(grep -vc '^[#z]' '$tmp/p') = 32 ] && awk 'NR == 3 { exit !(\$1 > 0.098 && \$1 < 0.0983) }' '$tmp/p'"
summary
