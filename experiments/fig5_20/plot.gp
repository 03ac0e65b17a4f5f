# Figs. 5.20-5.21 look.  Top: the bridge density of six map frames equidistant in time (first
# seed; Fig. 5.20).  Bottom: the number of crystalline domains N_d (black) and their share of
# the box (red) against t / T_driv, log-log, with the fit N_d = a (t/T_driv)^beta over its
# window and the thesis's slope -2/3 through the fit's first point (Fig. 5.21).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $2; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
d1 = word(doms, 1)
fitline = system(sprintf("sed -n 's/.*fit n_d = a (t\\/T_driv)^beta over .*: a = \\([^,]*\\), beta = \\([^ ]*\\) .*/\\1 \\2/p' %s", d1))
fa = real(word(fitline, 1)); fb = real(word(fitline, 2))
tf = system(sprintf("awk 'NF > 0 && !s[$NF]++ { printf \"%%s \", $(NF - 1) }' %s", frames))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1500,900 font ",11"; set output png } \
  else { set terminal pdfcairo size 15in,9in font ",11"; set output pdf }
  set multiplot title sprintf("crystalline domains coarsen: {/Symbol G} = 90, E^* = 1.3, {/Symbol e} = 0.96, %g d x %g d x 9 d (%s profile)", lx, lx, prof)
  set palette gray negative; unset colorbox; set size ratio -1
  unset xtics; unset ytics
  do for [i = 0:5] {
    set origin i / 6.0, 0.5; set size 1 / 6.0, 0.45
    set title sprintf("t / T_{driv} = %.0f", real(word(tf, i + 1)) / 0.06003)
    plot frames index i using 2:3:5 with image notitle
  }
  set size noratio; set xtics; set ytics
  set origin 0.1, 0; set size 0.8, 0.5
  set logscale xy; set xlabel "t / T_{driv}"; set ylabel "N_d"; set y2label "crystalline share of the box"
  set y2tics; set ytics nomirror; set logscale y2; set key bottom left box
  set title "Fig. 5.21"
  plot for [i = 1:words(doms)] word(doms, i) using 3:($4 > 0 ? $4 : NaN) with points pt 6 ps 1 lc rgb "black" title (i == 1 ? "N_d" : ""), \
       for [i = 1:words(doms)] word(doms, i) using 3:($5 > 0 ? $5 : NaN) axes x1y2 with lines lw 2 lc rgb "red" title (i == 1 ? "share" : ""), \
       (x > f0 && x <= f1 ? fa * x**fb : NaN) with lines lw 2 lc rgb "blue" title sprintf("fit: {/Symbol b} = %.2f {/Symbol \261} %.2f", val("beta"), err("beta")), \
       (x > f0 && x <= f1 ? fa * f0**fb * (x / f0)**(-2.0/3) : NaN) with lines dt 2 lw 1.5 lc rgb "gray40" title "thesis: t^{-2/3}"
  unset multiplot
}
