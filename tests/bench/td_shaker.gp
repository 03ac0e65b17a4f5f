# Time-driven 2D shaker: error against the time step and against the cost (bench run.sh).
set terminal pngcairo size 1300,550 font ",11"
set output png
set multiplot layout 1,2
set logscale xy
set key bottom left
set format y "10^{%T}"
set xlabel "steps per contact k  (dt = t_{contact} / k)"
set ylabel "error"
plot tsv using 1:5 with linespoints pt 7 title "energy-ledger residual", \
     tsv using 1:(abs($8) > 0 ? abs($8) : 1/0) with linespoints pt 5 title "|T_g / T_g(k = 400) - 1|", \
     tsv using 1:(abs($9)) with linespoints pt 9 title "|T_g / T_g(event-driven) - 1|", \
     tsv using 1:($7 / $6) with lines dt 2 lc rgb "gray" title "statistical error of T_g (3 seeds)"
set xlabel "wall-clock seconds per simulated time unit (150 disks)"
plot tsv using 3:5 with linespoints pt 7 title "energy-ledger residual", \
     tsv using 3:(abs($9)) with linespoints pt 9 title "|T_g / T_g(event-driven) - 1|"
unset multiplot
