# Figs. 5.14 and 5.15 look.  Left: A_d / d (seeds' mean, error bars their standard deviation)
# against t after the field is switched off, log scale, one colour per E*, with the fitted
# exponential over the fitted window.  Right: mu_f = 1 / ((2 pi)^2 sigma tau) (Eq. 5.13)
# against E*.
# (integers with an exponent, 4e-07, are written 4.0e-07: gnuplot's real() stops at the e)
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $2; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $3; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
n = words(relax)
ename(i) = system(sprintf("basename %s .tsv | sed 's/relax_E//'", word(relax, i)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,520 font ",12"; set output png } \
  else { set terminal pdfcairo size 12in,5.2in font ",12"; set output pdf }
  set multiplot layout 1, 2 title sprintf("relaxation of the sheared elastic strip, {/Symbol G} = 100, L_x = %g d (%s profile)", lx, prof)
  set logscale y
  set xlabel "t / (d/g)^{1/2} after the field is off"; set ylabel "A_d / d"
  set key bottom left box; set yrange [0.1:20]
  set title "Fig. 5.14"
  plot for [i = 1:n] word(relax, i) using 1:($2 * lx):($3 * lx) with yerrorbars pt 7 ps 1 lc i title sprintf("E^* = %s", ename(i)), \
       for [i = 1:n] (x >= f0 && x <= f1 ? val(sprintf("ad0_E%s", ename(i))) * lx * exp(-x / val(sprintf("tau_E%s", ename(i)))) : NaN) with lines lw 2 lc i \
         title sprintf("{/Symbol t} = %.0f {/Symbol \261} %.0f", val(sprintf("tau_E%s", ename(i))), err(sprintf("tau_E%s", ename(i))))
  unset logscale y
  set xlabel "E^*"; set ylabel "{/Symbol m}_f  [(m g)^{-1} (g/d)^{1/2}]"
  array ex[n]; array ey[n]; array ee[n]
  do for [i = 1:n] { ex[i] = real(ename(i)); ey[i] = val(sprintf("mu_f_E%s", ename(i))); ee[i] = err(sprintf("mu_f_E%s", ename(i))) }
  set xrange [(ex[1] - 0.05):(ex[n] + 0.05)]; set yrange [0:*]
  set title "mobility (Fig. 5.15)"; unset key
  plot for [i = 1:n] '+' using (ex[i]):(ey[i]):(ee[i]) every ::0::0 with yerrorbars pt 7 ps 1.5 lc rgb "black" notitle
  unset multiplot
}
