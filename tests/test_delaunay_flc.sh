#!/bin/bash
# wetgran-delaunay-flc (thesis Sec. 3.A.1.1, f_lc; Sec. 4.3.3, layer diffusion) on exact cases
# written with awk as --tsv text input: a static lattice has no location changes, a slip of
# half a triangular lattice by one spacing flips exactly one diagonal per column, swapping two
# neighbours makes exactly 6 new neighbour pairs, a rigid motion through the periodic faces
# changes nothing (2D and 3D); random walks with known D per layer are recovered; then a real
# run, and errors that must name the file.
set -u
tool=${WG_BIN:?}/wetgran-delaunay-flc
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"
# value KEY FILE: the value column of row KEY of a key/value/error table
value() { awk -F'\t' -v k="$1" '$1 == k { print $2; f = 1 } END { exit !f }' "$2"; }
# column NAME FILE: that column of every data row of a table with a header
column() { awk -F'\t' -v c="$1" 'NR == 1 { for (i = 1; i <= NF; i++) k[$i] = i; next } { print $k[c] }' "$2"; }
# within A B REL: |A - B| <= REL |B|
within() { awk -v a="$1" -v b="$2" -v r="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a == a + 0 && d <= r * (b < 0 ? -b : b)) }'; }
export -f value column within

# Triangular lattice, spacing 1 d (touching disks), NX columns periodic in x, NY rows between
# walls, every site moved by up to +-0.04 d (deterministic: srand(seed)), so that no four
# centres are cocircular and the triangulation is unique.  One snapshot per unit of time.
#   mode=static   no motion
#   mode=slide    rows NY/2 ... NY-1 slide by -1 d in K steps (and back in K more if F > K+1)
#   mode=swap     particles A and B exchange places at snapshot 3 and back at snapshot 6
#   mode=move     everything moves by (vx, vy) per snapshot, wrapped through x = 0
lattice() {
  awk "$@" 'BEGIN {
    srand(seed); h = sqrt(3) / 2; n = 0
    for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
      X[n] = i + 0.5 * (j % 2) + 0.25 + 0.04 * (2 * rand() - 1)
      Y[n] = 0.5 + j * h + 0.04 * (2 * rand() - 1); row[n] = j; n++ }
    printf "# box %d %.10g periodic none\n", nx, ny * h + 1
    print "# a comment line"; print "time\tid\tx\ty"
    for (f = 0; f < F; f++) for (p = 0; p < n; p++) {
      x = X[p]; y = Y[p]; q = p
      if (mode == "slide" && row[p] >= ny / 2) x -= (f <= K ? f : 2 * K - f) / K
      if (mode == "swap" && f >= 3 && f < 6) q = (p == A ? B : p == B ? A : p)
      if (mode == "move") { x += vx * f; y += vy * f }
      x -= nx * int(x / nx); if (x < 0) x += nx
      printf "%g\t%d\t%.12g\t%.12g\n", f, q, x, y } }'
}
# the same in 3D: a simple cubic lattice NX x NY x NZ, periodic in x and y, walls in z,
# sites moved by up to +-0.08 d
cubic() {
  awk "$@" 'BEGIN {
    srand(seed); n = 0
    for (k = 0; k < nz; k++) for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
      X[n] = i + 0.5 + 0.08 * (2 * rand() - 1); Y[n] = j + 0.5 + 0.08 * (2 * rand() - 1)
      Z[n] = k + 0.5 + 0.08 * (2 * rand() - 1); n++ }
    printf "# box %d %d %d periodic periodic none\n", nx, ny, nz + 1
    for (f = 0; f < F; f++) for (p = 0; p < n; p++) {
      q = p
      if (mode == "swap" && f >= 3 && f < 6) q = (p == A ? B : p == B ? A : p)
      printf "%g %d %.12g %.12g %.12g\n", f, q, X[p] + vx * f, Y[p] + vy * f, Z[p] } }'
}
changes() { value changes "$1"; } # total location changes of a --summary table
export -f changes

check "--help names the thesis section of f_lc (3.A.1.1) and of the layer diffusion (4.3.3)" \
  bash -c "'$tool' --help > '$tmp/help' && grep -q 'Sec. 3.A.1.1' '$tmp/help' && grep -q 'Fig. 3.28a' '$tmp/help' && grep -q 'Sec. 4.3.3' '$tmp/help'"

