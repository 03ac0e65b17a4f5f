#!/bin/bash
# wetgran-interface on synthetic run files with known answers (tests/interface_synth.py): a 2D
# gas stretch of known length, a 3D gas disk and fluid disk of known area split over the
# periodic corner, a strip with a cosine edge of known amplitude (and one decaying in time),
# then one short real run; bad input names the file and the dataset.
set -u
tool=${WG_BIN:?}/wetgran-interface
synth="/usr/bin/python3 ${WG_TESTS:?}/interface_synth.py"
. "$(dirname "$0")/checks.sh"
# col NAME FILE [ROW]: the value of column NAME in data row ROW (default 1) of a table whose
# header starts with 'file' (comment lines skipped)
col() { awk -F'\t' -v c="$1" -v r="${3:-1}" '/^#/ { next } $1 == "file" && !h { for (i = 1; i <= NF; i++) k[$i] = i; h = 1; next } h && ++n == r { print $k[c]; exit }' "$2"; }
# value KEY FILE: the value of row KEY of a key/value/error table
value() { awk -F'\t' -v k="$1" '$1 == k { print $2; exit }' "$2"; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a == a + 0 && d <= t) }'; }
export -f near

check "--help names the modes and the thresholds" \
  bash -c "'$tool' --help | grep -q 'powerfit' && '$tool' --help | grep -q Otsu && '$tool' --help | grep -q 'Eq. 5.9'"

# (1) 2D profile: 100 bins, gas in [20, 60): a_g = 0.4, one gas and one dense component; the
# same stretch across the periodic boundary ([80, 100) + [0, 20)) is one component, not two
$synth profile2d "$tmp/p.h5" && $synth profile2d "$tmp/pw.h5" g0=80 g1=20
"$tool" ag "$tmp/p.h5" "$tmp/pw.h5" > "$tmp/p.out" 2> "$tmp/p.err"; rc=$?
check "profile 2D: exit 0, nothing on stderr" bash -c "[ $rc -eq 0 ] && [ ! -s '$tmp/p.err' ]"
check "profile 2D: a '# threshold' line with Otsu's cut between 3 and 50 E_cb" \
  bash -c "grep -q '^# threshold T_g/E_cb = ' '$tmp/p.out' && near \$(sed -n 's/^# threshold T_g\/E_cb = \([0-9.]*\).*/\1/p' '$tmp/p.out') 12.25 0.01"
check "profile 2D: a_g = 0.4 exactly" test "$(col a_g "$tmp/p.out")" = 0.4
check "profile 2D: one gas, one dense component, shape plug" \
  test "$(col n_gas "$tmp/p.out") $(col n_dense "$tmp/p.out") $(col shape "$tmp/p.out")" = "1 1 plug"
check "periodic 2D: the gas across x = 0 is one component, a_g = 0.4" \
  test "$(col n_gas "$tmp/p.out" 2) $(col a_g "$tmp/p.out" 2)" = "1 0.4"
"$tool" ag --ends 8:12 "$tmp/p.h5" "$tmp/pw.h5" > "$tmp/pe.out"
check "--ends 8:12: estar 10 gives estar_tilde 0.5" test "$(col estar_tilde "$tmp/pe.out")" = 0.5
"$tool" ag --field density --source profile "$tmp/p.h5" > "$tmp/pd.out"
check "--field density: the dilute class is the gas, a_g = 0.4" test "$(col a_g "$tmp/pd.out")" = 0.4
"$tool" ag "$tmp/p.h5" --t-fg 100 > /dev/null 2> "$tmp/one.err"
check "--t-fg 100 (above every cell): a_g = 0, shape f" \
  test "$("$tool" ag --t-fg 100 "$tmp/p.h5" | awk -F'\t' '!/^#/ && $1 != "file" { print $5, $9 }')" = "0 f"

