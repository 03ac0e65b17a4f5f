#!/bin/bash
# rest.sh TOOL_BIN_DIR: the cost of resting beds (`make bench`, or BENCH_ONLY=rest).  For each
# layer the same grains run three ways: fluidized (Gamma = 15), resting on a floor at Gamma = 0.8
# with the resting rule (rest_speed = 0.01), and at Gamma = 0.8 without it.  Events per time unit
# (collisions, bridge events, wall contacts) are counted over the second half of each run, after
# the layer has settled.  Also issue 43's bed (400 wet disks, 4 layers, Gamma = 1.01; fluidized
# at Gamma = 20).
# Writes tests/bench/out/rest.tsv; about 4 minutes.
set -euo pipefail
case ${1:-} in --help|-h) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
bindir=$(cd "${1:?usage: rest.sh TOOL_BIN_DIR}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
S=$here/../../sim/scenes
out=$here/out
mkdir -p "$out"
tsv=$out/rest.tsv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo -e "layer\tcase\tn\tt_end\tevents_per_time\twall_s" > "$tsv"

# one NAME CASE N SCENE key=value ...: events per time unit over the run's second half
one() {
  local layer=$1 case=$2 n=$3 scene=$4; shift 4
  "$bindir/wetgran-run" "$scene" n="$n" dt_snapshot=0 profile_bins=0 profile_start=0 \
    dt_checkpoint=0 "$@" -q -o "$tmp/run.h5" 2> "$tmp/err" || { cat "$tmp/err"; return 1; }
  local wall
  wall=$(grep -o 'wall_s=[0-9.]*' "$tmp/err" | cut -d= -f2)
  /usr/bin/python3 - "$tmp/run.h5" "$layer" "$case" "$n" "$wall" >> "$tsv" <<'PY'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
o = f["observables"]
t = np.asarray(o["collisions/time"])
ev = sum(np.asarray(o[k + "/value"], dtype=float)
         for k in ("collisions", "reflections", "ruptures", "wall_hits") if k in o)
h = len(t) // 2
print(f"{sys.argv[2]}\t{sys.argv[3]}\t{sys.argv[4]}\t{t[-1]:g}\t{(ev[-1] - ev[h]) / (t[-1] - t[h]):.4g}\t{sys.argv[5]}")
PY
  tail -1 "$tsv"
}

d2="$S/shake2d_dry.ini lx=100 eps=0.9 eps_wall=0.5 tg_init_abs=1 dt_series=0.5"
one 2d_dry fluidized 80 $d2 gamma=15 estar_d=4.5 t_end=100
one 2d_dry resting 80 $d2 gamma=0.8 estar_d=1 rest_speed=0.01 t_end=100
one 2d_dry no_rule 80 $d2 gamma=0.8 estar_d=1 t_end=10
w2="$S/shake2d.ini lx=100 eps=0.9 eps_wall=0.5 tg_init=0.01 dt_series=0.5"
one 2d_wet fluidized 80 $w2 gamma=15 estar=1.42 t_end=100
one 2d_wet resting 80 $w2 gamma=0.8 estar=5 rest_speed=0.01 t_end=100
one 2d_wet no_rule 80 $w2 gamma=0.8 estar=5 t_end=10
w3="$S/shake3d_5_2c.ini lx=10 ly=10 eps=0.9 eps_wall=0.5 tg_init=0.1 dt_series=0.5"
one 3d_wet fluidized 60 $w3 gamma=15 estar=1.42 t_end=40
one 3d_wet resting 60 $w3 gamma=0.8 estar=1 rest_speed=0.01 t_end=40
one 3d_wet no_rule 60 $w3 gamma=0.8 estar=1 t_end=5
bed="$S/shake2d.ini lx=100 gamma=1.01 eps=0.9 estar=5 t_end=36 dt_series=0.5"
one bed_400 fluidized 400 $bed gamma=20
one bed_400 no_rule 400 $bed
one bed_400 resting 400 $bed rest_speed=0.01
awk -F'\t' 'NR > 1 { r[$1 "/" $2] = $5 }
  END { for (l in r) { split(l, a, "/"); if (a[2] == "resting") {
          f = r[a[1] "/fluidized"]; o = r[a[1] "/no_rule"]
          printf "%s: resting / fluidized = %s, no rule / resting = %.3g\n", a[1],
                 f ? sprintf("%.3g", r[l] / f) : "-", o / r[l] } } }' "$tsv" | sort | tee "$out/rest_ratios.txt"