# (1) static perturbed lattice: nothing changes
lattice -v seed=1 -v nx=8 -v ny=6 -v F=5 -v mode=static > "$tmp/static.tsv"
"$tool" --tsv "$tmp/static.tsv" > "$tmp/static.out" 2> "$tmp/static.err"; rc=$?
check "static 2D lattice: exit 0, nothing on stderr" bash -c "[ $rc -eq 0 ] && [ ! -s '$tmp/static.err' ]"
check "static 2D lattice: header t_mid dt changes f_lc f_lc_per_particle, 4 intervals" \
  bash -c "[ \"\$(head -n 1 '$tmp/static.out')\" = \$'t_mid\tdt\tchanges\tf_lc\tf_lc_per_particle' ] && [ \$(wc -l < '$tmp/static.out') -eq 5 ]"
check "static 2D lattice: f_lc = 0 in every interval" \
  bash -c "[ \"\$(column f_lc '$tmp/static.out' | sort -u)\" = 0 ]"

# (2a) slip: the upper three rows slide by one spacing over the lower three.  Between the two
# rows at the slip plane every cell of two columns flips its diagonal once, when the upper
# pair passes over the lower one (the four centres are then nearly cocircular), so a slip by
# one spacing makes exactly NX = 8 changes, and sliding back 8 more; nothing else moves
# relative to its neighbours.
lattice -v seed=1 -v nx=8 -v ny=6 -v F=21 -v K=20 -v mode=slide > "$tmp/slide.tsv"
"$tool" --tsv "$tmp/slide.tsv" --summary > "$tmp/slide.sum"
check "slip by one spacing: exactly 8 changes (one per column)" test "$(changes "$tmp/slide.sum")" = 8
check "slip: f_lc = 8 / 20 time units, per particle / 48" \
  bash -c "within \"\$(value f_lc '$tmp/slide.sum')\" 0.4 1e-9 && within \"\$(value f_lc_per_particle '$tmp/slide.sum')\" \$(awk 'BEGIN { print 0.4 / 48 }') 1e-6"
lattice -v seed=2 -v nx=10 -v ny=6 -v F=15 -v K=7 -v mode=slide > "$tmp/slide2.tsv"
"$tool" --tsv "$tmp/slide2.tsv" --summary > "$tmp/slide2.sum"
check "slip there and back (10 columns, other jitter, 7 steps each way): exactly 20 changes" \
  test "$(changes "$tmp/slide2.sum")" = 20
"$tool" --tsv "$tmp/slide2.tsv" --from 3.5 --to 12 --summary > "$tmp/win.sum"
check "--from 3.5 --to 12: snapshots 4 ... 12, the 10 changes of the slip back (7 ... 12)" \
  bash -c "[ \$(value snapshots '$tmp/win.sum') = 9 ] && [ \$(value t_from '$tmp/win.sum') = 4 ] && [ \$(value t_to '$tmp/win.sum') = 12 ] && [ \$(value changes '$tmp/win.sum') = 10 ]"

# (2b) two neighbours in the middle of the lattice (particles 19, 20: row 2, columns 3, 4)
# exchange places: each of them has 6 neighbours, 2 in common, so each gains the other's 3
# others: 6 new pairs; exchanging back restores the first 6.
lattice -v seed=1 -v nx=8 -v ny=6 -v F=8 -v A=19 -v B=20 -v mode=swap > "$tmp/swap.tsv"
"$tool" --tsv "$tmp/swap.tsv" > "$tmp/swap.out"
check "swap of two neighbours: 6 changes at the swap, 6 at the swap back, 0 otherwise" \
  test "$(column changes "$tmp/swap.out" | tr '\n' ' ')" = "0 0 6 0 0 6 0 "

# (3) rigid motion by 1.3 box lengths through the periodic faces (x), drifting in y: nothing
# changes.  With --margin 0.5 the copies are too thin at first and must grow (same answer).
lattice -v seed=3 -v nx=8 -v ny=6 -v F=36 -v mode=move -v vx=0.3 -v vy=0.01 > "$tmp/move.tsv"
"$tool" --tsv "$tmp/move.tsv" --summary > "$tmp/move.sum"
"$tool" --tsv "$tmp/move.tsv" --summary --margin 0.5 > "$tmp/move05.sum"
check "rigid motion through the periodic faces: f_lc = 0 (margin 3 and 0.5)" \
  bash -c "[ \$(changes '$tmp/move.sum') = 0 ] && [ \$(changes '$tmp/move05.sum') = 0 ] && [ \$(value f_lc '$tmp/move.sum') = 0 ]"

