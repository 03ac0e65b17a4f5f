# The oscillation table of the sweep (one run a row, sorted by E*) -> key value error.
# omega_ratio: omega_p over Eq. 6.5's, the mean over the runs with a period (error: their
# standard error); omega_ratio_min/max: its range; h0_min/max: the cushions' range [d];
# omega_h0_slope: the slope of log omega_p against log h0 over those runs (Eq. 6.5: -1/2 for an
# ideal gas, a little steeper with the excluded volume; error from the fit's scatter);
# lp_estar: the least E* of the sweep from which every run has less than lp_share of its grains
# in the gas above the plug (error: half the gap to the E* below; nan when no run qualifies
# or the first one already does); runs: rows with a period.
NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
{
  e[++n] = $c["estar"]; a[n] = $c["above_fraction"]
  r = $c["omega_ratio"]
  if (r == r + 0) {
    k++; s += r; s2 += r * r
    if (k == 1 || r < rmin) rmin = r; if (k == 1 || r > rmax) rmax = r
    h = $c["h0"]; if (k == 1 || h < hmin) hmin = h; if (k == 1 || h > hmax) hmax = h
    lx[k] = log(h); ly[k] = log($c["omega_p"])
  }
}
END {
  print "key\tvalue\terror"
  m = k ? s / k : "nan"
  printf "omega_ratio\t%s\t%s\n", (k ? sprintf("%.4g", m) : "nan"), (k > 1 ? sprintf("%.2g", sqrt((s2 - k * m * m) / (k - 1) / k)) : "nan")
  printf "omega_ratio_min\t%s\tnan\nomega_ratio_max\t%s\tnan\n", (k ? rmin : "nan"), (k ? rmax : "nan")
  printf "h0_min\t%s\tnan\nh0_max\t%s\tnan\n", (k ? hmin : "nan"), (k ? hmax : "nan")
  if (k >= 3) {
    for (i = 1; i <= k; i++) { mx += lx[i] / k; my += ly[i] / k }
    for (i = 1; i <= k; i++) { sxx += (lx[i] - mx) ^ 2; sxy += (lx[i] - mx) * (ly[i] - my) }
    b = sxy / sxx
    for (i = 1; i <= k; i++) ss += (ly[i] - my - b * (lx[i] - mx)) ^ 2
    printf "omega_h0_slope\t%.4g\t%.2g\n", b, sqrt(ss / (k - 2) / sxx)
  } else printf "omega_h0_slope\tnan\tnan\n"
  lp = "nan"; lpe = "nan"
  for (j = n; j >= 1 && a[j] < lp_share; j--);
  if (j < n && j >= 1) { lp = e[j + 1]; lpe = sprintf("%.2g", (e[j + 1] - e[j]) / 2) }
  printf "lp_estar\t%s\t%s\nruns\t%d\tnan\n", lp, lpe, k
}
