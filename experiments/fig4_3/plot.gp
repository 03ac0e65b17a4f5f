# Figs. 4.3 and 4.4 look.  Left, (a) (4.3): lateral diffusion coefficient D of each layer h = 1
# (floor) ... 6 (surface) against Gamma, log scale, with the cut between solid and fluidized
# layers.  Right, (b) (4.4): fluidization depth l_s against Gamma (circles), the fit
# l_s = l0 ln(1/(1 - (Gamma - Gamma_M)/(Gamma_C - Gamma_M))) (black, capped at M; dotted: l0
# alone, Gamma_M and Gamma_C where the top layer melts and the whole bed is fluid), Eq. 4.11's
# line (M - 1)(Gamma - Gamma_M)/(Gamma_C - Gamma_M) with the fitted Gamma_M, Gamma_C (red) and
# the thesis's fit (l0 = 1.27, Gamma_M = 1.16, Gamma_C = 2.65; grey dashed).
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
cut = val("d_cut"); l0 = val("l0"); gm = val("gamma_m"); gc = val("gamma_c")
dl0 = err("l0"); dgm = err("gamma_m"); dgc = err("gamma_c")
l0x = val("l0_fixed"); dl0x = err("l0_fixed"); gmx = val("gamma_melt_h6"); gcx = val("gamma_complete")
min(a, b) = a < b ? a : b
lsfit(x, l, m, c) = x <= m ? 0 : (x >= c ? M : min(M, l * log(1 / (1 - (x - m) / (c - m)))))
eq411(x, m, c) = x <= m ? 0 : (x >= c ? 1/0 : (M - 1) * (x - m) / (c - m))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1500,650 font ",12"; set output png } \
  else { set terminal pdfcairo size 15in,6.5in font ",12"; set output pdf }
  set multiplot layout 1,2
  set xlabel "{/Symbol G}"
  set ylabel "D  [d^2 / (d/g)^{1/2}]"
  set logscale y
  set format y "10^{%L}"
  # bottom right: the surface layer's curve runs through the top left
  set key bottom right Left reverse samplen 2 opaque
  set offsets 0.05, 0.05, 0, 0
  set title sprintf("(a) Fig. 4.3: lateral diffusion per layer ({/Symbol w} = %g (g/d)^{1/2}, E^* = {/Symbol G}^2 (100/{/Symbol w}^2))", omega)
  plot for [h = 1:M] lay index (h - 1) using 1:2:3 with yerrorlines lw 2 pt 7 ps 1.1 lc h title sprintf("h = %d", h), \
       cut with lines dt 2 lw 2 lc rgb "black" title sprintf("fluidized above %.2g", cut)
  unset logscale y
  set format y "%g"
  set ylabel "l_s  (fluidized layers at the surface)"
  set yrange [-0.3:M + 1.8]
  set samples 1000
  set key top left Left reverse samplen 2
  set title "(b) Fig. 4.4: fluidization depth"
  plot dep using 1:2 every ::1 with points pt 6 ps 2 lw 2 lc rgb "black" title "simulation", \
       lsfit(x, l0, gm, gc) with lines lw 2 lc rgb "black" \
         title sprintf("fit: l_0 = %.2f {/Symbol \261} %.2f, {/Symbol G}_M = %.2f {/Symbol \261} %.2f, {/Symbol G}_C = %.2f {/Symbol \261} %.2f", l0, dl0, gm, dgm, gc, dgc), \
       lsfit(x, l0x, gmx, gcx) with lines lw 2 dt 3 lc rgb "black" \
         title sprintf("l_0 = %.2f {/Symbol \261} %.2f with {/Symbol G}_M = %.3g, {/Symbol G}_C = %.3g read from the layers", l0x, dl0x, gmx, gcx), \
       eq411(x, gm, gc) with lines lw 2 lc rgb "#c02020" title "Eq. 4.11: (M-1)({/Symbol G}-{/Symbol G}_M)/({/Symbol G}_C-{/Symbol G}_M)", \
       lsfit(x, 1.27, 1.16, 2.65) with lines lw 2 dt 2 lc rgb "#808080" title "thesis fit: l_0 = 1.27, {/Symbol G}_M = 1.16, {/Symbol G}_C = 2.65"
  unset multiplot
}
