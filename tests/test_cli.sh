#!/bin/bash
# wetgran-run as a user meets it: --help, clear errors for bad scenes, identical bytes for the
# same scene and seed, and a crashed-then-resumed run identical to an uninterrupted one.
set -u
run=${WG_BIN:?}/wetgran-run
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"

check "--help lists the scene keys" bash -c "'$run' --help | grep -q 'estar'"
check "--version answers" bash -c "'$run' --version | grep -q wetgran-run"

# bad scenes: file, line and key named, non-zero exit, no output file left behind
printf 'dim = 2\nn = 10\nlx = 20\nheight = 9\ngama = 15\n' > "$tmp/bad1.ini"
"$run" "$tmp/bad1.ini" -o "$tmp/bad1.h5" 2> "$tmp/err1"; rc=$?
check "unknown key: non-zero exit ($rc)" test "$rc" -ne 0
check "unknown key: message names file, line 5 and key" grep -q "bad1.ini:5.*'gama'" "$tmp/err1"
check "unknown key: suggests 'gamma'" grep -q "gamma" "$tmp/err1"
check "no run file written" test ! -e "$tmp/bad1.h5"
"$run" "$scenes/shake2d.ini" eps=1.5 -o "$tmp/bad2.h5" 2> "$tmp/err2"; rc=$?
check "out-of-range override: non-zero exit" test "$rc" -ne 0
check "out-of-range override: names the command line and key" grep -q "command line.*'eps'" "$tmp/err2"
"$run" -o "$tmp/x.h5" "$tmp/none.ini" 2> "$tmp/err3"; rc=$?
check "missing scene file: non-zero exit and file named" bash -c "[ $rc -ne 0 ] && grep -q none.ini '$tmp/err3'"

# same scene and seed: identical bytes (volatile provenance switched off).  The command line
# is part of the provenance, so each run writes run.h5 in a directory of its own.
short="t_end=60 dt_series=1 dt_snapshot=20 profile_start=30 dt_checkpoint=20"
runin() { # runin DIR [extra args]: run shake2d briefly in DIR, writing DIR/run.h5
  local dir=$1; shift
  mkdir -p "$dir" && (cd "$dir" && "$run" "$scenes/shake2d.ini" $short -q "$@" -o run.h5 2> err)
}
runin "$tmp/a" --no-volatile
runin "$tmp/b" --no-volatile
check "two runs of one scene and seed are byte-identical" cmp -s "$tmp/a/run.h5" "$tmp/b/run.h5"
check "summary line on stderr" grep -qE '^summary: events=[0-9]+ sim_time=60 wall_s=[0-9.]+ events_per_s=[0-9.e+]+ ledger_residual=' "$tmp/a/err"
check "no temporary files left" bash -c "! ls '$tmp'/a/run.h5.* 2>/dev/null | grep -q ."
runin "$tmp/c" --no-volatile seed=2
check "another seed gives another run" bash -c "! cmp -s '$tmp/a/run.h5' '$tmp/c/run.h5'"

# crash after the second checkpoint, then the same command resumes: identical file
runin "$tmp/r" --no-volatile --abort-after-checkpoint 2; rc=$?
check "aborted run exits 3 and leaves its checkpoint" bash -c "[ $rc -eq 3 ] && [ -e '$tmp/r/run.h5.ckpt' ] && [ ! -e '$tmp/r/run.h5' ]"
runin "$tmp/r" --no-volatile
check "resumed run completes" test -e "$tmp/r/run.h5"
check "resumed run is byte-identical to the uninterrupted one" cmp -s "$tmp/a/run.h5" "$tmp/r/run.h5"
if command -v h5diff >/dev/null; then
  runin "$tmp/v1"
  sleep 1
  runin "$tmp/v2"
  check "with volatile provenance the files differ, but h5diff finds nothing outside /provenance/volatile" \
    bash -c "! cmp -s '$tmp/v1/run.h5' '$tmp/v2/run.h5' && h5diff -q --exclude-path /provenance/volatile '$tmp/v1/run.h5' '$tmp/v2/run.h5'"
fi
runin "$tmp/m" seed=3 --no-volatile --abort-after-checkpoint 1
runin "$tmp/m" seed=4 --no-volatile; rc=$?
check "a checkpoint of another configuration is refused" bash -c "[ $rc -ne 0 ] && grep -q 'different configuration' '$tmp/m/err'"

