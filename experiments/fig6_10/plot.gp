# Figs. 6.10-6.11 look.  Top: the E* = 98.9 run's height-time map with its interface h_I (red)
# and the turning points found (green: top, blue: bottom), as Fig. 6.10.  Bottom: omega_p
# against h0 / d for each E* (circles, with errors) beside Eq. 6.5 at each run's h0 and grains
# below (crosses) and the adiabatic ideal gas sqrt(kappa g / h0) (line), as Fig. 6.11.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
col(n) = int(system(sprintf("awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == \"%s\") print i }' %s", n, osc)))
ce = col("estar"); ch = col("h0"); che = col("h0_err"); cw = col("omega_p"); cwe = col("omega_p_err"); ct = col("omega_theory")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,1000 font ",11"; set output png } \
  else { set terminal pdfcairo size 12in,10in font ",11"; set output pdf }
  set multiplot layout 2,1 title sprintf("the plug's frequency: {/Symbol G} = 60 (%s profile)", profile)
  set palette gray negative; set cbrange [0:1]; unset colorbox
  set xlabel "t / T_{driv}"; set ylabel "h / d"; set yrange [0:zmax]
  set title "Fig. 6.10: E^* = 98.9, interface at {/Symbol f} = 0.51 and its turning points"
  plot map using 3:4:6 with image notitle, \
       itf using 3:($10 == 0 ? $4 : NaN) every 2 with points pt 7 ps 0.3 lc rgb "red" title "h_I", \
       itf using 3:($10 > 0 ? $4 : NaN) with impulses lw 2 lc rgb "dark-green" title "top", \
       itf using 3:($10 < 0 ? $4 : NaN) with impulses lw 2 lc rgb "blue" title "bottom"
  set autoscale; set xlabel "h_0 / d"; set ylabel "{/Symbol w}_p (g/d)^{1/2}"; set key top right box
  set title sprintf("Fig. 6.11: {/Symbol w}_p / Eq. 6.5 = %.2f {/Symbol \261} %.2f over the sweep; Leidenfrost point E^*_{LP} = %g", val("omega_ratio"), real(system(sprintf("awk -F'\t' '$1 == \"omega_ratio\" { print $3 }' %s", res))), val("lp_estar"))
  set xrange [0:*]; set yrange [0:*]
  plot osc every ::1 using ch:cw:che:cwe with xyerrorbars pt 6 ps 1.5 lc rgb "black" title "simulations", \
       osc every ::1 using ch:ct with points pt 2 ps 1.5 lc rgb "red" title "Eq. 6.5 at h_0 and N", \
       osc every ::1 using ch:cw:(sprintf("%g", column(ce))) with labels offset 2.5,0.8 notitle, \
       sqrt(5.0 / 3 / x) with lines dt 2 lc rgb "gray40" title "(5g / 3h_0)^{1/2}"
  unset multiplot
}
