# The look of the Fig. 7.5 sweeps (fig7_5a-d), loaded by their plot.gp after they set:
#   ttl, xl, yl     title and axis labels;       keypos   where the key goes ("top left" ...)
#   xrun(v)         a run's x from the swept value v (column 1 of sweep.tsv)
#   yrun(v, f)      a run's y from v and its F_smax f (column 2)
#   xcol            the column of boundary.tsv that holds x (1: the value, 6: scaled)
#   ref1(x), ref1_t and ref2(x), ref2_t   reference lines and their titles (ref2 NaN: none)
# with a, b the line fit's coefficients; the files sweep, bnd and png/pdf come from the Makefile.
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,650 font ",11"; set output png } \
  else { set terminal pdfcairo size 10in,6.5in font ",11"; set output pdf }
  set title ttl
  set xlabel xl; set ylabel yl
  eval sprintf("set key %s box opaque", keypos)
  set xrange [0:*]; set yrange [0:*]
  plot sweep every ::1 using (xrun($1)):(strcol(5) eq "solid" ? yrun($1, $2) : NaN) with points pt 7 ps 1 lc rgb "gray50" title "solid run", \
       sweep every ::1 using (xrun($1)):(strcol(5) eq "fluidized" ? yrun($1, $2) : NaN) with points pt 6 ps 1 lc rgb "gray50" title "fluidized run", \
       bnd every ::1 using xcol:4:5 with yerrorbars pt 7 ps 1.5 lc rgb "red" title "F_{scrit} (midpoint)", \
       (a == a ? a + b * x : NaN) with lines lw 2 lc rgb "red" title "line fit", \
       ref1(x) with lines dt 2 lw 2 lc rgb "blue" title ref1_t, \
       ref2(x) with lines dt 3 lw 2 lc rgb "dark-green" title ref2_t
}
