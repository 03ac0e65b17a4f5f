#!/bin/bash
# scripts/check-archive on a small made-up archive: a point re-simulated by the engine that
# made it is the same to the bit; under another engine version its numbers pass the z test
# when the physics agree and fail it when they do not; a changed scene is refused.
set -u
bin=${WG_BIN:?}
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"
t=$tmp/top
arch=$t/data/records/figX/full
mkdir -p "$t/sim/scenes" "$arch" "$t/experiments/figX/out/full/runs"
cp "$top/sim/scenes/shake2d.ini" "$t/sim/scenes/"
echo "cccc000000000000" > "$tmp/version"
small="n=200 lx=60 t_end=60 profile_start=20 profile_bins=10 dt_series=0.5 dt_checkpoint=0"
keep="--snapshots none --series temperature,bridges"
runs=$t/experiments/figX/out/full/runs
record() { (cd "$t/experiments/figX" && "$top/scripts/record" "$arch" "$tmp/version" "$keep" "$bin/wetgran-run" "$t/sim/scenes/shake2d.ini" $small "$@" -q -o "out/full/runs/$name.h5" 2> /dev/null); }
name=P1 record gamma=15 estar=1.42
"$top/scripts/archive-records" "$runs" "$arch" 2> /dev/null
check "check-archive: setup, one archived point" test -f "$arch/P1.h5.rec"
ca() { WG_TOP=$t WG_BIN=$bin WG_ENGINE_VERSION=$1 "$top/scripts/check-archive" figX 1 1 0 full > "$tmp/out" 2> "$tmp/err"; }
ca cccc000000000000; rc=$?
check "same engine version: exit 0 ($rc)" test "$rc" -eq 0
check "every number the same and the observables bit-identical" \
  bash -c "grep -q 'observables_bitwise.*pass' '$tmp/out' && [ \$(grep -c 'same	pass' '$tmp/out') -eq 9 ]"
check "the table is written to out/full/check-archive.tsv" test -s "$t/experiments/figX/out/full/check-archive.tsv"
check "and ends with the counts" test "$(tail -n 1 "$tmp/out")" = "10 passed, 0 failed"
ca dddd000000000000; rc=$?
check "another engine version, the same physics: the z tests pass (z = 0 here)" \
  bash -c "[ $rc -eq 0 ] && [ \$(grep -c '	0.00	pass' '$tmp/out') -eq 3 ] && grep -q 'label.*reported' '$tmp/out'"
# a record that is not what its command makes (Gamma = 30, filed under Gamma = 15's key):
# under the same version it differs; under another, T_g's z test fails
rm -rf "$runs"/*
name=P1 record gamma=30 estar=1.42
cp "$runs/P1.h5" "$arch/P1.h5"
ca cccc000000000000; rc=$?
check "a record that its command does not reproduce fails under the same version ($rc)" \
  bash -c "[ $rc -ne 0 ] && grep -q 'differs under the same engine version' '$tmp/out' && grep -q 'observables_bitwise.*FAIL' '$tmp/out'"
ca dddd000000000000; rc=$?
check "and under another version T_g's z test fails (z > 3.29)" \
  bash -c "[ $rc -ne 0 ] && awk -F'\t' '\$2 == \"tg_window_orderparam\" && \$7 > 3.29 && \$8 == \"FAIL\" { ok = 1 } END { exit !ok }' '$tmp/out'"
sed -i 's/^eps_wall *=.*/eps_wall = 0.9/' "$t/sim/scenes/shake2d.ini"
ca cccc000000000000; rc=$?
check "a scene file changed since the record: the point is refused" \
  bash -c "[ $rc -ne 0 ] && grep -q 'REFUSED (scene file or arguments changed' '$tmp/out'"
WG_TOP=$t "$top/scripts/check-archive" figY > /dev/null 2> "$tmp/err"; rc=$?
check "no archive for the figure: exit 2 naming it" bash -c "[ $rc -eq 2 ] && grep -q 'no archive' '$tmp/err'"
summary
