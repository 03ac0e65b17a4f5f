# Figs. 5.7-5.11 look, six panels.  (a) Fig. 5.7: the time-averaged bridge density n_cb of the
# thesis's point (dark: many bridges) with the force F(x) = F_smax cos(2 pi x / L_x) along y.
# (b) Fig. 5.8: A_d / d per window of 10 t.u. after the field is switched on, E* = 2.14, one
# colour per force.  (c) Fig. 5.9: A~_d = A_d / L_x from t = avg_from on against F_smax L_x / E_cb,
# one colour per E*, with the line through the origin fitted per E*.  (d, e) Fig. 5.10: the
# fraction of the spheres in the fluid, N_p / N, against the force and against E*.  (f) Fig.
# 5.11 (log scale): sigma / gamma against E* (E~* needs both ends, which the scan may not bracket): Eq. 5.9 as printed (energy per length of the
# interface line, in units of d; black), the same with A_d in d for A~_d (over L_x; grey),
# Eq. 5.10 from the fluid's densities per volume (red squares) and per lateral area (red open
# squares), and the thesis's range 0.15-0.40 (band).
# (integers with an exponent, 4e-07, are written 4.0e-07: gnuplot's real() stops at the e)
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $2; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $3; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
estars = system(sprintf("awk -F'\t' 'NR > 1 { print $1 }' %s | sort -u -g | tr '\n' ' '", strips))
forces = system(sprintf("awk -F'\t' 'NR > 1 { print $2 }' %s | sort -u -g | tr '\n' ' '", strips))
ne = words(estars); nf = words(forces)
key(f, i) = val(sprintf("%s_E%s", f, word(estars, i)))
kerr(f, i) = err(sprintf("%s_E%s", f, word(estars, i)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1500,950 font ",11"; set output png } \
  else { set terminal pdfcairo size 15in,9.5in font ",11"; set output pdf }
  set multiplot layout 2, 3 title sprintf("3D elastic strip, {/Symbol G} = 100, %g d × %g d, N = %g (%s profile)", lx, ly, n, prof)
  # (a)
  set title sprintf("(a) n_cb of %s (Fig. 5.7)", maprun) noenhanced
  set xlabel "x / d"; set ylabel "y / d"; set size ratio -1; set xtics 12
  set xrange [0:lx]; set yrange [0:ly]; set palette gray negative; unset colorbox
  plot map using 2:3:5 with image notitle, \
       ly * 0.95 + 0.04 * ly * cos(2 * pi * x / lx) with lines lw 2 lc rgb "red" title "F(x)"
  set size noratio; set autoscale xy; set xtics autofreq; set title "" enhanced
  # (b)
  set title "(b) A_d after the field is on, E^* = 2.14 (Fig. 5.8)"
  set xlabel "t / (d/g)^{1/2}"; set ylabel "A_d / d"; set key top left box
  set xrange [0:*]; set yrange [0:*]
  plot for [j = 1:nf] adt using (column("estar") == 2.14 && column("f_lx_ecb") == real(word(forces, j)) ? column("t") : NaN):(column("ad_tilde") * lx) \
         with linespoints pt 7 ps 0.8 lc j title sprintf("F_{smax} L_x / E_{cb} = %s", word(forces, j))
  # (c)
  set title "(c) A_d linear in F_{smax} (Fig. 5.9)"
  set xlabel "F_{smax} L_x / E_{cb}"; set ylabel "Ã_d = A_d / L_x"; set xrange [0:*]; set offsets 0, 0.3, 0, 0
  plot for [i = 1:ne] strips using (column("estar") == real(word(estars, i)) ? column("f_lx_ecb") : NaN):(column("ad_tilde")):(column("ad_err")) \
         with yerrorbars pt 7 ps 1.3 lc i title sprintf("E^* = %s", word(estars, i)), \
       for [i = 1:ne] x * key("ad_slope", i) * ecb / lx with lines lc i notitle
  # (d)
  set offsets 0, 0, 0, 0
  set title "(d) spheres in the fluid (Fig. 5.10, left)"
  set xlabel "F_{smax} L_x / E_{cb}"; set ylabel "N_p / N"; set yrange [0:1]
  plot for [i = 1:ne] strips using (column("estar") == real(word(estars, i)) ? column("f_lx_ecb") : NaN):(column("n_p") / n) \
         with linespoints pt 7 ps 1.3 lc i title sprintf("E^* = %s", word(estars, i))
  # (e)
  ef = val("estar_f_fgc"); eg = val("estar_fgc_g")
  emin = real(word(estars, 1)); emax = real(word(estars, ne)); pad = 0.25 * (emax - emin) + 0.02
  set title sprintf("(e) N_p / N against E^* (Fig. 5.10, right); f-fgc at %.3g%s", ef, eg == eg ? sprintf(", fgc-g at %.3g", eg) : "")
  set xlabel "E^*"; set xrange [emin - pad:emax + pad]; unset key
  if (ef == ef) { set arrow 1 from ef, graph 0 to ef, graph 1 nohead dt 3 lc rgb "gray50" }
  if (eg == eg) { set arrow 2 from eg, graph 0 to eg, graph 1 nohead dt 3 lc rgb "gray50" }
  plot for [i = 1:ne] '+' using (real(word(estars, i))):(key("n_p", i) / n) every ::0::0 with points pt 7 ps 1.5 lc i notitle
  # (f)
  set title "(f) interfacial energy (Fig. 5.11)"
  set xlabel "E^*"; set ylabel "{/Symbol s} / {/Symbol g}"
  set yrange [0.01:1e4]; set logscale y
  set key top left box font ",8" samplen 1
  set style fill transparent solid 0.15 noborder
  plot '+' using 1:(0.15):(0.40) with filledcurves lc rgb "gray50" title "thesis 0.15-0.40", \
       for [i = 1:ne] '+' using (real(word(estars, i))):(key("sigma_over_gamma", i)):(kerr("sigma_over_gamma", i)) every ::0::0 \
         with yerrorbars pt 7 ps 1.5 lc rgb "black" title (i == 1 ? "Eq. 5.9 with Ã_d (per length, units of d)" : ""), \
       for [i = 1:ne] '+' using (real(word(estars, i))):(key("sigma_ad_in_d_over_gamma", i)):(kerr("sigma_ad_in_d_over_gamma", i)) every ::0::0 \
         with yerrorbars pt 6 ps 1.5 lc rgb "gray40" title (i == 1 ? "Eq. 5.9 with A_d in d" : ""), \
       for [i = 1:ne] '+' using (real(word(estars, i))):(key("eq5_10_sigma_over_gamma", i)) every ::0::0 \
         with points pt 5 ps 1.3 lc rgb "red" title (i == 1 ? "Eq. 5.10, densities per volume" : ""), \
       for [i = 1:ne] '+' using (real(word(estars, i))):(key("eq5_10_lateral_sigma_over_gamma", i)) every ::0::0 \
         with points pt 4 ps 1.3 lc rgb "red" title (i == 1 ? "Eq. 5.10, per lateral area" : "")
  unset multiplot
}
