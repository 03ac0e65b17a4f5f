# Cluster picture of the free-cooling run: spheres within 10 d of the mid-plane, seen from above.
set terminal pngcairo size 900,900
set output png
set size square
set xrange [0:600]
set yrange [0:600]
set xlabel "x / d"
set ylabel "y / d"
set title "free cooling, 2.5 10^6 wet spheres, L = 600 d: slab |z - L/2| < 10 d"
plot slab using 1:2 with dots lc rgb "black" notitle