# (3b) a dilute gas: 40 disks random-walking in 16 d x 8 d (periodic x, walls y).  Its
# triangles are large; copies 0.3 d thick are too thin (and do not reach the walls' mirror
# planes, 0.5 d beyond the outermost centres), so the check must grow them: the table must
# equal the one with copies of the whole box.
awk -v seed=5 'BEGIN { srand(seed); n = 40; L = 16; H = 8
  for (p = 0; p < n; p++) { X[p] = L * rand(); Y[p] = 0.5 + (H - 1) * rand() }
  printf "# box %d %d periodic none\n", L, H
  for (f = 0; f < 30; f++) for (p = 0; p < n; p++) {
    if (f > 0) { X[p] += 0.6 * (rand() - 0.5); Y[p] += 0.6 * (rand() - 0.5)
      if (Y[p] < 0.5) Y[p] = 1 - Y[p]; if (Y[p] > H - 0.5) Y[p] = 2 * H - 1 - Y[p] }
    X[p] -= L * int(X[p] / L); if (X[p] < 0) X[p] += L
    printf "%g\t%d\t%.12g\t%.12g\n", f, p, X[p], Y[p] } }' > "$tmp/gas.tsv"
"$tool" --tsv "$tmp/gas.tsv" --margin 0.3 > "$tmp/gas03.out" 2> "$tmp/gas03.err"
"$tool" --tsv "$tmp/gas.tsv" --margin 16 > "$tmp/gas16.out"
check "dilute gas: copies 0.3 d (grown where needed) and 16 d give the same table, f_lc > 0" \
  bash -c "cmp -s '$tmp/gas03.out' '$tmp/gas16.out' && [ ! -s '$tmp/gas03.err' ] && [ \$(column changes '$tmp/gas16.out' | awk '{ s += \$1 } END { print s }') -gt 0 ]"

# (4) 3D: simple cubic 6 x 6 x 4, periodic in x and y (margin 1 d: quicker, same answer)
cubic -v seed=3 -v nx=6 -v ny=6 -v nz=4 -v F=4 > "$tmp/sc.tsv"
"$tool" --tsv "$tmp/sc.tsv" --summary --margin 1 > "$tmp/sc.sum"; rc=$?
check "3D static lattice: exit 0, f_lc = 0, 144 particles" \
  bash -c "[ $rc -eq 0 ] && [ \$(changes '$tmp/sc.sum') = 0 ] && [ \$(value particles '$tmp/sc.sum') = 144 ]"
cubic -v seed=3 -v nx=6 -v ny=6 -v nz=4 -v F=8 -v A=57 -v B=58 -v mode=swap > "$tmp/sc_swap.tsv"
"$tool" --tsv "$tmp/sc_swap.tsv" --margin 1 > "$tmp/sc_swap.out"
read -r c1 c2 <<< "$(column changes "$tmp/sc_swap.out" | awk 'NR == 3 { a = $1 } NR == 6 { b = $1 } END { print a, b }')"
check "3D hop (two neighbours exchange places): $c1 new pairs, as many at the swap back, 0 otherwise" \
  bash -c "[ '$c1' -gt 0 ] && [ '$c1' = '$c2' ] && [ \$(column changes '$tmp/sc_swap.out' | awk '\$1 != 0' | wc -l) -eq 2 ]"
cubic -v seed=4 -v nx=6 -v ny=6 -v nz=4 -v F=10 -v vx=0.9 -v vy=-0.7 > "$tmp/sc_move.tsv"
"$tool" --tsv "$tmp/sc_move.tsv" --summary --margin 1 > "$tmp/sc_move.sum"
check "3D rigid motion through both periodic faces: f_lc = 0" test "$(changes "$tmp/sc_move.sum")" = 0

