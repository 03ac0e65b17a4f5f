# Fig. 4.2 look: linear axes; runs filled by phase (solid grey, fluid blue, fluid-gas
# coexistence white, gas orange), the measured Gamma_C per E*, Eq. 4.15 (red) and the floor
# 1 - 1/M of Eq. 4.13-4.14 (dashed).
# A key box per phase the runs show.
load '../phase_key.gp'
phases = phases_in(ph, "phase")
# Tables read by column name need no `every ::1`: naming a column makes gnuplot take the header
# line as titles, and `every ::1` then dropped the first data row.
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,750 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7.5in font ",12"; set output pdf }
  set xlabel "E^*"
  set ylabel "{/Symbol G}"
  set xrange [0:*]; set yrange [0:*]
  set offsets 0, 0.2, 0.6, 0
  set key top right opaque box
  plot ph using (column("estar")):(column("gamma")):(color(strcol("phase"))) with points pt 5 ps 2.5 lc rgb variable notitle, \
       ph using (column("estar")):(column("gamma")) with points pt 4 ps 2.5 lc rgb "black" notitle, \
       for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title "run: ".phase_name(p), \
       gc using 1:3:4 every ::1 with yerrorbars pt 9 ps 1.5 lc rgb "black" title "{/Symbol G}_C (solid to mobile)", \
       th using (column("estar")):(column("gamma_c_415")) with lines lw 2 lc rgb "#c02020" title "Eq. 4.15", \
       th using (column("estar")):(column("gamma_c_min")) with lines lw 2 dt 2 lc rgb "black" title "1 - 1/M (Eq. 4.13-4.14)"
}
