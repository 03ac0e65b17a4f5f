#!/bin/bash
# What a long run tells its user: progress lines in a batch log (stderr not a terminal, -q as
# the figures pass it), and the stall watch, which warns once (or stops) when the event-driven
# engine crawls through a bed that makes thousands of events per particle and time unit.
# Nothing here depends on how fast the machine is: the log interval is tiny, and a stall is a
# rate per simulated time unit (the issue's bed makes ~1500-2800, a shaken gas ~11).
set -u
run=${WG_BIN:?}/wetgran-run
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"

logline='^progress: t = [0-9]+\.[0-9]{2} / [0-9.]+ \([0-9]+%\), [0-9.]+(e[+-][0-9]+)? UNIT/s, wall [0-9.]+ (s|min|h), ETA ([0-9.]+ (s|min|h)|unknown)$'
# a shaken gas of the issue's box: Gamma = 20, E* = 1.2, eps = 0.9 (11 events per particle
# and time unit), and the issue's bed: Gamma = 1.01, E* = 5 (collapses near t = 17)
box="n=400 lx=100 eps=0.9 profile_bins=0 profile_start=0 dt_checkpoint=0"
gas="$box gamma=20 estar=1.2"
bed="$box gamma=1.01 estar=5"

# --- the batch log: stderr to a file, -q as in every figure Makefile ---
"$run" "$scenes/shake2d.ini" $gas t_end=30 dt_series=0.1 -q --log-every 0.01 -o "$tmp/log.h5" 2> "$tmp/log.err"; rc=$?
n=$(grep -cE "${logline/UNIT/events}" "$tmp/log.err")
check "ed, -q, stderr a file, --log-every 0.01: exit 0, progress lines ($n) in the format" \
  bash -c "[ $rc -eq 0 ] && [ $n -ge 1 ]"
check "ed: every stderr line but the summary is such a progress line" \
  bash -c "[ \$(grep -vcE '^summary: ' '$tmp/log.err') -eq $n ]"
check "ed: the last progress line is the latest (t and % grow)" \
  bash -c "grep '^progress:' '$tmp/log.err' | awk '{ t = \$4 + 0; if (t < last) bad = 1; last = t } END { exit bad }'"
"$run" "$scenes/shake2d_td.ini" n=300 lx=100 t_end=1 dt_series=0.05 profile_bins=0 profile_start=0 dt_checkpoint=0 \
  --log-every 0.01 -o "$tmp/td.h5" 2> "$tmp/td.err"; rc=$?
n=$(grep -cE "${logline/UNIT/particle-steps}" "$tmp/td.err")
check "td: progress lines ($n) count particle-steps/s" bash -c "[ $rc -eq 0 ] && [ $n -ge 1 ]"
"$run" "$scenes/shake2d.ini" $gas t_end=30 dt_series=0.1 -q --log-every 0 -o "$tmp/nolog.h5" 2> "$tmp/nolog.err"; rc=$?
check "--log-every 0: no progress line, the summary still there" \
  bash -c "[ $rc -eq 0 ] && ! grep -q '^progress' '$tmp/nolog.err' && grep -q '^summary: ' '$tmp/nolog.err'"
check "--log-every 0 changes nothing in the run file" \
  bash -c "h5diff --exclude-path /provenance '$tmp/log.h5' '$tmp/nolog.h5' > /dev/null"
"$run" "$scenes/shake2d.ini" $gas t_end=5 -o "$tmp/dflt.h5" 2> "$tmp/dflt.err"
check "default (60 s): a short run prints only its summary" \
  bash -c "[ \$(wc -l < '$tmp/dflt.err') -eq 1 ] && grep -q '^summary: ' '$tmp/dflt.err'"
for bad in abc -1 '' 1x; do
  "$run" "$scenes/shake2d.ini" --log-every "$bad" -o "$tmp/bad.h5" 2> "$tmp/bad.err"; rc=$?
  check "--log-every '$bad': exit 2, one line naming the option, no file" \
    bash -c "[ $rc -eq 2 ] && grep -q -- '--log-every' '$tmp/bad.err' && [ \$(wc -l < '$tmp/bad.err') -eq 1 ] && [ ! -e '$tmp/bad.h5' ]"
done

# --- the new keys in --help and the parser ---
check "--help lists stall_rate and stall_action with unit and default" \
  bash -c "'$run' --help | grep -qE '^  stall_rate +1000 +sqrt\(g/d\)' && '$run' --help | grep -qE '^  stall_action +warn +1 +warn, stop'"
"$run" "$scenes/shake2d.ini" stall_action=halt -o "$tmp/bad.h5" 2> "$tmp/bad.err"; rc=$?
check "stall_action=halt: exit 1, the parser's message names the key" \
  bash -c "[ $rc -eq 1 ] && grep -q \"command line: key 'stall_action'\" '$tmp/bad.err' && [ ! -e '$tmp/bad.h5' ]"
printf 'stall_rate = -5\n' > "$tmp/neg.ini"
"$run" "$tmp/neg.ini" dim=2 n=10 lx=20 height=9 gamma=15 estar_d=1 tg_init_abs=1 seed=1 t_end=1 -o "$tmp/bad.h5" 2> "$tmp/bad.err"; rc=$?
check "stall_rate = -5 in a file: exit 1, file, line and key named" \
  bash -c "[ $rc -eq 1 ] && grep -q \"neg.ini:1: key 'stall_rate'\" '$tmp/bad.err'"

