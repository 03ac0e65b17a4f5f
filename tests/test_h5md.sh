#!/bin/bash
# Run files as standard H5MD 1.1 readers see them.  tests/h5md_check.py (rules from the H5MD
# 1.1 specification and its units module, plus wetgran's layout 2; --list prints them) passes
# every kind of run file wetgran-run makes: both engines, 2D and 3D, wet and dry, friction, the
# periodic gas, crashed-and-resumed runs; archived layout-1 runs pass the H5MD rules.  Planted
# faults are each named by their rule.  tests/h5md_read.py reads a run file as a user does
# with h5py (positions, box, a series with its unit, a parameter as a number, two datasets
# aligned by step), and a layout-1 file too; the analysis tools read both layouts.
set -u
run=${WG_BIN:?}/wetgran-run
here=$(cd "$(dirname "$0")" && pwd)
scenes=$(cd "$here/../sim/scenes" && pwd)
# layout-1 files: the archived runs, or the records cut from them (wetgran-reduce)
archive=$here/../data/runs
[ -e "$archive/fig3_2/full/seed1.h5" ] && [ -e "$archive/fig3_4a/full/G15_E1.4.h5" ] || archive=$here/../data/records
py=/usr/bin/python3
. "$here/checks.sh"

if ! "$py" -c 'import h5py' 2> /dev/null; then
  check "Debian's python3-h5py is installed (scripts/install-deps.sh)" false
  summary
  exit
fi
chk() { "$py" "$here/h5md_check.py" "$@"; }
# quiet CMD...: run CMD, showing its output only when it fails
quiet() { "$@" > "$tmp/quiet.out" 2>&1 || { cat "$tmp/quiet.out"; false; }; }

