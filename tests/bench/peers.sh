#!/bin/bash
# peers.sh TOOL_BIN_DIR: the event-driven engine side by side with EDMD (the fastest public
# event-driven hard-sphere code we know) and with wetgran's own engine of an earlier commit,
# in one invocation, one program after the other (never two at once).  Part of `make bench`.
#
#   EDMD_SRC=DIR   EDMD's folder Single/ (github.com/FSmallenburg/EDMD, MIT licence; on the
#                  project's machines ../shared/peers/edmd).  Unset: EDMD is skipped, said once.
#   BENCH_BASE=C   the commit whose engine is the baseline (default: the engine before the
#                  engine-speed work, 363c15b); built once into tests/bench/out/base-C/.
#   REPS=3         best of REPS for every side-by-side rate.
#   SCAN_MAX=N     largest N of the scan of events/s against N (default 2456500 = 4 * 85^3).
#
# Writes to tests/bench/out/: peers.tsv (gas, N = 108 000, phi = 0.30 and 0.42), scenes.tsv
# (wetgran against its baseline on the 2D shaker, the Fig. 5.2c 3D shaker and a thin-thread
# wet gas), scan.tsv and scan.png (events/s against N at phi = 0.30, EDMD beside).
# Rates count collisions (wetgran: every event but cell crossings) per second of wall time,
# set-up included for both codes; runs are long enough for set-up to be a few per cent.
set -euo pipefail
case ${1:-} in --help|-h) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
bindir=$(cd "${1:?usage: peers.sh TOOL_BIN_DIR}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
scenes=$top/sim/scenes
out=$here/out
mkdir -p "$out"
reps=${REPS:-3}
base=${BENCH_BASE:-363c15b}
scan_max=${SCAN_MAX:-2456500}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

edmd=
if [ -n "${EDMD_SRC:-}" ]; then
  edmd=$(cd "$EDMD_SRC" && pwd)
else
  echo "peers: EDMD_SRC not set: EDMD's columns are skipped (EDMD_SRC=<EDMD's Single/ folder>, see docs/benchmarks.md)"
fi

# the baseline engine, built from its commit
basedir=$out/base-$base
if [ ! -x "$basedir/bin/wetgran-run" ]; then
  echo "peers: building the baseline engine of commit $base in $basedir"
  rm -rf "$basedir" && mkdir -p "$basedir"
  git -C "$top" archive "$base" | tar -x -C "$basedir"
  make -C "$basedir" -s bin/wetgran-run > "$basedir/build.log" 2>&1 || { cat "$basedir/build.log"; exit 1; }
fi
old=$basedir/bin/wetgran-run
new=$bindir/wetgran-run

# wg BIN SCENE ARGS...: "events wall_s rate peak_rss_kb bytes_per_particle" of one run
wg() {
  local bin=$1; shift
  "$bin" "$@" -q -o "$tmp/run.h5" 2> "$tmp/err" || { cat "$tmp/err" >&2; return 1; }
  rm -f "$tmp/run.h5"
  grep '^summary:' "$tmp/err" | awk '{ for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
    printf "%d %.3f %.6g %d %d\n", v["events"], v["wall_s"], v["events"] / v["wall_s"], v["peak_rss_kb"], v["engine_bytes_per_particle"] }'
}
# ed N PHI T_END: the same for EDMD
ed() {
  "$here/edmd.sh" "$edmd" "$out/edmd-build" "$@" | awk '{ for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
    printf "%d %.3f %.6g %d 0\n", v["collisions"], v["wall_s"], v["collisions_per_s"], v["peak_rss_kb"] }'
}
# best of the rows on stdin: the row with the highest rate (field 3)
best() { sort -k3,3g | tail -n 1; }

