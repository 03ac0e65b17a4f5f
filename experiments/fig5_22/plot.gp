# Figs. 5.22-5.24 look.  Left: bridge density along x against time for the first seed (Fig.
# 5.22).  Middle: the plug's centre against t / T_driv for up to six seeds (Fig. 5.23).  Right:
# the seeds' mean square displacement over L_x^2 against the lag, log-log, with the fitted
# power law over its window and the thesis's line (D_x = 1.6e-8, alpha = 1.27) (Fig. 5.24).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $2; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
files = system(sprintf("awk -F'\t' '!/^#/ && $1 != \"file\" && !s[$1]++ { printf \"%%s \", $1 }' %s", tracks))
a = val("alpha"); dx = val("d_x")
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1500,480 font ",11"; set output png } \
  else { set terminal pdfcairo size 15in,4.8in font ",11"; set output pdf }
  set multiplot layout 1, 3 title sprintf("the plug's random walk: 1200 wet disks, 400d x 9d, {/Symbol G} = 15, E^* = 1.42 (%s profile, %d seeds)", prof, int(val("seeds")))
  set title "bridge density, first seed (Fig. 5.22)"
  set xlabel "t / T_{driv}"; set ylabel "x / d"
  set palette gray negative; set cblabel "n_{cb} d"
  plot st using ($1 / tdriv):2:4 with image notitle
  set title "centre of the plug (Fig. 5.23)"
  set ylabel "x_{com} / d"; unset colorbox
  plot for [i = 1:words(files)] sprintf("< awk -F'\t' '$1 == \"%s\"' %s", word(files, i), tracks) using 3:4 with lines lw 1.5 lc i notitle
  set title "mean square displacement (Fig. 5.24)"
  set logscale xy; set format y "10^{%L}"
  set xlabel "lag t / T_{driv}"; set ylabel "{/Symbol s}_{rw} / L_x^2"
  set key top left box
  plot msd using 2:($4 > 0 ? $4 : NaN):5 with yerrorbars pt 7 ps 0.6 lc rgb "black" title "seeds' mean", \
       (x > f0 && x <= f1 ? dx * x**a : NaN) with lines lw 2 lc rgb "red" title sprintf("fit: D_x = %.2g, {/Symbol a} = %.2f {/Symbol \261} %.2f", dx, a, err("alpha")), \
       (x > 1000 ? 1.6e-8 * x**1.27 : NaN) with lines lw 1.5 dt 2 lc rgb "blue" title "thesis: D_x = 1.6e-8, {/Symbol a} = 1.27"
  unset multiplot
}
