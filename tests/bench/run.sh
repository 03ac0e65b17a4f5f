#!/bin/bash
# Benchmarks (numbers for the closing notes; never asserted in tests).
# Usage: tests/bench/run.sh BENCH_BIN_DIR TOOL_BIN_DIR.  Writes tests/bench/out/bench.tsv.
set -eu
benchdir=${1:?}; bindir=$(cd "${2:?}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
scenes=$here/../../sim/scenes
out=$here/out
mkdir -p "$out"
tsv=$out/bench.tsv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo -e "case\tn\tevents\tcell_crossings\twall_s\tevents_per_s\tall_events_per_s\tns_per_event\tpeak_rss_kb\tengine_bytes_per_particle\trss_bytes_per_particle_above_baseline" > "$tsv"
# baseline: the resident memory of a run with a handful of particles (libraries, buffers)
"$bindir/wetgran-run" "$scenes/gas3d.ini" n=27 t_end=1 -q -o "$tmp/base.h5" 2> "$tmp/base.err"
base_kb=$(grep -o 'peak_rss_kb=[0-9]*' "$tmp/base.err" | cut -d= -f2)
echo "baseline peak RSS (27 particles): $base_kb kB"

# run NAME SCENE [key=value ...]: one wetgran-run, its summary line turned into a row
run() {
  local name=$1 scene=$2; shift 2
  "$bindir/wetgran-run" "$scene" "$@" -q -o "$tmp/run.h5" 2> "$tmp/err" || { cat "$tmp/err"; return 1; }
  local line n
  line=$(grep '^summary:' "$tmp/err")
  n=$(h5dump -d /particles/all/diameter -H "$tmp/run.h5" 2>/dev/null | grep -o 'DATASPACE  SIMPLE { ( [0-9]*' | grep -o '[0-9]*$')
  echo "$line" | awk -v name="$name" -v n="$n" -v base="$base_kb" '{
    for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
    ev = v["events"]; cc = v["cell_crossings"]; w = v["wall_s"]
    printf "%s\t%d\t%d\t%d\t%.3f\t%.4g\t%.4g\t%.1f\t%d\t%d\t%.0f\n", name, n, ev, cc, w, ev / w, (ev + cc) / w,
           1e9 * w / ev, v["peak_rss_kb"], v["engine_bytes_per_particle"], 1024 * (v["peak_rss_kb"] - base) / n
  }' | tee -a "$tsv"
  rm -f "$tmp/run.h5"
}

echo "== event rates (events: collisions, bridge ruptures/reflections, wall hits; cell crossings apart)"
run "a_shake2d"            "$scenes/shake2d.ini" t_end=1000 profile_start=500 dt_checkpoint=0
run "b_gas3d_N1e5_phi0.3"  "$scenes/gas3d.ini" n=100000 t_end=2
run "c_shake3d_fig5.2c_N1e4" "$scenes/shake3d_5_2c.ini" t_end=30 dt_checkpoint=0
echo "== cost per event against N (gas3d, phi = 0.3)"
for n in 1000 10000 100000 1000000; do
  run "d_gas3d_N$n" "$scenes/gas3d.ini" n=$n t_end=$(awk -v n=$n "BEGIN { print 2e6 / n }")
done
echo "== exact wall solver against the brute-force scan at T_driv/1000 (same trajectories, same run)"
"$benchdir/bench_wall" | tee "$out/bench_wall.tsv"
echo "== time-driven engine: particle-steps/s of a 3D bed of 1e4 spheres; cost against event-driven for one state"
"$benchdir/bench_td" | tee "$out/bench_td.tsv"
echo "results: $tsv, $out/bench_wall.tsv, $out/bench_td.tsv"
