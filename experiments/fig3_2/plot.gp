# Fig. 3.2 look: snapshot strip on top (blue: at least one bridge, red: none), below the
# time-averaged T_g / E_cb (red, log scale) and number density (black) against x.
do for [k = 1:2] {
  reset
  if (k == 1) { set terminal pngcairo size 1400,800 font ",12"; set output png } \
  else { set terminal pdfcairo size 14in,8in font ",12"; set output pdf }
  set multiplot
  set lmargin at screen 0.08; set rmargin at screen 0.92
  set tmargin at screen 0.97; set bmargin at screen 0.80
  set xrange [0:400]; set yrange [-0.5:9.5]
  unset key; unset ytics; set xtics format ""
  set style fill solid 1.0 noborder
  plot out.'/snapshot.tsv' using 2:3:($6/2):($8 > 0 ? 0x3060d0 : 0xd03030) with circles lc rgb variable
  set tmargin at screen 0.77; set bmargin at screen 0.10
  set xtics format "%g"; set xlabel "x / d"
  set ylabel "T_g / E_{cb}" textcolor rgb "#c02020"
  set y2label "number density  n d" textcolor rgb "black"
  set logscale y; set autoscale y; set ytics nomirror; set y2tics
  set key top left
  plot prof using 1:5 axes x1y1 with lines lw 2 lc rgb "#c02020" title "T_g / E_{cb} (event-driven)", \
       prof using 1:2 axes x1y2 with lines lw 2 lc rgb "black" title "number density"
  unset multiplot
}
