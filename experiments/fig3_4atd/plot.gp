# Fig. 3.4a look, both engines: event-driven squares and time-driven circles filled by phase
# (fluid blue, coexistence white, gas orange) on log E* and log Gamma axes (phase_diagram.gp), the A = s_crit line, Eq. 4.15
# in red, and arrows at each engine's fitted f-fgc line.
# A key box per phase that either engine's runs show.
load '../phase_key.gp'
phases = phases_in(ed." ".td, "18")
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
xe = val("ed_vertical_f_fgc"); xt = val("td_vertical_f_fgc")
stats ed using 3:2 every ::1 nooutput
xmin = STATS_min_x; xmax = STATS_max_x; ymin = STATS_min_y; ymax = STATS_max_y
stats td using 3:2 every ::1 nooutput
xmin = (STATS_min_x < xmin ? STATS_min_x : xmin) / 1.3; xmax = (STATS_max_x > xmax ? STATS_max_x : xmax) * 1.3
ymin = (STATS_min_y < ymin ? STATS_min_y : ymin) / 1.12; ymax = (STATS_max_y > ymax ? STATS_max_y : ymax) * 1.8
# Tables read by column name need no `every ::1`: naming a column makes gnuplot take the header
# line as titles, and `every ::1` then dropped the first data row.
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,820 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,8.2in font ",12"; set output pdf }
  set logscale xy
  set xrange [xmin:xmax]; set yrange [ymin:ymax]
  set xtics (0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1, 1.25, 1.5, 2, 3, 4, 5)
  set ytics (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 15, 20, 30, 40, 50, 60, 80, 100)
  set xlabel "E^*"
  set ylabel "{/Symbol G}"
  set key below maxrows 4 box width 1
  set arrow 1 from xe, graph 0.99 to xe, graph 0.93 head filled lw 2 lc rgb "black"
  set arrow 2 from xt, graph 0.99 to xt, graph 0.93 head filled lw 2 lc rgb "#606060"
  # the labels face away from each other: the smaller value's to the left of its arrow
  if (xe >= xt) { set label 1 sprintf("event-driven: %.3g", xe) at xe * 1.03, graph 0.96 left; \
                  set label 2 sprintf("time-driven: %.3g", xt) at xt / 1.03, graph 0.96 right } \
  else { set label 1 sprintf("event-driven: %.3g", xe) at xe / 1.03, graph 0.96 right; \
         set label 2 sprintf("time-driven: %.3g", xt) at xt * 1.03, graph 0.96 left }
  plot ed using 3:2:(color(strcol(18))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       ed using 3:2 every ::1 with points pt 4 ps 2.5 lc rgb "black" title "event-driven (fig3\\_4a's runs; fill: phase)", \
       td using 3:2:(color(strcol(18))) every ::1 with points pt 7 ps 2.2 lc rgb variable notitle, \
       td using 3:2 every ::1 with points pt 6 ps 2.2 lc rgb "black" title "time-driven (fig3\\_3's runs; fill: phase)", \
       for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title phase_name(p), \
       2 * x * ecb / scrit title "A = s_{crit}" with lines lw 2 lc rgb "black", \
       eq using (column("estar")):(column("gamma_c_415")) with lines lw 2 lc rgb "#c02020" title "Eq. 4.15 (solid-fluid)"
}
