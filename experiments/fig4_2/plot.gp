# Fig. 4.2 look: linear axes; runs filled by phase (solid grey, fluid blue, fluid-gas
# coexistence white, gas orange), the measured Gamma_C per E*, Eq. 4.15 (red) and the floor
# 1 - 1/M of Eq. 4.13-4.14 (dashed).
color(l) = l eq "s" ? 0x909090 : l eq "f" ? 0x3070d0 : l eq "g" ? 0xf0a030 : \
           l eq "fgc" ? 0xffffff : l eq "sfc" ? 0xd0d0ff : l eq "sgc" ? 0xffe0c0 : 0xff0000
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,750 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7.5in font ",12"; set output pdf }
  set xlabel "E^*"
  set ylabel "{/Symbol G}"
  set xrange [0:*]; set yrange [0:*]
  set offsets 0, 0.2, 0.6, 0
  set key top right opaque box
  plot ph using (column("estar")):(column("gamma")):(color(strcol("phase"))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       ph using (column("estar")):(column("gamma")) every ::1 with points pt 4 ps 2.5 lc rgb "black" title "runs (fill: phase; grey s, blue f, white fgc, orange g)", \
       gc using 1:3:4 every ::1 with yerrorbars pt 9 ps 1.5 lc rgb "black" title "{/Symbol G}_C (solid to mobile)", \
       th using (column("estar")):(column("gamma_c_415")) every ::1 with lines lw 2 lc rgb "#c02020" title "Eq. 4.15", \
       th using (column("estar")):(column("gamma_c_min")) every ::1 with lines lw 2 dt 2 lc rgb "black" title "1 - 1/M (Eq. 4.13-4.14)"
}
