#!/bin/bash
# stress.sh BIN_DIR [--quick]: the stress matrix (issue 49), `make stress`; --quick: the subset
# CI runs (tests/test_stress.sh).  Each cell is a short run far from the figures' parameters;
# it passes when the run ends (exit 0, the stuck guard silent), the ledger closes (event-driven
# 1e-9 of the energy scale), and no two grains of the last snapshot overlap beyond the engine's
# tolerance (event-driven: 1e-9 d, hard spheres touch to round-off; time-driven: 0.1 d, twice
# what the softest contact of the matrix, t_contact = 0.02, reaches at the shaker's impact
# speeds, u t_c / pi ~ 0.03-0.05 d: an integration that diverges overlaps by far more).
# Writes tests/bench/out/stress.tsv: cell, events (or particle steps), wall s, ledger, largest
# overlap [d], verdict; prints "N passed, N failed".
set -u
bindir=$(cd "${1:?usage: stress.sh BIN_DIR [--quick]}" && pwd)
quick=0; [ "${2:-}" = --quick ] && quick=1
here=$(cd "$(dirname "$0")" && pwd)
S=$here/../sim/scenes
out=$here/bench/out
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3
passed=0 failed=0
table=$out/stress.tsv
[ $quick = 1 ] && table=$tmp/stress.tsv
echo -e "cell\tengine\tevents\twall_s\tledger\tmax_overlap_d\tverdict" > "$table"