# (5) --diffusion: 2D random walkers in x, box 20 d periodic, three layers of 150 at heights
# 1, 3, 5 with D = 0, 0.002, 0.01 (steps of sd sqrt(2 D dt), dt = 0.5, 401 snapshots)
awk -v seed=7 'function gauss() { return sqrt(-2 * log(1 - rand())) * cos(6.283185307179586 * rand()) }
  BEGIN { srand(seed); L = 20; dt = 0.5; n = 0
    for (l = 0; l < 3; l++) for (k = 0; k < 150; k++) {
      X[n] = L * rand(); Y[n] = 1 + 2 * l + 0.2 * (rand() - 0.5); D[n] = l == 0 ? 0 : l == 1 ? 0.002 : 0.01; n++ }
    printf "# box %d 7 periodic none\n", L
    for (f = 0; f < 401; f++) for (p = n - 1; p >= 0; p--) {
      if (f > 0) X[p] += sqrt(2 * D[p] * dt) * gauss()
      X[p] -= L * int(X[p] / L); if (X[p] < 0) X[p] += L
      printf "%.10g\t%d\t%.12g\t%.12g\n", f * dt, p, X[p], Y[p] } }' > "$tmp/walk.tsv"
"$tool" --tsv "$tmp/walk.tsv" --diffusion --layers 3 --max-lag 10 > "$tmp/walk.out"; rc=$?
"$tool" --tsv "$tmp/walk.tsv" --diffusion --layers 3 > "$tmp/walk_half.out"
row() { awk -F'\t' -v l="$1" '$1 == l' "$2"; }
check "diffusion: exit 0, header layer z_mean particles D D_err, 3 layers of 150 at heights 1, 3, 5" \
  bash -c "[ $rc -eq 0 ] && [ \"\$(head -n 1 '$tmp/walk.out')\" = \$'layer\tz_mean\tparticles\tD\tD_err' ] && [ \"\$(column particles '$tmp/walk.out' | tr '\n' ' ')\" = '150 150 150 ' ] && [ \"\$(column z_mean '$tmp/walk.out' | awk '{ printf \"%.0f \", \$1 }')\" = '1 3 5 ' ]"
check "diffusion: bottom layer (static) D < 1e-12" \
  awk -v d="$(row 1 "$tmp/walk.out" | cut -f4)" 'BEGIN { exit !(d < 1e-12 && d > -1e-12) }'
check "diffusion, lags up to 10: middle D = $(row 2 "$tmp/walk.out" | cut -f4) within 20 % of 0.002" \
  within "$(row 2 "$tmp/walk.out" | cut -f4)" 0.002 0.2
check "diffusion, lags up to 10: top D = $(row 3 "$tmp/walk.out" | cut -f4) within 20 % of 0.01" \
  within "$(row 3 "$tmp/walk.out" | cut -f4)" 0.01 0.2
check "diffusion, lags up to half the window: top D within 4 D_err of 0.01 (D_err honest, > 0)" \
  bash -c "read -r d e <<< \"\$(awk -F'\t' '\$1 == 3 { print \$4, \$5 }' '$tmp/walk_half.out')\"; awk -v d=\"\$d\" -v e=\"\$e\" 'BEGIN { x = d - 0.01; if (x < 0) x = -x; exit !(e > 0 && x < 4 * e) }'"
awk 'NR == 1 || $2 != 5 || $1 < 10 { print; next } { $3 += 6; print }' OFS='\t' "$tmp/walk.tsv" > "$tmp/jump.tsv"
"$tool" --tsv "$tmp/jump.tsv" --diffusion > /dev/null 2> "$tmp/jump.err"; rc=$?
check "a jump of 6 d in a 20 d periodic box (more than a quarter): refused, naming file and particle" \
  bash -c "[ $rc -ne 0 ] && grep -q 'jump.tsv: particle 5 moves .*quarter' '$tmp/jump.err'"

# (6) a real run: 200 wet disks shaken (scene of thesis Fig. 3.2, smaller), snapshots every 0.05
"$WG_BIN/wetgran-run" "$scenes/shake2d.ini" n=200 lx=40 t_end=8 dt_snapshot=0.05 profile_start=0 \
  dt_checkpoint=0 seed=1 -q -o "$tmp/run.h5" 2> /dev/null
"$tool" --summary --from 1 "$tmp/run.h5" > "$tmp/run.sum" 2> "$tmp/run.err"; rc=$?
check "real run: exit 0, nothing on stderr, f_lc > 0 for 200 particles over t = 1 ... 8" \
  bash -c "[ $rc -eq 0 ] && [ ! -s '$tmp/run.err' ] && [ \$(value particles '$tmp/run.sum') = 200 ] && awk -v f=\"\$(value f_lc '$tmp/run.sum')\" 'BEGIN { exit !(f > 0) }' && [ \$(value t_to '$tmp/run.sum') = 8 ]"