"$tool" ag --h5 "$tmp/ag.h5" "$tmp/p.h5" "$tmp/pw.h5" > /dev/null
check "--h5: /ag/a_g = [0.4, 0.4], run names and shapes as attributes, the threshold" \
  bash -c "/usr/bin/python3 -c \"import h5py; f = h5py.File('$tmp/ag.h5', 'r'); g = f['ag']; assert list(g['a_g'][()]) == [0.4, 0.4]; assert [s.decode() for s in g.attrs['shape']] == ['plug', 'plug']; assert g.attrs['file'][1].decode().endswith('pw.h5'); assert abs(g.attrs['threshold'] - 12.247) < 0.01\" && [ ! -e '$tmp/ag.h5.tmp' ]"

# --ends auto: fluid at E* = 4, 6, coexistence at 8, 10, gas at 12: ends 7 +- 1 and 11 +- 1
for e in 4 6; do $synth profile2d "$tmp/e$e.h5" estar=$e g0=20 g1=20; done
for e in 8 10; do $synth profile2d "$tmp/e$e.h5" estar=$e; done
$synth profile2d "$tmp/e12.h5" estar=12 g0=0 g1=99.999
"$tool" ag --ends auto "$tmp"/e4.h5 "$tmp"/e6.h5 "$tmp"/e8.h5 "$tmp"/e10.h5 "$tmp"/e12.h5 > "$tmp/auto.out"
check "--ends auto: the ends from the scan, 7 +- 1 and 11 +- 1" \
  grep -q '^# ends from the scan: E\*_f-fgc = 7 +- 1, E\*_fgc-g = 11 +- 1$' "$tmp/auto.out"
check "--ends auto: E* = 8 gives estar_tilde 0.25, E* = 12 gives 1.25" \
  test "$(col estar_tilde "$tmp/auto.out" 3) $(col estar_tilde "$tmp/auto.out" 5)" = "0.25 1.25"
"$tool" ag --ends auto "$tmp"/e8.h5 "$tmp"/e10.h5 "$tmp"/e12.h5 > "$tmp/auto1.out" 2> "$tmp/auto.err"; rc=$?
check "--ends auto without a fluid run below the coexistence: E*_f-fgc nan, said on stderr, the gas end still 11 +- 1" \
  bash -c "[ $rc -eq 0 ] && grep -q 'no fluid run (a_g = 0) below E\* = 8: E\*_f-fgc is nan' '$tmp/auto.err' && grep -q '^# ends from the scan: E\*_f-fgc = nan +- nan, E\*_fgc-g = 11 +- 1$' '$tmp/auto1.out'"
check "--ends auto without a fluid run: estar_tilde nan" test "$(col estar_tilde "$tmp/auto1.out")" = nan
"$tool" ag --ends auto "$tmp"/e4.h5 "$tmp"/e12.h5 > /dev/null 2> "$tmp/auto3.err"; rc=$?
check "--ends auto with no coexisting run: refused" \
  bash -c "[ $rc -ne 0 ] && grep -q 'no coexisting run' '$tmp/auto3.err'"
"$tool" ag --ends auto --window 10 "$tmp"/e8.h5 > /dev/null 2> "$tmp/auto2.err"; rc=$?
check "--ends auto with --window: refused (exit 2)" test "$rc" -eq 2

# (2) 2D snapshots: lx = 100, gas in [30, 70) on 40 cells: a_g = 0.4 from particles
$synth snap2d "$tmp/s.h5"
"$tool" ag --bins 40 "$tmp/s.h5" > "$tmp/s.out"
check "snapshots 2D: a_g = 0.4 from the coarse-grained T_g" test "$(col a_g "$tmp/s.out")" = 0.4
"$tool" field --bins 40 "$tmp/s.h5" > "$tmp/sf.out"
check "field: 40 cells, gas cells exactly those with 30 < x < 70" \
  bash -c "[ \$(awk -F'\t' '!/^#/ && \$1 != \"file\"' '$tmp/sf.out' | wc -l) -eq 40 ] && awk -F'\t' '!/^#/ && \$1 != \"file\" && ((\$8 == \"g\") != (\$2 > 30 && \$2 < 70)) { bad++ } END { exit bad > 0 }' '$tmp/sf.out'"
