# Fig. 3.28 look: (a) f_lc against Gamma, rising (filled) and falling (open) branches with
# arrows' directions; (b) T_g / E_cb against E* (log), likewise.  Dashed: where each branch
# crosses its transition (results.tsv), in the key.
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1400,700 font ",12"; set output png } \
  else { set terminal pdfcairo size 14in,7in font ",12"; set output pdf }
  set multiplot layout 1,2
  set title sprintf("(a) solid-fluid, E^* = %g", estar_a)
  set xlabel "{/Symbol G}"
  set ylabel "f_{lc} per particle  [(g/d)^{1/2}]"
  set key below left Left reverse samplen 2 font ",11"
  set arrow 1 from val("a_gamma_up"), graph 0 to val("a_gamma_up"), graph 1 nohead dt 2 lc rgb "#c02020"
  set arrow 2 from val("a_gamma_down"), graph 0 to val("a_gamma_down"), graph 1 nohead dt 2 lc rgb "#2040c0"
  plot sprintf("< awk -F'\\t' '$1 == \"up\"' %s", a) using 2:3:4 with yerrorlines pt 7 lc rgb "#c02020" title "{/Symbol G} rising", \
       sprintf("< awk -F'\\t' '$1 == \"down\"' %s", a) using 2:3:4 with yerrorlines pt 6 lc rgb "#2040c0" title "{/Symbol G} falling", \
       NaN with lines dt 2 lc rgb "#c02020" title sprintf("rising crossing (half the largest f_{lc}): {/Symbol G} = %.3g", val("a_gamma_up")), \
       NaN with lines dt 2 lc rgb "#2040c0" title sprintf("falling crossing: {/Symbol G} = %.3g", val("a_gamma_down"))
  unset arrow
  set title sprintf("(b) fluid-gas, {/Symbol G} = %g", gamma_b)
  set xlabel "E^*"
  set ylabel "T_g / E_{cb}"
  set logscale y
  set arrow 1 from val("b_estar_up"), graph 0 to val("b_estar_up"), graph 1 nohead dt 2 lc rgb "#c02020"
  set arrow 2 from val("b_estar_down"), graph 0 to val("b_estar_down"), graph 1 nohead dt 2 lc rgb "#2040c0"
  plot sprintf("< awk -F'\\t' '$1 == \"up\"' %s", b) using 2:3:4 with yerrorlines pt 7 lc rgb "#c02020" title "E^* rising", \
       sprintf("< awk -F'\\t' '$1 == \"down\"' %s", b) using 2:3:4 with yerrorlines pt 6 lc rgb "#2040c0" title "E^* falling", \
       NaN with lines dt 2 lc rgb "#c02020" title sprintf("rising crossing (geometric mean of the extremes): E^* = %.3g", val("b_estar_up")), \
       NaN with lines dt 2 lc rgb "#2040c0" title sprintf("falling crossing: E^* = %.3g", val("b_estar_down"))
  unset multiplot
}
