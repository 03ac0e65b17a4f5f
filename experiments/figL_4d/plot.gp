# Layering paper Fig. 4d and 3c, continuum: <|grad c|^2> against k_c = sqrt(K/4 kappa) (runs,
# the line fit, and the flat-interface value of each run), and the 1D profile c(z).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
a = val("grad2_a"); b = val("grad2_b"); be = err("grad2_b")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,520 font ",11"; set output png } \
  else { set terminal pdfcairo size 12in,5.2in font ",11"; set output pdf }
  set multiplot layout 1,2 title sprintf("sheared Cahn-Hilliard (Mahajan and Singh, Eq. 1-4), K = 25 (%s profile)", prof)
  set title sprintf("<|{/Symbol \321}c|^2> = %.3f + (%.3f {/Symbol \261} %.3f) k_c", a, b, be)
  set xlabel "k_c = (K / 4{/Symbol k})^{1/2}"; set ylabel "<|{/Symbol \321}c|^2>"
  set key top left box opaque; set xrange [0:*]; set yrange [0:*]
  plot scan every ::1 using 3:4 with points pt 7 ps 1.2 lc rgb "red" title "2D runs (seeds)", \
       scan every ::1 using 3:7 with points pt 6 ps 1.5 lc rgb "blue" title "flat tanh interfaces of each run", \
       a + b * x with lines lw 2 lc rgb "red" title "line fit"
  set title sprintf("1D, {/Symbol k} = 0.7 (k_c = 2.99): %d bands above the mean", val("layers_1d"))
  set xlabel "z"; set ylabel "c"; set key off; set xrange [0:2*pi]; set yrange [-0.1:1.1]
  plot oned using 1:2 with lines lw 2 lc rgb "black"
  unset multiplot
}
