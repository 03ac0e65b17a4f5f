# Fig. 8.2b look: E_perp and E_par per grain against time, one panel per F_smax / F_scrit.
n = words(ratios)
do for [k = 1:2] {
  reset
  if (k == 1) { eval sprintf("set terminal pngcairo size 1000,%d font ',11'", 80 + 360 * n); set output png } \
  else { eval sprintf("set terminal pdfcairo size 10in,%gin font ',11'", 0.8 + 3.6 * n); set output pdf }
  set multiplot layout n,1 title sprintf("sheared wet grains in the 48 d x 96 d box (%s profile): the shear band and its burst", prof)
  do for [i = 1:n] {
    r = word(ratios, i)
    set title sprintf("F_{smax} / F_{scrit} = %s", r)
    set xlabel "t / sqrt(d/g)"; set ylabel "energy per grain / m g d"; set logscale y
    set key top right box opaque
    plot sprintf("%s/series_R%s.tsv", out, r) every ::1 using 1:2 with lines lw 2 lc rgb "red" title "E_{perp}", \
         "" every ::1 using 1:3 with lines lw 2 lc rgb "blue" title "E_{par}"
  }
  unset multiplot
}