check "field: fluid cells hold 16 particles per d (lattice 1/4 d), gas cells 4; n_cb 24 and 0" \
  bash -c "awk -F'\t' '!/^#/ && \$1 != \"file\" && !((\$8 == \"g\" && \$4 == 4 && \$5 == 0) || (\$8 == \"f\" && \$4 == 16 && \$5 == 24)) { bad++ } END { exit bad > 0 }' '$tmp/sf.out'"

# --window: a gas stretch growing by 10 d a frame (frames every 10 t.u.): one row per window
$synth snap2d "$tmp/grow.h5" grow=10
"$tool" ag --bins 40 --window 10 "$tmp/grow.h5" > "$tmp/grow.out"
check "--window 10: four windows, a_g = 0.4 0.5 0.6 0.7, t_from = 0 10 20 30" \
  test "$(awk -F'\t' '!/^#/ && $1 != "file" { printf "%s/%s ", $5, $12 }' "$tmp/grow.out")" = "0.4/0 0.5/10 0.6/20 0.7/30 "
"$tool" ag --bins 40 --window 20 --from 0 "$tmp/grow.h5" > "$tmp/grow2.out"
check "--window 20: two windows of two snapshots each (t_from/t_to 0/10, 20/30)" \
  test "$(awk -F'\t' '!/^#/ && $1 != "file" { printf "%s/%s ", $12, $13 }' "$tmp/grow2.out")" = "0/10 20/30 "

# (3) 3D disks split over the periodic corner (centre 0, 0) on a 30 x 30 grid of 2 d cells:
# gas disk r = 15 (a_g = pi 15^2 / 60^2 = 0.196, class I, r_eq 15); fluid disk r = 20 in the
# middle (a_g = 1 - pi 20^2 / 60^2 = 0.651, class III, r_eq 20); within the cells' resolution
$synth disk3d "$tmp/d.h5" && $synth disk3d "$tmp/f.h5" inside=fluid r=20 cx=30 cy=30
"$tool" ag --bins 30x30 "$tmp/d.h5" "$tmp/f.h5" > "$tmp/d.out"
check "gas disk: a_g = $(col a_g "$tmp/d.out") within 0.02 of 0.196" near "$(col a_g "$tmp/d.out")" 0.19635 0.02
check "gas disk over the periodic corner: one gas component, shape I" \
  test "$(col n_gas "$tmp/d.out") $(col shape "$tmp/d.out")" = "1 I"
check "gas disk: r_eq = $(col r_eq "$tmp/d.out") within 1 d of 15" near "$(col r_eq "$tmp/d.out")" 15 1
check "fluid disk: a_g = $(col a_g "$tmp/d.out" 2) within 0.02 of 0.651, shape III" \
  bash -c "near '$(col a_g "$tmp/d.out" 2)' 0.6509 0.02 && [ '$(col shape "$tmp/d.out" 2)' = III ]"
check "fluid disk: r_eq = $(col r_eq "$tmp/d.out" 2) within 1 d of 20" near "$(col r_eq "$tmp/d.out" 2)" 20 1

# (4) a strip along x, width 36, edges 48 -/+ 18 + 6 cos(2 pi x / 96): A~_d = 6/96 = 0.0625;
# a_g = 1 - 36/96 = 0.625, shape II; the same strip centred on y = 0 (across the boundary)
$synth strip3d "$tmp/st.h5" && $synth strip3d "$tmp/st0.h5" c=0
"$tool" ag --bins 48x48 "$tmp/st.h5" "$tmp/st0.h5" > "$tmp/st.ag"
check "strip: a_g = $(col a_g "$tmp/st.ag") within 0.02 of 0.625, shape II (both)" \
  bash -c "near '$(col a_g "$tmp/st.ag")' 0.625 0.02 && [ '$(col shape "$tmp/st.ag") $(col shape "$tmp/st.ag" 2)' = 'II II' ]"
