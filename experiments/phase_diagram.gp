# Fig. 3.4a look: phases coloured as in the thesis (fluid blue, gas orange, coexistence
# white; solid grey; sfc/sgc pale) on log E* and log Gamma axes (the thesis's "log/linear
# scale"; a log Gamma axis keeps the rows Gamma = 1.2-3 of the bulge apart), the Delaunay boundary points, the
# A = s_crit line (Gamma = 2 E* E_cb / (m g s_crit), from Eq. 2.18-2.19) and an arrow at the
# fitted f-fgc transition; a key box per phase drawn; panels (a) the diagram, (b) the line
# against the time one watches (where the experiment measures it).
load '../phase_key.gp'
phases = phases_in(op, "18")
fit_x = real(system(sprintf("awk '$1 == \"vertical_f_fgc\" { print $2 }' %s", res)))
hi_x = real(system(sprintf("awk '$1 == \"vertical_f_fgc_hi_gamma\" { v = $2 } END { print v + 0 }' %s", res)))
# the bulge of the fgc-g line (keys fgc_g_bulge_*, where the experiment reports it)
bulge_x = real(system(sprintf("awk '$1 == \"fgc_g_bulge_estar\" { v = $2 } END { print v + 0 }' %s", res)))
bulge_y = real(system(sprintf("awk '$1 == \"fgc_g_bulge_gamma\" { v = $2 } END { print v + 0 }' %s", res)))
bulge_a = real(system(sprintf("awk '$1 == \"fgc_g_bulge_a_over_scrit\" { v = $2 } END { print v + 0 }' %s", res)))
# the line against the time one watches (keys vertical_f_fgc_hi_gamma_t<T>), drawn as an inset
waits = system(sprintf("awk -F'\t' '$1 ~ /^vertical_f_fgc_hi_gamma_t[0-9]+$/ && $2 != \"nan\" { t = $1; sub(/.*_t/, \"\", t); printf \"%%s %%s %%s\\n\", t, $2, ($3 == \"nan\" ? 0 : $3) }' %s", res))
stats op using 3 every ::1 nooutput
xmin = STATS_min / 1.3; xmax = STATS_max * 1.3
stats op using 2 every ::1 nooutput
ymin = STATS_min / 1.12; ymax = STATS_max * 1.6
do for [k = 1:2] {
  reset
  wide = strlen(waits) > 0 ? 1.3 : 1   # room for the t_w panel
  pw = 1000 * wide; dw = 10 * wide
  if (k == 1) { set terminal pngcairo size pw,750 font ",12"; set output png } \
  else { set terminal pdfcairo size dw*1in,7.5in font ",12"; set output pdf }
  set logscale xy
  set xrange [xmin:xmax]; set yrange [ymin:ymax]
  set xtics (0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1, 1.25, 1.5, 2, 3, 4, 5)
  set ytics (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 15, 20, 30, 40, 50, 60, 70, 80, 100)
  set xlabel "E^*"
  set ylabel "{/Symbol G}"
  set tmargin 4
  set arrow 1 from fit_x, graph 1.09 to fit_x, graph 1.0 head filled lw 2 lc rgb "black"
  # the two labels point away from each other, whichever line lies left
  hi_left = hi_x > 0 && hi_x < fit_x
  if (hi_left) { set label 1 sprintf(" f-fgc: E* = %.3g", fit_x) at fit_x, graph 1.06 left } \
  else { set label 1 sprintf("f-fgc: E* = %.3g ", fit_x) at fit_x, graph 1.06 right }
  if (hi_x > 0) {
    set arrow 2 from hi_x, graph 1.09 to hi_x, graph 1.0 head filled lw 2 lc rgb "#3070d0"
    if (hi_left) { set label 2 sprintf("{/Symbol G} {/Symbol \263} 8: %.3g ", hi_x) at hi_x, graph 1.06 right tc rgb "#3070d0" } \
    else { set label 2 sprintf(" {/Symbol G} {/Symbol \263} 8: %.3g", hi_x) at hi_x, graph 1.06 left tc rgb "#3070d0" }
  }
  if (bulge_x > 0) {
    set style textbox opaque noborder
    set label 3 sprintf("bulge: A = %.2f s_{crit}", bulge_a) at bulge_x, bulge_y left point pt 3 ps 3 lw 2 lc rgb "black" offset 1.5, 1.3 boxed front
  }
  set samples 200
  if (strlen(waits) > 0) { set multiplot; set origin 0, 0; set size 0.75, 1 }
  set key below box maxrows 3 width 1
  if (strlen(waits) > 0) { set label 11 "(a)" at screen 0.01, screen 0.97 font ",14" }
  plot op using 3:2:(color(strcol(18))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       op using 3:2 every ::1 with points pt 4 ps 2.5 lc rgb "black" notitle, \
       for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title "run: ".phase_name(p), \
       bd using 1:2 every ::1 with points pt 7 ps 0.8 lc rgb "red" title "boundary (Delaunay midpoints)", \
       2 * x * ecb / scrit title "A = s_{crit}" with lines lw 2 lc rgb "black"
  if (strlen(waits) > 0) {
    set origin 0.75, 0.3; set size 0.25, 0.5
    unset arrow; unset label; unset key; set tmargin
    set logscale x; unset logscale y
    set xrange [*:*]; set yrange [*:*]; set autoscale
    set xtics auto; set ytics auto; set format x "10^{%T}"
    set xlabel "t_w [(d/g)^{1/2}]"; set ylabel "f-fgc E^*, {/Symbol G} {/Symbol \263} 8"
    set title "metastable fluid:\nthe line if runs stop at t_w"
    unset key
    set label 13 "thesis 1.02" at graph 0.97, first 1.02 right offset 0, -0.8 tc rgb "grey40"
    set label 12 "(b)" at screen 0.76, screen 0.83 font ",14"
    plot 1.02 with lines lc rgb "grey40" dt 2 notitle, \
         "<echo '".waits."'" using 1:2:3 with yerrorlines pt 7 lc rgb "#3070d0" notitle
    unset multiplot
  }
}
