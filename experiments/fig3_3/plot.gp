# Fig. 3.3 look: the runs in the (omega, Gamma) plane filled by phase as in Fig. 3.4 (fluid
# blue, coexistence white, gas orange), each omega's transition from fluid to gas-like with its
# error, and the fitted line through them (dashed, as in the thesis).
color(l) = l eq "s" ? 0x909090 : l eq "f" ? 0x3070d0 : l eq "g" ? 0xf0a030 : \
           l eq "fgc" ? 0xffffff : l eq "sfc" ? 0xd0d0ff : l eq "sgc" ? 0xffe0c0 : 0xff0000
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
a = val("line_a"); b = val("line_b"); bp = val("prop_b"); es = val("estar_f_fgc")
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
  plot op using (column("omega")):(column("gamma")):(color(strcol(lab))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       op using (column("omega")):(column("gamma")) every ::1 with points pt 4 ps 2.5 lc rgb "black" title "runs (fill: phase; grey s, blue f, white fgc, orange g)", \
       gb using 1:3:4 every ::1 with yerrorbars pt 9 ps 1.5 lc rgb "black" title "fluid to gas-like (fgc or g), per {/Symbol w}", \
       a + b * x with lines lw 2 lc rgb "black" title sprintf("fit {/Symbol G} = %.2f + %.3f {/Symbol w}", a, b), \
       bp * x with lines lw 2 dt 2 lc rgb "black" title sprintf("through the origin: {/Symbol G}/{/Symbol w} = %.3f (E^* = %.2f)", bp, es)
}
