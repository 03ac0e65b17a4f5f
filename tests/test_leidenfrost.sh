#!/bin/bash
# Height maps (height_bins, dt_height: /observables/heights, sim/run/maps.c) and wetgran-leidenfrost
# reading them (thesis Ch. 6): every grain's volume counted once (exact slices), the packing
# fraction the snapshots give, no effect on the trajectory, a resumed run byte-identical; the
# tool on synthetic maps with a known plug period, cushion height and gas, Eq. 6.5 as
# wetgran-theory plug, and bad input.
set -u
run=${WG_BIN:?}/wetgran-run
tool=$WG_BIN/wetgran-leidenfrost
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"
py=/usr/bin/python3
synth=$WG_TESTS/leidenfrost_synth.py

# a short Leidenfrost column: 900 spheres on 6 d x 6 d, 25 layers, E* = 98.9, Gamma = 60
base="$scenes/leidenfrost3d.ini n=900 lx=6 ly=6 height=120 t_end=6 dt_series=1 dt_checkpoint=2"
runin() { # runin DIR [extra args]
  local dir=$1; shift
  mkdir -p "$dir" && (cd "$dir" && "$run" $base -q --no-volatile "$@" -o run.h5 2> err)
}
hts="height_bins=488 dt_height=1"
runin "$tmp/a" $hts dt_snapshot=1; rc=$?
check "a run with height maps completes (exit $rc)" test "$rc" -eq 0
check "height maps: 7 frames x 488 slabs of the four fields, slabs over -A ... height + A" \
  $py -c "
import h5py; f = h5py.File('$tmp/a/run.h5', 'r'); g = f['observables/heights']
assert all(g[k]['value'].shape == (7, 488) for k in ('number_density', 'bridge_density', 'temperature', 'packing_fraction'))
A = f['parameters'].attrs['amplitude']
assert abs(g.attrs['z0'] + A) < 1e-12 and abs(g.attrs['span'] - 120 - 2 * A) < 1e-9"
check "every grain's volume counted once: sum phi x slab volume = sum of the grains' volumes (1e-12)" \
  $py -c "
import h5py, numpy as np; f = h5py.File('$tmp/a/run.h5', 'r'); g = f['observables/heights']
w = g.attrs['span'] / 488; phi = g['packing_fraction/value'][()]
r = f['particles/all/diameter'][()] / 2
v = (4 * np.pi / 3 * r ** 3).sum()
assert np.allclose(phi.sum(1) * w * 36, v, rtol=1e-12, atol=0), (phi.sum(1) * w * 36, v)
n = g['number_density/value'][()]; assert np.allclose(n.sum(1) * w * 36, 900, rtol=1e-12)"
check "packing fraction per slab = exact sphere slices of the snapshot at the same instant (1e-9)" \
  $py -c "
import h5py, numpy as np; f = h5py.File('$tmp/a/run.h5', 'r'); g = f['observables/heights']
z0, w = g.attrs['z0'], g.attrs['span'] / 488
pos = f['particles/all/position/value'][()]; tp = f['particles/all/position/time'][()]
rr = f['particles/all/diameter'][()] / 2
th = g['packing_fraction/time'][()]
def below(a, u):
    u = np.clip(u, -a, a); return np.pi * (a + u) ** 2 * (2 * a - u) / 3
edges = z0 + w * np.arange(489)
for k in (2, 6):
    i = int(np.argmin(abs(tp - th[k]))); assert tp[i] == th[k]
    z = pos[i][:, 2]
    vol = (below(rr[:, None], edges[None, 1:] - z[:, None]) - below(rr[:, None], edges[None, :-1] - z[:, None])).sum(0)
    phi = g['packing_fraction/value'][k]
    assert np.allclose(phi, vol / (w * 36), rtol=0, atol=1e-9), abs(phi - vol / (w * 36)).max()"
check "a run file with height maps passes the H5MD checker" $py "$WG_TESTS/h5md_check.py" "$tmp/a/run.h5"

runin "$tmp/b" dt_snapshot=1 height_bins=0
check "height maps do not change the trajectory: final positions and velocities bit-identical" \
  $py -c "
import h5py, numpy as np
a, b = h5py.File('$tmp/a/run.h5', 'r'), h5py.File('$tmp/b/run.h5', 'r')
for q in ('position', 'velocity'):
    assert np.array_equal(a['particles/all/%s/value' % q][-1], b['particles/all/%s/value' % q][-1])"
check "a run without height maps records no height keys (its checkpoint fingerprint as before)" \
  $py -c "
import h5py; p = h5py.File('$tmp/b/run.h5', 'r')['parameters'].attrs
assert not any(k.startswith('height_') or k == 'dt_height' for k in p), list(p)"

