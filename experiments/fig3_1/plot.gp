# Six strips like Fig. 3.1, each the 400 d x 9 d box at its true aspect ratio: colour =
# log10(kinetic energy / E_cb); filled: at least one bridge, ring: none (both in the key).  Each
# strip is titled (a), (b), ... with the caption's state, its driving and the label the order
# parameters give.
n = words(states)
lab(s) = system(sprintf("awk -F'\\t' '$1 ~ /\\/%s\\.h5$/ { printf \"%%s  ({/Symbol G} = %%s, E* = %%s; T_g/E_{cb} = %%.3g; order parameters: %%s)\", \"%s\", $2, $3, $11, $NF }' %s", s, s, op))
# canvas: one 170 px strip per state above a 110 px band for the colour bar
strip = 170.0; band = 110.0; H = strip * n + band
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1500, H font ",11"; set output png } \
  else { set terminal pdfcairo size 15in, (H / 100.0)*1in font ",11"; set output pdf }
  set multiplot
  set size ratio -1
  set palette defined (-4 "#202080", -2 "#2090f0", 0 "#30c030", 1 "#f0d020", 2 "#e03020")
  set cbrange [-4:2]
  set xrange [0:400]; set yrange [0:9]
  unset ytics
  set style fill solid 1.0 noborder
  do for [i = 1:n] {
    s = word(states, i)
    set title "(".substr("abcdefghijklmnop", i, i).")  ".lab(s)
    set origin 0, (band + (n - i) * strip) / H
    set size 1, strip / H
    if (i == n) { set colorbox horizontal user origin 0.25, 45 / H size 0.4, 12 / H; \
                  set label 99 "log_{10}(E_{kin} / E_{cb})" at screen 0.24, screen 51 / H right; \
                  set key at screen 0.95, screen 60 / H right vertical Left reverse samplen 1 }\
    else { unset colorbox; unset key }
    f = out.'/'.s.'.frame.tsv'
    # an undefined x (not radius) is what makes gnuplot skip a point
    plot f using ($8 > 0 ? $2 : 1/0):3:($6/2):(log10($7/ecb + 1e-12)) with circles fill solid 1.0 lc palette notitle, \
         f using ($8 == 0 ? $2 : 1/0):3:($6/2):(log10($7/ecb + 1e-12)) with circles fill empty lw 1 lc palette notitle, \
         NaN with points pt 7 ps 1.5 lc rgb "gray30" title "filled: bridged (at least one bridge)", \
         NaN with points pt 6 ps 1.5 lc rgb "gray30" title "ring: unbridged"
  }
  unset multiplot
}
