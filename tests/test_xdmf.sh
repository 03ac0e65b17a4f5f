#!/bin/bash
# wetgran-xdmf: the XDMF view of a run's snapshots.  The XML parses and holds one grid per
# snapshot at its time; beside the run it names the run file, elsewhere its absolute path;
# errors are clear.  Where ParaView is installed (scripts/install-deps.sh --viz: Debian
# paraview, python3-paraview, xvfb), pvpython reads it, 2D and 3D, and finds every snapshot,
# every grain, the arrays, and the last snapshot's positions and velocities as wetgran-frame
# prints them, and renders a frame (under xvfb-run: Debian's ParaView needs an X display).
set -u
run=${WG_BIN:?}/wetgran-run
xdmf=${WG_BIN}/wetgran-xdmf
frame=${WG_BIN}/wetgran-frame
py=/usr/bin/python3
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
. "$here/checks.sh"

check "--help" bash -c "'$xdmf' --help | grep -q ParaView"
"$run" "$scenes/shake2d.ini" n=300 lx=100 t_end=6 dt_snapshot=0.5 profile_start=0 dt_checkpoint=0 -q -o "$tmp/run2.h5" 2> /dev/null
"$run" "$scenes/shake3d_5_2c.ini" n=400 lx=12 ly=12 t_end=3 dt_snapshot=0.5 profile_start=0 dt_checkpoint=0 -q -o "$tmp/run3.h5" 2> /dev/null
"$xdmf" "$tmp/run2.h5"; rc=$?
check "beside the run: run2.xdmf written (exit $rc), no temporary left" \
  bash -c "[ $rc -eq 0 ] && [ -s '$tmp/run2.xdmf' ] && [ ! -e '$tmp/run2.xdmf.tmp' ]"
mkdir -p "$tmp/elsewhere"
"$xdmf" "$tmp/run3.h5" -o "$tmp/elsewhere/view3.xdmf"
grids() { # grids FILE: "count first_time last_time HDF-file-names" of the XML
  "$py" - "$1" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
g = root.findall('./Domain/Grid/Grid')
t = [float(x.find('Time').get('Value')) for x in g]
files = sorted({d.text.split(':')[0] for d in root.iter('DataItem') if d.get('Format') == 'HDF'})
print(len(g), t[0], t[-1], ' '.join(files))
PY
}
read -r n2 t0 t1 f2 <<< "$(grids "$tmp/run2.xdmf")"
check "2D: 13 grids, from t = 0 to 6 ($n2, $t0, $t1)" test "$n2 $t0 $t1" = "13 0.0 6.0"
check "2D beside the run: the run file by its name ($f2)" test "$f2" = run2.h5
read -r n3 t0 t1 f3 <<< "$(grids "$tmp/elsewhere/view3.xdmf")"
check "3D: 7 grids, from t = 0 to 3 ($n3, $t0, $t1)" test "$n3 $t0 $t1" = "7 0.0 3.0"
check "3D elsewhere: the run file by its absolute path ($f3)" test "$f3" = "$(realpath "$tmp/run3.h5")"
"$xdmf" "$tmp/none.h5" 2> "$tmp/err1"; rc=$?
check "missing run: non-zero exit, named" bash -c "[ $rc -ne 0 ] && grep -q none.h5 '$tmp/err1'"
"${WG_BIN}/wetgran-reduce" "$tmp/run2.h5" -o "$tmp/nosnap.h5" --snapshots none 2> /dev/null
"$xdmf" "$tmp/nosnap.h5" 2> "$tmp/err2"; rc=$?
check "a record without snapshots: exit 1, says so, nothing written" \
  bash -c "[ $rc -eq 1 ] && grep -q snapshots '$tmp/err2' && [ ! -e '$tmp/nosnap.xdmf' ]"

if command -v pvpython > /dev/null && command -v xvfb-run > /dev/null; then
  for d in 2 3; do
    if [ $d = 2 ]; then view=$tmp/run2.xdmf nf=13; else view=$tmp/elsewhere/view3.xdmf nf=7; fi
    "$frame" "$tmp/run$d.h5" > "$tmp/frame$d.tsv"
    # xvfb-run's server is sometimes not ready when ParaView connects ("bad X server
    # connection", about one start in four here): such a start is tried again, up to 3 times
    for attempt in 1 2 3; do
      (cd "$tmp" && timeout 300 xvfb-run -a pvpython "$here/pv_check.py" "$view" "$tmp/frame$d.tsv" "$tmp/pv$d.png" $nf 2> "$tmp/pv$d.err") > "$tmp/pv$d.out"
      grep -q 'bad X server connection' "$tmp/pv$d.err" || break
      echo "# ${d}D: the X server was not ready (start $attempt)"
    done
    while read -r status what; do
      check "${d}D ParaView: $what" test "$status" = ok
    done < <(grep -E '^(ok|FAIL)' "$tmp/pv$d.out")
    check "${d}D ParaView: four checks reported" test "$(grep -cE '^(ok|FAIL)' "$tmp/pv$d.out")" -eq 4
    check "${d}D ParaView: a frame rendered to PNG" bash -c "[ \"\$(head -c 4 '$tmp/pv$d.png' | tail -c 3)\" = PNG ]"
  done
else
  echo "# ParaView not installed (scripts/install-deps.sh --viz): the pvpython checks are not run"
fi
summary
