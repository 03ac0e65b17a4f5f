#!/bin/bash
# Every reader answers a bad input with one line on stderr that starts with its own name and
# the file, nothing on stdout, and exit status 1: each tool x (missing file, empty file, text
# file, truncated run file, foreign HDF5 file).  Also: numeric options read whole (exit 2),
# T_g's unit in the column names, wetgran-orderparam's n/a for runs without profiles, its
# refusal to mix wet and dry runs, and --calibrate on a sweep of one phase (seven fluids).
set -u
bin=${WG_BIN:?}
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"
small="n=300 lx=100 t_end=300 profile_start=150 profile_bins=25 dt_series=1 dt_snapshot=100 dt_checkpoint=0"
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=0.5 -q -o "$tmp/run.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d.ini" $small estar=0.5 profile_bins=0 -q -o "$tmp/noprof.h5" 2>/dev/null
"$bin/wetgran-run" "$scenes/shake2d_dry.ini" n=300 lx=100 t_end=100 profile_start=50 profile_bins=25 \
  dt_checkpoint=0 -q -o "$tmp/dry.h5" 2>/dev/null

# the five bad inputs
missing=$tmp/missing.h5
: > "$tmp/empty.h5"
printf 'this is a text file\nnot a run\n' > "$tmp/text.h5"
head -c 2000 "$tmp/run.h5" > "$tmp/truncated.h5"
"$bin/wetgran-orderparam" --h5 "$tmp/foreign.h5" "$tmp/run.h5" > /dev/null 2>&1 # HDF5 without /h5md
declare -A says=(
  [missing]="no such file"
  [empty]="empty file (0 bytes), not a run file"
  [text]="not an HDF5 file, so not a wetgran run file"
  [truncated]="truncated or damaged HDF5 file ("
  [foreign]="not a wetgran run file (no /h5md group)")

# one_line STATUS PREFIX TEXT CMD...: exit status STATUS, nothing on stdout, one line on stderr
# that starts with PREFIX and holds TEXT
one_line() {
  local status=$1 prefix=$2 text=$3 rc; shift 3
  "$@" > "$tmp/o" 2> "$tmp/e"
  rc=$?
  [ "$rc" -eq "$status" ] && [ ! -s "$tmp/o" ] && [ "$(wc -l < "$tmp/e")" -eq 1 ] &&
    [ "${prefix}" = "$(head -c ${#prefix} "$tmp/e")" ] && grep -qF -- "$text" "$tmp/e" ||
    { echo "      exit $rc, stdout $(wc -l < "$tmp/o") lines, stderr: $(head -3 "$tmp/e")"; return 1; }
}

for kind in missing empty text truncated foreign; do
  f=$tmp/$kind.h5
  for tool in series profiles frame orderparam delaunay-flc; do
    check "wetgran-$tool on a $kind file: '${says[$kind]}', exit 1" \
      one_line 1 "wetgran-$tool: $f: " "${says[$kind]}" "$bin/wetgran-$tool" "$f"
  done
  check "wetgran-orderparam --calibrate on a $kind file among good runs: one line, exit 1" \
    one_line 1 "wetgran-orderparam: $f: " "${says[$kind]}" "$bin/wetgran-orderparam" --calibrate "$tmp/run.h5" "$f"
done
# the table readers: a run file (or a broken one) where a table was meant, an empty or missing
# table, and a text file that is no table
table_says() {
  case $1 in
    missing) echo "no such file" ;; empty) echo "empty file (0 bytes), not a table" ;;
    truncated | foreign) echo "an HDF5 file, not a tab-separated table" ;;
    text) echo "no column" ;;
  esac
}
for kind in missing empty text truncated foreign; do
  f=$tmp/$kind.h5
  check "wetgran-fit on a $kind file: '$(table_says $kind)', exit 1" \
    one_line 1 "wetgran-fit: $f" "$(table_says $kind)" "$bin/wetgran-fit" --model line --x estar --y tg_ecb "$f"
  check "wetgran-transitions on a $kind file: '$(table_says $kind)', exit 1" \
    one_line 1 "wetgran-transitions: $f" "$(table_says $kind)" "$bin/wetgran-transitions" --x estar --pair f:g "$f"
  check "wetgran-boundary on a $kind file: '$(table_says $kind)', exit 1" \
    one_line 1 "wetgran-boundary: $f" "$(table_says $kind)" "$bin/wetgran-boundary" "$f"
  t=$(table_says $kind); [ "$kind" = text ] && t="line"
  check "wetgran-delaunay-flc --tsv on a $kind file: '$t', exit 1" \
    one_line 1 "wetgran-delaunay-flc: $f" "$t" "$bin/wetgran-delaunay-flc" --tsv "$f"
