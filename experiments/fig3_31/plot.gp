# Fig. 3.31 look: Delta n_cb (black, left axis) and Delta n_area (red, right axis) against E*,
# with the fitted critical power laws.
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
a1 = val("dn_cb_a"); xc1 = val("dn_cb_xc"); b1 = val("dn_cb_beta")
a2 = val("dn_area_a"); xc2 = val("dn_area_xc"); b2 = val("dn_area_beta")
f1(x) = x < xc1 ? a1 * (xc1 - x)**b1 : 0
f2(x) = x < xc2 ? a2 * (xc2 - x)**b2 : 0
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,700 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7in font ",12"; set output pdf }
  set xlabel "E^*"
  set ylabel "{/Symbol D}n_{cb} d"
  set y2label "{/Symbol D}n_{area}" textcolor rgb "#c02020"
  set ytics nomirror; set y2tics textcolor rgb "#c02020"
  set key top right
  set samples 400
  plot op using 3:15 every ::1 with points pt 7 ps 1.5 lc rgb "black" title "{/Symbol D}n_{cb}", \
       f1(x) with lines lw 2 lc rgb "black" title sprintf("fit: E*_{fgc-g} = %.3g, {/Symbol b}_1 = %.2f", xc1, b1), \
       op using 3:16 every ::1 axes x1y2 with points pt 5 ps 1.5 lc rgb "#c02020" title "{/Symbol D}n_{area}", \
       f2(x) axes x1y2 with lines lw 2 lc rgb "#c02020" title sprintf("fit: E*_{fgc-g} = %.3g, {/Symbol b}_2 = %.2f", xc2, b2)
}
