# Time-driven 2D shaker: error against the time step and against the cost, for velocity
# Verlet (filled) and Gear's predictor-corrector (open) (bench run.sh).
set terminal pngcairo size 1300,550 font ",11"
set output png
set multiplot layout 1,2
set logscale xy
set key bottom left
set format y "10^{%T}"
V(c) = strcol(10) eq "verlet" ? column(c) : 1/0
G(c) = strcol(10) eq "gear" ? column(c) : 1/0
set xlabel "steps per contact k  (dt = t_{contact} / k)"
set ylabel "error"
plot tsv using 1:(V(5)) with linespoints pt 7 lc 1 title "energy-ledger residual, Verlet", \
     tsv using 1:(G(5)) with linespoints pt 6 lc 1 dt 2 title "energy-ledger residual, Gear", \
     tsv using 1:(abs(V(9))) with linespoints pt 9 lc 2 title "|T_g / T_g(event-driven) - 1|, Verlet", \
     tsv using 1:(abs(G(9))) with linespoints pt 8 lc 2 dt 2 title "|T_g / T_g(event-driven) - 1|, Gear", \
     tsv using 1:(V(7) / V(6)) with lines dt 3 lc rgb "gray" title "statistical error of T_g (3 seeds)"
set xlabel "wall-clock seconds per simulated time unit (150 disks)"
plot tsv using 3:(V(5)) with linespoints pt 7 lc 1 title "energy-ledger residual, Verlet", \
     tsv using 3:(G(5)) with linespoints pt 6 lc 1 dt 2 title "energy-ledger residual, Gear", \
     tsv using 3:(abs(V(9))) with linespoints pt 9 lc 2 title "|T_g / T_g(event-driven) - 1|, Verlet", \
     tsv using 3:(abs(G(9))) with linespoints pt 8 lc 2 dt 2 title "|T_g / T_g(event-driven) - 1|, Gear"
unset multiplot