"$tool" strip --bins 48x48 --fsmax 0.01 "$tmp/st.h5" > "$tmp/st.out"
ad=$(value ad_tilde "$tmp/st.out")
check "strip: A~_d = $ad within 1/96 (half a cell over L) of 0.0625" near "$ad" 0.0625 0.0105
np=$(value n_p "$tmp/st.out")
check "strip: N_p = $np, the fluid's 36 x 96 x 4 = 13824 particles within a row of cells" near "$np" 13824 800
check "strip: sigma = N_p F_smax / ((2 pi)^2 A~_d) (Eq. 5.9)" \
  near "$(value sigma "$tmp/st.out")" "$(awk -v n="$np" -v a="$ad" 'BEGIN { print n * 0.01 / (4 * 3.14159265358979 ^ 2 * a) }')" 0.01
check "strip: sigma/gamma = sigma pi / F_B (F_B = 4)" \
  near "$(value sigma_over_gamma "$tmp/st.out")" "$(awk -v s="$(value sigma "$tmp/st.out")" 'BEGIN { print s * 3.14159265358979 / 4 }')" 0.01
check "strip: sigma_area_over_gamma = sigma_over_gamma / height (8)" \
  near "$(value sigma_area_over_gamma "$tmp/st.out")" "$(awk -v s="$(value sigma_over_gamma "$tmp/st.out")" 'BEGIN { print s / 8 }')" 0.001
# Eq. 5.10 from the fluid's densities: 3 bridge ends a particle (n_cb = 1.5 n), n = 4 / d^2 over
# the height 8: (pi/6) n_cb s_crit n^(-1/3) = (pi/6) 0.75 0.0711 2^(1/3) = 0.0352
check "strip: Eq. 5.10 estimate $(value eq5_10_sigma_over_gamma "$tmp/st.out") within 3 % of 0.0352" \
  near "$(value eq5_10_sigma_over_gamma "$tmp/st.out")" 0.03519 0.001
"$tool" strip --bins 48x48 "$tmp/st0.h5" > "$tmp/st0.out"
check "strip across y = 0: A~_d = $(value ad_tilde "$tmp/st0.out") within 1/96 of 0.0625" \
  near "$(value ad_tilde "$tmp/st0.out")" 0.0625 0.0105
"$tool" strip --bins 48x48 "$tmp/d.h5" > /dev/null 2> "$tmp/nostrip.err"; rc=$?
check "strip on a drop: refused, naming the file" bash -c "[ $rc -eq 1 ] && grep -q 'd.h5: no strip along x to trace (shape I, not II)' '$tmp/nostrip.err'"

# (5) relaxation: three seeds, amplitude 8 exp(-t / 50) in frames every 10 t.u.; tau = 50
for s in 1 2 3; do $synth strip3d "$tmp/r$s.h5" a=8 tau=50 frames=8 seed=$s; done
"$tool" relax --bins 48x48 --t-fg 27 --sigma 2 "$tmp"/r[123].h5 > "$tmp/r.out"
tau=$(sed -n 's/.*tau = \([0-9.e+-]*\) +-.*/\1/p' "$tmp/r.out")
check "relax: 8 times, each averaged over 3 seeds" \
  bash -c "[ \$(awk -F'\t' '!/^#/ && \$1 != \"t\" && \$4 == 3' '$tmp/r.out' | wc -l) -eq 8 ]"
check "relax: tau = $tau within 20 % of 50" near "$tau" 50 10
mu=$(sed -n 's/^# mu_f = .* = \([0-9.e+-]*\) +-.*/\1/p' "$tmp/r.out")
check "relax: mu_f = 1 / ((2 pi)^2 sigma tau) (Eq. 5.13)" \
  near "$mu" "$(awk -v t="$tau" 'BEGIN { print 1 / (4 * 3.14159265358979 ^ 2 * 2 * t) }')" 1e-5

