#!/bin/bash
# The run archive (scripts/run-archived, scripts/archive-runs): an archived run is reused only
# when engine, scene text and arguments are all the same, and reused unchanged.
set -u
bin=${WG_BIN:?}
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"
cp "$top/sim/scenes/shake2d.ini" "$tmp/scene.ini"
echo "engine-a" > "$tmp/stamp"
mkdir -p "$tmp/runs" "$tmp/arch"
small="n=200 lx=60 t_end=20 profile_start=10 profile_bins=10 dt_series=1 dt_checkpoint=0"
run() { "$top/scripts/run-archived" "$tmp/arch" "$tmp/stamp" "$bin/wetgran-run" "$tmp/scene.ini" $small "$@" -q -o "$tmp/runs/r.h5" > "$tmp/out" 2> "$tmp/err"; }
simulated() { grep -q '^summary: events=' "$tmp/err"; }
reused() { grep -q 'from .*same engine, scene and arguments' "$tmp/err" && ! simulated; }

run
check "a run with no archive is simulated" simulated
check "and leaves its key" test -s "$tmp/runs/r.h5.key"
check "the key's first line is the engine fingerprint" test "$(head -n 1 "$tmp/runs/r.h5.key")" = engine-a
"$top/scripts/archive-runs" "$tmp/runs" "$tmp/arch" 2> "$tmp/arch.err"
check "archive-runs files it" grep -q '1 filed, 0 already there, 0 checkpoints' "$tmp/arch.err"
check "the archived copy holds the same data (h5diff)" h5diff -q "$tmp/runs/r.h5" "$tmp/arch/r.h5"
mkdir -p "$tmp/arch0"
ARCHIVE_MAX_KB=1 "$top/scripts/archive-runs" "$tmp/runs" "$tmp/arch0" 2> "$tmp/arch.err"
rc=$?
check "a run over ARCHIVE_MAX_KB is refused: non-zero exit ($rc), named with its size" \
  bash -c "[ $rc -ne 0 ] && grep -q 'r.h5 is [0-9]* kB repacked, over ARCHIVE_MAX_KB = 1: not filed' '$tmp/arch.err'"
check "and leaves no file in the archive" bash -c "[ -z \"\$(ls -A '$tmp/arch0')\" ]"
cp "$tmp/runs/r.h5" "$tmp/first.h5"
rm "$tmp/runs/r.h5" "$tmp/runs/r.h5.key"
run
check "the same run again is taken from the archive, not simulated" reused
check "and is the archived file, byte for byte" cmp -s "$tmp/runs/r.h5" "$tmp/arch/r.h5"
"$top/scripts/archive-runs" "$tmp/runs" "$tmp/arch" 2> "$tmp/arch.err"
check "archiving it again files nothing" grep -q '0 filed, 1 already there' "$tmp/arch.err"
run seed=2
check "another argument (seed = 2) is simulated" simulated
run
check "the first arguments again are reused" reused
echo "engine-b" > "$tmp/stamp"
run
check "another engine fingerprint is simulated" simulated
echo "engine-a" > "$tmp/stamp"
sed -i 's/^eps_wall *=.*/eps_wall = 0.9/' "$tmp/scene.ini"
run
check "another scene text (eps_wall = 0.9) is simulated" simulated
check "and gives another run (the archive is not what it returned)" bash -c "! h5diff -q '$tmp/runs/r.h5' '$tmp/first.h5' /observables/kinetic_energy/value /observables/kinetic_energy/value"
# a run cut off (killed after its first checkpoints) is filed as a checkpoint and resumed from
# it elsewhere: the result equals an uninterrupted run's
long="n=200 lx=60 t_end=1000 profile_start=0 profile_bins=10 dt_series=1 dt_snapshot=10 dt_checkpoint=2"
mkdir -p "$tmp/cut" "$tmp/arch2" "$tmp/whole"
"$top/scripts/run-archived" "$tmp/arch2" "$tmp/stamp" "$bin/wetgran-run" "$tmp/scene.ini" $long -q -o "$tmp/cut/c.h5" > /dev/null 2>&1 &
pid=$!
for i in $(seq 100); do [ -f "$tmp/cut/c.h5.ckpt" ] && break; sleep 0.05; done
kill -KILL $pid; wait $pid 2> /dev/null
"$top/scripts/archive-runs" "$tmp/cut" "$tmp/arch2" 2> "$tmp/arch.err"
check "a run killed after its first checkpoint files that checkpoint" \
  bash -c "grep -q '0 filed, 0 already there, 1 checkpoints' '$tmp/arch.err' && test -s '$tmp/arch2/partial/c.h5.ckpt'"
rm -f "$tmp/cut"/c.h5*
"$top/scripts/run-archived" "$tmp/arch2" "$tmp/stamp" "$bin/wetgran-run" "$tmp/scene.ini" $long -q -o "$tmp/cut/c.h5" > /dev/null 2> "$tmp/err"
check "a fresh directory resumes it from the filed checkpoint" grep -q 'resumes from the checkpoint filed' "$tmp/err"
"$bin/wetgran-run" "$tmp/scene.ini" $long -q -o "$tmp/whole/c.h5" > /dev/null 2>&1
check "the resumed run equals an uninterrupted one (energies, final positions)" \
  bash -c "h5diff -q '$tmp/cut/c.h5' '$tmp/whole/c.h5' /observables/kinetic_energy/value /observables/kinetic_energy/value && \
           h5diff -q '$tmp/cut/c.h5' '$tmp/whole/c.h5' /particles/all/position/value /particles/all/position/value"
"$top/scripts/archive-runs" "$tmp/cut" "$tmp/arch2" 2> "$tmp/arch.err"
check "once filed complete, its checkpoint is dropped" bash -c "test -s '$tmp/arch2/c.h5' && test ! -e '$tmp/arch2/partial'"

"$top/scripts/run-archived" "$tmp/arch" "$tmp/stamp" "$bin/wetgran-run" "$tmp/scene.ini" $small > /dev/null 2> "$tmp/err"
rc=$?
check "no -o among the arguments: non-zero exit ($rc) naming it" bash -c "[ $rc -ne 0 ] && grep -q \"no '-o RUN.h5'\" '$tmp/err'"
summary
