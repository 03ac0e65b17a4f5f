# Fig. 7.5 look: E_perp / E_cb (log, left) and coordination (bridges per grain) (right) against F_smax, solid
# runs filled, fluidized open; the measured F_scrit (shaded: its error) and the thesis's fit
# (3.7 mg + 1.4 F_B) / L_x.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
fc = val("fscrit"); fe = err("fscrit"); fit = (3.7 + 1.4 * fb) / lx
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,650 font ",11"; set output png } \
  else { set terminal pdfcairo size 10in,6.5in font ",11"; set output pdf }
  set title sprintf("sheared wet grains fluidize: L_x = %g d, F_B = %g mg (%s profile): F_{scrit} = %.2f {/Symbol \261} %.2f mg, thesis's fit %.2f mg", lx, fb, profile, fc, fe, fit)
  set xlabel "F_{smax} / mg"; set ylabel "E_{/Symbol \\136} / E_{cb}"; set y2label "coordination (bridges per grain)"
  set logscale y; set ytics nomirror; set y2tics; set key top right box; set offsets 0.1, 0.1, 0, 0
  if (fc == fc) { set object 1 rect from fc - fe, graph 0 to fc + fe, graph 1 fc rgb "light-gray" fs solid 0.5 behind }
  set arrow 2 from fit, graph 0 to fit, graph 1 nohead dt 2 lw 2 lc rgb "red"
  plot sweep every ::1 using 1:(strcol(4) eq "solid" ? $2 : NaN) with points pt 7 ps 1.5 lc rgb "black" title "solid", \
       sweep every ::1 using 1:(strcol(4) eq "fluidized" ? $2 : NaN) with points pt 6 ps 1.5 lc rgb "black" title "fluidized", \
       sweep every ::1 using 1:3 axes x1y2 with linespoints pt 4 lc rgb "blue" title "coordination (bridges per grain)", \
       NaN with lines dt 2 lw 2 lc rgb "red" title "thesis: (3.7 mg + 1.4 F_B) / L_x"
}
