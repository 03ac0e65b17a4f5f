# Fig. 3.16a look: critical E* of f-fgc (black) and fgc-g (red) against eps, with Eq. 3.1.
nc(e) = 7.3e-3 * exp(6.95 * e) + 2
eq31(e) = 6 * (1.0 / 6) / e**(2 * nc(e))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,700 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7in font ",12"; set output pdf }
  set xlabel "{/Symbol e}"
  set ylabel "E^*_{crit}"
  set logscale y; set yrange [0.5:20]
  set xrange [0.76:1.02]
  set key top right
  set samples 200
  plot tr using ($1 == $1 && strcol(2) eq "f_fgc" ? $1 : NaN):3:4 every ::1 with yerrorbars pt 7 ps 1.5 lc rgb "black" title "f - fgc", \
       tr using ($1 == $1 && strcol(2) eq "fgc_g" ? $1 : NaN):3:4 every ::1 with yerrorbars pt 5 ps 1.5 lc rgb "#c02020" title "fgc - g", \
       eq31(x) with lines lw 2 lc rgb "black" title "Eq. 3.1: E^* = n_{Kn} E_0^* / {/Symbol e}^{2 n_c}"
}