done
check "wetgran-theory (no input file): a value that is not a number, one line, exit 2" \
  one_line 2 "wetgran-theory: " "'abc' is not a finite number" "$bin/wetgran-theory" ffgc eps=abc
check "wetgran-run's messages start with its own name" \
  one_line 1 "wetgran-run: scene: command line: key 'gama'" "did you mean 'gamma'" \
  "$bin/wetgran-run" "$scenes/shake2d.ini" gama=15 -o "$tmp/x.h5"

# integers and numbers are read whole
for v in abc 2x "" 1.5; do
  check "wetgran-frame -f '$v': not an integer, exit 2" \
    one_line 2 "wetgran-frame: option -f: '$v' is not an integer" "" "$bin/wetgran-frame" "$tmp/run.h5" -f "$v"
done
check "wetgran-frame -f 1 prints snapshot 1" \
  bash -c "'$bin/wetgran-frame' '$tmp/run.h5' -f 1 | head -1 | grep -q '^# time 100 snapshot 1 of'"
check "wetgran-frame -f -1 is the last snapshot" \
  bash -c "'$bin/wetgran-frame' '$tmp/run.h5' -f -1 | head -1 | grep -q '^# time 300 snapshot 3 of 4'"
printf 'x\ty\n1\t2\n2\t4.1\n3\t5.9\n4\t8.1\n' > "$tmp/line.tsv"
for o in "--xmin 1e" "--xmax two" "--cap 3%" "--guess 1,x"; do
  check "wetgran-fit $o: not a number, exit 2" \
    one_line 2 "wetgran-fit: option ${o%% *}: " "is not a number" "$bin/wetgran-fit" --model line --x x --y y $o "$tmp/line.tsv"
done
check "wetgran-fit --xmin 1.5 --guess 1,2 still fits" \
  bash -c "'$bin/wetgran-fit' --model line --x x --y y --xmin 1.5 --guess 1,2 '$tmp/line.tsv' | grep -q '^fit_n	3	'"

# T_g's unit: series and profiles give temperature in m g d and temperature_ecb = T_g / E_cb
check "wetgran-series --help lists every column with its unit" \
  bash -c "'$bin/wetgran-series' --help | grep -q '^  temperature  *\[m g d\]' && '$bin/wetgran-series' --help | grep -q '^  temperature_ecb  *\[E_cb\]' && '$bin/wetgran-series' --help | grep -q '^  bridges  *\[1\]'"
check "wetgran-series: an unknown column names the run's columns, exit 1" \
  one_line 1 "wetgran-series: $tmp/run.h5: no column 'tempreature' (this run has: kinetic_energy," \
  "temperature, bridges," "$bin/wetgran-series" "$tmp/run.h5" tempreature
check "wetgran-series: temperature_ecb is temperature / E_cb (E_cb = 0.2844)" \
  bash -c "'$bin/wetgran-series' '$tmp/run.h5' temperature temperature_ecb | awk -F'\t' 'NR > 1 { n++; d = \$3 * 0.2844 / \$2 - 1; if (d > 1e-9 || d < -1e-9) bad++ } END { exit !(n > 100 && !bad) }'"
check "wetgran-series: a dry run has no temperature_ecb (named as the reason), exit 1" \
  one_line 1 "wetgran-series: $tmp/dry.h5: no column 'temperature_ecb'" "needs E_cb > 0" \
  "$bin/wetgran-series" "$tmp/dry.h5" temperature_ecb
check "wetgran-series' default columns of a dry run end in temperature's raw series, no temperature_ecb" \
  bash -c "'$bin/wetgran-series' '$tmp/dry.h5' | head -1 | grep -q 'temperature' && ! '$bin/wetgran-series' '$tmp/dry.h5' | head -1 | grep -q temperature_ecb"
check "wetgran-profiles: temperature [m g d] and temperature_ecb agree with E_cb" \
  bash -c "'$bin/wetgran-profiles' '$tmp/run.h5' | awk -F'\t' 'NR == 1 { ok = \$4 == \"temperature\" && \$5 == \"temperature_ecb\"; next } { d = \$5 * 0.2844 / \$4 - 1; if (d > 1e-9 || d < -1e-9) ok = 0 } END { exit !ok }'"
check "wetgran-orderparam: wet runs' T_g columns are tg_ecb tg_ecb_err tg_dense_ecb tg_dilute_ecb" \
  bash -c "'$bin/wetgran-orderparam' '$tmp/run.h5' 2>/dev/null | head -1 | cut -f11-14 | grep -qx 'tg_ecb	tg_ecb_err	tg_dense_ecb	tg_dilute_ecb'"
check "wetgran-orderparam: dry runs' are tg_mgd tg_mgd_err tg_dense_mgd tg_dilute_mgd" \
  bash -c "'$bin/wetgran-orderparam' '$tmp/dry.h5' 2>/dev/null | head -1 | cut -f11-14 | grep -qx 'tg_mgd	tg_mgd_err	tg_dense_mgd	tg_dilute_mgd'"
