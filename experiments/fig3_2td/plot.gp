# Fig. 3.2 look, both engines: T_g / E_cb (red, log) and number density (black), time-driven
# solid, event-driven dashed, plugs centred.
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1400,650 font ",12"; set output png } \
  else { set terminal pdfcairo size 14in,6.5in font ",12"; set output pdf }
  set xlabel "x / d  (plug centred)"
  set ylabel "T_g / E_{cb}" textcolor rgb "#c02020"
  set y2label "number density  n d"
  set logscale y; set ytics nomirror; set y2tics
  set xrange [0:400]
  set key top left
  plot td using 1:5 axes x1y1 with lines lw 2 lc rgb "#c02020" title "T_g / E_{cb}, time-driven", \
       ed using 1:5 axes x1y1 with lines lw 2 dt 2 lc rgb "#c02020" title "T_g / E_{cb}, event-driven", \
       td using 1:2 axes x1y2 with lines lw 2 lc rgb "black" title "density, time-driven", \
       ed using 1:2 axes x1y2 with lines lw 2 dt 2 lc rgb "black" title "density, event-driven"
}