# cell NAME ENGINE QUICK SCENE ARGS...: one run, its checks, one row
cell() {
  local name=$1 engine=$2 inquick=$3 scene=$4; shift 4
  [ $quick = 1 ] && [ "$inquick" = 0 ] && return 0
  local f=$tmp/$name.h5 rc
  timeout 600 "$bindir/wetgran-run" "$S/$scene" "$@" dt_checkpoint=0 -q -o "$f" 2> "$tmp/$name.err"; rc=$?
  local sum ev wall led ov verdict=pass why=""
  sum=$(grep '^summary:' "$tmp/$name.err")
  ev=$(sed -n 's/.*events=\([0-9]*\).*/\1/p' <<< "$sum"); [ -z "$ev" ] && ev=$(sed -n 's/.*particle_steps=\([0-9]*\).*/\1/p' <<< "$sum")
  wall=$(sed -n 's/.*wall_s=\([0-9.]*\).*/\1/p' <<< "$sum")
  led=$(sed -n 's/.*ledger_residual=\([0-9.e+-]*\).*/\1/p' <<< "$sum")
  ov=nan
  if [ $rc -ne 0 ]; then verdict=FAIL why="exit $rc: $(tail -n 1 "$tmp/$name.err")"
  else
    ov=$("$py" "$here/max_overlap.py" "$f")
    local tol=1e-9; [ "$engine" = td ] && tol=0.1
    if [ "$engine" = ed ] && ! awk -v l="$led" 'BEGIN { exit !(l <= 1e-9) }'; then verdict=FAIL why="ledger $led"; fi
    if ! awk -v o="$ov" -v t=$tol 'BEGIN { exit !(o <= t) }'; then verdict=FAIL why="$why overlap $ov"; fi
  fi
  echo -e "$name\t$engine\t${ev:-nan}\t${wall:-nan}\t${led:-nan}\t$ov\t$verdict" >> "$table"
  if [ $verdict = pass ]; then passed=$((passed + 1)); echo "ok    $name ($engine): ends, ledger ${led:-nan}, largest overlap $ov d"
  else failed=$((failed + 1)); echo "FAIL  $name ($engine): $why"; fi
  rm -f "$f"
}
# collapse NAME QUICK SCENE ARGS...: a cell that must stop with the stuck guard's diagnosis
collapse() {
  local name=$1 inquick=$2 scene=$3; shift 3
  [ $quick = 1 ] && [ "$inquick" = 0 ] && return 0
  local s0 rc wall
  s0=$(date +%s.%N)
  timeout 600 "$bindir/wetgran-run" "$S/$scene" "$@" dt_checkpoint=0 -q -o "$tmp/$name.h5" 2> "$tmp/$name.err"; rc=$?
  wall=$(awk -v a="$s0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  if [ $rc -eq 1 ] && grep -q 'the run is stuck (a rigid cluster or inelastic collapse)' "$tmp/$name.err" && [ ! -e "$tmp/$name.h5" ]; then
    passed=$((passed + 1)); echo "ok    $name (ed): inelastic collapse, stopped in $wall s with the diagnosis, no run file"
    echo -e "$name\ted\tnan\t$wall\tnan\tnan\tcollapse (stopped, diagnosed)" >> "$table"
  else
    failed=$((failed + 1)); echo "FAIL  $name: exit $rc, $(tail -n 1 "$tmp/$name.err")"
    echo -e "$name\ted\tnan\t$wall\tnan\tnan\tFAIL" >> "$table"
  fi
}
# td_pair NAME QUICK SCENE ARGS...: the cell at steps_per_contact 25 and 400; the ledger must fall
td_pair() {
  local name=$1 inquick=$2 scene=$3; shift 3
  [ $quick = 1 ] && [ "$inquick" = 0 ] && return 0
  cell "${name}_dt25" td "$inquick" "$scene" "$@" steps_per_contact=25
  cell "${name}_dt400" td "$inquick" "$scene" "$@" steps_per_contact=400
  local a b
  a=$(awk -v n="${name}_dt25" '$1 == n { print $5 }' "$table"); b=$(awk -v n="${name}_dt400" '$1 == n { print $5 }' "$table")
  local p
  p=$(awk -v a="$a" -v b="$b" 'BEGIN { if (a > 0 && b > 0) printf "%.2f", log(a / b) / log(16); else print "nan" }')
  if awk -v p="$p" 'BEGIN { exit !(p >= 1.3) }'; then passed=$((passed + 1)); echo "ok    $name: ledger $a at dt = t_c/25, $b at t_c/400: order $p (>= 1.3)"
  else failed=$((failed + 1)); echo "FAIL  $name: ledger $a at dt = t_c/25, $b at t_c/400: order $p (< 1.3)"; fi
  echo -e "${name}_order\ttd\tnan\tnan\t$p\tnan\t$(awk -v p="$p" 'BEGIN { print (p >= 1.3 ? "pass" : "FAIL") }')" >> "$table"
}

W="n=300 lx=100 profile_start=0"        # a 2D shaker of 300 wet disks
W3="n=400 lx=12 ly=12 profile_start=0"  # a 3D shaker of 400 wet spheres
# --- event-driven: the drive from resting to violent, the amplitude down to 1e-4 d
cell gamma0.5_wet           ed 1 shake2d.ini $W gamma=0.5 t_end=50
cell gamma1.01_wet          ed 0 shake2d.ini $W gamma=1.01 t_end=50
cell gamma15_wet            ed 1 shake2d.ini $W gamma=15 t_end=50
cell gamma1000_wet          ed 0 shake2d.ini $W gamma=1000 t_end=20
cell amp1e-4_wet            ed 0 shake2d.ini $W gamma=15 estar=0.0015 t_end=50
cell amp1e-4_dry            ed 0 shake2d_dry.ini $W gamma=15 estar_d=0.0015 t_end=50
# --- inelastic down to eps = 0.1, with and without the TC model, wet and dry, 2D and 3D
cell eps0.1_tc_wet          ed 1 shake2d.ini $W eps=0.1 eps_wall=0.5 t_end=50
cell eps0.1_tc_dry          ed 0 shake2d_dry.ini $W eps=0.1 eps_wall=0.5 t_end=50
# without the TC model hard spheres at eps = 0.1 collapse (McNamara and Young): infinitely many
# collisions in finite time.  The engine cannot run through it; the cell checks that it stops
# at once with its one-line diagnosis instead of hanging (the TC model is the cure)
collapse eps0.1_notc_dry    0 shake2d_dry.ini $W eps=0.1 eps_wall=0.5 tc=0 t_end=10
collapse eps0.1_notc_wet    0 shake2d.ini $W eps=0.1 eps_wall=0.5 tc=0 t_end=10
cell eps0.1_tc_wet_3d       ed 1 shake3d_5_2c.ini $W3 eps=0.1 eps_wall=0.5 t_end=10
cell eps0.5_gamma1000_3d    ed 0 shake3d_5_2c.ini $W3 eps=0.5 gamma=1000 t_end=5
# --- dense gases (the lattice start's limits: 2D 0.75, 3D 0.45), elastic and inelastic
cell dense2d_phi0.75        ed 1 gas3d.ini dim=2 n=2000 phi=0.75 t_end=2
cell dense3d_phi0.45        ed 0 gas3d.ini n=2000 phi=0.45 t_end=2
cell dense3d_phi0.45_wet    ed 0 gas3d.ini n=2000 phi=0.45 s_crit=0.1 e_cb=0.5 t_end=2
# --- the rigid bonded cluster that once hung an inelastic wet run
cell rigid_cluster_seed1    ed 0 shake2d.ini eps=0.96 gamma=15 estar=1.9 seed=1 profile_start=0 t_end=300
# --- time-driven: soft and stiff contacts, cohesion on and off, two steps each
T="n=150 lx=50 profile_start=0 t_end=5"                                  # a wet 2D shaker
G="engine=td n=1000 phi=0.3 eps=0.9 contact=linear t_end=2 dt_series=0.5" # a dry 3D gas
td_pair td_soft_wet   1 shake2d_td.ini $T t_contact=0.02
td_pair td_stiff_wet  0 shake2d_td.ini $T t_contact=0.001
td_pair td_soft_dry   0 gas3d.ini $G t_contact=0.02
td_pair td_stiff_dry  0 gas3d.ini $G t_contact=0.001
td_pair td_cohesive_gas 0 gas3d.ini $G t_contact=0.005 s_crit=0.1 e_cb=0.5
[ $quick = 0 ] && echo "table: $table"
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
