#!/bin/bash
# Lateral maps (map_bins, dt_map: /observables/maps, sim/run/maps.c) and wetgran-interface reading
# them: every particle counted once per sample, the bridges of the series, the same field as
# the snapshots give on the same cells and instants, a resumed run byte-identical, no effect
# on the trajectory, an unfinished window leaving no frame, the 2D row of cells.
set -u
run=${WG_BIN:?}/wetgran-run
tool=$WG_BIN/wetgran-interface
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"
py=/usr/bin/python3

# 3D wet shaker, 400 spheres on 12 d x 12 d, maps of 4 x 3 cells (3 d x 4 d), one sample per
# window of 2 t.u., snapshots at the same instants
base="$scenes/shake3d_5_2c.ini n=400 lx=12 ly=12 estar=20 t_end=10 dt_series=2 dt_checkpoint=4"
runin() { # runin DIR [extra args]
  local dir=$1; shift
  mkdir -p "$dir" && (cd "$dir" && "$run" $base -q --no-volatile "$@" -o run.h5 2> err)
}
maps="map_bins=4 map_bins_y=3 dt_map=2 map_samples=1"
runin "$tmp/a" $maps dt_snapshot=2; rc=$?
check "a run with maps completes (exit $rc)" test "$rc" -eq 0
check "maps: frames x 3 x 4 cells for the three fields" \
  $py -c "
import h5py; f = h5py.File('$tmp/a/run.h5', 'r'); g = f['observables/maps']
assert all(g[k]['value'].shape == (6, 3, 4) for k in ('number_density', 'bridge_density', 'temperature'))
assert list(g.attrs['cells']) == [4, 3] and g.attrs['window'] == 2"
check "every particle counted once per frame: sum of n over cells x cell area = 400" \
  $py -c "
import h5py, numpy as np; f = h5py.File('$tmp/a/run.h5', 'r')
n = f['observables/maps/number_density/value'][()]
assert np.allclose(n.sum(axis=(1, 2)) * 3.0 * 4.0, 400, rtol=1e-12, atol=0)"
check "bridges: sum of n_cb x cell area = the series' bridge count at the same instants" \
  $py -c "
import h5py, numpy as np; f = h5py.File('$tmp/a/run.h5', 'r')
b = f['observables/maps/bridge_density/value'][()].sum(axis=(1, 2)) * 12.0
t = f['observables/maps/bridge_density/time'][()]
st, sv = f['observables/bridges/time'][()], f['observables/bridges/value'][()]
want = np.array([sv[np.argmin(abs(st - x))] for x in t])
assert np.all(abs(st[[np.argmin(abs(st - x)) for x in t]] - t) == 0), 'instants differ'
assert want.max() > 0 and np.allclose(b, want, rtol=1e-12, atol=1e-9), (b, want)"
check "the run file with maps passes the H5MD checker" $py "$WG_TESTS/h5md_check.py" "$tmp/a/run.h5"

"$tool" field --t-fg 5 --source maps "$tmp/a/run.h5" > "$tmp/fm.tsv" 2> "$tmp/fm.err"
"$tool" field --t-fg 5 --source snapshots --bins 4x3 "$tmp/a/run.h5" > "$tmp/fs.tsv" 2> "$tmp/fs.err"
check "field from the maps = field from the snapshots on the same cells and instants (n, n_cb, T_g to 1e-9)" \
  bash -c "paste '$tmp/fm.tsv' '$tmp/fs.tsv' | awk -F'\t' '!/^#/ && \$1 != \"file\" { \
    rows++; for (c = 4; c <= 6; c++) { a = \$c; b = \$(c + 10); d = a - b; if (d < 0) d = -d; \
    if (d > 1e-9 * (a < 0 ? -a : a) + 1e-12) bad++ } } END { exit !(rows == 12 && bad == 0) }'"
"$tool" field --source maps --bins 8x8 "$tmp/a/run.h5" > /dev/null 2> "$tmp/bins.err"; rc=$?
check "--bins other than the maps' cells is refused, naming them" \
  bash -c "[ $rc -ne 0 ] && grep -q '4x3 cells' '$tmp/bins.err'"

# no maps, no snapshots: the same trajectory (the last snapshot is always written)
runin "$tmp/b"
check "maps do not change the trajectory: the final snapshot is bit-identical" \
  h5diff -q "$tmp/a/run.h5" "$tmp/b/run.h5" /particles/all/position/value /particles/all/position/value
check "maps do not change the trajectory: the final snapshot is bit-identical (velocities)" \
  $py -c "
import h5py, numpy as np
a = h5py.File('$tmp/a/run.h5', 'r')['particles/all/velocity/value'][-1]
b = h5py.File('$tmp/b/run.h5', 'r')['particles/all/velocity/value'][-1]
assert np.array_equal(a, b)"

# crash after the second checkpoint (t = 8, a window open), resume: identical file
runin "$tmp/r" $maps dt_snapshot=2 map_samples=4 --abort-after-checkpoint 2; rc=$?
check "an aborted run with maps leaves its checkpoint (exit $rc)" \
  bash -c "[ $rc -eq 3 ] && [ -e '$tmp/r/run.h5.ckpt' ]"
runin "$tmp/r" $maps dt_snapshot=2 map_samples=4
runin "$tmp/u" $maps dt_snapshot=2 map_samples=4
check "resumed run with maps is byte-identical to the uninterrupted one" cmp -s "$tmp/r/run.h5" "$tmp/u/run.h5"

# windows of 3 t.u. to t_end = 10: three frames (the window [9, 12) is unfinished), times
# at the windows' sample centres 0 + 4.5 x 0.3 = 1.35, 4.35, 7.35
runin "$tmp/w" map_bins=2 dt_map=3 map_samples=10
check "an unfinished window leaves no frame; frame times are the windows' centres" \
  $py -c "
import h5py, numpy as np; t = h5py.File('$tmp/w/run.h5', 'r')['observables/maps/temperature/time'][()]
assert np.allclose(t, [1.35, 4.35, 7.35], rtol=0, atol=1e-12), t"

# 2D: one row of cells per frame; map_bins_y other than 1 is refused naming the key
"$run" "$scenes/shake2d.ini" t_end=20 profile_start=0 map_bins=10 dt_map=5 -q -o "$tmp/m2.h5" 2> /dev/null
check "2D maps: frames x 10 cells" \
  $py -c "import h5py; assert h5py.File('$tmp/m2.h5', 'r')['observables/maps/number_density/value'].shape == (4, 10)"
"$tool" spacetime "$tmp/m2.h5" > "$tmp/st.tsv"
check "spacetime reads a 2D run's maps: 4 frames x 10 cells" \
  test "$(awk -F'\t' 'NF == 4 && $1 != "t"' "$tmp/st.tsv" | wc -l)" -eq 40
"$run" "$scenes/shake2d.ini" t_end=20 profile_start=0 map_bins=10 map_bins_y=2 -o "$tmp/bad.h5" 2> "$tmp/bad.err"; rc=$?
check "2D map_bins_y = 2 is refused, naming the key, no file" \
  bash -c "[ $rc -ne 0 ] && grep -q \"'map_bins_y'\" '$tmp/bad.err' && [ ! -e '$tmp/bad.h5' ]"

summary
