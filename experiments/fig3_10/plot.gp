# (a) Fig. 3.10 look: the runs in the (E*_d, Gamma) plane, coloured by phase (colder
# homogeneous gas blue, coexistence white, hotter gas orange), the A = d line
# (Gamma = 2 E*_d) and the fitted band centre A = A_c; (b) Fig. 3.25 look: Delta n_area
# against A/d per Gamma, with the thesis's maximum 0.29 at Gamma = 10.  A key box per colour.
load '../phase_key.gp'
# dry grains: the order parameters' f is the colder homogeneous gas
name(l) = l eq "f" ? "colder homogeneous gas (labelled f)" : l eq "fgc" ? "coexistence (fgc)" : \
          l eq "g" ? "hotter homogeneous gas (g)" : phase_name(l)
phases = phases_in(op, "18")
ac = real(system(sprintf("awk '$1 == \"amp_centre\" { print $2 }' %s", res)))
stats op using 4 every ::1 nooutput
xmin = STATS_min / 1.3; xmax = STATS_max * 1.3
stats op using 2 every ::1 nooutput
ymax = STATS_max * 1.5
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1400,600 font ",12"; set output png } \
  else { set terminal pdfcairo size 14in,6in font ",12"; set output pdf }
  set multiplot layout 1,2
  set logscale x
  set xrange [xmin:xmax]; set yrange [0:ymax]
  set xlabel "E^*_d = (A{/Symbol w})^2 / 2gd"
  set ylabel "{/Symbol G}"
  set key top left Left reverse opaque box font ",10"
  set title "(a) dry, {/Symbol e} = 0.96, height 18d"
  set samples 200
  plot op using 4:2:(color(strcol(18))) every ::1 with points pt 5 ps 2.5 lc rgb variable notitle, \
       op using 4:2 every ::1 with points pt 4 ps 2.5 lc rgb "black" notitle, \
       for [p in phases] NaN with boxes fs solid 1 border lc rgb "black" lc rgb color(p) title name(p), \
       2 * x title "A = d" with lines lw 2 lc rgb "black", \
       2 * x / ac title sprintf("A = %.2f d (band centre)", ac) with lines lw 2 dt 2 lc rgb "red"
  unset logscale x
  set autoscale x
  set xlabel "A / d"
  set ylabel "{/Symbol D}n_{area}"
  set yrange [0:0.45]
  set key top right
  set title "(b) density contrast across the band (Eq. 3.3)"
  plot for [g in system("awk -F'\t' 'NR > 1 { print $2 }' ".op." | sort -gu | tr '\\n' ' '")] \
         op using (column(2) == real(g) ? column(19) : 1/0):16 every ::1 smooth unique with linespoints pt 7 lw 2 title sprintf("{/Symbol G} = %s", g), \
       0.29 title "thesis max at {/Symbol G} = 10 (Fig. 3.25)" with lines dt 2 lc rgb "black"
  unset multiplot
}
