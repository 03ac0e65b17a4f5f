# Fig. 5.2b look: a_g against E~* (runs below E~* = 0 at a_g = 0, above 1 at a_g = 1), the fit
# a E~*^beta over the coexisting runs with 0 < E~* <= 1; grey: the same runs masked by the
# bridge density instead of T_g (shifted by 0.01 so both show) (wetgran-interface powerfit) and the thesis's 0.72 E~*^0.32.
# (integers with an exponent, 4e-07, are written 4.0e-07: gnuplot's real() stops at the e)
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $2; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $3; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
a = val("ag_prefactor"); b = val("ag_beta"); da = err("ag_prefactor"); db = err("ag_beta")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 900,650 font ",12"; set output png } \
  else { set terminal pdfcairo size 9in,6.5in font ",12"; set output pdf }
  set xrange [-0.3:1.3]; set yrange [-0.05:1.1]
  set xlabel "Ẽ^* = (E^* - E^*_{f-fgc}) / (E^*_{fgc-g} - E^*_{f-fgc})"
  set ylabel "a_g"
  set title sprintf("2D, {/Symbol e} = 0.8, {/Symbol G} = 8 (%s profile)", prof)
  set key top left box
  set arrow from 0, graph 0 to 0, graph 1 nohead dt 3 lc rgb "gray50"
  set arrow from 1, graph 0 to 1, graph 1 nohead dt 3 lc rgb "gray50"
  set samples 300
  f(x) = x > 0 && x <= 1 ? a * x**b : NaN
  t(x) = x > 0 && x <= 1 ? 0.72 * x**0.32 : NaN
  plot ag using (column("estar_tilde")):(column("a_g")):(column("a_g_err")) with yerrorbars pt 7 ps 1.5 lc rgb "black" title "runs (wetgran-interface ag)", \
       agb using (column("estar_tilde") + 0.01):(column("a_g")) with points pt 6 ps 1.5 lc rgb "gray50" title "runs masked by n_{cb} (not fitted here)", \
       f(x) with lines lw 2 lc rgb "red" title sprintf("fit %.2f Ẽ^{*%.2f}, {/Symbol b} = %.2f {/Symbol \261} %.2f", a, b, b, db), \
       t(x) with lines lw 2 dt 2 lc rgb "blue" title "thesis 0.72 Ẽ^{*0.32}"
}
