# Fig. 7.5a look: F_scrit L_x / (F_B d) against s_crit (points with the sweep's bracket), the
# fitted line and its intercept, and Eq. 7.9's two candidate bounds at s_crit -> 0; the sweep's
# runs behind (solid filled, fluidized open).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
a = val("line_a"); ae = err("line_a"); b = val("line_b")
printed = val("eq7_9_bound_printed"); bound = val("eq7_9_bound")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,650 font ",11"; set output png } \
  else { set terminal pdfcairo size 10in,6.5in font ",11"; set output pdf }
  set title sprintf("fluidization boundary against s_{crit}: L_x = %g d, F_B = %g mg (%s profile): intercept %.2f {/Symbol \261} %.2f", lx, fb, profile, a, ae)
  set xlabel "s_{crit} / d"; set ylabel "F_{smax} L_x / (F_B d)"
  set key bottom right box opaque; set xrange [0:*]; set yrange [0:*]
  plot sweep every ::1 using 1:(strcol(5) eq "solid" ? $2 * lx / fb : NaN) with points pt 7 ps 1 lc rgb "gray50" title "solid run", \
       sweep every ::1 using 1:(strcol(5) eq "fluidized" ? $2 * lx / fb : NaN) with points pt 6 ps 1 lc rgb "gray50" title "fluidized run", \
       bnd every ::1 using 1:4:5 with yerrorbars pt 7 ps 1.5 lc rgb "red" title "F_{scrit} (midpoint)", \
       (a == a ? a + b * x : NaN) with lines lw 2 lc rgb "red" title "line fit", \
       printed with lines dt 2 lw 2 lc rgb "blue" title "Eq. 7.9 as printed: 1/(4 F_{cmin}) = 0.923", \
       bound with lines dt 3 lw 2 lc rgb "dark-green" title "1/F_{cmin} = 3.69"
}
