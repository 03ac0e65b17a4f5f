# Fig. 5.2c look: a_g against E~*, each run coloured by its shape (green I gas drop, black II
# strip, yellow III fluid drop, grey one phase); dashed: the strip window of least interface
# 1/pi <= a_g <= 1 - 1/pi; dash-dotted red: the measured drop-to-strip boundary a_D/S and its
# mirror 1 - a_D/S; dotted blue: the thesis's a_D/S = 0.413.  Below, as the thesis's insets:
# the time-averaged bridge density n_cb on the lateral plane (dark: many bridges, the fluid)
# of the first run of each shape.
# (integers with an exponent, 4e-07, are written 4.0e-07: gnuplot's real() stops at the e)
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $2; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $3; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
shape_rgb(s) = s eq "I" ? 0x1a9a1a : s eq "II" ? 0x000000 : s eq "III" ? 0xd4a000 : 0x909090
ads = val("a_ds"); dads = err("a_ds")
ef = val("estar_f_fgc"); eg = val("estar_fgc_g")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 900,900 font ",12"; set output png } \
  else { set terminal pdfcairo size 9in,9in font ",12"; set output pdf }
  set multiplot
  set size 1, 0.68; set origin 0, 0.32
  set xrange [-0.4:1.4]; set yrange [-0.05:1.1]
  set xlabel "Ẽ^* = (E^* - E^*_{f-fgc}) / (E^*_{fgc-g} - E^*_{f-fgc})"
  set ylabel "a_g"
  set title sprintf("3D, {/Symbol e} = 0.8, {/Symbol G} = 100, %s d × %s d (%s profile); E^*_{f-fgc} = %.3g, E^*_{fgc-g} = %.3g", side, side, prof, ef, eg)
  set key bottom right box opaque font ",10" 
  set arrow from 0, graph 0 to 0, graph 1 nohead dt 3 lc rgb "gray50"
  set arrow from 1, graph 0 to 1, graph 1 nohead dt 3 lc rgb "gray50"
  set samples 2
  lo = 1 / pi; hi = 1 - 1 / pi
  plot lo with lines dt 2 lw 1.5 lc rgb "black" title "strip window 1/{/Symbol p}, 1 - 1/{/Symbol p} (least interface)", \
       hi with lines dt 2 lw 1.5 lc rgb "black" notitle, \
       (ads == ads ? ads : NaN) with lines dt 4 lw 2 lc rgb "red" title sprintf("a_{D/S} = %.3f {/Symbol \261} %.3f (last drop, first strip)", ads, dads), \
       (ads == ads ? 1 - ads : NaN) with lines dt 4 lw 2 lc rgb "red" notitle, \
       0.413 with lines dt 3 lw 2 lc rgb "blue" title "thesis a_{D/S} = 0.413", \
       ag using (column("estar_tilde")):(column("a_g")):(column("a_g_err")):(shape_rgb(strcol("shape"))) with yerrorbars pt 7 ps 1.6 lc rgb variable notitle, \
       NaN with points pt 7 ps 1.6 lc rgb "#1a9a1a" title "I gas drop", \
       NaN with points pt 7 ps 1.6 lc rgb "black" title "II strip", \
       NaN with points pt 7 ps 1.6 lc rgb "#d4a000" title "III fluid drop", \
       NaN with points pt 7 ps 1.6 lc rgb "#909090" title "one phase (f or g)"
  unset arrow; unset key; set size ratio -1
  set palette gray negative; unset colorbox
  set xrange [0:side + 0]; set yrange [0:side + 0]
  set xlabel "x / d" offset 0, 0.5; set ylabel "y / d" offset 1, 0
  set tics font ",9"
  do for [s = 1:3] {
    name = s == 1 ? "I" : s == 2 ? "II" : "III"
    set size 0.33, 0.32; set origin (s - 1) * 0.33, 0
    file = system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2; exit }' %s", name, fields))
    set title sprintf("%s: %s", name, file eq "" ? "no run" : system("basename " . file . " .h5")) font ",11"
    if (file eq "") { unset border; unset tics; unset xlabel; unset ylabel; plot NaN notitle; set border; set tics; \
      set xlabel "x / d"; set ylabel "y / d" } \
    else { plot sprintf("< awk -F'\t' '$1 == \"%s\"' %s", name, fields) using 3:4:6 with image notitle }
  }
  unset multiplot
}
