# Fig. 6.6 look.  Top: the packing fraction over phi_max against height and t / T_driv, with the
# plug's lower interface (red).  Bottom: the same with the contrast raised twentyfold, so that
# the dilute gas above the plug shows.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,1000 font ",11"; set output png } \
  else { set terminal pdfcairo size 12in,10in font ",11"; set output pdf }
  set multiplot layout 2,1 title sprintf("a modulated plug with gas above: {/Symbol G} = 60, E^* = 63.3 (%s profile)", profile)
  set palette gray negative; set cblabel "{/Symbol f} / {/Symbol f}_{max}"
  set xlabel "t / T_{driv}"; set ylabel "h / d"; set yrange [0:zmax]; set xrange [0:*]
  set cbrange [0:1]
  set title "Fig. 6.6 top: the plug and its interface h_I ({/Symbol f} = 0.51)"
  plot map using 3:4:6 with image notitle, itf using 3:4 every 4 with points pt 7 ps 0.3 lc rgb "red" title "h_I"
  set cbrange [0:0.05]
  set title sprintf("Fig. 6.6 bottom: low contrast; gas above the plug %.1f %% of the grains, sound speed %.1f d/T_{driv} (thesis 11.3)", 100 * val("above_fraction"), val("v_sound"))
  plot map using 3:4:6 with image notitle
  unset multiplot
}
