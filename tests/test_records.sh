#!/bin/bash
# The record archive (scripts/record, scripts/archive-records, wetgran-reduce, scripts/run-key):
# a record reads like its run in every analysis tool; an archived record is reused when scene
# text, arguments and reduction are the same, whatever engine version made it (said on
# stderr; RERUN=1 re-simulates); checkpoints of cut-off runs are filed and resumed.
set -u
bin=${WG_BIN:?}
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"
cp "$top/sim/scenes/shake2d.ini" "$tmp/scene.ini"
echo "aaaa000000000000" > "$tmp/version"
mkdir -p "$tmp/runs" "$tmp/arch"
small="n=200 lx=60 t_end=40 profile_start=10 profile_bins=10 dt_series=1 dt_snapshot=5 dt_checkpoint=0"
keep="--snapshots last --series temperature,bridges"
run() { "$top/scripts/record" "$tmp/arch" "$tmp/version" "$keep" "$bin/wetgran-run" "$tmp/scene.ini" $small "$@" -q -o "$tmp/runs/r.h5" > "$tmp/out" 2> "$tmp/err"; }
simulated() { grep -q '^summary: events=' "$tmp/err"; }
reused() { grep -q "from $tmp/arch" "$tmp/err" && ! simulated; }
field() { awk -F'\t' -v k="$2" '$1 == k { print $2 }' "$1"; }

run
check "a run with no archive is simulated" simulated
check "its whole run is kept under whole/" test -s "$tmp/runs/whole/r.h5"
check "the record carries its provenance: key, engine version, CPU seconds, seed, command" \
  bash -c "[ \"\$(awk -F'\t' '{ print \$1 }' '$tmp/runs/r.h5.rec' | sort | tr '\n' ' ')\" = 'command commit cpu_s date engine_version key reduce scene_sha256 seed ' ]"
check "the key is scripts/run-key's sum of scene text and arguments" \
  test "$(field "$tmp/runs/r.h5.rec" key)" = "$("$top/scripts/run-key" "$bin/wetgran-run" "$tmp/scene.ini" $small -q -o elsewhere.h5)"
check "engine version and seed as given" \
  bash -c "[ '$(field "$tmp/runs/r.h5.rec" engine_version)' = aaaa000000000000 ] && [ '$(field "$tmp/runs/r.h5.rec" seed)' = 1 ]"
check "cpu_s is the simulator's CPU time: a positive number ($(field "$tmp/runs/r.h5.rec" cpu_s) s)" bash -c "awk -v c='$(field "$tmp/runs/r.h5.rec" cpu_s)' 'BEGIN { exit !(c == c + 0 && c > 0) }'"
check "the provenance is in the file too (/record)" bash -c "h5dump -a /record/key '$tmp/runs/r.h5' | grep -q '$(field "$tmp/runs/r.h5.rec" key)'"
# the record reads like the run
w=$tmp/runs/whole/r.h5 r=$tmp/runs/r.h5
check "record and run: the same profiles" cmp -s <("$bin/wetgran-profiles" "$w") <("$bin/wetgran-profiles" "$r")
check "the same T_g and bridge series" cmp -s <("$bin/wetgran-series" "$w" temperature bridges) <("$bin/wetgran-series" "$r" temperature bridges)
check "the same last snapshot" cmp -s <("$bin/wetgran-frame" "$w" | tail -n +2) <("$bin/wetgran-frame" "$r" | tail -n +2)
check "the same order parameters" cmp -s <("$bin/wetgran-orderparam" "$w" | cut -f2-) <("$bin/wetgran-orderparam" "$r" | cut -f2-)
check "and no other snapshot or series" bash -c "! '$bin/wetgran-frame' '$r' -f 1 > /dev/null 2>&1 && ! '$bin/wetgran-series' '$r' kinetic_energy > /dev/null 2>&1"
check "the record is smaller than the run" test "$(stat -c %s "$r")" -lt "$(stat -c %s "$w")"
"$bin/wetgran-reduce" "$w" -o "$tmp/again.h5" $keep
"$bin/wetgran-reduce" "$w" -o "$tmp/again2.h5" $keep
check "wetgran-reduce is deterministic (byte-identical records)" cmp -s "$tmp/again.h5" "$tmp/again2.h5"
"$bin/wetgran-reduce" "$w" -o "$tmp/all.h5" --snapshots all --series all
check "--snapshots all --series all keeps every snapshot, bridge list and series" \
  bash -c "h5diff -q '$w' '$tmp/all.h5' /particles/all/position /particles/all/position && h5diff -q '$w' '$tmp/all.h5' /bridges /bridges && h5diff -q '$w' '$tmp/all.h5' /observables /observables"
