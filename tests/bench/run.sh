#!/bin/bash
# Benchmarks (numbers for the closing notes; never asserted in tests).
# Usage: tests/bench/run.sh BENCH_BIN_DIR TOOL_BIN_DIR.  Writes tests/bench/out/bench.tsv.
# BENCH_ONLY=peers runs only the comparison with EDMD and the baseline engine (peers.sh, which
# reads EDMD_SRC, BENCH_BASE, REPS, SCAN_MAX); BENCH_ONLY=rest only the resting beds (rest.sh);
# BENCH_ONLY=lists only neighbour lists against cells (lists.sh, REPS); BENCH_ONLY=rates only
# the event rates (shakers, gas, the Leidenfrost column, the shear field's hooks, wall solver, td);
# BENCH_ONLY=td_shaker only the last part
# (time-driven shaker: Verlet and Gear); BENCH_ONLY=lammps only the time-driven engine beside
# LAMMPS (lammps.sh, REPS).
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

if [ -z "${BENCH_ONLY:-}" ] || [ "${BENCH_ONLY:-}" = peers ]; then
echo "== the event-driven engine beside EDMD and beside its own baseline commit (tests/bench/peers.sh)"
"$here/peers.sh" "$bindir"
[ "${BENCH_ONLY:-}" = peers ] && exit 0
fi

if [ -z "${BENCH_ONLY:-}" ] || [ "${BENCH_ONLY:-}" = lammps ]; then
echo "== the time-driven engine beside LAMMPS, frictionless gas of 10 648 spheres (tests/bench/lammps.sh)"
"$here/lammps.sh" "$bindir"
[ "${BENCH_ONLY:-}" = lammps ] && exit 0
fi

if [ -z "${BENCH_ONLY:-}" ] || [ "${BENCH_ONLY:-}" = lists ]; then
echo "== neighbour lists (shell) against cells, same build (tests/bench/lists.sh)"
"$here/lists.sh" "$bindir"
[ "${BENCH_ONLY:-}" = lists ] && exit 0
fi

if [ -z "${BENCH_ONLY:-}" ] || [ "${BENCH_ONLY:-}" = rest ]; then
echo "== resting beds: events per time unit resting (rest_speed), fluidized and without the rule (tests/bench/rest.sh)"
"$here/rest.sh" "$bindir"
[ "${BENCH_ONLY:-}" = rest ] && exit 0
fi

