#!/bin/bash
# large.sh TOOL_BIN_DIR: `make bench-large` (not in CI).  Free cooling of 2.5 10^6 wet spheres in
# a periodic cube of edge 600 d (thesis Fig. 2.6; sim/scenes/cool3d_wet.ini): events/s, cell
# crossings/s, peak memory and wall time of the whole run, T_g and the bridge count against
# time, and the cluster picture (a slab 20 d thick through the final state).  About 17 min, 0.75 GB.
# T_END=... shortens or lengthens the run (default: the scene's 40 time units).
set -euo pipefail
case ${1:-} in --help|-h) sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
bindir=$(cd "${1:?usage: large.sh TOOL_BIN_DIR}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
out=$here/out
mkdir -p "$out"
run=$out/large.h5
args=()
[ -n "${T_END:-}" ] && args+=(t_end="$T_END" dt_snapshot="$T_END")
"$bindir/wetgran-run" "$here/../../sim/scenes/cool3d_wet.ini" "${args[@]}" -o "$run" 2> "$out/large.log" || {
  cat "$out/large.log"; exit 1; }
grep '^summary:' "$out/large.log" | tee "$out/large_summary.txt"
"$bindir/wetgran-series" "$run" temperature bridges > "$out/large_series.tsv"
# the slab |z - L/2| < 10 of the last snapshot, as x y
/usr/bin/python3 - "$run" "$out/large_slab.tsv" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    r = f["/particles/all/position/value"][-1]
    box = f["/particles/all/box/edges"][()]
z = r[:, 2] % box[2]
s = np.abs(z - 0.5 * box[2]) < 10
np.savetxt(sys.argv[2], r[s, :2] % box[:2], fmt="%.3f", delimiter="\t")
PY
gnuplot -e "slab='$out/large_slab.tsv'; png='$out/large.png'" "$here/large.gp"
echo "results: $out/large_summary.txt $out/large_series.tsv $out/large.png (run file $run)"