echo "== gas: N = 108 000 elastic spheres, periodic cube, best of $reps (EDMD, wetgran, wetgran at $base)"
peers=$out/peers.tsv
echo -e "phi\tn\tedmd_collisions_per_s\twetgran_events_per_s\tbase_events_per_s\twetgran_over_edmd\twetgran_over_base\tedmd_peak_rss_kb\twetgran_peak_rss_kb\twetgran_engine_bytes_per_particle" > "$peers"
for phi in 0.30 0.42; do
  # about 40 collisions per particle: 4e6 events, 5-15 s per run
  t_end=$(awk -v phi=$phi 'BEGIN { print phi < 0.35 ? 8 : 3.5 }')
  : > "$tmp/e"; : > "$tmp/n"; : > "$tmp/o"
  for r in $(seq "$reps"); do
    [ -n "$edmd" ] && ed 108000 $phi "$t_end" >> "$tmp/e"
    wg "$new" "$scenes/gas3d.ini" n=108000 phi=$phi t_end="$t_end" >> "$tmp/n"
    wg "$old" "$scenes/gas3d.ini" n=108000 phi=$phi t_end="$t_end" >> "$tmp/o"
  done
  e=$(best < "$tmp/e"); n=$(best < "$tmp/n"); o=$(best < "$tmp/o")
  echo "$phi ${e:-0 0 0 0 0} $n $o" | awk -v OFS='\t' '{ re = $4; rn = $9; rb = $14
    print $1, 108000, (re > 0 ? re : "nan"), rn, rb, (re > 0 ? sprintf("%.3f", rn / re) : "nan"), sprintf("%.3f", rn / rb), (re > 0 ? $5 : "nan"), $10, $11 }' | tee -a "$peers"
done

echo "== scenes: wetgran against its baseline (commit $base), best of $reps"
sc=$out/scenes.tsv
echo -e "case\tn\twetgran_events_per_s\tbase_events_per_s\tratio\twetgran_engine_bytes_per_particle" > "$sc"
scene_case() {
  local name=$1 n=$2; shift 2
  : > "$tmp/n"; : > "$tmp/o"
  for r in $(seq "$reps"); do
    wg "$new" "$@" >> "$tmp/n"
    wg "$old" "$@" >> "$tmp/o"
  done
  echo "$name $n $(best < "$tmp/n") $(best < "$tmp/o")" | awk -v OFS='\t' '{
    print $1, $2, $5, $10, sprintf("%.3f", $5 / $10), $7 }' | tee -a "$sc"
}
scene_case shake2d_fig3.4a 1200 "$scenes/shake2d.ini" t_end=300 profile_start=150 dt_checkpoint=0
scene_case shake3d_fig5.2c 10000 "$scenes/shake3d_5_2c.ini" t_end=20 dt_checkpoint=0
scene_case wet_gas_thin_thread 10976 "$scenes/gas3d.ini" n=10976 phi=0.3 s_crit=0.1 e_cb=0.5 t_end=10

echo "== scan: events/s against N, gas at phi = 0.30 (one run each; >= 10 collisions per particle)"
scan=$out/scan.tsv
echo -e "n\twetgran_events_per_s\twetgran_ns_per_event\twetgran_peak_rss_kb\twetgran_engine_bytes_per_particle\tedmd_collisions_per_s\tedmd_ns_per_collision\tedmd_peak_rss_kb" > "$scan"
for k in 7 10 16 22 30 40 50 63 80 85; do
  n=$((4 * k * k * k))
  [ "$n" -le "$scan_max" ] || continue
  # gas at phi = 0.3: about 5 collisions per particle per time unit
  t_end=$(awk -v n=$n 'BEGIN { e = n * 12; if (e < 4e6) e = 4e6; printf "%.4g\n", e / (5 * n) }')
  w=$(wg "$new" "$scenes/gas3d.ini" n=$n phi=0.3 t_end="$t_end" dt_series="$t_end")
  e="0 0 0 0 0"
  [ -n "$edmd" ] && e=$(ed $n 0.30 "$t_end")
  echo "$n $w $e" | awk -v OFS='\t' '{ nan = "nan"
    print $1, $4, sprintf("%.0f", 1e9 / $4), $5, $6, ($9 > 0 ? $9 : nan), ($9 > 0 ? sprintf("%.0f", 1e9 / $9) : nan), ($9 > 0 ? $10 : nan) }' | tee -a "$scan"
done
gnuplot -e "tsv='$scan'; png='$out/scan.png'" "$here/scan.gp" && echo "plot: $out/scan.png"
awk -F'\t' 'NR > 1 && $1 >= 1000 && $1 <= 1100000 { if (!lo) lo = $3; hi = $3 }
  END { if (lo) printf "cost per event, N = 1e3 -> 1e6: x%.2f\n", hi / lo }' "$scan" | tee "$out/scan_growth.txt"
echo "results: $peers $sc $scan"
