# Fig. 3.30 look: (a) the system, a snapshot strip of the 400 d x 9 d box at its true aspect
# ratio (blue: at least one bridge, red: none); (b) the time-averaged bridge density n_cb
# against x, the seeds' mean (each seed centred on its plug: fig3_2's mean_profile.awk) with the
# standard error as a band, its maximum and minimum dashed and Delta n_cb = max - min (Eq. 3.3)
# as a double arrow; the label also gives results.tsv's Delta n_cb (per seed, then averaged).
# Variables: mean, snap, res, nseeds.
L = 400.0; H = 9.0
stats mean using 10 nooutput
nmax = STATS_max; nmin = STATS_min
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $3 }' %s", k, res))
dn = val("dn_cb"); dne = err("dn_cb")
# the snapshot's centre: circular mean of the particles' x (column 2)
stats snap using (cos(2 * pi * $2 / L)) nooutput; cx = STATS_sum
stats snap using (sin(2 * pi * $2 / L)) nooutput; sx = STATS_sum
shift = L / 2 - L * atan2(sx, cx) / (2 * pi)
wrap(x) = x - L * floor(x / L)
tsnap = system(sprintf("awk 'NR == 1 && $2 == \"time\" { print $3 } { exit }' %s", snap))
W = 1400.0; Hpx = 800.0
left = 0.08; right = 0.95
strip = (right - left) * (W / Hpx) * H / L
top = 0.92
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size W,Hpx font ",12"; set output png } \
  else { set terminal pdfcairo size (W / 100)*1in,(Hpx / 100)*1in font ",12"; set output pdf }
  set multiplot
  set lmargin at screen left; set rmargin at screen right
  set tmargin at screen top; set bmargin at screen top - strip
  set xrange [0:L]; set yrange [0:H]
  set xtics 50 format ""; unset ytics; set x2tics 50 format "%g" mirror
  set label 1 "(a)" at screen 0.015, screen top - strip / 2 font ",14"
  set label 2 sprintf("snapshot of seed 1 at t = %s (plug centred)", tsnap) at screen left, screen top + 0.045 left
  set key at screen right, screen top + 0.06 horizontal right reverse Left samplen 1 width 1
  set style fill solid 1.0 noborder
  plot snap using (wrap($2 + shift)):3:($6 / 2):($8 > 0 ? 0x3060d0 : 0xd03030) with circles lc rgb variable notitle, \
       NaN with points pt 7 ps 1.5 lc rgb "#3060d0" title "bridged (at least one bridge)", \
       NaN with points pt 7 ps 1.5 lc rgb "#d03030" title "unbridged"
  unset label 1; unset label 2; unset x2tics
  set tmargin at screen top - strip - 0.07; set bmargin at screen 0.09
  set label 3 "(b)" at screen 0.015, screen top - strip - 0.07 font ",14"
  set xtics format "%g" mirror; set xlabel "lateral position  x / d  (plug centred)"
  set ylabel "capillary-bridge density  n_{cb} d"
  set ytics; set yrange [0:nmax * 1.2]
  xa = 20
  set arrow 1 from xa, nmin to xa, nmax heads lw 2 lc rgb "black"
  perseed = nseeds > 1 ? sprintf("per seed, mean of %d: %.2f {/Symbol \261} %.2f", nseeds, dn, real(dne)) : sprintf("one seed: %.2f", dn)
  set label 4 sprintf("{/Symbol D}n_{cb} d = %.2f  (Eq. 3.3, mean profile)\n%s", nmax - nmin, perseed) at xa + 5, (nmax + nmin) / 2
  set key default; set key inside top right box opaque samplen 2 width 1
  set style fill transparent solid 0.3 noborder
  band = nseeds > 1 ? sprintf("mean of %d seeds {/Symbol \261} s.e.", nseeds) : "one seed"
  plot mean using 1:($10 - $11):($10 + $11) with filledcurves lc rgb "gray50" title "band: ".band, \
       mean using 1:10 with lines lw 2 lc rgb "black" title "n_{cb} d", \
       nmax with lines dt 2 lc rgb "gray40" title "its maximum and minimum", nmin with lines dt 2 lc rgb "gray40" notitle
  unset multiplot
}