$synth strip3d "$tmp/r4.h5" a=8 tau=50 frames=3
"$tool" relax --bins 48x48 --t-fg 27 "$tmp"/r1.h5 "$tmp/r4.h5" > /dev/null 2> "$tmp/r.err"; rc=$?
check "relax: a seed with fewer snapshots is refused, naming it and the dataset" \
  bash -c "[ $rc -eq 1 ] && grep -q 'r4.h5: /particles/all/position/value: no snapshot 3 (3 snapshots)' '$tmp/r.err'"

# (6) powerfit on y = 0.72 x^0.32 exactly, plus points outside (0, 1] that must be left out
awk 'BEGIN { print "x\ty"; print "-0.2\t0"; print "1.2\t1"; for (i = 1; i <= 8; i++) { x = i / 8; printf "%g\t%.12g\n", x, 0.72 * x ^ 0.32 } }' > "$tmp/pow.tsv"
"$tool" powerfit --x x --y y "$tmp/pow.tsv" > "$tmp/pow.out"
check "powerfit: a = 0.72, beta = 0.32, 8 points" \
  bash -c "near \$(awk '\$1 == \"a\" { print \$2 }' '$tmp/pow.out') 0.72 1e-5 && near \$(awk '\$1 == \"beta\" { print \$2 }' '$tmp/pow.out') 0.32 1e-5 && [ \$(awk '\$1 == \"n\" { print \$2 }' '$tmp/pow.out') = 8 ]"

# (7) one short real run (fig5_2b quick's system, E* = 10: coexistence), with snapshots:
# a_g from the profile and from the snapshots' field agree within 0.1 and lie inside (0, 1)
"$WG_BIN/wetgran-run" "$WG_TESTS/../sim/scenes/shake2d.ini" n=300 lx=100 gamma=8 estar=10 eps=0.8 t_end=400 \
  profile_start=200 profile_bins=50 dt_profile=1 dt_series=1 dt_snapshot=10 dt_checkpoint=0 -q -o "$tmp/real.h5" 2> /dev/null
"$tool" ag "$tmp/real.h5" > "$tmp/real.p" && "$tool" ag --source snapshots --from 200 --bins 50 "$tmp/real.h5" > "$tmp/real.s"
a1=$(col a_g "$tmp/real.p"); a2=$(col a_g "$tmp/real.s")
check "real run: a_g from the profile ($a1) and the snapshots ($a2) agree within 0.1, inside (0, 1)" \
  bash -c "near '$a1' '$a2' 0.1 && awk -v a='$a1' 'BEGIN { exit !(a > 0.2 && a < 0.8) }'"
check "real run: one gas stretch, shape plug" test "$(col n_gas "$tmp/real.p") $(col shape "$tmp/real.p")" = "1 plug"
"$tool" spacetime --bins 25 --from 300 "$tmp/real.h5" > "$tmp/st.map"
check "spacetime: 11 snapshots (t = 300 ... 400) x 25 cells" \
  test "$(awk -F'\t' 'NF == 4 && $1 != "t"' "$tmp/st.map" | wc -l)" = 275
check "spacetime: densities average to N / L_x = 3 per snapshot" \
  bash -c "awk -F'\t' 'NF == 4 && \$1 != \"t\" { s[\$1] += \$3; n[\$1]++ } END { for (t in s) if ((s[t] / n[t] - 3) ^ 2 > 1e-9) bad++; exit bad > 0 }' '$tmp/st.map'"

# (8) bad input: one line naming the file (and the dataset), exit 1; bad options exit 2
"$WG_BIN/wetgran-run" "$WG_TESTS/../sim/scenes/shake2d.ini" n=50 lx=20 t_end=2 profile_bins=0 profile_start=0 dt_series=1 dt_checkpoint=0 -q -o "$tmp/noprof.h5" 2> /dev/null
"$tool" ag --source profile "$tmp/noprof.h5" > /dev/null 2> "$tmp/e1"; rc=$?
check "no profiles: exit 1, names the file and /observables/profiles/x" \
  bash -c "[ $rc -eq 1 ] && [ \$(wc -l < '$tmp/e1') -eq 1 ] && grep -q 'noprof.h5: no dataset /observables/profiles/x' '$tmp/e1'"