runin "$tmp/r" $hts height_samples=4 --abort-after-checkpoint 2; rc=$?
check "an aborted run with height maps leaves its checkpoint (exit $rc)" \
  bash -c "[ $rc -eq 3 ] && [ -e '$tmp/r/run.h5.ckpt' ]"
runin "$tmp/r" $hts height_samples=4
runin "$tmp/u" $hts height_samples=4
check "resumed run with height maps is byte-identical to the uninterrupted one" cmp -s "$tmp/r/run.h5" "$tmp/u/run.h5"

# 2D: exact disk slices, every disk's area once
"$run" "$scenes/shake2d.ini" t_end=4 profile_start=0 height_bins=90 dt_height=1 -q -o "$tmp/h2.h5" 2> /dev/null
check "2D height maps: sum phi x slab area = the disks' area (1e-12)" \
  $py -c "
import h5py, numpy as np; f = h5py.File('$tmp/h2.h5', 'r'); g = f['observables/heights']
w = g.attrs['span'] / 90; phi = g['packing_fraction/value'][()]; lx = f['parameters'].attrs['lx']
a = (np.pi * (f['particles/all/diameter'][()] / 2) ** 2).sum()
assert phi.shape == (5, 90) and np.allclose(phi.sum(1) * w * lx, a, rtol=1e-12, atol=0)"
"$run" "$scenes/shake2d.ini" t_end=4 height_bins=-3 -o "$tmp/bad.h5" 2> "$tmp/bad.err"; rc=$?
check "height_bins = -3 is refused, naming the key, no file" \
  bash -c "[ $rc -ne 0 ] && grep -q \"'height_bins'\" '$tmp/bad.err' && [ ! -e '$tmp/bad.h5' ]"

# the tool on synthetic maps: h_I = 50 + 10 sin(2 pi t / 25), plug 20 d of phi 0.62, a gas of
# 100/V_bead grains below, none above
$py "$synth" "$tmp/s.h5"
"$tool" oscillation --from 20 "$tmp/s.h5" > "$tmp/osc.tsv" 2> "$tmp/osc.err"; rc=$?
col() { awk -F'\t' -v c="$1" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i } NR == 2 { print $k }' "$2"; }
near() { awk -v g="$1" -v v="$2" -v t="$3" 'BEGIN { d = g - v; if (d < 0) d = -d; exit !(g == g + 0 && d <= t) }'; }
export -f near
check "oscillation: exit 0, one row" bash -c "[ $rc -eq 0 ] && [ \$(wc -l < '$tmp/osc.tsv') -eq 2 ]"
check "oscillation: T_p = 25 (+- 0.1) from $(col turning_points "$tmp/osc.tsv") turning points; got $(col t_p "$tmp/osc.tsv")" \
  near "$(col t_p "$tmp/osc.tsv")" 25 0.1
check "oscillation: omega_p = 2 pi / 25 = 0.2513 (+- 0.001)" near "$(col omega_p "$tmp/osc.tsv")" 0.25133 0.001
check "oscillation: h0 = 50 (+- 0.3 d, slabs of 0.25 d); got $(col h0 "$tmp/osc.tsv")" near "$(col h0 "$tmp/osc.tsv")" 50 0.3
check "oscillation: n_gas = 100 / V_bead = 191 (+- 30: h_I to within a slab, whose plug holds 30 grains); got $(col n_gas "$tmp/osc.tsv")" near "$(col n_gas "$tmp/osc.tsv")" 191 30
check "oscillation: half swing 10 d (+- 0.3), eps_rms = 10 / (sqrt 2 x 50) = 0.1414 (+- 0.003)" \
  bash -c "near $(col amplitude "$tmp/osc.tsv") 10 0.3 && near $(col eps_rms "$tmp/osc.tsv") 0.14142 0.003"
check "oscillation: plug 20 d (+- 0.5, two slabs) of phi 0.62 (+- 0.01), no gas above (less than a slab's grains, 0.012 N)" \
  bash -c "near $(col h_p "$tmp/osc.tsv") 20 0.5 && near $(col phi_plug "$tmp/osc.tsv") 0.62 0.01 && near $(col above_fraction "$tmp/osc.tsv") 0 0.012"
want=$("$WG_BIN/wetgran-theory" plug h0="$(col h0 "$tmp/osc.tsv")" n="$(col n_gas "$tmp/osc.tsv")" area=100 | awk -F'\t' '$1 == "omega_p" { print $2 }')
check "omega_theory = wetgran-theory plug's Eq. 6.5 at the measured h0 and n_gas (1e-4): $want" \
  near "$(col omega_theory "$tmp/osc.tsv")" "$want" 1e-4
