#!/bin/bash
# edmd.sh SRC BUILD_DIR N PHI T_END: build (once per N and PHI) and run EDMD, the event-driven
# hard-sphere code of F. Smallenburg (Eur. Phys. J. E 45, 22 (2022); MIT licence), on an elastic
# gas of N spheres (N = 4 k^3, FCC start) at packing fraction PHI in a periodic cube, no
# thermostat, to T_END (its units sigma = m = kT = 1, the units of sim/scenes/gas3d.ini).
# SRC is its folder Single/ (mdSingle.c, mdSingle.h, mt19937ar.c) from github.com/FSmallenburg/EDMD
# (on the project's machines: ../shared/peers/edmd).  Built with the peer's own flags
# (-Ofast -funroll-loops -march=native); EDMD_CFLAGS overrides them.  Prints one line:
#   edmd n=... phi=... collisions=... wall_s=... collisions_per_s=... peak_rss_kb=...
# The wall time is the whole run, set-up included, as wetgran's wall_s.
set -eu
case ${1:-} in --help|-h) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
src=${1:?} build=${2:?} n=${3:?} phi=${4:?} t_end=${5:?}
flags=${EDMD_CFLAGS:--Ofast -funroll-loops -march=native}
for f in mdSingle.c mdSingle.h mt19937ar.c; do
  [ -r "$src/$f" ] || { echo "edmd.sh: no $src/$f (EDMD_SRC must be EDMD's folder Single/)" >&2; exit 2; }
done
dir=$build/edmd_${n}_${phi}_${t_end}
if [ ! -x "$dir/md" ]; then
  mkdir -p "$dir"
  cp "$src/mdSingle.h" "$src/mt19937ar.c" "$dir/"
  # the run's parameters are globals at the top of mdSingle.c
  sed -e "s/^double maxtime = [0-9.]*;/double maxtime = $t_end;/" \
      -e "s/^int initialconfig = 0;/int initialconfig = 1;/" \
      -e "s/^double packfrac = [0-9.]*;/double packfrac = $phi;/" \
      -e "s/^int N = [0-9]*;/int N = $n;/" \
      -e "s/^const int usethermostat = 1;/const int usethermostat = 0;/" \
      "$src/mdSingle.c" > "$dir/md.c"
  for key in "maxtime = $t_end;" "packfrac = $phi;" "N = $n;" "usethermostat = 0;"; do
    grep -q "$key" "$dir/md.c" || { echo "edmd.sh: could not set '$key' in $src/mdSingle.c" >&2; exit 2; }
  done
  # shellcheck disable=SC2086
  gcc $flags -w "$dir/md.c" -o "$dir/md" -lm
fi
cd "$dir"
rm -f ./*.sph
s=$(date +%s.%N)
/usr/bin/time -f %M -o time.txt ./md > log
e=$(date +%s.%N)
c=$(grep '^Simtime' log | tail -n 1 | sed 's/.*Collisions: \([0-9]*\).*/\1/')
rm -f ./*.sph
awk -v n="$n" -v phi="$phi" -v c="$c" -v s="$s" -v e="$e" -v rss="$(cat time.txt)" 'BEGIN {
  w = e - s; printf "edmd n=%d phi=%s collisions=%d wall_s=%.3f collisions_per_s=%.4g peak_rss_kb=%d\n", n, phi, c, w, c / w, rss }'