if [ -z "${BENCH_ONLY:-}" ] || [ "${BENCH_ONLY:-}" = rates ]; then
echo "== event rates (events: collisions, bridge ruptures/reflections, wall hits; cell crossings apart)"
run "a_shake2d"            "$scenes/shake2d.ini" t_end=1000 profile_start=500 dt_checkpoint=0
run "b_gas3d_N1e5_phi0.3"  "$scenes/gas3d.ini" n=100000 t_end=2
run "c_shake3d_fig5.2c_N1e4" "$scenes/shake3d_5_2c.ini" t_end=30 dt_checkpoint=0
echo "== the Leidenfrost column (issue 45): 3e4 spheres, 400 d high, against the gas above"
# the thesis's Fig. 6.3 column for 20 t.u. after its plug has lifted (t = 10 ... 30 from the
# packed start), without height maps and with the figures' 1 d slabs every 0.5 t.u.: events/s
# of the column over the gas's (a container that cost per event would show here)
run "h_leidenfrost3d_N3e4"  "$scenes/leidenfrost3d.ini" t_end=30 height_bins=0 dt_checkpoint=0
run "i_leidenfrost3d_maps"  "$scenes/leidenfrost3d.ini" t_end=30 height_bins=402 dt_height=0.5 dt_checkpoint=0
awk -F'\t' '$1 ~ /^b_gas3d/ { g = $6 } $1 ~ /^h_leid/ { c = $6; w = $5 } $1 ~ /^i_leid/ { m = $5 }
  END { printf "leidenfrost column: %.3g events/s, %.2f x the gas'"'"'s; height maps cost %.1f %% of the wall time\n", c, c / g, 100 * (m / w - 1) }' "$tsv" | tee "$out/bench_leidenfrost.txt"
echo "== shear field (issue 42): cost of the hooks when the field is absent or off, and with it on"
# the same 3D wet shaker three times in a row: no field; a field that is never switched on
# (every hook's flag is tested, nothing else runs); the field on.  Ratios against the first.
sh3d="$scenes/shake3d_5_2c.ini t_end=10 dt_checkpoint=0"
run "e_shake3d_no_field"     $sh3d
run "f_shake3d_field_never_on" $sh3d shear_force=0.5 shear_on=1e9
run "g_shake3d_field_on"     $sh3d shear_force=0.5
awk -F'\t' '$1 ~ /^[efg]_shake3d/ { w[substr($1, 1, 1)] = $5 }
  END { printf "shear: wall time never-on / no field = %.3f, on / no field = %.3f\n", w["f"] / w["e"], w["g"] / w["e"] }' "$tsv" | tee "$out/bench_shear.txt"
echo "== exact wall solver against the brute-force scan at T_driv/1000 (same trajectories, same run)"
"$benchdir/bench_wall" | tee "$out/bench_wall.tsv"
echo "== time-driven engine: particle-steps/s of a 3D bed of 1e4 spheres; cost against event-driven for one state"
"$benchdir/bench_td" | tee "$out/bench_td.tsv"
[ "${BENCH_ONLY:-}" = rates ] && { echo "results: $tsv, $out/bench_wall.tsv, $out/bench_td.tsv"; exit 0; }
fi

echo "== time-driven 2D shaker: accuracy against cost for the time step dt = t_contact / k"
# A dry shaken bed (150 disks, eps = 0.8, Gamma = 10, E*_d = 4.5; tests/test_run_td.sh compares
# it with the event-driven engine), three seeds: the energy ledger's residual, the mean T_g
# over t = 20..60 (mean of the seeds, error from their spread) against the finest step
# (k = 400) and against the event-driven engine (hard disks, the t_contact -> 0 limit), and the
# cost per time unit.
bed="n=150 lx=50 eps=0.8 t_end=60 dt_series=0.5 dt_checkpoint=0 profile_bins=0 profile_start=30 dt_snapshot=0"
seeds="5 6 7"
tgmean() { "$bindir/wetgran-series" "$1" temperature | awk -F'\t' 'NR > 1 && $1 > 20 { s += $2; n++ } END { printf "%.6g\n", s / n }'; }
# mean and standard error over the seeds of: wetgran-run SCENE ARGS (prints "tg err")
seedmean() { for sd in $seeds; do "$bindir/wetgran-run" "$@" seed=$sd -q -o "$tmp/s.h5" 2> "$tmp/err.$sd"; tgmean "$tmp/s.h5"; done |
  awk '{ s += $1; s2 += $1 * $1; n++ } END { m = s / n; printf "%.6g\t%.3g\n", m, sqrt((s2 / n - m * m) / (n - 1)) }'; }
ed=$(seedmean "$scenes/shake2d_dry.ini" $bed)
shaker=$out/bench_td_shaker.tsv
echo -e "k\tdt\twall_s_per_time_unit\tparticle_steps_per_s\tledger_residual\ttg\ttg_err\ttg_rel_dev_k400\ttg_rel_dev_ed\tintegrator" > "$tmp/rows"
# both integrators: velocity Verlet (the default) and the thesis's Gear predictor-corrector;
# the reference T_g is Verlet's at k = 400
for ig in verlet gear; do
  for k in 400 200 100 50 25 12.5; do
    tg=$(seedmean "$scenes/shake2d_dry.ini" $bed engine=td tc= steps_per_contact=$k integrator=$ig)
    [ -z "${ref:-}" ] && ref=${tg%%$'\t'*}
    cat "$tmp"/err.* | grep '^summary:' | awk -v k=$k -v tg="$tg" -v ref=$ref -v ed="${ed%%$'\t'*}" -v ig=$ig '{
      for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] += kv[2] } n++ }
      END { split(tg, t, "\t")
      printf "%s\t%.4g\t%.4g\t%.4g\t%.3g\t%.5g\t%.3g\t%+.4f\t%+.4f\t%s\n", k, 0.005 / k, v["wall_s"] / n / 60, v["particle_steps_per_s"] / n,
        v["ledger_residual"] / n, t[1], t[2], t[1] / ref - 1, t[1] / ed - 1, ig }' >> "$tmp/rows"
  done
done
{ echo "# event-driven reference (3 seeds): T_g = ${ed%%$'\t'*} +- ${ed#*$'\t'}"; cat "$tmp/rows"; } | tee "$shaker"
echo "== wet shaker: the energy ledger of both integrators when bridges form and rupture"
# shake2d_td.ini at 300 disks on 100 d (elastic, F_B = 4 mg), 20 time units, three seeds: a
# bond switches on or off between steps; Verlet books the half step's work (td.c), Gear not
wet=$out/bench_td_wet.tsv
echo -e "k\tintegrator\twall_s_per_time_unit\tledger_residual\truptures_per_time_unit" > "$wet"
for ig in verlet gear; do
  for k in 100 50 25; do
    for sd in $seeds; do
      "$bindir/wetgran-run" "$scenes/shake2d_td.ini" n=300 lx=100 t_end=20 profile_start=10 dt_snapshot=0 \
        dt_checkpoint=0 steps_per_contact=$k integrator=$ig seed=$sd -q -o "$tmp/w.h5" 2> "$tmp/werr.$sd"
    done
    cat "$tmp"/werr.* | grep '^summary:' | awk -v k=$k -v ig=$ig '{ for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] += kv[2] } n++ }
      END { printf "%s\t%s\t%.4g\t%.3g\t%.4g\n", k, ig, v["wall_s"] / n / 20, v["ledger_residual"] / n, v["ruptures"] / n / 20 }' >> "$wet"
  done
done
cat "$wet"
gnuplot -e "tsv='$shaker'; png='$out/bench_td_shaker.png'" "$here/td_shaker.gp" && echo "plot: $out/bench_td_shaker.png"
[ -z "${BENCH_ONLY:-}" ] && echo "results: $tsv, $out/bench_wall.tsv, $out/bench_td.tsv, $shaker, $wet" || echo "results: $shaker, $wet"
