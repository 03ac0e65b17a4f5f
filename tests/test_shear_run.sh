#!/bin/bash
# The shear field through wetgran-run: the series field_work, e_par and e_perp (Ch. 8) and the
# closed ledger in the run file, the field switched on and off, --help, a run resumed from its checkpoints (also from
# one taken at a switching time) identical to the uninterrupted run, and a run without a
# field writing none of it.
set -u
run=${WG_BIN:?}/wetgran-run
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"
py=/usr/bin/python3

args="$scenes/shake3d_5_2c.ini n=400 lx=12 ly=12 t_end=8 dt_series=0.25 dt_snapshot=2 profile_bins=8
      profile_start=1 eps=0.9 seed=2 shear_force=0.5 shear_on=1 shear_off=6 --no-volatile -q"
# shellcheck disable=SC2086
"$run" $args dt_checkpoint=1 -o "$tmp/a.h5" 2> "$tmp/a.err"; rc=$?
check "a sheared 3D wet shaker runs (exit $rc)" bash -c "[ $rc -eq 0 ]"
check "its series: field_work zero before t_on = 1, growing while on, constant after t_off = 6; ledger_residual < 1e-9" \
  "$py" - "$tmp/a.h5" <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
t = f['/observables/field_work/time'][:]; w = f['/observables/field_work/value'][:]
r = f['/observables/ledger_residual/value'][:]
assert f['/observables/field_work/value'].attrs['unit'] in (b'm d+2 tau-2', 'm d+2 tau-2')
assert np.all(w[t <= 1] == 0), w[t <= 1]
on = w[(t >= 1) & (t <= 6)]
assert abs(on[-1] - on[0]) > 1, on
after = w[t >= 6]
assert np.all(after == after[0]), after
assert r.max() < 1e-9, r.max()
assert float(f['/parameters'].attrs['shear_force']) == 0.5
EOF
check "e_par and e_perp (Ch. 8): per-particle sum m v_y^2 / 2 and m v_x^2 / 2 of the snapshots at t = 2, 4, 6, 8 (1e-12); equal at the isotropic start, e_par above e_perp by 1.3 while the field drives along y" \
  "$py" - "$tmp/a.h5" <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
t = f['/observables/e_par/time'][:]; par = f['/observables/e_par/value'][:]; perp = f['/observables/e_perp/value'][:]
ts = f['/particles/all/velocity/time'][:]; v = f['/particles/all/velocity/value'][:]; m = f['/particles/all/mass'][:]
n = 0
for k, tk in enumerate(ts):
    i = np.where(t == tk)[0]
    if len(i) == 0: continue
    n += 1
    assert abs(par[i[0]] - (0.5 * m * v[k][:, 1] ** 2).mean()) < 1e-12 * max(1, par[i[0]]), (tk, par[i[0]])
    assert abs(perp[i[0]] - (0.5 * m * v[k][:, 0] ** 2).mean()) < 1e-12 * max(1, perp[i[0]]), (tk, perp[i[0]])
assert n >= 4, n
on = (t > 3) & (t <= 6)
assert par[on].mean() > 1.3 * perp[on].mean(), (par[on].mean(), perp[on].mean())
assert abs(par[t == 0][0] / perp[t == 0][0] - 1) < 0.05
EOF
for k in 1 3 6; do
  rm -f "$tmp/b.h5" "$tmp/b.h5.ckpt"
  # shellcheck disable=SC2086
  "$run" $args dt_checkpoint=1 --abort-after-checkpoint $k -o "$tmp/b.h5" 2> /dev/null
  # shellcheck disable=SC2086
  "$run" $args dt_checkpoint=1 -o "$tmp/b.h5" 2> /dev/null
  check "stopped after checkpoint $k (t = $k) and resumed: the same run file" \
    bash -c "h5diff --exclude-path /provenance '$tmp/a.h5' '$tmp/b.h5' > /dev/null"
done
"$run" "$scenes/shake3d_5_2c.ini" n=400 lx=12 ly=12 t_end=2 seed=2 dt_checkpoint=0 -q -o "$tmp/c.h5" 2> /dev/null
check "without a field: no field_work, e_par or e_perp series, no shear_* parameters" \
  bash -c "! h5ls '$tmp/c.h5/observables' | grep -qE 'field_work|e_par|e_perp' && ! h5dump -A -g /parameters '$tmp/c.h5' | grep -q shear && h5dump -A -g /parameters '$tmp/c.h5' | grep -q grazing_angle"
check "--help lists shear_force, shear_bins, shear_on, shear_off" \
  bash -c "[ \$('$run' --help 2>&1 | grep -cE '^  shear_(force|bins|on|off) ') -eq 4 ]"
# container = box: the sheared systems of Ch. 7-8 (floor and lid at rest, lateral axes periodic)
cat > "$tmp/box.ini" <<'EOF'
engine = ed
dim = 3
container = box
n = 720
lx = 12
ly = 12
height = 7.5
sigma_p = 0
s_crit = 0.0625
e_cb_mgs = 6
tg_init = 40
seed = 1
t_end = 20
dt_series = 0.5
dt_snapshot = 1
shear_force = 2
dt_checkpoint = 0
EOF
"$run" "$tmp/box.ini" -q -o "$tmp/box.h5" 2> /dev/null; rc=$?
check "a sheared box (walls at rest): every snapshot within R <= z <= height - R, grains hit the walls, which do no work, ledger < 1e-9" \
  "$py" - "$tmp/box.h5" <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
z = f['/particles/all/position/value'][:, :, 2]; r = f['/particles/all/diameter'][:] / 2
assert z.shape[0] == 21 and np.all(z >= r - 1e-9) and np.all(z <= 7.5 - r + 1e-9), (z.min(), z.max())
assert f['/observables/wall_hits/value'][-1] > 1000
assert np.all(f['/observables/injected_wall/value'][:] == 0)
assert f['/observables/ledger_residual/value'][:].max() < 1e-9
assert np.all(f['/observables/walls/floor/value'][:] == 0) and np.all(f['/observables/walls/lid/value'][:] == 7.5)
EOF
grep -v shear_force "$tmp/box.ini" > "$tmp/box_still.ini"
"$run" "$tmp/box_still.ini" engine=td -o "$tmp/boxtd.h5" 2> "$tmp/boxtd.err"; rc=$?
check "container = box with engine = td is refused, naming both keys" \
  bash -c "[ $rc -ne 0 ] && grep -q \"'container' and 'engine'\" '$tmp/boxtd.err' && [ ! -e '$tmp/boxtd.h5' ]"
"$run" "$tmp/box.ini" gamma=5 -o "$tmp/boxg.h5" 2> "$tmp/boxg.err"; rc=$?
check "container = box with gamma is refused (walls at rest)" \
  bash -c "[ $rc -ne 0 ] && grep -q \"'gamma'\" '$tmp/boxg.err'"
"$run" "$scenes/shake2d.ini" shear_force=1 t_end=1 profile_start=0 -q -o "$tmp/d.h5" 2> "$tmp/d.err"; rc=$?
check "a 2D shaker with a field: exit $rc, one line naming shear_force and container" \
  bash -c "[ $rc -ne 0 ] && [ \$(wc -l < '$tmp/d.err') -eq 1 ] && grep -q \"'shear_force' and 'container'\" '$tmp/d.err' && [ ! -e '$tmp/d.h5' ]"
summary