"$bin/wetgran-reduce" "$w" -o "$tmp/two.h5" --snapshots 1,-1
check "--snapshots 1,-1 keeps those two, with their bridge lists" \
  bash -c "cmp -s <('$bin/wetgran-frame' '$w' -f 1 | tail -n +2) <('$bin/wetgran-frame' '$tmp/two.h5' -f 0 | tail -n +2) && cmp -s <('$bin/wetgran-frame' '$w' | tail -n +2) <('$bin/wetgran-frame' '$tmp/two.h5' -f 1 | tail -n +2)"
"$bin/wetgran-reduce" "$w" -o "$tmp/bad.h5" --snapshots 1x 2> "$tmp/rerr"
rc=$?
check "a bad --snapshots list: exit 2 naming it ($rc)" bash -c "[ $rc -eq 2 ] && grep -q \"'1x' is not an integer\" '$tmp/rerr'"

"$top/scripts/archive-records" "$tmp/runs" "$tmp/arch" 2> "$tmp/arch.err"
check "archive-records files it" grep -q '1 filed, 0 already there, 0 checkpoints' "$tmp/arch.err"
check "with an index line" bash -c "[ \$(wc -l < '$tmp/arch/index.tsv') -eq 2 ] && grep -q '^r.h5	' '$tmp/arch/index.tsv'"
mkdir -p "$tmp/arch0"
ARCHIVE_MAX_KB=1 "$top/scripts/archive-records" "$tmp/runs" "$tmp/arch0" 2> "$tmp/arch.err"
rc=$?
check "a record over ARCHIVE_MAX_KB is refused: non-zero exit ($rc), named with its size" \
  bash -c "[ $rc -ne 0 ] && grep -q 'r.h5 is [0-9]* kB, over ARCHIVE_MAX_KB = 1: not filed' '$tmp/arch.err'"