# snapshots every 1.25 and samples every 0.5: some instants have both, some one of them
E="t_end=6 dt_series=0.5 dt_snapshot=1.25 profile_bins=10 profile_start=3 dt_profile=0.5 dt_checkpoint=2"
E3="t_end=2 dt_series=0.5 dt_snapshot=1.25 profile_bins=4 profile_start=1 dt_profile=0.5 dt_checkpoint=1"
DRY="s_crit=0 f_b= estar= estar_d=2 tg_init= tg_init_abs=1"
runs=(
  "ed2_wet|$scenes/shake2d.ini n=300 lx=100 $E"
  "ed2_dry|$scenes/shake2d.ini n=300 lx=100 $DRY $E"
  "ed3_wet|$scenes/shake3d_5_2c.ini n=300 lx=10 ly=10 $E"
  "ed3_gas|$scenes/gas3d.ini n=300 $E"
  "td2_wet_rough|$scenes/shake2d_td.ini n=300 lx=100 mu=0.5 gt_ratio=0.5 $E3"
  "td2_dry|$scenes/shake2d_td.ini n=300 lx=100 $DRY $E3"
  "td3_wet|$scenes/shake2d_td.ini dim=3 n=200 lx=8 ly=8 $E3"
)
for r in "${runs[@]}"; do
  name=${r%%|*} args=${r#*|}
  mkdir -p "$tmp/$name"
  (cd "$tmp/$name" && "$run" $args -q --no-volatile -o run.h5 2> err); rc=$?
  check "$name: run completes (exit $rc)" test "$rc" -eq 0
  chk --expect-layout 2 "$tmp/$name/run.h5" > "$tmp/$name/check" 2>&1
  check "$name: conforms (H5MD 1.1, units module, layout 2)" \
    bash -c "[ ! -s '$tmp/$name/check' ] || { cat '$tmp/$name/check'; false; }"
done
# crash after the first checkpoint and resume: still conforming, and the same bytes
for r in "ed2_wet|${runs[0]#*|}" "td2_wet_rough|${runs[4]#*|}"; do
  name=${r%%|*} args=${r#*|}
  mkdir -p "$tmp/r_$name"
  (cd "$tmp/r_$name" && "$run" $args -q --no-volatile --abort-after-checkpoint 1 -o run.h5 2> err); rc=$?
  (cd "$tmp/r_$name" && "$run" $args -q --no-volatile -o run.h5 2> err)
  check "$name resumed: byte-identical to the uninterrupted run (abort exit $rc)" \
    bash -c "[ $rc -eq 3 ] && cmp -s '$tmp/$name/run.h5' '$tmp/r_$name/run.h5'"
  check "$name resumed: conforms" bash -c "[ -z \"\$('$py' '$here/h5md_check.py' --expect-layout 2 '$tmp/r_$name/run.h5')\" ]"
done

# one clock: the 2D wet run has samples at 0, 0.5, ... 6 and snapshots at 0, 1.25, ... 6
f=$tmp/ed2_wet/run.h5
check "clock: snapshot steps 0 3 6 9 12 14 (t = 0 1.25 2.5 3.75 5 6), series steps all but 3 and 9" \
  "$py" -c "
import h5py, numpy as np
f = h5py.File('$f')
ps = f['particles/all/position/step'][()].tolist(); ts = f['observables/temperature/step'][()].tolist()
assert ps == [0, 3, 6, 9, 12, 14], ps
assert ts == [k for k in range(15) if k not in (3, 9)], ts
assert f['observables/walls/floor/step'][()].tolist() == list(range(15))
"
check "planted: the checker's rules are listed" bash -c "chk() { '$py' '$here/h5md_check.py' \"\$@\"; }; [ \$(chk --list | grep -cE '^(H|T|P|U|W)[0-9] ') -ge 25 ]"

# planted faults, each in a copy of its own: the checker exits 1 naming the rule
faults="drop_version:H2 drop_author:H3 step_rows:T3 time_back:T5 step_float:T1 boundary_open:P3
        id_twice:P6 bad_unit:U3 fixed_unit:U2 foreign_symbol:W2 drop_layout:W1 drop_description:W3
        drop_step_meaning:W4 own_steps:W5 text_parameter:W7 wall_moved:W8 bridges_step:W9"
mkdir -p "$tmp/faults"
"$py" "$here/h5md_plant.py" "$f" "$tmp/faults" $(for fr in $faults; do echo "${fr%%:*}"; done)
chk --expect-layout 2 "$tmp"/faults/*.h5 > "$tmp/faults.out"; rc=$?
check "planted faults: the checker exits 1 (exit $rc)" test "$rc" -eq 1
for fr in $faults; do
  check "planted fault ${fr%%:*} is named ${fr##*:}" grep -q "^$tmp/faults/${fr%%:*}.h5: ${fr##*:} " "$tmp/faults.out"
done
check "every planted fault is tested" \
  bash -c "[ \$('$py' '$here/h5md_plant.py' --list | wc -l) -eq 17 ]"

# archived layout-1 runs (or records): the H5MD rules hold, and every tool reads them
old1=$archive/fig3_4a/full/G15_E1.4.h5 old2=$archive/fig3_2/full/seed1.h5
if [ -e "$old1" ] && [ -e "$old2" ]; then
  check "archived layout-1 runs conform to H5MD 1.1 (H, T, P rules)" \
    bash -c "[ -z \"\$('$py' '$here/h5md_check.py' '$old1' '$old2')\" ]"
  check "but are not layout 2 (W1 named when asked for it)" \
    bash -c "'$py' '$here/h5md_check.py' --expect-layout 2 '$old1' | grep -q ' W1 '"
  check "wetgran-orderparam reads a layout-1 file's text parameters (Gamma = 15)" \
    bash -c "'$WG_BIN/wetgran-orderparam' '$old1' 2> /dev/null | awk -F'\t' 'NR == 2 { exit !(\$2 == 15) }'"
  check "wetgran-series, -profiles, -frame read a layout-1 file" \
    bash -c "'$WG_BIN/wetgran-series' '$old1' temperature | tail -n 1 | grep -q . && '$WG_BIN/wetgran-profiles' '$old1' | tail -n 1 | grep -q . && '$WG_BIN/wetgran-frame' '$old2' | tail -n 1 | grep -q ."
  mkdir -p "$tmp/init_old"
  (cd "$tmp/init_old" && "$run" "$scenes/shake2d.ini" init_from="$old2" t_end=1 dt_checkpoint=0 profile_bins=0 profile_start=0 -q -o run.h5 2> err); rc=$?
  check "init_from a layout-1 run file (text parameters) works (exit $rc)" test "$rc" -eq 0
  check "python reads old-layout parameters next to new ones" quiet "$py" "$here/h5md_read.py" "$f" "$old2"
else
  check "archived runs $old1 and $old2 present" false
fi
check "python (h5py) reads positions, box, a series with its unit, a parameter, aligns by step" \
  quiet "$py" "$here/h5md_read.py" "$f"
# the same run with layout 1's text parameters: every tool prints the same
"$py" - "$f" "$tmp/as_text.h5" << 'EOF'
import shutil, sys, h5py, numpy as np
shutil.copyfile(sys.argv[1], sys.argv[2])
with h5py.File(sys.argv[2], "r+") as f:
    p = f["parameters"].attrs
    for k in list(p):
        v = p[k]
        if not isinstance(v, bytes):
            p[k] = np.bytes_(repr(float(v)) if isinstance(v, np.floating) else str(int(v)))
    del f["h5md/creator"].attrs["wetgran_layout"]
EOF
same_out() { # same_out TOOL: TOOL's output on both files, file names aside
  diff <("$WG_BIN/$1" "$f" 2>&1 | sed "s|$f||") <("$WG_BIN/$1" "$tmp/as_text.h5" 2>&1 | sed "s|$tmp/as_text.h5||") > /dev/null
}
for t in wetgran-orderparam wetgran-series wetgran-profiles wetgran-frame; do
  check "$t prints the same for typed and for text parameters" same_out "$t"
done
check "wetgran-orderparam reads typed parameters (Gamma = 15)" \
  bash -c "'$WG_BIN/wetgran-orderparam' '$f' 2> /dev/null | awk -F'\t' 'NR == 2 { exit !(\$2 == 15) }'"
mkdir -p "$tmp/init_new"
(cd "$tmp/init_new" && "$run" "$scenes/shake2d.ini" n=300 lx=100 init_from="$f" t_end=1 dt_checkpoint=0 profile_bins=0 profile_start=0 -q -o run.h5 2> err); rc=$?
check "init_from a layout-2 run file (typed parameters) works (exit $rc)" test "$rc" -eq 0
summary
