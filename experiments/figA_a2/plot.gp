# App. A look: a_2 against eps_cb = 2 E_cb / T_g: Eq. A.59 (line) and A.60 (dashed), the DSMC
# of the Boltzmann equation (squares), the event-driven free grains (filled circles) and all
# grains (open circles), runs that clustered (crosses; their all-grain a_2 is off the scale),
# and the free grains again at the printed reading E_cb / T_g (grey).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,650 font ",11"; set output png } \
  else { set terminal pdfcairo size 10in,6.5in font ",11"; set output pdf }
  set title sprintf("a_2 of the white-noise-driven wet gas, 2D (%s profile): a_2 / Eq. A.59 = %.2f {/Symbol \261} %.2f (ED free grains), %.2f {/Symbol \261} %.2f (DSMC)", \
    prof, val("ed_free_scale"), err("ed_free_scale"), val("dsmc_scale"), err("dsmc_scale"))
  set xlabel "{/Symbol e}_{cb} = 2 E_{cb} / T_g"; set ylabel "a_2"
  set key top right box opaque; set xrange [0:3.2]; set yrange [-0.05:0.08]
  set xzeroaxis lt 1 lc rgb "gray70"
  plot th every ::1 using 1:3 with lines lw 2 lc rgb "black" title "Eq. A.59 (first Sonine)", \
       th every ::1 using 1:4 with lines dt 2 lw 1.5 lc rgb "black" title "Eq. A.60 (to {/Symbol e}_{cb}^2)", \
       dsmc every ::1 using 2:3:4 with yerrorbars pt 5 ps 1.2 lc rgb "blue" title "DSMC of the Boltzmann equation", \
       ed every ::1 using 2:($9 <= maxb ? $4 : NaN):3:5 with xyerrorbars pt 7 ps 1.3 lc rgb "red" title "event-driven, grains without a bridge", \
       ed every ::1 using 2:($9 <= maxb ? $6 : NaN):7 with yerrorbars pt 6 ps 1.3 lc rgb "red" title "event-driven, all grains (bound pairs too)", \
       ed every ::1 using 2:($9 > maxb ? $4 : NaN):5 with yerrorbars pt 2 ps 1.5 lc rgb "dark-red" title sprintf("event-driven, clustered (> %g bridges per grain): free grains", maxb), \
       ed every ::1 using ($2 / 2):($9 <= maxb ? $4 : NaN):5 with yerrorbars pt 9 ps 1.1 lc rgb "gray50" title "free grains at the printed reading E_{cb} / T_g"
}