"$tool" profiles --from 20 "$tmp/s.h5" > "$tmp/prof.tsv"
check "profiles: at the tops phi = 0.62 on 61-79 d and the gas below, at the bottoms 0.62 on 41-59 d" \
  awk -F'\t' 'NR > 1 { z = $2; if (z > 61 && z < 79 && ($3 < 0.615 || $3 > 0.625)) bad++;
    if (z > 41 && z < 59 && ($4 < 0.615 || $4 > 0.625)) bad++; if (z > 1 && z < 39 && $3 > 0.05) bad++; n++ }
    END { exit !(n == 808 && bad == 0) }' "$tmp/prof.tsv"
"$tool" profiles --from 20 --last 3 "$tmp/s.h5" > "$tmp/prof3.tsv"
check "profiles --last 3: three tops and three bottoms averaged" \
  awk -F'\t' 'NR == 2 { exit !($5 == 3 && $6 == 3) }' "$tmp/prof3.tsv"
"$tool" interface --from 25 --to 25 "$tmp/s.h5" > "$tmp/if.tsv"
check "interface at t = 25 (h_I = 50): h_i 50 +- 0.25, h_top 70 +- 0.25" \
  bash -c "near $(col h_i "$tmp/if.tsv") 50 0.25 && near $(col h_top "$tmp/if.tsv") 70 0.25"

"$tool" interface --from 20 "$tmp/s.h5" > "$tmp/if_all.tsv"
check "interface marks the same turning points as oscillation counts" \
  test "$(awk -F'\t' 'NR > 1 && $10 != 0' "$tmp/if_all.tsv" | wc -l)" -eq "$(col turning_points "$tmp/osc.tsv")"

# bubbling: a column at 0.3 of the mean from t = 101 on (the map frame at 101), plug 20 d high
$py "$synth" "$tmp/b.h5" hole=100
"$tool" bubbling --from 20 "$tmp/b.h5" > "$tmp/bub.tsv"
check "bubbling: onset at t = 101, emptiest column 0.3 x 16 / 15.3 of the mean, h_p 20 (+- 0.5), L / (pi h_p) = 10 / (20 pi) (+- 0.01)" \
  bash -c "near $(col onset_t "$tmp/bub.tsv") 101 1e-9 && near $(col min_column "$tmp/bub.tsv") 0.31373 1e-4 && \
    near $(col h_p "$tmp/bub.tsv") 20 0.5 && near $(col l_over_pi_hp "$tmp/bub.tsv") 0.159 0.01"
"$tool" bubbling --from 20 --hole 0.2 "$tmp/b.h5" > "$tmp/bub2.tsv"
check "bubbling: with --hole 0.2 no onset (nan), the emptiest column as before, the least h_p (20 +- 0.5)" \
  bash -c "[ '$(col onset_t "$tmp/bub2.tsv")' = nan ] && near $(col min_column "$tmp/bub2.tsv") 0.31373 1e-4 && near $(col h_p_min "$tmp/bub2.tsv") 20 0.5"
"$tool" bubbling "$tmp/s.h5" > /dev/null 2> "$tmp/nolat.err"; rc=$?
check "bubbling on a run without lateral maps: exit 1, the message says map_bins" \
  bash -c "[ $rc -eq 1 ] && grep -q 'map_bins' '$tmp/nolat.err'"

$py "$synth" "$tmp/flat.h5" a=0
"$tool" oscillation "$tmp/flat.h5" > "$tmp/flat.tsv" 2> "$tmp/flat.err"; rc=$?
check "a plug that does not oscillate: no period (nan), a message naming the turning points, exit 0" \
  bash -c "[ $rc -eq 0 ] && [ '$(col t_p "$tmp/flat.tsv")' = nan ] && grep -q 'turning points' '$tmp/flat.err'"
"$tool" oscillation "$tmp/b/run.h5" > /dev/null 2> "$tmp/nomap.err"; rc=$?
check "a run without height maps: exit 1, the message says height_bins" \
  bash -c "[ $rc -eq 1 ] && grep -q 'height_bins' '$tmp/nomap.err'"
"$tool" oscillation --phi-c 1.5 "$tmp/s.h5" > /dev/null 2>&1; rc=$?
check "--phi-c 1.5 is refused (exit 2)" test "$rc" -eq 2
"$tool" wobble "$tmp/s.h5" > /dev/null 2>&1; rc=$?
check "an unknown mode is refused (exit 2)" test "$rc" -eq 2
check "--help names the modes" bash -c "'$tool' --help | grep -q oscillation"

summary
