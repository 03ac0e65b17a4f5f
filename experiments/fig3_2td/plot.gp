# Fig. 3.2 look, both engines: T_g / E_cb (red, log) and number density (black), time-driven
# solid, event-driven dashed; each the mean over its seeds (plugs centred, mean_profile.awk)
# with the standard error as a band.  Variables: td, ed (mean profiles), ntd, ned (seeds).
bandname(n) = n > 1 ? sprintf("mean of %d seeds {/Symbol \261} s.e.", n) : "one seed"
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1400,760 font ",12"; set output png } \
  else { set terminal pdfcairo size 14in,7.6in font ",12"; set output pdf }
  set xlabel "x / d  (plug centred)"
  set ylabel "T_g / E_{cb}" textcolor rgb "#c02020"
  set y2label "number density  n d"
  set logscale y; set ytics nomirror tc rgb "#c02020"; set y2tics
  set xrange [0:400]
  set key below Left reverse samplen 2 width 2 maxrows 3 font ",11"
  set style fill transparent solid 0.2 noborder
  plot td using 1:($8 - $9):($8 + $9) axes x1y1 with filledcurves lc rgb "#c02020" notitle, \
       ed using 1:($8 - $9):($8 + $9) axes x1y1 with filledcurves lc rgb "#c02020" notitle, \
       td using 1:($2 - $3):($2 + $3) axes x1y2 with filledcurves lc rgb "black" notitle, \
       ed using 1:($2 - $3):($2 + $3) axes x1y2 with filledcurves lc rgb "black" notitle, \
       td using 1:8 axes x1y1 with lines lw 2 lc rgb "#c02020" title "T_g / E_{cb}, time-driven (".bandname(ntd).")", \
       ed using 1:8 axes x1y1 with lines lw 2 dt 2 lc rgb "#c02020" title "T_g / E_{cb}, event-driven (".bandname(ned).")", \
       td using 1:2 axes x1y2 with lines lw 2 lc rgb "black" title "density, time-driven", \
       ed using 1:2 axes x1y2 with lines lw 2 dt 2 lc rgb "black" title "density, event-driven", \
       NaN with filledcurves lc rgb "gray50" title "bands: standard error of the seeds' mean"
}
