# The oscillation table (one run a row, sorted by E*) -> key value error.
# eps_rms_low, eps_rms_high: the rms excursion at the least and the largest E*; eps_rms_ratio:
# their ratio (a damped plug below the onset, an oscillating one above: much more than 1);
# e_onset: -b/a of the least-squares line eps_rms^2 = a E* + b over the runs with E* >= fit_from
# (error from the line's covariance), nan with fewer than three such runs; fit_points.
NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
{ n++; e[n] = $c["estar"]; r[n] = $c["eps_rms"] }
END {
  print "key\tvalue\terror"
  printf "eps_rms_low\t%s\tnan\neps_rms_high\t%s\tnan\n", r[1], r[n]
  printf "eps_rms_ratio\t%s\tnan\n", (r[1] > 0 ? sprintf("%.4g", r[n] / r[1]) : "nan")
  for (i = 1; i <= n; i++) if (e[i] >= fit_from && r[i] == r[i] + 0) { m++; x[m] = e[i]; y[m] = r[i] * r[i] }
  if (m >= 3) {
    for (i = 1; i <= m; i++) { sx += x[i]; sy += y[i] }
    mx = sx / m; my = sy / m
    for (i = 1; i <= m; i++) { sxx += (x[i] - mx) ^ 2; sxy += (x[i] - mx) * (y[i] - my) }
    a = sxy / sxx; b = my - a * mx
    for (i = 1; i <= m; i++) ss += (y[i] - a * x[i] - b) ^ 2
    s2 = ss / (m - 2); va = s2 / sxx; vb = s2 * (1 / m + mx * mx / sxx); cab = -mx * s2 / sxx
    x0 = -b / a
    # var(-b/a) = (vb + x0^2 va + 2 x0 cab) / a^2
    v0 = (vb + x0 * x0 * va + 2 * x0 * cab) / (a * a)
    printf "e_onset\t%.4g\t%.2g\n", x0, (v0 > 0 ? sqrt(v0) : 0)
  } else printf "e_onset\tnan\tnan\n"
  printf "fit_points\t%d\tnan\n", m
}
