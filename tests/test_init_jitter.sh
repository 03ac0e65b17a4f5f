#!/bin/bash
# init_jitter: seeds of one recorded state (the relaxations of Fig. 5.14).  The jitter
# multiplies each velocity component by 1 + init_jitter x (x Gaussian from the seed), moves
# no particle, and seeds then part; the same seed gives the same run; no jitter, the state.
set -u
run=${WG_BIN:?}/wetgran-run
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"
py=/usr/bin/python3
base="$scenes/shake3d_5_2c.ini n=400 lx=12 ly=12 estar=20 dt_checkpoint=0 -q --no-volatile"
"$run" $base t_end=10 -o "$tmp/src.h5" 2> /dev/null
for s in 1 2; do "$run" $base t_end=10 dt_snapshot=10 init_from="$tmp/src.h5" init_jitter=1e-6 seed=$s -o "$tmp/j$s.h5" 2> /dev/null; done
"$run" $base t_end=10 dt_snapshot=10 init_from="$tmp/src.h5" init_jitter=1e-6 seed=1 -o "$tmp/j1b.h5" 2> /dev/null
"$run" $base t_end=10 dt_snapshot=10 init_from="$tmp/src.h5" seed=5 -o "$tmp/j0.h5" 2> /dev/null
check "t = 0: positions as recorded, velocities within 1e-6 x 6 relative, none equal to all digits" \
  $py -c "
import h5py, numpy as np
s = h5py.File('$tmp/src.h5', 'r')['particles/all']; j = h5py.File('$tmp/j1.h5', 'r')['particles/all']
assert j['position/time'][0] == 0
dz = j['position/value'][0] - s['position/value'][-1]   # lab frame: the floor's phase restarts
assert np.array_equal(dz[:, :2], 0 * dz[:, :2]) and np.ptp(dz[:, 2]) < 1e-12
v0, v = s['velocity/value'][-1], j['velocity/value'][0]
rel = np.abs(v / v0 - 1)
assert rel.max() < 6e-6 and rel.min() >= 0 and np.count_nonzero(rel) > 0.99 * rel.size, (rel.max(), np.count_nonzero(rel))
assert 0.5e-6 < np.sqrt((rel ** 2).mean()) < 1.5e-6"
check "seeds part: the final states of seeds 1 and 2 differ by more than a diameter somewhere" \
  $py -c "
import h5py, numpy as np
a = h5py.File('$tmp/j1.h5', 'r')['particles/all/position/value'][-1]
b = h5py.File('$tmp/j2.h5', 'r')['particles/all/position/value'][-1]
assert np.abs(a - b).max() > 1"
check "the same seed twice: the same trajectory bit for bit (only the command line differs)" \
  h5diff -q --exclude-path /provenance "$tmp/j1.h5" "$tmp/j1b.h5"
check "without jitter the seed does not matter: t = 0 is the recorded state exactly" \
  $py -c "
import h5py, numpy as np
s = h5py.File('$tmp/src.h5', 'r')['particles/all']; j = h5py.File('$tmp/j0.h5', 'r')['particles/all']
assert np.array_equal(j['velocity/value'][0], s['velocity/value'][-1])"
"$run" $base t_end=10 init_jitter=1e-6 -o "$tmp/bad.h5" 2> "$tmp/bad.err"; rc=$?
check "init_jitter without init_from: refused naming both keys, no file" \
  bash -c "[ $rc -ne 0 ] && grep -q \"'init_jitter' and 'init_from'\" '$tmp/bad.err' && [ ! -e '$tmp/bad.h5' ]"
summary
