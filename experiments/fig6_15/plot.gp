# Figs. 6.14-6.15 look.  Top: height-time maps of the least (damped) and the largest E*.
# Bottom: the rms excursion eps_h against E* with the fit eps_h = (a (E* - E*_onset))^(1/2).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
col(n) = int(system(sprintf("awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == \"%s\") print i }' %s", n, osc)))
ce = col("estar"); cr = col("eps_rms")
e0 = val("e_onset")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,1100 font ",11"; set output png } \
  else { set terminal pdfcairo size 12in,11in font ",11"; set output pdf }
  set multiplot title sprintf("inelastic plugs: {/Symbol e} = 0.98, {/Symbol e}_{wall} = 0.99, {/Symbol G} = 60 (%s profile)", profile)
  set palette gray negative; set cbrange [0:1]; unset colorbox
  set xlabel "t / T_{driv}"; set ylabel "h / d"; set yrange [0:zmax]; set xrange [0:*]
  set origin 0, 0.66; set size 1, 0.33; set title sprintf("Fig. 6.14 top: E^* = %g", elow)
  plot low using 3:4:6 with image notitle
  set origin 0, 0.33; set size 1, 0.33; set title sprintf("Fig. 6.14 bottom: E^* = %g", ehigh)
  plot high using 3:4:6 with image notitle
  set origin 0, 0; set size 1, 0.33; set autoscale; set xrange [0:*]; set yrange [0:*]
  set xlabel "E^*"; set ylabel "{/Symbol e}_{h,rms}"; set key top left box
  set title sprintf("Fig. 6.15: onset E^*_{onset} = %g (thesis about 2750)", e0)
  f(x) = (e0 == e0 && x > e0) ? sqrt((x - e0) / (ehigh - e0)) * val("eps_rms_high") : NaN
  plot osc every ::1 using ce:cr with points pt 7 ps 1.5 lc rgb "black" title "simulations", \
       f(x) with lines lw 2 lc rgb "red" title "(E^* - E^*_{onset})^{1/2}"
  unset multiplot
}
