# Fig. 3.2 look: (a) a snapshot strip of the 400 d x 9 d box at its true aspect ratio (blue:
# at least one bridge, red: none), (b) the time-averaged T_g / E_cb (red, log scale) and number
# density (black) against x, averaged over the seeds with the standard error as a band.  Every
# seed's plug sits elsewhere: each profile is centred on its density-weighted centre
# (mean_profile.awk), and the snapshot on its particles' centre, both on the periodic x axis.
# Variables: mean (mean_profile.awk's file), snap (wetgran-frame), nseeds.
L = 400.0; H = 9.0
# the snapshot's centre: circular mean of the particles' x (column 2)
stats snap using (cos(2 * pi * $2 / L)) nooutput; cx = STATS_sum
stats snap using (sin(2 * pi * $2 / L)) nooutput; sx = STATS_sum
xc = L * atan2(sx, cx) / (2 * pi)
shift = L / 2 - xc
wrap(x) = x - L * floor(x / L)
tsnap = system(sprintf("awk 'NR == 1 && $2 == \"time\" { print $3 } { exit }' %s", snap))
band = sprintf("mean of %d seeds %s s.e.", nseeds, nseeds > 1 ? "{/Symbol \261}" : "")
if (nseeds == 1) band = "one seed"
# room above the density's peak for the key
stats mean using ($2 + $3) nooutput; dmax = STATS_max
W = 1400.0; Hpx = 800.0
left = 0.08; right = 0.92
# the strip's height in screen units for the box's true 9 : 400
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
  set xtics format "%g"; set xtics mirror; set xlabel "x / d  (plug centred)"
  set ylabel "T_g / E_{cb}" textcolor rgb "#c02020"
  set y2label "number density  n d" textcolor rgb "black"
  set logscale y; set autoscale y; set ytics nomirror tc rgb "#c02020"; set y2tics
  set y2range [0:dmax * 1.15]
  set key default; set key inside top left horizontal box opaque samplen 2 width 1 maxrows 2
  set style fill transparent solid 0.25 noborder
  plot mean using 1:($8 - $9):($8 + $9) axes x1y1 with filledcurves lc rgb "#c02020" notitle, \
       mean using 1:8 axes x1y1 with lines lw 2 lc rgb "#c02020" title "T_g / E_{cb} (event-driven)", \
       mean using 1:($2 - $3):($2 + $3) axes x1y2 with filledcurves lc rgb "black" notitle, \
       mean using 1:2 axes x1y2 with lines lw 2 lc rgb "black" title "number density", \
       NaN with filledcurves lc rgb "gray50" title "band: ".band
  unset multiplot
}
