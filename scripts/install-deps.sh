#!/bin/sh
# Installs the Debian packages wetgran needs, if any is missing.  Run as root (or with sudo).
set -e
PKGS="build-essential pkg-config libhdf5-dev hdf5-tools libgsl-dev gnuplot-nox libqhull-dev libfftw3-dev python3-h5py time ffmpeg"
# --bench: also the peers `make bench` runs beside wetgran (LAMMPS)
[ "${1:-}" = --bench ] && PKGS="$PKGS lammps"
# --viz: ParaView for tests/test_xdmf.sh's pvpython checks (about 0.5 GB; xvfb: Debian's
# ParaView renders through an X display)
[ "${1:-}" = --viz ] && PKGS="$PKGS paraview python3-paraview xvfb xauth"
# --cluster: Slurm and munge, for tests/test_slurm.sh's single-node cluster (SCHED=slurm)
[ "${1:-}" = --cluster ] && PKGS="$PKGS slurm-wlm munge"
missing=""
for p in $PKGS; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "wetgran: installing Debian packages:$missing" >&2
SUDO=""
[ "$(id -u)" = 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
