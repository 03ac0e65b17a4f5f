#!/bin/bash
# wetgran-dsmc solves the homogeneous Boltzmann equation of the white-noise-driven gas: an
# elastic gas stays Gaussian, the inelastic one meets van Noije & Ernst's first Sonine a_2
# (Granular Matter 1, 57 (1998)), the wet one the thesis's Eq. A.59 (which a Monte Carlo of
# its own integrals reproduces to 2 %); same seed, same bytes; bad arguments named.
set -u
ds=${WG_BIN:?}/wetgran-dsmc
th=${WG_BIN:?}/wetgran-theory
. "$(dirname "$0")/checks.sh"
v() { local out=${!#}; "$ds" "${@:1:$#-1}" | awk -F'\t' -v k="$out" '$1 == k { print $2 }'; }
near() { awk -v x="$1" -v y="$2" -v t="$3" 'BEGIN { d = x - y; if (d < 0) d = -d; exit !(x != "" && d <= t) }'; }
quick="n=10000 t_end=400 dt=0.05 burn=100"
[ -n "${WG_TEST_SHORT:-}" ] && quick="n=8000 t_end=300 dt=0.05 burn=100"  # sanitizers: slower

check "--help names the collision rule and the keys" bash -c "'$ds' --help | grep -q 'sqrt(u^2 - 4 E_cb)' && '$ds' --help | grep -q eps_cb"
"$ds" eps_cb=-1 2> "$tmp/e1"; rc=$?
check "eps_cb = -1 refused (exit $rc), argument named" bash -c "[ $rc -eq 2 ] && grep -q \"eps_cb=-1\" '$tmp/e1'"
"$ds" gama=1 2> "$tmp/e2"; rc=$?
check "unknown key refused (exit $rc), named" bash -c "[ $rc -eq 2 ] && grep -q gama '$tmp/e2'"
"$ds" eps=1 2> "$tmp/e3"; rc=$?
check "nothing to drive or dissipate refused (exit $rc)" bash -c "[ $rc -eq 2 ] && grep -q 'gamma > 0' '$tmp/e3'"

a=$(v $quick eps=1 gamma=0.01 a2); e=$(v $quick eps=1 gamma=0.01 a2_err)
check "elastic gas heated by the noise stays Gaussian: a_2 = $a +- $e (band 0.006)" near "$a" 0 0.006
out=$("$ds" $quick eps=0.5)
a=$(awk -F'\t' '$1 == "a2" { print $2 }' <<< "$out"); t=$(awk -F'\t' '$1 == "temperature" { print $2 }' <<< "$out")
ne=$(awk 'BEGIN { a = 0.5; d = 2; printf "%.6f", 16 * (1 - a) * (1 - 2 * a * a) / (73 + 56 * d - 24 * a * d - 105 * a + 30 * (1 - a) * a * a) }')
check "eps = 0.5, 2D: a_2 = $a vs first Sonine $ne (band 0.005; eps = 0.6 gives 0.018)" near "$a" "$ne" 0.005
check "eps = 0.5: the default gamma holds T near 1 ($t)" near "$t" 1 0.1
for x in 0.2 1; do
  out=$("$ds" $quick eps_cb=$x)
  a=$(awk -F'\t' '$1 == "a2" { print $2 }' <<< "$out"); eps=$(awk -F'\t' '$1 == "eps_cb" { print $2 }' <<< "$out")
  a59=$("$th" a2 dim=2 eps_cb=$eps | awk -F'\t' '$1 == "a2" { print $2 }')
  check "wet, eps_cb = $eps: a_2 = $a vs Eq. A.59 $a59 (band 0.005)" near "$a" "$a59" 0.005
done
a=$(v $quick eps_cb=3 a2)
check "wet, eps_cb = 3: a_2 = $a negative, as Eq. A.59's -0.027" awk -v x="$a" 'BEGIN { exit !(x < -0.015) }'
"$ds" n=2000 t_end=50 burn=10 eps_cb=0.5 > "$tmp/r1"; "$ds" n=2000 t_end=50 burn=10 eps_cb=0.5 > "$tmp/r2"
"$ds" n=2000 t_end=50 burn=10 eps_cb=0.5 seed=2 > "$tmp/r3"
check "same seed, same output" cmp -s "$tmp/r1" "$tmp/r2"
check "another seed, another output" bash -c "! cmp -s '$tmp/r1' '$tmp/r3'"
summary
