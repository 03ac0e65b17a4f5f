# Figs. 6.3b and 6.4 look.  Top: the packing fraction over phi_max = 0.74 against height and
# t / T_driv (white: empty, black: close packed).  Bottom: the profiles at the plug's top
# (black) and bottom (red) turning points, with phi_c = 0.51 (the interface) dashed.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,1000 font ",11"; set output png } \
  else { set terminal pdfcairo size 12in,10in font ",11"; set output pdf }
  set multiplot title sprintf("the wet granular Leidenfrost state: {/Symbol G} = 60, E^* = 98.9 (%s profile)", profile)
  set origin 0, 0.45; set size 1, 0.55
  set palette gray negative; set cbrange [0:1]; set cblabel "{/Symbol f} / {/Symbol f}_{max}"
  set xlabel "t / T_{driv}"; set ylabel "h / d"; set yrange [0:zmax]; set xrange [0:*]
  set title "Fig. 6.3b"
  plot map using 3:4:6 with image notitle
  unset colorbox
  set origin 0, 0; set size 1, 0.45
  set xlabel "h / d"; set ylabel "{/Symbol f}"; set xrange [0:zmax]; set yrange [0:0.75]; set key top left box
  set title sprintf("Fig. 6.4: plug {/Symbol f} = %.3f (thesis 0.62), h_0 = %.1f d, plug %.1f d high", val("phi_plug"), val("h0"), val("h_p"))
  plot prof using 2:3 with lines lw 2 lc rgb "black" title "top turning points", \
       prof using 2:4 with lines lw 2 lc rgb "red" title "bottom turning points", \
       0.51 with lines dt 2 lc rgb "gray40" title "{/Symbol f}_c = 0.51"
  unset multiplot
}
