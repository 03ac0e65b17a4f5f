# Fig. 7.5b look: F_scrit L_x / d against L_x (points with the sweep's bracket), the fitted
# line, and the thesis's constant 3.7 mg + 1.4 F_B; the runs behind (solid filled, fluidized
# open).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
a = val("line_a"); ae = err("line_a"); b = val("line_b"); be = err("line_b")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,650 font ",11"; set output png } \
  else { set terminal pdfcairo size 10in,6.5in font ",11"; set output pdf }
  set title sprintf("boundary against the width, F_B = %g mg (%s): F_{scrit} L_x / d = (%.1f {/Symbol \261} %.1f) mg + (%.2f {/Symbol \261} %.2f) mg L_x / d", fb, profile, a, ae, b, be)
  set xlabel "L_x / d"; set ylabel "F_{smax} L_x / (mg d)"
  set key top left box opaque; set xrange [0:*]; set yrange [0:*]
  plot sweep every ::1 using 1:(strcol(5) eq "solid" ? $2 * $1 : NaN) with points pt 7 ps 1 lc rgb "gray50" title "solid run", \
       sweep every ::1 using 1:(strcol(5) eq "fluidized" ? $2 * $1 : NaN) with points pt 6 ps 1 lc rgb "gray50" title "fluidized run", \
       bnd every ::1 using 6:4:5 with yerrorbars pt 7 ps 1.5 lc rgb "red" title "F_{scrit} (midpoint)", \
       (a == a ? a + b * x : NaN) with lines lw 2 lc rgb "red" title "line fit", \
       3.7 + 1.4 * fb with lines dt 2 lw 2 lc rgb "blue" title "thesis: 3.7 mg + 1.4 F_B, independent of L_x"
}
