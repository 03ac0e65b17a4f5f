# The 3D scans: T_g/E_cb against E* for eps = 1 and 0.96 (points coloured by phase), the
# fitted f-fgc transitions (solid) and the thesis's values 2.08 and 4.36 (dashed).
color(l) = l eq "s" ? 0x909090 : l eq "f" ? 0x3070d0 : l eq "g" ? 0xf0a030 : \
           l eq "fgc" ? 0xffffff : l eq "sfc" ? 0xd0d0ff : l eq "sgc" ? 0xffe0c0 : 0xff0000
val(k) = real(system(sprintf("awk '$1 == \"%s\" { print $2 } END { if (!NR) print \"nan\" }' %s", k, res)))
x1 = val("f_fgc_eps1"); x2 = val("f_fgc_eps0.96")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,860 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,8.6in font ",12"; set output pdf }
  set logscale xy
  set xlabel "E^*"
  set ylabel "T_g / E_{cb}"
  set key below box font ",11" maxcols 1
  set title "3D, 3.24 spheres per d^2, {/Symbol G} = 30"
  set arrow 1 from x1, graph 0 to x1, graph 1 nohead lw 2 lc rgb "black"
  set arrow 2 from x2, graph 0 to x2, graph 1 nohead lw 2 lc rgb "red"
  set arrow 3 from 2.08, graph 0 to 2.08, graph 1 nohead lw 2 dt 2 lc rgb "black"
  set arrow 4 from 4.36, graph 0 to 4.36, graph 1 nohead lw 2 dt 2 lc rgb "red"
  plot op using ($6 == 1 ? $3 : 1/0):11:(color(strcol(18))) every ::1 with points pt 5 ps 2.2 lc rgb variable notitle, \
       op using ($6 == 1 ? $3 : 1/0):11 every ::1 with points pt 4 ps 2.2 lc rgb "black" title sprintf("{/Symbol e} = 1: f-fgc at %.3g (thesis 2.08, dashed)", x1), \
       op using ($6 < 1 ? $3 : 1/0):11:(color(strcol(18))) every ::1 with points pt 7 ps 2.2 lc rgb variable notitle, \
       op using ($6 < 1 ? $3 : 1/0):11 every ::1 with points pt 6 ps 2.2 lc rgb "red" title sprintf("{/Symbol e} = 0.96: f-fgc at %.3g (thesis 4.36, dashed)", x2), \
       keyentry with points pt 5 ps 2 lc rgb color("f") title "fluid (f)", \
       keyentry with points pt 5 ps 2 lc rgb color("g") title "gas (g)", \
       keyentry with points pt 4 ps 2 lc rgb "black" title "fluid-gas coexistence (fgc, open)"
}