cp "$tmp/runs/r.h5" "$tmp/first.h5"
rm -rf "$tmp/runs"/*
run
check "the same run again is taken from the archive, not simulated" reused
check "and is the archived record, byte for byte" cmp -s "$tmp/runs/r.h5" "$tmp/arch/r.h5"
touch -d '1 hour ago' "$tmp/runs/r.h5"
run
check "asked again with its record in place (its conf newer, say): kept, neither simulated nor copied" \
  bash -c "grep -q \"already this run's record\" '$tmp/err' && ! grep -q '^summary: events=' '$tmp/err' && [ '$tmp/runs/r.h5' -nt '$tmp/arch/r.h5' ] && cmp -s '$tmp/runs/r.h5' '$tmp/arch/r.h5'"
"$top/scripts/archive-records" "$tmp/runs" "$tmp/arch" 2> "$tmp/arch.err"
check "archiving it again files nothing" grep -q '0 filed, 1 already there' "$tmp/arch.err"
echo "bbbb000000000000" > "$tmp/version"
rm -rf "$tmp/runs"/*
run
check "another engine version: the archived record is still used" reused
check "and says which version made it" grep -q 'made by engine version aaaa000000000000 (today.s: bbbb000000000000' "$tmp/err"
rm -rf "$tmp/runs"/*
RERUN=1 run
check "RERUN=1 simulates it again" simulated
check "and records the new version" test "$(field "$tmp/runs/r.h5.rec" engine_version)" = bbbb000000000000
check "with the same numbers (the engine did not really change)" \
  h5diff -q "$tmp/runs/r.h5" "$tmp/first.h5" /observables/temperature/value /observables/temperature/value
rm -rf "$tmp/runs"/*
run seed=2
check "another argument (seed = 2) is simulated" simulated
keep="--snapshots none --series temperature,bridges"
rm -rf "$tmp/runs"/*
run
check "another reduction is simulated" simulated
keep="--snapshots last --series temperature,bridges"
sed -i 's/^eps_wall *=.*/eps_wall = 0.9/' "$tmp/scene.ini"
rm -rf "$tmp/runs"/*
run
check "another scene text (eps_wall = 0.9) is simulated" simulated
check "and gives another run" bash -c "! h5diff -q '$tmp/runs/r.h5' '$tmp/first.h5' /observables/temperature/value /observables/temperature/value"
# a run cut off after its first checkpoints files its checkpoint, and a fresh directory resumes
# it: the record equals an uninterrupted run's
long="n=200 lx=60 t_end=1000 profile_start=0 profile_bins=10 dt_series=1 dt_snapshot=10 dt_checkpoint=2"
mkdir -p "$tmp/cut" "$tmp/arch2" "$tmp/plain"
"$top/scripts/record" "$tmp/arch2" "$tmp/version" "$keep" "$bin/wetgran-run" "$tmp/scene.ini" $long -q -o "$tmp/cut/c.h5" > /dev/null 2>&1 &
pid=$!
for i in $(seq 200); do [ -f "$tmp/cut/whole/c.h5.ckpt" ] && break; sleep 0.05; done
sleep 0.2
pkill -KILL -P $pid; kill -KILL $pid 2> /dev/null; wait $pid 2> /dev/null
"$top/scripts/archive-records" "$tmp/cut" "$tmp/arch2" 2> "$tmp/arch.err"
check "a run killed after its first checkpoint files that checkpoint" \
  bash -c "grep -q '0 filed, 0 already there, 1 checkpoints' '$tmp/arch.err' && test -s '$tmp/arch2/partial/c.h5.ckpt'"
rm -rf "$tmp/cut"
mkdir -p "$tmp/cut"
"$top/scripts/record" "$tmp/arch2" "$tmp/version" "$keep" "$bin/wetgran-run" "$tmp/scene.ini" $long -q -o "$tmp/cut/c.h5" > /dev/null 2> "$tmp/err"
check "a fresh directory resumes it from the filed checkpoint" grep -q 'resumes from the checkpoint filed' "$tmp/err"
"$bin/wetgran-run" "$tmp/scene.ini" $long -q -o "$tmp/plain/c.h5" > /dev/null 2>&1
check "the resumed record equals an uninterrupted run (T_g series, last snapshot)" \
  bash -c "h5diff -q '$tmp/cut/c.h5' '$tmp/plain/c.h5' /observables/temperature/value /observables/temperature/value && \
           cmp -s <('$bin/wetgran-frame' '$tmp/cut/c.h5' | tail -n +2) <('$bin/wetgran-frame' '$tmp/plain/c.h5' | tail -n +2)"
"$top/scripts/archive-records" "$tmp/cut" "$tmp/arch2" 2> "$tmp/arch.err"
check "once filed complete, its checkpoint is dropped" bash -c "test -s '$tmp/arch2/c.h5' && test ! -e '$tmp/arch2/partial'"
"$top/scripts/record" "$tmp/arch" "$tmp/version" "$keep" "$bin/wetgran-run" "$tmp/scene.ini" $small > /dev/null 2> "$tmp/err"
rc=$?
check "no -o among the arguments: non-zero exit ($rc) naming it" bash -c "[ $rc -ne 0 ] && grep -q \"no '-o RUN.h5'\" '$tmp/err'"
# an archived record of the real archive: its key is what run-key makes of its command
arch=$top/data/records/fig3_4a/full
if [ -f "$arch/G1.2_E0.2.h5.rec" ]; then
  read -r -a c <<< "$(field "$arch/G1.2_E0.2.h5.rec" command)"
  a=("$bin/wetgran-run")
  for x in "${c[@]:1}"; do if [ -f "$top/$x" ]; then a+=("$top/$x"); else a+=("$x"); fi; done
  check "a filed fig3_4a record's key is run-key of its recorded command (the archive is reachable)" \
    test "$("$top/scripts/run-key" "${a[@]}")" = "$(field "$arch/G1.2_E0.2.h5.rec" key)"
fi
summary