tg_series=$("$bin/wetgran-series" "$tmp/run.h5" temperature_ecb | awk -F'\t' 'NR > 1 && $1 >= 150 { s += $2; n++ } END { print s / n }')
tg_op=$("$bin/wetgran-orderparam" "$tmp/run.h5" 2>/dev/null | awk -F'\t' 'NR == 2 { print $11 }')
check "orderparam's tg_ecb is the window mean of series' temperature_ecb ($tg_op, $tg_series)" \
  awk -v a="$tg_op" -v b="$tg_series" 'BEGIN { exit !(a > 0 && a / b - 1 < 1e-5 && b / a - 1 < 1e-5) }'
check "wetgran-orderparam refuses wet and dry runs in one table, exit 2" \
  one_line 2 "wetgran-orderparam: " "give wet and dry runs in separate tables" \
  "$bin/wetgran-orderparam" "$tmp/run.h5" "$tmp/dry.h5"

# a run without profiles has no contrasts: label n/a, named, exit 1; --tg-only asks for T_g alone
"$bin/wetgran-orderparam" "$tmp/run.h5" "$tmp/noprof.h5" > "$tmp/na.tsv" 2> "$tmp/na.err"
rc=$?
check "orderparam on a run without profiles: exit 1" test "$rc" -eq 1
check "... its label is n/a, the other run's is f" \
  bash -c "awk -F'\t' '\$1 ~ /noprof/ { a = \$NF } \$1 ~ /run.h5/ { b = \$NF } END { exit !(a == \"n/a\" && b == \"f\") }' '$tmp/na.tsv'"
check "... and stderr names it" grep -q "noprof.h5: no profiles (profile_bins = 0), so no contrasts: label n/a" "$tmp/na.err"
check "... and no nan contrast is labelled" bash -c "! awk -F'\t' 'NR > 1 && \$15 == \"nan\" && \$NF != \"n/a\"' '$tmp/na.tsv' | grep -q ."
"$bin/wetgran-orderparam" --tg-only "$tmp/noprof.h5" > "$tmp/tgo.tsv" 2>/dev/null
rc=$?
check "orderparam --tg-only on it: exit 0, T_g given, label '-'" \
  bash -c "[ $rc -eq 0 ] && awk -F'\t' 'NR == 2 { exit !(\$11 > 0 && \$NF == \"-\") }' '$tmp/tgo.tsv'"
check "--tg-only does not go with --calibrate (exit 2)" \
  one_line 2 "wetgran-orderparam: --tg-only goes without" "" "$bin/wetgran-orderparam" --tg-only --calibrate "$tmp/noprof.h5"

# --calibrate on a sweep of one phase: seven fluids at Gamma = 15, E* = 0.6-0.9 (T_g/E_cb about
# 1.6-3: Otsu's classes lie 0.17 decades apart; before, the three hottest were called gas)
for e in 0.6 0.65 0.7 0.75 0.8 0.85 0.9; do
  "$bin/wetgran-run" "$scenes/shake2d.ini" $small gamma=15 estar=$e -q -o "$tmp/fl_$e.h5" 2>/dev/null &
done
wait
"$bin/wetgran-orderparam" --calibrate "$tmp"/fl_*.h5 > "$tmp/one.tsv" 2> "$tmp/one.err"
check "one-phase sweep: all seven fluids labelled f ($(awk -F'\t' 'NR > 2 { printf "%s ", $NF }' "$tmp/one.tsv"))" \
  bash -c "[ \$(awk -F'\t' '!/^#/ && \$1 != \"file\" && \$NF == \"f\"' '$tmp/one.tsv' | wc -l) -eq 7 ]"
check "... and stderr says they are not separated into fluid and gas" \
  grep -q "homogeneous runs are not separated into fluid and gas (.*not more than 0.5): one phase, fluid" "$tmp/one.err"
# the same sweep with a gas beside it (E* = 2.5, T_g/E_cb ~ 10^3) is separated again
"$bin/wetgran-run" "$scenes/shake2d.ini" $small gamma=15 estar=2.5 -q -o "$tmp/gas.h5" 2>/dev/null
"$bin/wetgran-orderparam" --calibrate "$tmp"/fl_*.h5 "$tmp/gas.h5" > "$tmp/two.tsv" 2> "$tmp/two.err"
check "with a gas added: the gas is g, the seven fluids f, no 'not separated' line" \
  bash -c "awk -F'\t' '!/^#/ && \$1 != \"file\" { if (\$1 ~ /gas/) g = \$NF == \"g\"; else f += \$NF == \"f\" } END { exit !(g && f == 7) }' '$tmp/two.tsv' && ! grep -q 'not separated' '$tmp/two.err'"
summary
