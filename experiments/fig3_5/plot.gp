# Fig. 3.5 look: transition energies E~kin = m v_w^2 / (2 F_g s_crit) against the bridge
# energy E~cb = E_cb / (F_g s_crit); f-fgc (blue) and fgc-g (orange) with the fitted lines
# through the origin, whose slopes are the critical E* (dotted: the thesis's); open squares (when the Makefile
# passes after = lines_after.tsv): the lines had every run stopped at t_w = wait.
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
b1 = val("slope_f_fgc_b"); e1 = err("slope_f_fgc_b")
b2 = val("slope_fgc_g_b"); e2 = err("slope_fgc_g_b")
if (!exists("after")) after = ""
if (after ne "") { b3 = val(sprintf("slope_f_fgc_t%s_b", wait)); e3 = err(sprintf("slope_f_fgc_t%s_b", wait)); \
                   b4 = val(sprintf("slope_fgc_g_t%s_b", wait)); e4 = err(sprintf("slope_fgc_g_t%s_b", wait)); \
                   n4 = int(val(sprintf("slope_fgc_g_t%s_n", wait))); n2 = int(val("slope_fgc_g_n")) }
# a row whose coexistence lasts past t_w up to its largest E* has no line then
rows(n, all) = (n < all) ? sprintf(" (%d of %d rows; the others coexist up to their largest E*)", n, all) : ""
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,700 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7in font ",12"; set output pdf }
  set xlabel "Ẽ_{cb} = E_{cb} / F_g s_{crit}"
  set ylabel "Ẽ_{kin} = m v_w^2 / 2 F_g s_{crit}"
  set key top left
  set xrange [0:*]; set yrange [0:*]; set offsets 0, 1, 1, 0
  plot x with lines lw 1.5 dt 3 lc rgb "#909090" notitle, 1.52 * x with lines lw 1.5 dt 3 lc rgb "#909090" title "thesis slopes 1.00, 1.52", \
       tr using (strcol(1) eq "f_fgc" ? $2 : NaN):3:4 every ::1 with yerrorbars pt 5 ps 1.5 lc rgb "#2a6fd6" title "f - fgc", \
       b1 * x with lines lw 2 lc rgb "#2a6fd6" title sprintf("slope E* = %.2f {/Symbol \261} %.2f (thesis 1.00 {/Symbol \261} 0.09)", b1, e1), \
       tr using (strcol(1) eq "fgc_g" ? $2 : NaN):3:4 every ::1 with yerrorbars pt 7 ps 1.5 lc rgb "#f0a030" title "fgc - g", \
       b2 * x with lines lw 2 lc rgb "#f0a030" title sprintf("slope E* = %.2f {/Symbol \261} %.2f (thesis 1.52 {/Symbol \261} 0.02)", b2, e2), \
       for [f in after] f using (strcol(1) eq sprintf("f_fgc_t%s", wait) ? $2 : NaN):3:4 every ::1 with yerrorbars pt 4 ps 1.5 lc rgb "#2a6fd6" \
         title sprintf("f - fgc, runs stopped at t = %s", wait), \
       for [f in after] b3 * x with lines lw 2 dt 2 lc rgb "#2a6fd6" title sprintf("slope E* = %.2f {/Symbol \261} %.2f", b3, e3), \
       for [f in after] f using (strcol(1) eq sprintf("fgc_g_t%s", wait) ? $2 : NaN):3:4 every ::1 with yerrorbars pt 6 ps 1.5 lc rgb "#f0a030" \
         title sprintf("fgc - g, runs stopped at t = %s", wait), \
       for [f in after] b4 * x with lines lw 2 dt 2 lc rgb "#f0a030" title sprintf("slope E* = %.2f {/Symbol \261} %.2f%s", b4, e4, rows(n4, n2))
}