cp "$tmp/p.h5" "$tmp/nosnap.h5"
"$tool" ag --source snapshots "$tmp/nosnap.h5" > /dev/null 2> "$tmp/e2"; rc=$?
check "no snapshots: exit 1, names the file and /particles/all/position/value" \
  bash -c "[ $rc -eq 1 ] && grep -q 'nosnap.h5: no dataset /particles/all/position/value' '$tmp/e2'"
/usr/bin/python3 -c "import h5py; f = h5py.File('$tmp/noecb.h5', 'w'); f.create_group('h5md'); f.create_group('parameters')"
"$tool" ag "$tmp/noecb.h5" > /dev/null 2> "$tmp/e3"; rc=$?
check "no e_cb: exit 1, names the file and the parameter" \
  bash -c "[ $rc -eq 1 ] && grep -q 'noecb.h5: no parameter e_cb in /parameters' '$tmp/e3'"
"$tool" ag "$tmp/missing.h5" > /dev/null 2> "$tmp/e4"; rc=$?
check "missing file: exit 1, one line naming it" bash -c "[ $rc -eq 1 ] && grep -q 'missing.h5: no such file' '$tmp/e4'"
$synth profile2d "$tmp/flat.h5" g0=0 g1=0
"$tool" ag "$tmp/flat.h5" > /dev/null 2> "$tmp/e6"; rc=$?
check "a field of one phase: refused (exit 1), naming the file, unless --t-fg" \
  bash -c "[ $rc -eq 1 ] && grep -q 'flat.h5: the cells.* form one class' '$tmp/e6' && '$tool' ag --t-fg 12 '$tmp/flat.h5' | grep -q 'f	'"
"$tool" bogus "$tmp/p.h5" 2> "$tmp/e7"; rc=$?
check "unknown mode: exit 2, names it" bash -c "[ $rc -eq 2 ] && grep -q \"unknown mode 'bogus'\" '$tmp/e7'"
"$tool" ag --bins 2x "$tmp/p.h5" 2> /dev/null; rc=$?
check "--bins 2x: exit 2" test $rc -eq 2
"$tool" ag --ends 8 "$tmp/p.h5" 2> /dev/null; rc=$?
check "--ends without ':': exit 2" test $rc -eq 2
"$tool" powerfit --x nope --y y "$tmp/pow.tsv" 2> "$tmp/e8"; rc=$?
check "powerfit: a missing column is named with file and line" \
  bash -c "[ $rc -eq 1 ] && grep -q \"pow.tsv:1: no column 'nope'\" '$tmp/e8'"
# (9) coarsening modes on synthetic maps with known answers.
# plug: two runs whose plugs move by +/- 2 k^0.65 d at frame k (t = k T_driv), one across
# x = 400: the MSD is 4 k^1.3 d^2 exactly, up to the 0.1 d cells
$synth plugwalk "$tmp/w1.h5" && $synth plugwalk "$tmp/w2.h5" sign=-1
"$tool" plug "$tmp/w1.h5" "$tmp/w2.h5" > "$tmp/w.out"
fitline=$(grep '^# fit msd' "$tmp/w.out")
alpha=$(sed -n 's/.*alpha = \([^ ]*\) .*/\1/p' <<< "$fitline"); dxf=$(sed -n 's/.*D_x = \([^ ]*\) .*/\1/p' <<< "$fitline")
check "plug: alpha = 1.3 ($alpha) and D_x = 4/400^2 = 2.5e-5 ($dxf) from |x(t) - x(0)| = 2 (t/T_driv)^0.65" \
  bash -c "near '$alpha' 1.3 0.005 && near '$dxf' 2.5e-5 2e-7"
