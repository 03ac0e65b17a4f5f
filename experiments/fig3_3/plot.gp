# Fig. 3.3 look: the runs in the (omega, Gamma) plane filled by phase as in Fig. 3.4 (fluid
# blue, coexistence white, gas orange), each omega's transition from fluid to gas-like with its
# error, and the fitted line through them (dashed, as in the thesis).  A key box per phase; the
# squares small enough that the rows' close Gamma steps (0.1-0.2 at small omega) stay apart.
load '../phase_key.gp'
phases = phases_in(op, "label")
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
a = val("line_a"); b = val("line_b"); bp = val("prop_b"); es = val("estar_f_fgc")
# Tables read by column name need no `every ::1`: naming a column makes gnuplot take the header
# line as titles, and `every ::1` then dropped the first data row.
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,750 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7.5in font ",12"; set output pdf }
  set xlabel "{/Symbol w} [(g/d)^{1/2}]"
  set ylabel "{/Symbol G}"
  set xrange [0:*]; set yrange [0:*]
  set offsets 0, 2, 1, 0
  set key top left opaque box
  lab = "label"
  plot op using (column("omega")):(column("gamma")):(color(strcol(lab))) with points pt 5 ps 1.1 lc rgb variable notitle, \
       op using (column("omega")):(column("gamma")) with points pt 4 ps 1.1 lc rgb "black" notitle, \
       for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title "run: ".phase_name(p), \
       gb using 1:3:4 every ::1 with yerrorbars pt 9 ps 1.5 lc rgb "black" title "fluid to gas-like (fgc or g), per {/Symbol w}", \
       a + b * x with lines lw 2 lc rgb "black" title sprintf("fit {/Symbol G} = %.2f + %.3f {/Symbol w}", a, b), \
       bp * x with lines lw 2 dt 2 lc rgb "black" title sprintf("through the origin: {/Symbol G}/{/Symbol w} = %.3f (E^* = %.2f)", bp, es)
}
