# Fig. 3.4a look: phases coloured as in the thesis (fluid blue, gas orange, coexistence
# white; solid grey; sfc/sgc pale) on log E* and log Gamma axes (the thesis's "log/linear
# scale"; a log Gamma axis keeps the rows Gamma = 1.2-3 of the bulge apart), the Delaunay boundary points, the
# A = s_crit line (Gamma = 2 E* E_cb / (m g s_crit), from Eq. 2.18-2.19) and an arrow at the
# fitted f-fgc transition.
color(l) = l eq "s" ? 0x909090 : l eq "f" ? 0x3070d0 : l eq "g" ? 0xf0a030 : \
           l eq "fgc" ? 0xffffff : l eq "sfc" ? 0xd0d0ff : l eq "sgc" ? 0xffe0c0 : 0xff0000
fit_x = real(system(sprintf("awk '$1 == \"vertical_f_fgc\" { print $2 }' %s", res)))
stats op using 3 every ::1 nooutput
xmin = STATS_min / 1.3; xmax = STATS_max * 1.3
stats op using 2 every ::1 nooutput
ymin = STATS_min / 1.12; ymax = STATS_max * 1.6
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,750 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7.5in font ",12"; set output pdf }
  set logscale xy
  set xrange [xmin:xmax]; set yrange [ymin:ymax]
  set xtics (0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1, 1.25, 1.5, 2, 3, 4, 5)
  set ytics (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 15, 20, 30, 40, 50, 60, 80, 100)
  set xlabel "E^*"
  set ylabel "{/Symbol G}"
  set key below box
  set arrow 1 from fit_x, graph 0.99 to fit_x, graph 0.92 head filled lw 2 lc rgb "black"
  set label 1 sprintf("f-fgc: E* = %.3g", fit_x) at fit_x * 1.03, graph 0.96 left
  set samples 200
  plot op using 3:2:(color(strcol(18))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       op using 3:2 every ::1 with points pt 4 ps 2.5 lc rgb "black" title "runs (fill: phase; grey s, blue f, white fgc, orange g)", \
       bd using 1:2 every ::1 with points pt 7 ps 0.8 lc rgb "red" title "boundary (Delaunay midpoints)", \
       2 * x * ecb / scrit title "A = s_{crit}" with lines lw 2 lc rgb "black"
}
