# The f-fgc transition E* of each combo F_B:s_crit against the bridge energy E_cb / m g d
# (log scale), labelled with F_B / m g; the thesis's universal value 1.00 +- 0.09 (Fig. 3.5)
# as a band, the gravity-free mean-field onset 0.67 (Sec. 3.2) dashed; each F_B / m g its own
# colour and symbol, in the key.  Points of equal E_cb but different F_B stack; points of equal
# F_B spread.
val(k) = real(system(sprintf("awk -F'\\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
pts = sprintf("< awk -F'\\t' -v OFS='\\t' '$1 ~ /^f_fgc_F/ { k = $1; sub(/^f_fgc_F/, \"\", k); split(k, p, \"_S\"); print p[1] * p[2], $2, $3, p[1] }' %s", res)
r = val("f_fgc_ratio_ecb")
# points of equal E_cb are spread sideways by F_B (7 % per doubling), so that all show
jit(e, f) = e * 1.07**(log(f / 8.0) / log(2.0))
# the bridge forces of this scan, in increasing order
forces = system(sprintf("awk -F'\\t' '$1 ~ /^f_fgc_F/ { k = $1; sub(/^f_fgc_F/, \"\", k); split(k, p, \"_S\"); print p[1] }' %s | sort -gu | tr '\\n' ' '", res))
fcol(i) = word("#d63a2a #2a9d3a #7b3fbf #e08a00 #1f77b4 #8c564b #e377c2", (i - 1) % 7 + 1)
fpt(i) = word("7 9 11 13 5 15 7", (i - 1) % 7 + 1) + 0
# fig3\\_5's scan at s_crit = 0.0711, when made, for the trend in E_cb; its forces for the key
f35 = system(sprintf("test -e %s && echo %s || echo /dev/null", tr35, tr35))
f35forces = system(sprintf("awk -F'\\t' '$1 == \"f_fgc\" { printf \"%%s%%s\", (n++ ? \", \" : \"\"), $2 }' %s", f35))
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1000,700 font ",12"; set output png } \
  else { set terminal pdfcairo size 10in,7in font ",12"; set output pdf }
  set logscale x
  set xrange [0.05:10]; set yrange [0.3:1.4]
  set xlabel "E_{cb} / m g d  (= F_B s_{crit} / m g d)"
  set ylabel "E* of the f - fgc transition  (Γ = 30)"
  set key top right font ",11"
  set title sprintf("E* ratio, largest to smallest E_{cb}: %.2f (thesis: 1)", r)
  plot 1.09 with filledcurves y1=0.91 fs solid 0.25 lc rgb "#2a6fd6" title "thesis Fig. 3.5: 1.00 {/Symbol \261} 0.09", \
       0.67 with lines dt 2 lw 2 lc rgb "#2a6fd6" title "onset in the thesis's gravity-free mean-field model (Sec. 3.2)", \
       f35 using (strcol(1) eq "f_fgc" ? $2 * 0.0711 : NaN):5:($4 / $2) every ::1 with yerrorbars pt 4 ps 1.0 lc rgb "#606060" title sprintf("fig3\\_5's scan, s_{crit} = 0.0711 (F_B / m g = %s)", f35forces), \
       for [i = 1:words(forces)] pts using ($4 == real(word(forces, i)) ? jit($1, $4) : NaN):2:3 with yerrorbars pt fpt(i) ps 1.6 lc rgb fcol(i) \
         title sprintf("this scan, F_B = %s m g", word(forces, i))
}