"$tool" --from 1 --margin 1 "$tmp/run.h5" > "$tmp/run_m1.out"
check "real run: a table of 140 intervals; summary's changes = its sum, f_lc = changes / 7" \
  bash -c "[ \$(wc -l < '$tmp/run_m1.out') -eq 141 ] && [ \$(column changes '$tmp/run_m1.out' | awk '{ s += \$1 } END { print s }') = \$(value changes '$tmp/run.sum') ] && within \$(value f_lc '$tmp/run.sum') \$(awk -v c=\$(value changes '$tmp/run.sum') 'BEGIN { print c / 7 }') 1e-5"
"$tool" --from 1 --to 3 --margin 40 "$tmp/run.h5" > "$tmp/run_m40.out"
check "real run: the copies' margin (1 d, growing where needed, or the whole box) changes nothing" \
  bash -c "head -n 41 '$tmp/run_m1.out' | cmp -s - '$tmp/run_m40.out'"
"$tool" --diffusion --layers 3 "$tmp/run.h5" > "$tmp/run_diff.out"; rc=$?
check "real run: --diffusion --layers 3 gives three layers, bottom to top, D > 0" \
  bash -c "[ $rc -eq 0 ] && [ \$(wc -l < '$tmp/run_diff.out') -eq 4 ] && [ \"\$(column z_mean '$tmp/run_diff.out' | sort -g)\" = \"\$(column z_mean '$tmp/run_diff.out')\" ] && [ -z \"\$(column D '$tmp/run_diff.out' | awk '!(\$1 > 0)')\" ]"

# (7) errors name the file and exit non-zero
"$tool" "$tmp/missing.h5" > /dev/null 2> "$tmp/e1.err"; rc=$?
check "missing file: non-zero exit, message names it" bash -c "[ $rc -ne 0 ] && grep -q 'missing.h5' '$tmp/e1.err'"
h5copy -i "$tmp/run.h5" -o "$tmp/nosnap.h5" -s /particles/all/box -d /particles/all/box -p
h5copy -i "$tmp/run.h5" -o "$tmp/nosnap.h5" -s /h5md -d /h5md
"$tool" "$tmp/nosnap.h5" > /dev/null 2> "$tmp/e2.err"; rc=$?
check "HDF5 file without snapshots: non-zero exit, 'nosnap.h5: no particle snapshots'" \
  bash -c "[ $rc -ne 0 ] && grep -q 'nosnap.h5: no particle snapshots' '$tmp/e2.err'"
"$WG_BIN/wetgran-run" "$scenes/shake2d.ini" n=50 lx=20 t_end=0.5 dt_snapshot=0 profile_start=0 dt_checkpoint=0 \
  seed=1 -q -o "$tmp/final.h5" 2> /dev/null
"$tool" "$tmp/final.h5" > /dev/null 2> "$tmp/e3.err"; rc=$?
check "run file with one snapshot (the final state): non-zero exit, 'final.h5: 1 snapshot'" \
  bash -c "[ $rc -ne 0 ] && grep -q 'final.h5: 1 snapshot; f_lc needs two' '$tmp/e3.err'"
"$tool" --tsv "$tmp/static.tsv" --from 3.5 --to 3.9 > /dev/null 2> "$tmp/e4.err"; rc=$?
check "empty --from/--to window: non-zero exit, names the file" \
  bash -c "[ $rc -ne 0 ] && grep -q 'static.tsv: 0 snapshots in the window' '$tmp/e4.err'"
head -n 30 "$tmp/static.tsv" | sed '20s/^0\t16\t/0\t3\t/' > "$tmp/dupid.tsv"
"$tool" --tsv "$tmp/dupid.tsv" > /dev/null 2> "$tmp/e5.err"; rc=$?
check "text input with a repeated id: non-zero exit, names file and line 20" \
  bash -c "[ $rc -ne 0 ] && grep -q 'dupid.tsv:20: particle id 3 repeated' '$tmp/e5.err'"
"$tool" --bogus "$tmp/run.h5" > /dev/null 2>&1; rc=$?
check "unknown option: exit 2" test "$rc" -eq 2

summary
