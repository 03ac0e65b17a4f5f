# Fig. 5.2c look: a_g against E~*, each run coloured by its shape (green I gas drop, black II
# strip, yellow III fluid drop, grey one phase); dashed: the strip window of least interface
# 1/pi <= a_g <= 1 - 1/pi; dash-dotted red: the measured drop-to-strip boundary a_D/S and its
# mirror 1 - a_D/S; dotted blue: the thesis's a_D/S = 0.413.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
shape_rgb(s) = s eq "I" ? 0x1a9a1a : s eq "II" ? 0x000000 : s eq "III" ? 0xd4a000 : 0x909090
ads = val("a_ds"); dads = err("a_ds")
ef = val("estar_f_fgc"); eg = val("estar_fgc_g")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 900,650 font ",12"; set output png } \
  else { set terminal pdfcairo size 9in,6.5in font ",12"; set output pdf }
  set xrange [-0.4:1.4]; set yrange [-0.05:1.1]
  set xlabel "Ẽ^* = (E^* - E^*_{f-fgc}) / (E^*_{fgc-g} - E^*_{f-fgc})"
  set ylabel "a_g"
  set title sprintf("3D, {/Symbol e} = 0.8, {/Symbol G} = 100, %s d × %s d (%s profile); E^*_{f-fgc} = %.3g, E^*_{fgc-g} = %.3g", side, side, prof, ef, eg)
  set key top left box opaque
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
}
