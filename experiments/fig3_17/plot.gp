# Fig. 3.17 look: the amplitude band of coexistence in the gas region against eps: runs
# (white coexisting, orange homogeneous gas; a key box per phase), the band's upper edge A_crit with its
# resolution, the lower edge where the scan shows one, the fitted lines, and the thesis's two
# fits A/d = -3.61 (eps - 1) + 0.24 (black) and -1.72 (eps - 1) + 0.24 (red).
# fe: the fixed-E* rows' edges (full profile only; empty otherwise), all at eps = fe_eps
if (!exists("fe")) fe = ""
fe_eps = 0.963
fixed_plot = strlen(fe) ? sprintf(", '%s' using (fe_eps + 0.004 * $0):3:4 every ::1 with yerrorbars pt 9 ps 1.5 lw 2 lc rgb 'dark-green' title 'A_{crit} at fixed E* = 5, 12 ({/Symbol G} = 2 E* E_{cb} / A; drawn right of 0.96)'", fe) : ""
load '../phase_key.gp'
phases = phases_in(op, "18")
a = real(system(sprintf("awk '$1 == \"acrit_line_a\" { print $2 }' %s", res)))
b = real(system(sprintf("awk '$1 == \"acrit_line_b\" { print $2 }' %s", res)))
# the lower edges' line, where the scans have one (NaN otherwise: not drawn)
la = real(system(sprintf("awk '$1 == \"lo_line_a\" { v = $2 } END { print v == \"\" ? \"NaN\" : v }' %s", res)))
lb = real(system(sprintf("awk '$1 == \"lo_line_b\" { v = $2 } END { print v == \"\" ? \"NaN\" : v }' %s", res)))
lower(x) = lb == lb ? la + lb * (1 - x) : 1 / 0
lower_title = lb == lb ? sprintf("fit: lower edge %.2f + %.2f (1 - {/Symbol e})", la, lb) : ""
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1100,850 font ",12"; set output png } \
  else { set terminal pdfcairo size 11in,8.5in font ",12"; set output pdf }
  set xrange [0.77:1.01]; set yrange [0:1.3]
  set xlabel "{/Symbol e}" offset 0, 0.3
  set ylabel "A / d"
  # below the plot, where it hides no run
  set key below box font ",11" width 1 maxrows 5 spacing 1.1
  set title "coexistence band inside the gas region, {/Symbol G} = 15"
  plot op using 6:19:(color(strcol(18))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       op using 6:19 every ::1 with points pt 4 ps 2.5 lc rgb "black" notitle, \
       for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title "run: ".phase_name(p), \
       ed using 1:3:4 every ::1 with yerrorbars pt 7 ps 1.5 lw 2 lc rgb "blue" title "A_{crit}: upper edge of the band", \
       ed using 1:5:6 every ::1 with yerrorbars pt 6 ps 1.5 lw 2 lc rgb "blue" title "lower edge (where gas lies below the band)", \
       a + b * (1 - x) title sprintf("fit: A_{crit}/d = %.2f + %.2f (1 - {/Symbol e})", a, b) with lines lw 2 dt 2 lc rgb "blue", \
       lower(x) title lower_title with lines lw 2 dt 3 lc rgb "blue", \
       0.24 - 3.61 * (x - 1) title "thesis: -3.61 ({/Symbol e} - 1) + 0.24" with lines lw 2 lc rgb "black", \
       0.24 - 1.72 * (x - 1) title "thesis: -1.72 ({/Symbol e} - 1) + 0.24" with lines lw 2 lc rgb "red" @fixed_plot
}
