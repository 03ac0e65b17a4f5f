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

# reproducible LABEL DIR ARGS...: the run ARGS twice byte-identical, and killed after its second
# checkpoint and resumed, identical too; its ledger closes (DIR: a scratch prefix)
reproducible() {
  local label=$1 d=$2; shift 2
  local args=("$@") rc
  runat() { local dir=$1; shift; mkdir -p "$dir" && (cd "$dir" && "$run" "${args[@]}" -q --no-volatile "$@" -o run.h5 2> err); }
  runat "$d.a"; runat "$d.b"
  check "$label: two runs byte-identical" cmp -s "$d.a/run.h5" "$d.b/run.h5"
  runat "$d.r" --abort-after-checkpoint 2; rc=$?
  check "$label: aborted after its second checkpoint (exit $rc)" test "$rc" -eq 3
  runat "$d.r"
  check "$label: resumed run is byte-identical to the uninterrupted one" cmp -s "$d.a/run.h5" "$d.r/run.h5"
  check "$label: ledger closes" bash -c "grep -oE 'ledger_residual=[^ ]+' '$d.a/err' | \
    awk -F= '{ n++; ok = (\$2 < 1e-9) } END { exit !(n == 1 && ok) }'"
}
# refused KEY=VALUE OTHER SCENE: the scene with KEY=VALUE exits non-zero naming KEY and OTHER
refused() {
  local kv=$1 other=$2 scene=$3 key=${1%%=*} rc
  "$run" "$scene" "$kv" -o "$tmp/bad_$key.h5" 2> "$tmp/err_$key"; rc=$?
  check "$key with $other: non-zero exit, both keys named" \
    bash -c "[ $rc -ne 0 ] && grep -q \"'$key'\" '$tmp/err_$key' && grep -q \"'$other'\" '$tmp/err_$key' && [ ! -e '$tmp/bad_$key.h5' ]"
}

# Neighbour lists (shell): a wet 3D shaker (the lists are rebuilt from the state at each
# checkpoint, so the resumed run is identical too).
reproducible "neighbour lists" "$tmp/l" "$scenes/shake3d_5_2c.ini" n=400 lx=12 ly=12 shell=0.3 \
  t_end=6 dt_series=0.5 dt_snapshot=3 profile_bins=0 profile_start=0 dt_checkpoint=2
refused shell=0.3 shear_force "$scenes/shear3d.ini"

# The random force (noise): kicks drawn from a counter-based generator of (seed, kick, grain),
# so reruns and resumes are byte-identical with nothing of the generator in the checkpoint;
# the kicks' work closes the ledger; another seed kicks otherwise.
noisy=("$scenes/noise2d_wet.ini" n=300 t_end=30 dt_series=1 dt_snapshot=10 dt_checkpoint=10)
reproducible "random force" "$tmp/n" "${noisy[@]}"
mkdir -p "$tmp/n.s2" && (cd "$tmp/n.s2" && "$run" "${noisy[@]}" seed=2 -q --no-volatile -o run.h5 2> err)
check "random force: another seed, other bytes" bash -c "! cmp -s '$tmp/n.a/run.h5' '$tmp/n.s2/run.h5'"
refused noise=0.1 shear_force "$scenes/shear3d.ini"

# A checkpoint written while the configuration listed "shell = 0" (before the key was left out
# at 0, as the shear field's keys are) still resumes, to the same bytes.
runin "$tmp/fp0" --no-volatile
runin "$tmp/fp" --no-volatile --abort-after-checkpoint 1
/usr/bin/python3 - "$tmp/fp/run.h5.ckpt" <<'PY' 2> "$tmp/err_fp"
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    s = f.attrs["scene"]
    s = s.decode() if isinstance(s, bytes) else s
    at = s.index("\nstall_rate") + 1 if "\nstall_rate" in s else s.index("\n") + 1
    f.attrs["scene"] = s[:at] + "shell = 0\n" + s[at:]
PY
check "old checkpoint: 'shell = 0' planted in its configuration" grep -q "shell = 0" <(h5dump -a /scene "$tmp/fp/run.h5.ckpt" 2>/dev/null)
runin "$tmp/fp" --no-volatile
check "old checkpoint with 'shell = 0': resumed, byte-identical to the uninterrupted run" cmp -s "$tmp/fp0/run.h5" "$tmp/fp/run.h5"

summary