check "plug: the MSD at lag 59 periods is 4 * 59^1.3 d^2 within 0.1 d of displacement" \
  bash -c "awk -F'\t' '\$2 == 59 { m = \$3 } END { e = 4 * 59 ^ 1.3; d = 2 * sqrt(e); exit !(m - e < 0.1 * d + 0.01 && e - m < 0.1 * d + 0.01) }' '$tmp/w.out'"
"$tool" plug "$tmp/w1.h5" --tracks > "$tmp/wt.out"
check "--help names the coarsening modes" bash -c "'$tool' --help | grep -q '^  droplets' && '$tool' --help | grep -q '^  domains' && '$tool' --help | grep -q '^  plug'"
check "plug --tracks: the centre is unwrapped across x = 400 (350 + 2 * 59^0.65) and the width stays 100 d" \
  bash -c "awk -F'\t' '!/^#/ && \$1 != \"file\" { x = \$4; w = \$6 - \$5; if ((w - 100) ^ 2 > 0.04) bad++ } END { e = 350 + 2 * 59 ^ 0.65; exit !(!bad && (x - e) ^ 2 < 0.01) }' '$tmp/wt.out'"
"$tool" plug --xmin 10 --xmax 30 "$tmp/w1.h5" "$tmp/w2.h5" | grep -q '^# fit .* over 10 < t/T_driv <= 30 (20 frames, 2 runs)'
check "plug: --xmin/--xmax set the fit window, which the fit line reports" test $? -eq 0
$synth plugwalk "$tmp/w3.h5" frames=30
"$tool" plug "$tmp/w1.h5" "$tmp/w3.h5" > /dev/null 2> "$tmp/we"; rc=$?
check "plug: runs with other frames are refused (exit 1), naming both files" \
  bash -c "[ $rc -eq 1 ] && grep -q 'w3.h5: 30 frames.*w1.h5 has 60' '$tmp/we'"
"$tool" plug "$tmp/p.h5" > /dev/null 2> "$tmp/we2"; rc=$?
check "plug: a run without maps or snapshots frames is refused (exit 1)" test $rc -eq 1
# droplets: counts 2,4,8,8,8,7,...,2,2,2,4,4,4 with T_g = (8/N)^2 E_cb: nucleation to the
# maximum at t = 20, coalescence to t = 120, N_f = 8 (T_g/E_cb)^(-1/2) with exponent -1/2
$synth droplets2d "$tmp/dr.h5"
"$tool" droplets --field density --smooth 1 "$tmp/dr.h5" > "$tmp/dr.out"
check "droplets: N_f per frame as built (2 4 8 8 8 7 6 5 4 3 2 2 2 4 4 4)" \
  test "$(awk -F'\t' '!/^#/ && $1 != "file" { printf "%s ", $4 }' "$tmp/dr.out")" = "2 4 8 8 8 7 6 5 4 3 2 2 2 4 4 4 "
check "droplets: the regimes: nucleation to t0 = 20 (maximum 8), coalescence to t1 = 120 (the last 2 before 4)" \
  grep -q 'nucleation to t0 = 20 (N_f reaches its maximum 8), coalescence to t1 = 120 (N_f 2, rising after' "$tmp/dr.out"
check "droplets: N_f = 8 (T_g/E_cb)^(-1/2) over the coalescence, free exponent -0.5" \
  grep -q 'N_f = 8 (T_g/E_cb)^(-1/2); free fit N_f ~ (T_g/E_cb)^-0.5 ' "$tmp/dr.out"
check "droplets: equally spaced, mean spacing L/N (8 droplets: 125 d) and positions" \
  bash -c "awk -F'\t' '\$2 == 20 { exit !(\$8 == 125 && \$9 ~ /^62.5,187.5,/) }' '$tmp/dr.out'"
