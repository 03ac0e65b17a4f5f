# Fig. 3.30 look: the system on top (blue: at least one bridge, red: none), below the
# time-averaged bridge density n_cb against x, its maximum and minimum dashed and
# Delta n_cb = max - min (Eq. 3.3) as a double arrow.
stats prof using 6 nooutput
nmax = STATS_max; nmin = STATS_min; xmax = STATS_index_max
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1400,800 font ",12"; set output png } \
  else { set terminal pdfcairo size 14in,8in font ",12"; set output pdf }
  set multiplot
  set lmargin at screen 0.08; set rmargin at screen 0.95
  set tmargin at screen 0.97; set bmargin at screen 0.80
  set xrange [0:400]; set yrange [-0.5:9.5]
  unset key; unset ytics; set xtics format ""
  set style fill solid 1.0 noborder
  plot snap using 2:3:($6/2):($8 > 0 ? 0x3060d0 : 0xd03030) with circles lc rgb variable
  set tmargin at screen 0.77; set bmargin at screen 0.10
  set xtics format "%g"; set xlabel "lateral position  x / d"
  set ylabel "capillary-bridge density  n_{cb} d"
  set ytics; set yrange [0:nmax * 1.15]
  xa = 20
  set arrow 1 from xa, nmin to xa, nmax heads lw 2 lc rgb "black"
  set label 1 sprintf("{/Symbol D}n_{cb} d = %.2f  (Eq. 3.3)", nmax - nmin) at xa + 5, (nmax + nmin) / 2
  plot prof using 1:6 with lines lw 2 lc rgb "black", \
       nmax with lines dt 2 lc rgb "gray40", nmin with lines dt 2 lc rgb "gray40"
  unset multiplot
}
