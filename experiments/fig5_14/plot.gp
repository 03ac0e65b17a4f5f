# Figs. 5.14 and 5.15 look.  Left: A_d / d (seeds' mean, error bars their standard deviation)
# against t after the field is switched off, log scale, one colour per E*, with the fitted
# exponential.  Right: mu_f = 1 / ((2 pi)^2 sigma tau) (Eq. 5.13) against E~*.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
n = words(relax)
ename(i) = system(sprintf("basename %s .tsv | sed 's/relax_E//'", word(relax, i)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,520 font ",12"; set output png } \
  else { set terminal pdfcairo size 12in,5.2in font ",12"; set output pdf }
  set multiplot layout 1, 2 title sprintf("relaxation of the sheared elastic strip, {/Symbol G} = 100, L_x = %g d (%s profile)", lx, prof)
  set logscale y
  set xlabel "t / (d/g)^{1/2} after the field is off"; set ylabel "A_d / d"
  set key top right box
  set title "Fig. 5.14"
  plot for [i = 1:n] word(relax, i) using 1:($2 * lx):($3 * lx) with yerrorbars pt 7 ps 1 lc i title sprintf("E^* = %s", ename(i)), \
       for [i = 1:n] val(sprintf("ad0_E%s", ename(i))) * lx * exp(-x / val(sprintf("tau_E%s", ename(i)))) with lines lw 2 lc i \
         title sprintf("{/Symbol t} = %.0f {/Symbol \261} %.0f", val(sprintf("tau_E%s", ename(i))), err(sprintf("tau_E%s", ename(i))))
  unset logscale y
  set xlabel "E^*"; set ylabel "{/Symbol m}_f  [(m g)^{-1} (g/d)^{1/2}]"
  set xrange [*:*]; set yrange [0:*]; set offsets 0.02, 0.02, 0, 0
  set title "mobility (Fig. 5.15)"; unset key
  plot for [i = 1:n] '+' using (real(ename(i))):(val(sprintf("mu_f_E%s", ename(i)))):(err(sprintf("mu_f_E%s", ename(i)))) every ::0::0 \
       with yerrorbars pt 7 ps 1.5 lc rgb "black" notitle
  unset multiplot
}
