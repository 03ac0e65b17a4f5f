# Fig. 3.11 look: the eps = 0.8 runs in the (E*, Gamma) plane coloured by phase, the A = d
# line (Gamma = 2 E* E_cb / (m g d)), the s-f line from the inflection of T_g along Gamma and
# the f-g boundary at Gamma = 2.7 from the inflection of T_g (Fig. 3.29).
# A key box per phase; the key below the plot, where it hides no run.
load '../phase_key.gp'
phases = phases_in(op, "18")
val(k) = real(system(sprintf("awk '$1 == \"%s\" { print $2 }' %s", k, res)))
sf = val("sf_gamma")
fgx = real(system(sprintf("awk '$1 == \"inflection_estar\" { print $2 }' %s", fg)))
fge = real(system(sprintf("awk '$1 == \"inflection_estar\" { print $3 }' %s", fg)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,820 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,8.2in font ",12"; set output pdf }
  set logscale xy
  set xrange [0.4:40]; set yrange [1.2:45]
  set xtics (0.5, 1, 2, 3, 5, 10, 20, 30)
  set ytics (1.5, 2, 3, 5, 8, 15, 30)
  set xlabel "E^*"
  set ylabel "{/Symbol G}"
  set key below box maxrows 3 width 1 font ",11"
  set title "{/Symbol e} = 0.8"
  set samples 200
  plot op using 3:2:(color(strcol(18))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       op using 3:2 every ::1 with points pt 4 ps 2.5 lc rgb "black" notitle, \
       for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title "run: ".phase_name(p), \
       2 * x * ecb title "A = d" with lines lw 2 lc rgb "black", \
       '+' using (fgx):(2.7):(fgx - fge):(fgx + fge) every ::::0 with xerrorbars pt 13 ps 2 lw 2 lc rgb "red" title sprintf("f-g: inflection of T_g at {/Symbol G} = 2.7 (Fig. 3.29), E* = %.2g", fgx), \
       sf title sprintf("s-f: inflection of T_g at {/Symbol G} = %.2f", sf) with lines lw 2 dt 2 lc rgb "gray40"
}
