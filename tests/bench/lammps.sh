#!/bin/bash
# lammps.sh TOOL_BIN_DIR: wetgran's time-driven engine beside LAMMPS (Debian `lammps`, the peer
# a user of soft-sphere DEM would pick) on the same system, one program after the other, best
# of REPS (default 3): 22^3 = 10 648 frictionless spheres (d = m = 1) in a periodic cube at
# phi = 0.45, started on a simple cubic lattice with Gaussian velocities (T = 1), the linear
# spring-dashpot with e = 0.9 and contact time 0.005 for two unit masses (LAMMPS `gran/hooke`
# with k_n = 1.976e5, gamma_n = 42.15 /time, no tangential force), dt = 1e-4, skin 0.1, 20 000
# steps.  The same with the streams paper's contact law (Waitukaitis et al. 2011): tangential
# springs with history, k_t = k_n, gamma_t = gamma_n, Coulomb mu = 0.5, rotation (LAMMPS
# `gran/hooke/history`; wetgran mu = 0.5, kt_ratio = gt_ratio = 1).  Rates are atom-steps per second of wall time (LAMMPS: its loop time; wetgran: the
# run's, set-up and time series included).  The two cool alike (Haff): their temperatures at
# the end go beside the rates, as the check that the systems are the same.  (In LAMMPS's LJ
# units `lattice sc X` takes a density, not a spacing.)  Without `lmp` the LAMMPS column is nan and one
# line says so.  Part of `make bench`, or BENCH_ONLY=lammps.  Writes tests/bench/out/lammps.tsv.
set -euo pipefail
case ${1:-} in --help|-h) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
bindir=$(cd "${1:?usage: lammps.sh TOOL_BIN_DIR}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
S=$here/../../sim/scenes
out=$here/out
mkdir -p "$out"
reps=${REPS:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=10648 steps=20000
# the linear law of wetgran's scene (t_contact for m_eff = 1/2, restitution e), in LAMMPS's terms
read -r kn gn < <(awk 'BEGIN { pi = atan2(0, -1); e = 0.9; tc = 0.005; l = -log(e)
  k = 0.5 * (pi * pi + l * l) / (tc * tc); w0 = sqrt(k / 0.5); printf "%.10g %.10g\n", k, 2 * w0 * l / sqrt(pi * pi + l * l) }')
write_input() { # write_input FILE PAIR_STYLE_ARGS
cat > "$1" <<LMP
units           lj
atom_style      sphere
boundary        p p p
comm_modify     vel yes
variable        a equal (${n}/(0.45*6/PI))^(1.0/3.0)/22
variable        rho equal 1.0/(\${a}*\${a}*\${a})
lattice         sc \${rho}
region          box block 0 22 0 22 0 22
create_box      1 box
create_atoms    1 box
set             type 1 diameter 1.0
set             type 1 density 1.909859317102744
velocity        all create 1.0 12345 dist gaussian mom yes
pair_style      $2
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0 every 1 check yes
fix             1 all nve/sphere
timestep        1e-4
thermo          ${steps}
run             ${steps}
LMP
}
write_input "$tmp/gas.in" "gran/hooke ${kn} 0.0 ${gn} 0.0 0.0 0"
write_input "$tmp/fric.in" "gran/hooke/history ${kn} ${kn} ${gn} ${gn} 0.5 1"
lammps_rate() { # lammps_rate INPUT
  (cd "$tmp" && lmp -in "$1" -log none -echo none > lmp.out 2>&1) || { cat "$tmp/lmp.out" >&2; return 1; }
  awk -v n=$n -v s=$steps '$1 == s { t = $2 } /^Loop time of/ { printf "%.6g %.5g\n", n * s / $4, t }' "$tmp/lmp.out"
}
wetgran_rate() { # wetgran_rate [key=value ...]
  "$bindir/wetgran-run" "$S/gas3d.ini" engine=td n=$n phi=0.45 eps=0.9 contact=linear t_contact=0.005 \
    steps_per_contact=50 skin=0.1 t_end=2 dt_series=1 dt_checkpoint=0 "$@" -q -o "$tmp/td.h5" 2> "$tmp/err"
  echo "$(grep -o 'particle_steps_per_s=[^ ]*' "$tmp/err" | cut -d= -f2) $("$bindir/wetgran-series" "$tmp/td.h5" temperature | tail -n 1 | cut -f2)"
  rm -f "$tmp/td.h5"
}
have_lmp=1
command -v lmp > /dev/null || { have_lmp=0; echo "lammps.sh: no 'lmp' (Debian package lammps: scripts/install-deps.sh --bench); LAMMPS column nan"; }
echo -e "system\tn\tsteps\twetgran_atom_steps_per_s\tlammps_atom_steps_per_s\twetgran_over_lammps\twetgran_T_end\tlammps_T_end" > "$out/lammps.tsv"
# compare NAME LAMMPS_INPUT [wetgran key=value ...]: best of reps each, one row
compare() {
  local name=$1 input=$2; shift 2
  local best_w=0 best_l=nan tw=nan tl=nan w l
  for r in $(seq "$reps"); do
    read -r w tw < <(wetgran_rate "$@"); best_w=$(awk -v a="$w" -v b="$best_w" 'BEGIN { print (a > b ? a : b) }')
    l=nan
    if [ $have_lmp = 1 ]; then
      read -r l tl < <(lammps_rate "$input"); best_l=$(awk -v a="$l" -v b="$best_l" 'BEGIN { print (b == "nan" || a > b ? a : b) }')
    fi
    echo "  $name, round $r: wetgran $w atom-steps/s (T at the end $tw), LAMMPS $l (T $tl)"
  done
  awk -v name="$name" -v w="$best_w" -v l="$best_l" -v n=$n -v s=$steps -v tw="$tw" -v tl="$tl" 'BEGIN {
    printf "%s\t%d\t%d\t%.4g\t%s\t%s\t%s\t%s\n", name, n, s, w, l, (l == "nan" ? "nan" : sprintf("%.3f", w / l)), tw, tl }' >> "$out/lammps.tsv"
}
compare "frictionless gas, phi = 0.45" gas.in
compare "streams paper's law (friction 0.5, k_t = k_n, gamma_t = gamma_n), phi = 0.45" fric.in mu=0.5 kt_ratio=1 gt_ratio=1
cat "$out/lammps.tsv"