"$tool" droplets --field density --smooth 1 --spacing 60:80 "$tmp/dr.h5" | grep -q 'spacing of adjacent droplets over t in \[60, 80\]: mean 200 d, sd 34.5, median 200, 15 gaps'
check "droplets: --spacing A:B pools the gaps of the frames in [A, B] (6, 5, 4 droplets: 15 gaps, mean 200 d)" test $? -eq 0
"$tool" droplets "$tmp/w3.h5" --field density --min-width 150 | awk -F'\t' '!/^#/ && $1 != "file" && $4 != 0 { bad++ } END { exit bad > 0 }'
check "droplets: --min-width 150 drops a 100 d plug" test $? -eq 0
# one frame's flicker (8 8 3 8 8) is smoothed away by the running median of 5, not of 1
$synth droplets2d "$tmp/df.h5" counts=2,4,8,8,3,8,8,6,4,2,2,2
"$tool" droplets --field density "$tmp/df.h5" > "$tmp/df.out"
check "droplets --smooth 5 (default): a one-frame dip is smoothed away (n_f 3, n_f_smooth 8); t0 = 30, t1 = 110 (the end)" \
  bash -c "grep -q 'nucleation to t0 = 30 (N_f reaches its maximum 8), coalescence to t1 = 110 (N_f 2, rising after; counts smoothed over 5 frames)' '$tmp/df.out' && awk -F'\t' '\$2 == 40 && !(\$4 == 3 && \$5 == 8) { bad++ } END { exit bad > 0 }' '$tmp/df.out'"
"$tool" droplets --field density --smooth 4 "$tmp/df.h5" > /dev/null 2>&1; rc=$?
check "droplets --smooth 4 (even): exit 2" test $rc -eq 2
# domains: 64, 32, 16, 8 crystalline rectangles at t/T_driv = 1, 8, 64, 512, one across the
# periodic corner: N_d = 64 (t/T_driv)^(-1/3), the area fraction 1/16 throughout
$synth domains3d "$tmp/dm.h5"
"$tool" domains "$tmp/dm.h5" > "$tmp/dm.out"
check "domains: N_d per frame 64 32 16 8 (the corner's rectangle is one domain)" \
  test "$(awk -F'\t' '!/^#/ && $1 != "file" { printf "%s ", $4 }' "$tmp/dm.out")" = "64 32 16 8 "
check "domains: the area fraction is 1/16 in every frame, mean areas 4 8 16 32 d^2" \
  test "$(awk -F'\t' '!/^#/ && $1 != "file" { printf "%s/%s ", $5, $6 }' "$tmp/dm.out")" = "0.0625/4 0.0625/8 0.0625/16 0.0625/32 "
check "domains: the fit gives beta = -1/3, a = 64" grep -q 'a = 64, beta = -0.3333 ' "$tmp/dm.out"
"$tool" domains --min-cells 5 "$tmp/dm.h5" | grep -q 'fit n_d = a (t/T_driv)^beta over 0 < t/T_driv <= inf (3 frames)'
check "domains: --min-cells 5 leaves out the 4-cell domains of the first frame" test $? -eq 0
check "domains: the default cut is on the coordination (Otsu's, classes 4 and 6 bridges per grain)" \
  grep -q '^# threshold coordination = 4.89898: .* class means 4 and 6 ' "$tmp/dm.out"
"$tool" domains --t-sf 0.01 "$tmp/dm.h5" | awk -F'\t' '!/^#/ && $1 != "file" { printf "%s ", $4 }' > "$tmp/dmt.out"
check "domains --t-sf 0.01: the temperature cut finds the same 64 32 16 8" test "$(cat "$tmp/dmt.out")" = "64 32 16 8 "
"$tool" domains --t-sf 1e-4 "$tmp/dm.h5" | awk -F'\t' '!/^#/ && $1 != "file" && $4 != 0 { bad++ } END { exit bad > 0 }'
check "domains: --t-sf below the crystal's T_g: no domains" test $? -eq 0
"$tool" domains "$tmp/dr.h5" > /dev/null 2> "$tmp/de"; rc=$?
check "domains: a 2D run is refused (exit 1), pointing to droplets" bash -c "[ $rc -eq 1 ] && grep -q 'dr.h5: domains needs a 3D run' '$tmp/de'"
summary
