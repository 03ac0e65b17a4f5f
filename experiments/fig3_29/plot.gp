# Fig. 3.29 look: T_g / E_cb against E* (log-log) at Gamma = 2.7, eps = 0.8, with the
# inflection point of log T_g that marks the fluid-gas boundary.
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
xi = val("inflection_estar"); dxi = err("inflection_estar")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,700 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7in font ",12"; set output pdf }
  set xlabel "E^*"
  set ylabel "T_g / E_{cb}"
  set logscale xy
  set key top left
  set arrow 1 from xi, graph 0 to xi, graph 1 nohead dt 2 lw 2 lc rgb "#c02020"
  set label 1 sprintf("inflection: E^* = %.2f {/Symbol \261} %.2f", xi, dxi) at xi, graph 0.92 right offset -1, 0 textcolor rgb "#c02020"
  plot op using 3:11:12 every ::1 with yerrorbars pt 7 ps 1.5 lc rgb "black" title "T_g / E_{cb} ({/Symbol G} = 2.7, {/Symbol e} = 0.8)", \
       op using 3:11 every ::1 with lines lc rgb "black" notitle
}
