# Figs. 5.9 and 5.11 look.  Left: A~_d = A_d / L_x of each sheared run against F_smax L_x / E_cb,
# one colour per E*, with the line through the origin fitted per E*.  Right (log scale):
# sigma / gamma against E~*: Eq. 5.9 as printed (energy per length of the interface line, in
# units of d; black), the same with A_d in d for A~_d (over L_x; grey), Eq. 5.10 from the
# fluid's densities per volume (red squares) and per lateral area (red open squares), and the
# thesis's range 0.15-0.40 (band).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
estars = system(sprintf("awk -F'\t' 'NR > 1 { print $1 }' %s | sort -u -g | tr '\n' ' '", strips))
n = words(estars)
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1200,520 font ",12"; set output png } \
  else { set terminal pdfcairo size 12in,5.2in font ",12"; set output pdf }
  set multiplot layout 1, 2 title sprintf("3D elastic strip, {/Symbol G} = 100, L_x = %g d (%s profile)", lx, prof)
  set xlabel "F_{smax} L_x / E_{cb}"; set ylabel "Ã_d = A_d / L_x"
  set key top left box
  set xrange [0:*]; set yrange [0:*]
  set title "A_d linear in F_{smax} (Fig. 5.9)"
  plot for [i = 1:n] strips using (column("estar") == real(word(estars, i)) ? column("f_lx_ecb") : NaN):(column("ad_tilde")):(column("ad_err")) \
         with yerrorbars pt 7 ps 1.3 lc i title sprintf("E^* = %s", word(estars, i)), \
       for [i = 1:n] x * val(sprintf("ad_slope_E%s", word(estars, i))) * ecb / lx with lines lc i notitle
  set xlabel "Ẽ^*"; set ylabel "{/Symbol s} / {/Symbol g}"
  set xrange [-0.1:1.1]; set yrange [0.01:100]; set logscale y
  set key top right box font ",10"
  set title "interfacial energy (Fig. 5.11)"
  set style fill transparent solid 0.15 noborder
  key(f, i) = val(sprintf("%s_E%s", f, word(estars, i)))
  kerr(f, i) = err(sprintf("%s_E%s", f, word(estars, i)))
  plot '+' using 1:(0.15):(0.40) with filledcurves lc rgb "gray50" title "thesis 0.15-0.40", \
       for [i = 1:n] '+' using (key("estar_tilde", i)):(key("sigma_over_gamma", i)):(kerr("sigma_over_gamma", i)) every ::0::0 \
         with yerrorbars pt 7 ps 1.5 lc rgb "black" title (i == 1 ? "Eq. 5.9 with Ã_d (per length, units of d)" : ""), \
       for [i = 1:n] '+' using (key("estar_tilde", i)):(key("sigma_ad_in_d_over_gamma", i)):(kerr("sigma_ad_in_d_over_gamma", i)) every ::0::0 \
         with yerrorbars pt 6 ps 1.5 lc rgb "gray40" title (i == 1 ? "Eq. 5.9 with A_d in d" : ""), \
       for [i = 1:n] '+' using (key("estar_tilde", i)):(key("eq5_10_sigma_over_gamma", i)) every ::0::0 \
         with points pt 5 ps 1.3 lc rgb "red" title (i == 1 ? "Eq. 5.10, densities per volume" : ""), \
       for [i = 1:n] '+' using (key("estar_tilde", i)):(key("eq5_10_lateral_sigma_over_gamma", i)) every ::0::0 \
         with points pt 4 ps 1.3 lc rgb "red" title (i == 1 ? "Eq. 5.10, per lateral area" : "")
  unset multiplot
}
