#!/bin/bash
# lists.sh TOOL_BIN_DIR: the event-driven engine with neighbour lists (scene key shell) against
# the same build with its cells (shell = 0), in one invocation, the two runs of each scene one
# after the other, best of REPS (default 3).  Part of `make bench`, or BENCH_ONLY=lists.
# Scenes: the hard-sphere gas of the EDMD comparison (N = 108 000, phi = 0.30 and 0.42), the
# wet 3D shakers of Figs. 5.2c and 5.20, the Leidenfrost column of Fig. 6.3 and the 2D shaker
# of Fig. 3.4a.  Rates count collisions, bridge events and wall hits per second of wall time,
# set-up included.  Writes tests/bench/out/lists.tsv; about 10 minutes.
set -euo pipefail
case ${1:-} in --help|-h) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
bindir=$(cd "${1:?usage: lists.sh TOOL_BIN_DIR}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
S=$here/../../sim/scenes
out=$here/out
mkdir -p "$out"
tsv=$out/lists.tsv
reps=${REPS:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo -e "case\tshell\tcells_events_per_s\tlists_events_per_s\tratio\tcell_crossings_per_event\trelists_per_event\tcells_bytes_per_particle\tlists_bytes_per_particle" > "$tsv"

# rate SCENE ARGS...: "events/s bookkeeping-per-event bytes-per-particle" of one run
rate() {
  "$bindir/wetgran-run" "$@" -q -o "$tmp/run.h5" 2> "$tmp/err" || { cat "$tmp/err" >&2; return 1; }
  rm -f "$tmp/run.h5"
  grep '^summary:' "$tmp/err" | awk '{ for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
    printf "%.6g %.4f %d\n", v["events"] / v["wall_s"], v["cell_crossings"] / v["events"], v["engine_bytes_per_particle"] }'
}
best() { sort -k1,1g | tail -n 1; }

# one NAME SHELL SCENE ARGS...
one() {
  local name=$1 shell=$2; shift 2
  : > "$tmp/c"; : > "$tmp/l"
  for r in $(seq "$reps"); do
    rate "$@" shell=0 >> "$tmp/c"
    rate "$@" shell="$shell" >> "$tmp/l"
  done
  echo "$name $shell $(best < "$tmp/c") $(best < "$tmp/l")" | awk -v OFS='\t' '{
    print $1, $2, $3, $6, sprintf("%.3f", $6 / $3), $4, $7, $5, $8 }' | tee -a "$tsv"
}

one gas_phi0.30_N108000 0.5 "$S/gas3d.ini" n=108000 phi=0.30 t_end=8
one gas_phi0.42_N108000 0.5 "$S/gas3d.ini" n=108000 phi=0.42 t_end=3.5
one shake3d_fig5.2c_N10000 0.4 "$S/shake3d_5_2c.ini" t_end=20 dt_checkpoint=0
one shake3d_fig5.20_N7465 0.4 "$S/shake3d_5_20.ini" n=7465 lx=48 ly=48 t_end=20 dt_checkpoint=0
one leidenfrost3d_fig6.3_N30000 0.4 "$S/leidenfrost3d.ini" t_end=6 height_bins=0 dt_checkpoint=0
one shake2d_fig3.4a_N1200 0.4 "$S/shake2d.ini" t_end=300 profile_start=150 dt_checkpoint=0
echo "results: $tsv"
