# Events/s of the event-driven engine against N (gas at phi = 0.3), EDMD beside it.
# gnuplot -e "tsv='scan.tsv'; png='scan.png'" scan.gp
set terminal pngcairo size 800,560
set output png
set datafile separator "\t"
set datafile missing "nan"
set key top right
set logscale x
set format x "10^{%L}"
set xlabel "N (spheres, phi = 0.30)"
set ylabel "collisions per second (10^5)"
set yrange [0:*]
set grid
plot tsv using 1:($2 / 1e5) skip 1 with linespoints pt 7 title "wetgran (ed engine)", \
     tsv using 1:($6 / 1e5) skip 1 with linespoints pt 5 title "EDMD (Smallenburg 2022)"