# --- the stall watch ---
warn='warning: t = [0-9.e+-]+: [0-9.e+]+ physical events per particle and unit time \(stall_rate = '
# a gas long enough for several one-second windows here: no warning at the default...
"$run" "$scenes/shake2d.ini" $gas t_end=400 -q -o "$tmp/gas.h5" 2> "$tmp/gas.err"; rc=$?
check "a shaken gas (11 per particle and time unit) runs without a warning" \
  bash -c "[ $rc -eq 0 ] && ! grep -q 'warning' '$tmp/gas.err' && [ -e '$tmp/gas.h5' ]"
# ...and the same gas under a threshold it exceeds: the watch does look at it
"$run" "$scenes/shake2d.ini" $gas t_end=400 stall_rate=5 -q -o "$tmp/gas5.h5" 2> "$tmp/gas5.err"; rc=$?
check "the same gas with stall_rate=5 warns, once, and finishes" \
  bash -c "[ $rc -eq 0 ] && [ \$(grep -cE '$warn' '$tmp/gas5.err') -eq 1 ] && [ -e '$tmp/gas5.h5' ]"

# the issue's bed, continued from a checkpoint at t = 18 where it has collapsed onto the floor
# (the stall keys do not enter the checkpoint's fingerprint, so every variant resumes from it)
ck="$bed t_end=300 dt_checkpoint=1"
mkdir -p "$tmp/prep"
"$run" "$scenes/shake2d.ini" $ck stall_rate=0 -q --log-every 0 --abort-after-checkpoint 18 -o "$tmp/prep/bed.h5" 2> /dev/null
resume() { # resume DIR ARGS...: the bed from t = 18 in DIR
  local dir=$1; shift
  mkdir -p "$dir" && cp "$tmp/prep/bed.h5.ckpt" "$tmp/prep/bed.h5.frames" "$dir/" &&
    "$run" "$scenes/shake2d.ini" $ck -q "$@" -o "$dir/bed.h5"
}
check "the bed: a checkpoint at t = 18" test -e "$tmp/prep/bed.h5.ckpt"
resume "$tmp/w" --log-every 0.2 --abort-after-checkpoint 20 2> "$tmp/w.err"; rc=$?
rate=$(grep -oE "$warn" "$tmp/w.err" | head -n 1 | awk '{ print $5 }')
check "the bed from t = 18 to 20 warns exactly once ($rate per particle and time unit)" \
  bash -c "[ $rc -eq 3 ] && [ \$(grep -cE '$warn' '$tmp/w.err') -eq 1 ]"
check "the bed's rate is above stall_rate = 1000" awk -v r="${rate:-0}" 'BEGIN { exit !(r > 1000) }'
check "the warning names the likely cause" \
  bash -c "grep -q 'Likely cause: inelastic collapse (eps < 1: a larger tc helps) or a bed resting on a slowly shaken floor (Gamma near or below 1)' '$tmp/w.err'"
check "the warning says what to do and that the run goes on" \
  bash -c "grep -q 'What to do: raise tc, Gamma or E\*, or use the time-driven engine (engine = td)' '$tmp/w.err' && grep -q 'Going on (stall_action = stop would stop here)' '$tmp/w.err'"
check "the run went on: progress lines after the warning" \
  bash -c "sed -n '/^wetgran-run: warning/,\$p' '$tmp/w.err' | grep -q '^progress: '"
resume "$tmp/z" stall_rate=0 --log-every 0 --abort-after-checkpoint 19 2> "$tmp/z.err"; rc=$?
check "stall_rate=0: the bed never warns" bash -c "[ $rc -eq 3 ] && ! grep -q 'warning' '$tmp/z.err'"
resume "$tmp/s" stall_action=stop --log-every 0 2> "$tmp/s.err"; rc=$?
check "stall_action=stop: exit 1, 'wetgran-run: error:', no run file" \
  bash -c "[ $rc -eq 1 ] && grep -qE 'wetgran-run: error: t = [0-9.]+: [0-9.e+]+ physical events' '$tmp/s.err' && [ ! -e '$tmp/s/bed.h5' ] && [ ! -e '$tmp/s/bed.h5.tmp' ]"
check "stall_action=stop after a checkpoint: it stays, and the message says so" \
  bash -c "[ -e '$tmp/s/bed.h5.ckpt' ] && grep -q 'no run file; .*bed.h5.ckpt resumes it (e.g. with stall_rate=0)' '$tmp/s.err'"
# from t = 0 without checkpoints: stops at the collapse, nothing left behind
mkdir -p "$tmp/s0"
"$run" "$scenes/shake2d.ini" $bed t_end=300 stall_action=stop -q -o "$tmp/s0/bed.h5" 2> "$tmp/s0.err"; rc=$?
check "stall_action=stop from t = 0: exit 1 near the collapse, no file of any kind left" \
  bash -c "[ $rc -eq 1 ] && grep -q 'Stopped (stall_action = stop): no run file\.' '$tmp/s0.err' && [ -z \"\$(ls -A '$tmp/s0')\" ]"
"$run" "$scenes/shake2d_td.ini" stall_rate=5 -o "$tmp/x.h5" 2> "$tmp/x.err"; rc=$?
check "the td engine refuses stall_rate, naming the key and engine" \
  bash -c "[ $rc -eq 1 ] && grep -q \"keys 'engine' and 'stall_rate': applies only to engine = ed\" '$tmp/x.err'"
summary
