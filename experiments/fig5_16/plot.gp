# Figs. 5.16-5.19 look, for the first seed.  Top: number density over its maximum (Fig. 5.16)
# and bridge density (Fig. 5.17) along x against t / T_driv; the spacing of adjacent droplets
# at the nucleation maximum (Fig. 5.16's inset).  Bottom: mean T_g / E_cb and the droplets'
# share of the box against time with the regimes' ends t0, t1 (Fig. 5.16, below); N_f against
# time; N_f against T_g / E_cb over the coalescence with c (T_g/E_cb)^(-1/2) (Fig. 5.19).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { v = $2; if (v ~ /^[-+]?[0-9]+e/) sub(/e/, \".0e\", v); print v }' %s", k, res)))
c = val("nf_c"); t0 = val("t0") / tdriv; t1 = val("t1") / tdriv; ex = val("nf_exponent")
nmax = real(system(sprintf("awk -F'\t' 'NF == 4 && $1 != \"t\" && $3 > m { m = $3 } END { print m }' %s", st)))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1500,900 font ",11"; set output png } \
  else { set terminal pdfcairo size 15in,9in font ",11"; set output pdf }
  set multiplot layout 2, 3 title sprintf("droplets in a long shaken wet box: L_x = %g d, 3 disks per d, 9d high, {/Symbol G} = 15, E^* = 1.42 (%s profile)", lx, prof)
  set palette gray negative
  set xlabel "t / T_{driv}"; set ylabel "x / d"
  set arrow 1 from t0, graph 0 to t0, graph 1 nohead dt 2 lc rgb "red" front
  set arrow 2 from t1, graph 0 to t1, graph 1 nohead dt 2 lc rgb "red" front
  set title "number density / maximum (Fig. 5.16)"; set cbrange [0:1]
  plot st using ($1 / tdriv):2:($3 / nmax) with image notitle
  set title "bridge density (Fig. 5.17)"; set cbrange [*:*]
  plot st using ($1 / tdriv):2:4 with image notitle
  unset arrow 1; unset arrow 2
  set title sprintf("spacing of adjacent droplets at t_0 (mean %.0f d)", val("spacing_mean"))
  set xlabel "spacing / d"; set ylabel "probability density"; set style fill solid 0.5
  bw = 20; set boxwidth bw
  stats gaps using 1 nooutput
  plot gaps using (bw * (floor($1 / bw) + 0.5)):(1.0 / (STATS_records * bw)) smooth frequency with boxes lc rgb "gray" notitle
  set style fill empty
  set xlabel "t / T_{driv}"; set ylabel "T_g / E_{cb}"; set y2label "droplets' share of the box"
  set ytics nomirror; set y2tics; set y2range [0:1]
  set arrow 1 from t0, graph 0 to t0, graph 1 nohead dt 2 lc rgb "red"
  set arrow 2 from t1, graph 0 to t1, graph 1 nohead dt 2 lc rgb "red"
  set title "mean granular temperature and droplets' share"; set key top left
  plot drops using 3:7 with lines lw 2 lc rgb "red" title "T_g / E_{cb}", drops using 3:6 axes x1y2 with lines lw 1.5 lc rgb "black" title "share"
  unset y2tics; unset y2label; set ytics mirror
  set title "number of droplets (t_0, t_1: the regimes' ends)"; set ylabel "N_f"; set key top right
  plot drops using 3:4 with steps lc rgb "gray" title "per frame", drops using 3:5 with steps lw 2 lc rgb "black" title "running median"
  unset arrow 1; unset arrow 2
  set title "N_f against T_g over the coalescence (Fig. 5.19)"; set logscale xy
  set xlabel "T_g / E_{cb}"; set ylabel "N_f"; set key top right box
  plot drops using ($3 >= t0 && $3 <= t1 ? $7 : NaN):5 with points pt 7 ps 0.8 lc rgb "black" title "running median, frames in [t_0, t_1]", \
       c / sqrt(x) with lines lw 2 lc rgb "red" title sprintf("N_f = %.3g (T_g/E_{cb})^{-1/2}; free exponent %.2f", c, ex)
  unset multiplot
}
