# (a) Fig. 3.16a look: critical E* of f-fgc (black) and fgc-g (red) against eps, with
# Eq. 3.1; (b) Fig. 3.16b look: n_c(eps) from the measured f-fgc E*, with the thesis's fit
# n_c = 7.3e-3 exp(6.95 eps) + n_ilc and the lower bound n_ilc = n_L - 1 = 2 (red).
nc(e) = 7.3e-3 * exp(6.95 * e) + 2
eq31(e) = 6 * (1.0 / 6) / e**(2 * nc(e))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1400,600 font ",12"; set output png } \
  else { set terminal pdfcairo size 14in,6in font ",12"; set output pdf }
  set multiplot layout 1,2
  set xlabel "{/Symbol e}"
  set ylabel "E^*_{crit}"
  set logscale y; set yrange [0.5:20]
  set xrange [0.76:1.02]
  set key top right
  set samples 200
  set title "(a)"
  plot tr using ($1 == $1 && strcol(2) eq "f_fgc" ? $1 : NaN):3:4 every ::1 with yerrorbars pt 7 ps 1.5 lc rgb "black" title "f - fgc", \
       tr using ($1 == $1 && strcol(2) eq "fgc_g" ? $1 : NaN):3:4 every ::1 with yerrorbars pt 5 ps 1.5 lc rgb "#c02020" title "fgc - g", \
       eq31(x) with lines lw 2 lc rgb "black" title "Eq. 3.1: E^* = n_{Kn} E_0^* / {/Symbol e}^{2 n_c}"
  unset logscale y
  set yrange [0:12]; set xrange [0.76:1.0]
  set ylabel "n_c"
  set key top left
  set title "(b)"
  plot res using (strstrt(strcol(1), "n_c_eps") == 1 ? real(strcol(1)[8:]) : NaN):2:3 with yerrorbars pt 7 ps 1.5 lc rgb "black" title "from the measured f-fgc E^*", \
       nc(x) with lines lw 2 lc rgb "black" title "thesis fit: 7.3x10^{-3} e^{6.95 {/Symbol e}} + 2", \
       2 with lines lw 2 lc rgb "red" title "n_{ilc} = n_L - 1 = 2"
  unset multiplot
}
