#!/bin/bash
# wetgran-theory reproduces the thesis's own numbers from its analytic models (Eq. 3.1,
# 4.9-4.15, 5.1-5.13, 6.5-6.33, 7.3-7.9, A.59-A.60), its equations agree with each other where
# they must, and the tool refuses bad arguments naming them.
set -u
th=${WG_BIN:?}/wetgran-theory
. "$(dirname "$0")/checks.sh"
# v MODEL [key=value ...] OUTPUT: the value of one output
v() { local out=${!#}; "$th" "${@:1:$#-1}" | awk -F'\t' -v k="$out" '$1 == k { print $2 }'; }
# near X Y TOL: |X - Y| <= TOL + 1e-9 |Y| (the tool prints 10 significant digits)
near() { awk -v x="$1" -v y="$2" -v t="$3" 'BEGIN { d = x - y; if (d < 0) d = -d; a = y < 0 ? -y : y
  exit !(x != "" && d <= t + 1e-9 * a) }'; }
# is X CONDITION (an awk expression in x)
is() { awk -v x="$1" "BEGIN { exit !(x != \"\" && ($2)) }"; }
pi=3.14159265358979
# calc EXPR: an awk expression (p = pi) to 15 digits
calc() { awk -v p="$pi" "BEGIN { printf \"%.15g\", $1 }"; }

# --- ffgc: Eq. 3.1 ---------------------------------------------------------------------------
e=$(v ffgc dim=2 eps=1 nl=3 estar)
check "ffgc: 2D, eps = 1, three layers: E* = n_Kn/6 = 1 ($e)" near "$e" 1 1e-12
e=$(v ffgc dim=3 eps=1 nl=3 estar)
check "ffgc: 3D, eps = 1, three layers: E* = 2 ($e)" near "$e" 2 1e-12
n=$(v ffgc eps=0.8 n_c); check "ffgc: n_c(0.8) = 3.90 (Fig. 3.16b fit): $n" near "$n" 3.90 0.005
n=$(v ffgc eps=0.96 n_c); check "ffgc: n_c(0.96) = 7.77 (Fig. 3.16b fit): $n" near "$n" 7.77 0.005
e=$(v ffgc dim=3 eps=0.96 nl=3 estar)
check "ffgc: 3D, eps = 0.96: E* = 2 / 0.96^(2 n_c) = $e" near "$e" \
  "$(calc "2 / 0.96 ^ (2 * $n)")" 1e-9
e=$(v ffgc dim=2 eps=0.96 estar)
check "ffgc: 2D, eps = 0.96: $e within the thesis's f-fgc line 1.84 +- 0.09 (Fig. 3.9)" near "$e" 1.84 0.09
e=$(v ffgc dim=3 eps=0.96 nl=3.24 estar)
check "ffgc: 3D, eps = 0.96, 3.24 layers: $e within 15 % of the measured 4.36 +- 0.14 (sanity)" \
  is "$e" "x > 0.85 * 4.36 && x < 1.15 * 4.36"
e=$(v ffgc eps=0.5 nc=0 estar)
check "ffgc: a given n_c = 0 makes E* independent of eps ($e)" near "$e" 1 1e-12
"$th" ffgc eps=0.5:1:0.1 > "$tmp/ffgc.tsv"
check "ffgc: curve eps = 0.5:1:0.1 has a header and 6 rows, E* falling to 1 at eps = 1" awk -F'\t' '
  NR == 1 { ok = ($1 == "eps" && $5 == "estar"); next } { n++; if (NR > 2 && $5 >= prev) ok = 0; prev = $5; last = $1 }
  END { exit !(ok && n == 6 && last == 1 && prev == 1) }' "$tmp/ffgc.tsv"

# --- solid-fluid: Eq. 4.9-4.15, Fig. 4.4 ------------------------------------------------------
g=$(v solid-fluid estar=1 fb=7 M=4 gamma_c_415)
check "solid-fluid: Eq. 4.15 at E* = 1 gives Gamma_C = 1 ($g)" near "$g" 1 1e-12
"$th" solid-fluid M=3 estar=0.4 fb=4:16:4 > "$tmp/sf.tsv"
check "solid-fluid: Fig. 4.1's Eq. 4.15 values 1.8, 2.6, 3.4, 4.2 at F_B/mg = 4..16, E* = 0.4" awk -F'\t' '
  NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { d = $c["gamma_c_415"] - (1 + $1 * 0.6 / 3); if (d * d > 1e-20) bad = 1; n++ } END { exit !(!bad && n == 4) }' "$tmp/sf.tsv"
"$th" solid-fluid estar=0:2:0.25 fb=6 scrit=0.05 M=5 > "$tmp/sf2.tsv"
check "solid-fluid: Eq. 4.13 and 4.15 coincide when f T_g = E* E_cb; Gamma_C - Gamma_M = 1 - 1/M (Eq. 4.14)" awk -F'\t' '
  NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { d1 = $c["gamma_c"] - $c["gamma_c_415"]; d2 = $c["gamma_c"] - $c["gamma_m"] - $c["gamma_c_min"]
    if (d1 * d1 > 1e-20 || d2 * d2 > 1e-20 || $c["gamma_c_min"] != 0.8) bad = 1 } END { exit bad }' "$tmp/sf2.tsv"
args="M=4 fb=5 scrit=0.04 estar=0.3 gamma=1.5"
hc=$(v solid-fluid $args h_c)
lm=$(v solid-fluid $args h="$hc" l_m)
check "solid-fluid: l_m(h_c) = s_crit: Eq. 4.9 and 4.11 agree (h_c = $hc, l_m = $lm)" near "$lm" 0.04 1e-12
gm=$(v solid-fluid $args gamma_m); gc=$(v solid-fluid $args gamma_c)
check "solid-fluid: h_c(Gamma_M) = M and h_c(Gamma_C) = 1" bash -c \
  "$(declare -f v near); th=$th; near \$(v solid-fluid $args gamma=$gm h_c) 4 1e-12 && near \$(v solid-fluid $args gamma=$gc h_c) 1 1e-12"
tmax=$(v solid-fluid $args f=3 tg_max)
g=$(v solid-fluid $args f=3 tg="$tmax" gamma_m)
check "solid-fluid: T_g at the bound of Eq. 4.12 gives Gamma_M = 0 ($g)" near "$g" 0 1e-12
lm=$(v solid-fluid M=3 fb=4 gamma=3 h=1 l_m)
check "solid-fluid: a layer nothing holds down has l_m = inf" test "$lm" = inf
fig44="M=6 gm=1.16 gc=2.65 l0=1.27"
l=$(v solid-fluid $fig44 gamma=1.905 l_s_log)
check "solid-fluid: Fig. 4.4 fit form at mid-range: 1.27 ln 2 = $l" near "$l" "$(calc "1.27 * log(2)")" 1e-9
l=$(v solid-fluid $fig44 gamma=2.6 l_s_log)
check "solid-fluid: Fig. 4.4 fit form at Gamma = 2.6: 1.27 ln(1.49/0.05) = $l" near "$l" "$(calc "1.27 * log(1.49 / 0.05)")" 1e-9
l=$(v solid-fluid $fig44 gamma=1.905 l_s_lin)
check "solid-fluid: Fig. 4.4 red line at mid-range: (M - 1)/2 = $l" near "$l" 2.5 1e-12
check "solid-fluid: no fluid layer below Gamma_M, all M from Gamma_C on" bash -c \
  "$(declare -f v); th=$th; [ \$(v solid-fluid $fig44 gamma=1.1 l_s_log) = 0 ] && [ \$(v solid-fluid $fig44 gamma=2.7 l_s_log) = 6 ] && [ \$(v solid-fluid $fig44 gamma=2.7 l_s_lin) = 6 ]"

# --- shapes: Sec. 5.2, Eq. 5.1, 5.2 -----------------------------------------------------------
lo=$(v shapes ag_lo); hi=$(v shapes ag_hi)
check "shapes: strip window 1/pi <= a_g <= 1 - 1/pi: $lo, $hi" bash -c \
  "$(declare -f near); near $lo $(calc "1 / p") 1e-10 && near $hi $(calc "1 - 1 / p") 1e-10"
check "shapes: gas drop (1) at a_g = 0.3, strip (2) at 0.5, fluid drop (3) at 0.7" test \
  "$(v shapes ag=0.3 shape)$(v shapes ag=0.5 shape)$(v shapes ag=0.7 shape)" = 123
l=$(v shapes ag="$lo" len_drop)
check "shapes: at a_g = 1/pi the drop's interface is as long as the strip's (2): $l" near "$l" 2 1e-9
l=$(v shapes ag=1e-6 len_lens)
check "shapes: a lens of vanishing area is the flat strip (length 2): $l" near "$l" 2 1e-9
"$th" shapes ag=0.05:0.75:0.05 > "$tmp/shapes.tsv"
check "shapes: the pinched strip is never shorter than the drop of the same area" awk -F'\t' '
  NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next } $c["len_lens"] < $c["len_drop"] - 1e-12 { bad = 1 } END { exit bad }' "$tmp/shapes.tsv"
x=$(v shapes excess_lens)
xa=$(awk 'BEGIN { a = 1 / atan2(0, -1); lo = 0.1; hi = 1.5
  for (i = 0; i < 100; i++) { t = (lo + hi) / 2; s = sin(t); if ((t - s * cos(t)) / (2 * s * s) < a) lo = t; else hi = t }
  printf "%.15g", t / sin(t) - 1 }')
check "shapes: lens excess length at a = 1/pi ($x) = theta/sin(theta) - 1 by bisection ($xa)" near "$x" "$xa" 1e-9
check "shapes: the lens (0.13485) and Leung-Zia's quoted 0.1346 (Eq. 5.1) differ by < 3e-4" bash -c \
  "$(declare -f near); near $x $(v shapes excess_lz) 3e-4 && [ $(v shapes excess_lz) = 0.1346 ]"
x=$(v shapes ads=0.413 ads_err=0.013 excess_52); xe=$(v shapes ads=0.413 ads_err=0.013 excess_52_err)
check "shapes: Eq. 5.2 from a_D/S = 0.413 +- 0.013: 0.139 +- 0.018 ($x +- $xe)" bash -c \
  "$(declare -f near); near $x 0.139 0.0005 && near $xe 0.018 0.0005"

# --- interface: Eq. 5.6-5.13 ------------------------------------------------------------------
s=$(v interface np=2000 fsmax=0.01 ad=0.066 sigma)
check "interface: Eq. 5.9 sigma = N_p F_smax/((2 pi)^2 A_d) = $s" near "$s" \
  "$(calc "2000 * 0.01 / (4 * p * p * 0.066)")" 1e-9
check "interface: H_V (Eq. 5.6) = H_sigma (Eq. 5.8) at the sigma of Eq. 5.9" bash -c \
  "$(declare -f v near); th=$th; near \$(v interface np=2000 fsmax=0.01 ad=0.066 h_v) \$(v interface np=2000 fsmax=0.01 ad=0.066 h_sigma) 1e-12"
s=$(v interface ncb=3 n=1.2 scrit=0.0625 sigma_gamma)
check "interface: Eq. 5.10 sigma/gamma = (pi/6) n_cb d s_crit n^(-1/3) = $s" near "$s" \
  "$(calc "p / 6 * 3 * 0.0625 / 1.2 ^ (1 / 3)")" 1e-9
t=$(awk -v p="$pi" 'BEGIN { printf "%.15g", 1 / (4 * p * p * 0.5 * 0.2) }')
a=$(v interface a0=0.066 sigma=0.5 mu=0.2 t="$t" ad_t)
check "interface: Eq. 5.13 decays by 1/e at t = 1/((2 pi)^2 sigma mu): $a" near "$a" "$(calc "0.066 / exp(1)")" 1e-12
m=$(v interface sigma=0.5 rate="$(calc "1 / $t")" np=2000 fsmax=0.01 ad=0.066 mu_f)
check "interface: mu_f from the decay rate inverts Eq. 5.13 (0.2): $m" near "$m" 0.2 1e-9
m=$(v interface rate="$(calc "1 / $t")" np=2000 fsmax=0.01 ad=0.066 mu_f)
check "interface: without sigma, mu_f uses that of Eq. 5.9: $m" near "$m" \
  "$(calc "0.2 * 0.5 / $(v interface np=2000 fsmax=0.01 ad=0.066 sigma)")" 1e-9
check "interface: outputs whose keys are not given are nan" test "$(v interface sigma)" = nan

# --- plug: Eq. 6.5-6.33 -----------------------------------------------------------------------
roots() { "$th" plug "$@" | awk -F'\t' '$1 ~ /^lam610_/ { printf "%s=%.12f ", $1, $2 + 0 == 0 ? 0 : $2 }'; }
r=$(roots B=0)
check "plug: Eq. 6.11 at B = 0 gives Lambda = +-i ($r)" test "$r" = \
  "lam610_p_re=0.000000000000 lam610_p_im=1.000000000000 lam610_m_re=0.000000000000 lam610_m_im=-1.000000000000 "
r=$(roots B=2)
check "plug: Eq. 6.11 at B = 2 gives the double root -1 ($r)" test "$r" = \
  "lam610_p_re=-1.000000000000 lam610_p_im=0.000000000000 lam610_m_re=-1.000000000000 lam610_m_im=0.000000000000 "
check "plug: for 0 < B < 2 the roots of Eq. 6.10 lie on the unit circle (Fig. 6.8)" bash -c "
  '$th' plug B=0.1:1.9:0.3 | awk -F'\t' 'NR == 1 { for (k = 1; k <= NF; k++) c[\$k] = k; next }
    { r = \$c[\"lam610_p_re\"] ^ 2 + \$c[\"lam610_p_im\"] ^ 2; if ((r - 1) ^ 2 > 1e-20 || \$c[\"lam610_p_re\"] >= 0) bad = 1 } END { exit bad }'"
check "plug: Eq. 6.15 with A = 0 has the roots of Eq. 6.10 (0 and Lambda_pm, B = 1)" bash -c \
  "$(declare -f v near); th=$th; near \$(v plug B=1 A=0 lam615_1_re) 0 1e-12 && near \$(v plug B=1 A=0 lam615_2_im) 0.8660254038 1e-9 && near \$(v plug B=1 A=0 lam615_3_re) -0.5 1e-9"
check "plug: Eq. 6.15 with A = B = 0.7 is undamped: Lambda = +-i" bash -c \
  "$(declare -f v near); th=$th; near \$(v plug B=0.7 A=0.7 lam615_1_re) 0 1e-9 && near \$(v plug B=0.7 A=0.7 lam615_1_im) 1 1e-9"
w=$(v plug h0=10 n=1000 area=625 omega_p)
check "plug: Eq. 6.5 omega_p = sqrt(kappa g/h0 (1 + 4 N V_bead/(A_g h0))) = $w" near "$w" \
  "$(calc "sqrt(5 / 3 / 10 * (1 + 4 * 1000 * p / 6 / 6250))")" 1e-9
check "plug: Eq. 6.5 without excluded volume is the adiabatic sqrt(kappa g/h0)" bash -c \
  "$(declare -f v near); th=$th; near \$(v plug h0=7 omega_p) \$(v plug h0=7 omega_p_ad) 1e-15 && near \$(v plug h0=7 omega_p) $(calc "sqrt(5 / 21)") 1e-9"
wv=$(v plug h0=10 n=10 area=625 omega_p_vdw); w=$(v plug h0=10 n=10 area=625 omega_p)
check "plug: Eq. 6.5 is the first order of the van der Waals cushion (V_ex/V = 3e-3): $w vs $wv" \
  is "$(awk -v a="$w" -v b="$wv" 'BEGIN { print (b - a) / a }')" "x > 0 && x < 1e-5"
tr=$(v plug h0=10 hp=10 nu=0.1 theta_rt)
check "plug: theta_RT at Q = 0 is nu h0/h_p (Eq. 6.26; kappa cancels): $tr" near "$tr" 0.1 1e-12
c=$(v plug h0=10 hp=10 nu=0.1 theta="$tr" C_624); z=$(v plug h0=10 hp=10 nu=0.1 theta="$tr" lam622_1_re)
check "plug: at theta = theta_RT, C = 0 (Eq. 6.24) and Eq. 6.22 has the root 0 ($c, $z)" bash -c \
  "$(declare -f near); near $c 0 1e-12 && near $z 0 1e-9"
tc=$(v plug h0=10 hp=10 nu=0.1 theta_c)
check "plug: theta_c = kappa nu (Eq. 6.23) makes Lambda = +-i a root of Eq. 6.22" bash -c \
  "$(declare -f v near); th=$th; near $tc $(calc "5 / 3 * 0.1") 1e-12 &&
   '$th' plug h0=10 hp=10 nu=0.1 theta=$tc | awk -F'\t' '\$1 ~ /^lam622_._re/ { re = \$2 } \$1 ~ /^lam622_._im/ && (re * re < 1e-18) && ((\$2 - 1) ^ 2 < 1e-18) { f = 1 } END { exit !f }'"
g=$(v plug h0=10 hp=10 nu=0.1 theta=0 growth_621)
check "plug: alpha > 0 without a temperature gradient: an unstable zero-frequency mode (Eq. 6.21): $g" is "$g" "x > 0"
pl="h0=50 hp=5 nu=0.1 beta=0.05 theta=0.5 l=1.3"
lc=$(v plug $pl lc_627)
q=$(awk -v L="$lc" -v p="$pi" 'BEGIN { printf "%.15g", 2 * p * 1.3 / L }')
tr=$(v plug $pl Q="$q" theta_rt)
check "plug: Eq. 6.27 (prefactor sqrt(2) pi l): theta_RT at Q = 2 pi l/L_c is theta = 0.5 (L_c = $lc): $tr" near "$tr" 0.5 1e-9
"$th" plug h0=50 nu=0.1 beta=0.05 theta=0.5 l=1.3 hp=0.01:0.04:0.01 > "$tmp/lc.tsv"
check "plug: Eq. 6.28 is Eq. 6.27 to first order in h_p, both -> 2 pi l (Eq. 6.31)" awk -F'\t' -v p="$pi" '
  NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
  { d[NR] = $c["lc_627"] - $c["lc_628"]; if (($c["lc_631"] - 2 * p * 1.3) ^ 2 > 1e-18) bad = 1 }
  END { r = d[5] / d[3]; exit !(!bad && d[2] > 0 && d[2] < 1e-5 && r > 3.5 && r < 4.5) }' "$tmp/lc.tsv"
l=$(v plug hp=7 lc_633)
check "plug: Eq. 6.33 L_c = pi h_p: $l" near "$l" "$(calc "7 * p")" 1e-9
d1=$(v plug zb=6 ecb=1 dtc_629); d2=$(v plug zb=6 ecb=1 dtc_630)
check "plug: Delta T_c of Eq. 6.29 (kappa = 5/3, H = Z_b E_cb) = Eq. 6.30 = 10/9 Z_b E_cb ($d1, $d2)" bash -c \
  "$(declare -f near); near $d1 $d2 1e-12 && near $d2 $(calc "60 / 9") 1e-9"

# --- chain: Eq. 7.3-7.9 -----------------------------------------------------------------------
a=$(v chain lambda=0.4 el_a)
check "chain: Euler-Lagrange shape at lambda = 0.4 has A = 0.07384 ($a)" near "$a" 0.07384 5e-6
d=$(v chain lambda=0.4 el_dev)
check "chain: the cosine deviates from it by less than 3 % ($d)" is "$d" "x > 0 && x < 0.03"
a=$(v chain a_opt); f=$(v chain f_cmin); l=$(v chain l_chain_opt)
check "chain: A_opt = 0.1912 ($a)" near "$a" 0.1912 5e-5
check "chain: F_cmin = 0.2709 ($f)" near "$f" 0.2709 5e-5
check "chain: l_chain = 1.2970 across the system ($l)" near "$l" 1.2970 1e-4
b=$(v chain bound_printed)
check "chain: the thesis's Eq. 7.9 bound 0.9229 = 1/(4 F_cmin) ($b)" near "$b" 0.9229 2e-4
b=$(v chain bound)
check "chain: Eq. 7.9 as written, 1/F_cmin = $b" near "$b" "$(calc "1 / $f")" 1e-9
f=$(v chain a=0.07384 f_chain)
check "chain: F_chain at the Euler-Lagrange amplitude is its tension lambda = 0.4 to 1 % ($f)" near "$f" 0.4 0.004
e=$(v chain a=0.15 e_pot)
eq=$(awk -v p="$pi" 'BEGIN { A = 0.15; n = 2000; h = 0.5 / n; s = 0
  for (i = 0; i <= n; i++) { x = -0.25 + i * h; c = cos(2 * p * x); w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2)
    s += w * c * (-A * c) * sqrt(1 + (2 * p * A * sin(2 * p * x)) ^ 2) }
  printf "%.12g", s * h / 3 }')
check "chain: corrected Eq. 7.6 equals the quadrature of Eq. 7.1 for the cosine ($e vs $eq)" near "$e" "$eq" 1e-9
fd=$(awk -v e1="$(v chain a=0.1499 e_pot)" -v e2="$(v chain a=0.1501 e_pot)" -v l1="$(v chain a=0.1499 l_chain_half)" \
  -v l2="$(v chain a=0.1501 l_chain_half)" 'BEGIN { printf "%.10g", -(e2 - e1) / (l2 - l1) }')
f=$(v chain a=0.15 f_chain)
check "chain: Eq. 7.8 is -dE_pot/dl of Eq. 7.6 and 7.7 ($f vs finite difference $fd)" near "$f" "$fd" 1e-6
l=$(v chain a=1e-4 l_chain_half)
check "chain: a flat chain is half the system long over -1/4..1/4 (Eq. 7.7: $l)" near "$l" 0.5 1e-6
check "chain: the shape is -A at 0, 0 at 1/4, +A at 1/2 (the field reverses)" bash -c \
  "$(declare -f v near); th=$th; A=\$(v chain el_a); near \$(v chain x=0 y_el) -\$A 1e-12 && near \$(v chain x=0.25 y_el) 0 1e-9 && near \$(v chain x=0.5 y_el) \$A 1e-12"
check "chain: no Euler-Lagrange shape below the least tension (lambda = 0.25)" test "$(v chain lambda=0.25 el_a)" = nan
a=$(v chain lambda=0.279 el_a)
check "chain: just above the least tension (lambda = 0.279), where the two branches nearly meet, a shape is found ($a)" is "$a" "x > 0.15 && x < 0.2"

# --- a2: Eq. A.59, A.60 -----------------------------------------------------------------------
check "a2: a2 = 0 at eps_cb = 0, and a2 -> 0 (< 2e-9 at eps_cb = 1e-8)" bash -c \
  "$(declare -f v near is); th=$th; [ \$(v a2 eps_cb=0 a2) = 0 ] && is \$(v a2 eps_cb=1e-8 a2) 'x > 0 && x < 2e-9'"
for dim in 2 3; do
  "$th" a2 dim=$dim eps_cb=0.005:0.08:0.005 > "$tmp/a2.tsv"
  check "a2: d = $dim: |A.59 - A.60| < 0.2 eps_cb^3 for 0.005 <= eps_cb <= 0.08" awk -F'\t' '
    NR > 1 { d = $5 < 0 ? -$5 : $5; if (d > 0.2 * $1 ^ 3) bad = 1 } END { exit bad }' "$tmp/a2.tsv"
  r=$(awk -v a="$(v a2 dim=$dim eps_cb=0.02 a2_diff)" -v b="$(v a2 dim=$dim eps_cb=0.01 a2_diff)" 'BEGIN { print a / b }')
  check "a2: d = $dim: halving eps_cb divides the difference by ~8 (third order, up to a log): $r" is "$r" "x > 6 && x < 10"
  s=$(awk -v a="$(v a2 dim=$dim eps_cb=1e-6 a2)" -v d=$dim 'BEGIN { print a / 1e-6 * 8 * (d - 1) }')
  check "a2: d = $dim: a2/eps_cb -> 1/(8 (d - 1)) ($s)" near "$s" 1 1e-5
done
check "a2: A.59 vanishes at eps_cb = 2 (its numerator)" near "$(v a2 eps_cb=2 a2)" 0 1e-15

# --- the command line -------------------------------------------------------------------------
"$th" --help > "$tmp/help"; rc=$?
check "--help: exit 0, lists the seven models" bash -c "[ $rc -eq 0 ] && [ \$(grep -cE '^  (ffgc|solid-fluid|shapes|interface|plug|chain|a2) ' '$tmp/help') -eq 7 ]"
check "every model answers --help with its keys and outputs" bash -c "for m in ffgc solid-fluid shapes interface plug chain a2; do
  '$th' \$m --help | grep -q '^Outputs:' || exit 1; done"
check "key/value output: header 'key<TAB>value', then one row per output" bash -c \
  "'$th' a2 | head -1 | grep -qx 'key	value' && [ \$('$th' a2 | wc -l) -eq 5 ]"
"$th" bogus > /dev/null 2> "$tmp/err"; rc=$?
check "unknown model: exit 2, named" bash -c "[ $rc -eq 2 ] && grep -q \"'bogus'\" '$tmp/err'"
"$th" ffgc epss=1 > /dev/null 2> "$tmp/err"; rc=$?
check "unknown key: exit 2, named with the model's keys" bash -c "[ $rc -eq 2 ] && grep -q \"'epss'\" '$tmp/err' && grep -q 'dim, eps' '$tmp/err'"
"$th" plug h0=ten > /dev/null 2> "$tmp/err"; rc=$?
check "not a number: exit 2, argument named" bash -c "[ $rc -eq 2 ] && grep -q \"'h0=ten'\" '$tmp/err'"
"$th" chain a=0.1:0.2 > /dev/null 2> "$tmp/err"; rc=$?
check "malformed range: exit 2, argument named" bash -c "[ $rc -eq 2 ] && grep -q \"'a=0.1:0.2'\" '$tmp/err'"
"$th" ffgc eps=0.5:1:0.1 dim=2:3:1 > /dev/null 2> "$tmp/err"; rc=$?
check "two ranges: exit 2" test "$rc" -eq 2
"$th" ffgc eps=0 > /dev/null 2> "$tmp/err"; rc=$?
check "value outside the model's domain: exit 1, key and value named" bash -c "[ $rc -eq 1 ] && grep -q 'eps = 0' '$tmp/err'"
"$th" ffgc eps=0:1:0.25 > /dev/null 2> "$tmp/err"; rc=$?
check "a curve entering an invalid domain stops with exit 1" bash -c "[ $rc -eq 1 ] && grep -q 'eps = 0' '$tmp/err'"
n=$("$th" a2 eps_cb=1:0:-0.25 | awk 'NR > 1' | wc -l)
check "a negative step runs downwards (5 points from 1 to 0)" test "$n" -eq 5
# --- si: the streams paper's table in wetgran's units ------------------------------------------
m=$(v si mass); w=$(v si weight); t0=$(v si t_c_undamped)
check "si: d = 200 um glass: m = 1.047e-8 kg, m g = 102.7 nN, pi/omega0 = 10.2 us (notes-streams 1.10): $m $w $t0" \
  bash -c "$(declare -f near); near $m 1.0472e-8 1e-12 && near $w 1.0273e-7 1e-11 && near $t0 1.0166e-5 1e-9"
for pair in "0.88 2.51e4" "0.73 6.16e4" "0.40 1.73e5" "0.04 4.42e5"; do
  set -- $pair; gn=$(v si e=$1 gamma_n)
  check "si: e = $1: gamma_n = $gn 1/s against the notes' $2 (0.5 %)" awk -v a="$gn" -v b="$2" 'BEGIN { d = a / b - 1; exit !(d < 0.005 && d > -0.005) }'
done
tc=$(v si e=0.04 t_c); check "si: e = 0.04: the damped contact lasts $tc s (notes: 14.6 us)" near "$tc" 1.46e-5 1e-7
wc=$(v si w_coh); check "si: W_coh = F_coh l_c = 1e-14 J at 100 nN, 100 nm ($wc)" near "$wc" 1e-14 1e-20
# round trip: the engine's linear law k = (1/2)(pi^2 + ln^2 e) / t_contact^2 gives back k_n d / (m g)
k=$(v si e=0.6 k_scaled); tcs=$(v si e=0.6 t_contact)
kk=$(awk -v t="$tcs" 'BEGIN { l = log(0.6); printf "%.10g", 0.5 * (3.14159265358979 ^ 2 + l * l) / (t * t) }')
check "si: t_contact = $tcs makes the engine's stiffness $kk = k_n d / (m g) = $k" awk -v a="$kk" -v b="$k" 'BEGIN { d = a / b - 1; exit !(d < 1e-8 && d > -1e-8) }'

summary
