# Fig. 4.1 look: Gamma_C against F_B/mg, the fit Gamma_C = 1 + F_B (1 - E~*) / 3mg (black) and
# Eq. 4.15 at the runs' E* (red); onset of fluidization in grey, drawn first and a little to the
# right (0.15 in F_B / mg), so that it hides no complete-fluidization point where both agree.
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
e = val("estar_tilde"); de = err("estar_tilde"); eo = val("estar_tilde_onset")
# Tables read by column name need no `every ::1`: naming a column makes gnuplot take the header
# line as titles, and `every ::1` then dropped the first data row.
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,700 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7in font ",12"; set output pdf }
  set xlabel "F_B / mg"
  set ylabel "{/Symbol G}_C"
  set key top left
  set xrange [0:*]
  set offsets 0, 1, 0, 0
  set yrange [0.8:*]
  plot gco using ($1 + 0.15):3:4 every ::1 with yerrorbars pt 6 ps 1.4 lc rgb "#808080" title "onset of fluidization (drawn 0.15 to the right)", \
       gcc using 1:3:4 every ::1 with yerrorbars pt 7 ps 1.6 lc rgb "black" title "complete fluidization (time-driven)", \
       1 + x * (1 - e) / 3 lw 2 lc rgb "black" title sprintf("fit: Ẽ^* = %.2f {/Symbol \261} %.2f (onset: %.2f)", e, de, eo), \
       eq using 1:(column("gamma_c_415")) with lines lw 2 dt 2 lc rgb "#c02020" title sprintf("Eq. 4.15, M = 3, E^* = %g (wetgran-theory)", estar)
}