# Regression: this inelastic wet run jammed at t = 526.12 (four bonded disks, contacts closed
# and a bridge taut, ringing elastically under the TC rule at one instant) before same-instant
# collisions were made perfectly inelastic.
mkdir -p "$tmp/j"
timeout 120 "$run" "$scenes/shake2d.ini" eps=0.96 gamma=15 estar=1.9 t_end=530 dt_checkpoint=0 \
  dt_snapshot=0 profile_bins=0 profile_start=0 -o "$tmp/j/run.h5" 2>"$tmp/j/err"; rc=$?
check "inelastic wet run through the former jam at t = 526 (exit $rc)" test "$rc" -eq 0
check "rigid-cluster collisions were resolved" grep -qE 'rigid_collisions=[1-9]' "$tmp/j/err"
check "ledger still closes" bash -c "grep -oE 'ledger_residual=[^ ]+' '$tmp/j/err' | \
  awk -F= '{ n++; ok = (\$2 < 1e-9 && \$2 > -1e-9) } END { exit !(n == 1 && ok) }'"

# Resting on the floor (rest_speed): a 3D wet layer at Gamma = 0.8 comes to rest; killed after a
# checkpoint and resumed, it gives the same bytes (the resting flags are in the checkpoint).
rest="$scenes/shake3d_5_2c.ini n=60 lx=10 ly=10 gamma=0.8 estar=1 eps=0.9 eps_wall=0.5 tg_init=0.1
  rest_speed=0.01 t_end=12 dt_series=0.5 dt_snapshot=6 profile_bins=0 profile_start=0 dt_checkpoint=4"
restin() { local dir=$1; shift; mkdir -p "$dir" && (cd "$dir" && "$run" $rest -q --no-volatile "$@" -o run.h5 2> err); }
restin "$tmp/ra"
check "resting layer runs" test -e "$tmp/ra/run.h5"
restin "$tmp/rr" --abort-after-checkpoint 2; rc=$?
check "resting layer: aborted after its second checkpoint (exit $rc)" test "$rc" -eq 3
restin "$tmp/rr"
check "resting layer: resumed run is byte-identical to the uninterrupted one" cmp -s "$tmp/ra/run.h5" "$tmp/rr/run.h5"
"$run" "$scenes/gas3d.ini" rest_speed=0.01 -o "$tmp/bad_rest.h5" 2> "$tmp/err_rest"; rc=$?
check "rest_speed in a periodic box: non-zero exit, both keys named" \
  bash -c "[ $rc -ne 0 ] && grep -q \"'rest_speed'\" '$tmp/err_rest' && grep -q \"'container'\" '$tmp/err_rest' && [ ! -e '$tmp/bad_rest.h5' ]"

# Neighbour lists (shell): a wet 3D shaker twice identical, and killed after its second
# checkpoint and resumed, identical too (the lists are rebuilt from the state at each checkpoint).
lists="$scenes/shake3d_5_2c.ini n=400 lx=12 ly=12 shell=0.3 t_end=6 dt_series=0.5 dt_snapshot=3
  profile_bins=0 profile_start=0 dt_checkpoint=2"
listin() { local dir=$1; shift; mkdir -p "$dir" && (cd "$dir" && "$run" $lists -q --no-volatile "$@" -o run.h5 2> err); }
listin "$tmp/la"
listin "$tmp/lb"
check "neighbour lists: two runs byte-identical" cmp -s "$tmp/la/run.h5" "$tmp/lb/run.h5"
listin "$tmp/lr" --abort-after-checkpoint 2; rc=$?
check "neighbour lists: aborted after its second checkpoint (exit $rc)" test "$rc" -eq 3
listin "$tmp/lr"
check "neighbour lists: resumed run is byte-identical to the uninterrupted one" cmp -s "$tmp/la/run.h5" "$tmp/lr/run.h5"
check "neighbour lists: ledger closes" bash -c "grep -oE 'ledger_residual=[^ ]+' '$tmp/la/err' | \
  awk -F= '{ n++; ok = (\$2 < 1e-9) } END { exit !(n == 1 && ok) }'"
"$run" "$scenes/shear3d.ini" shell=0.3 -o "$tmp/bad_shell.h5" 2> "$tmp/err_shell"; rc=$?
check "shell with the shear field: non-zero exit, both keys named" \
  bash -c "[ $rc -ne 0 ] && grep -q \"'shell'\" '$tmp/err_shell' && grep -q \"'shear_force'\" '$tmp/err_shell' && [ ! -e '$tmp/bad_shell.h5' ]"

summary
