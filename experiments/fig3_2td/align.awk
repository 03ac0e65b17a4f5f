# A lateral profile (wetgran-profiles) turned periodically so that its densest bin (the plug's
# packing fraction, smoothed over 5 bins) sits at the middle of the box; columns unchanged.
NR == 1 { print; next }
{ n++; line[n] = $0; x[n] = $1; pf[n] = $3 }
END {
  best = -1
  for (i = 1; i <= n; i++) {
    s = 0
    for (d = -2; d <= 2; d++) s += pf[(i + d + n - 1) % n + 1]
    if (s > best) { best = s; at = i }
  }
  shift = int(n / 2) + 1 - at
  for (i = 1; i <= n; i++) { j = (i - shift + n - 1) % n + 1; o[i] = line[j] }
  for (i = 1; i <= n; i++) { split(o[i], f, "\t"); f[1] = x[i]; s = f[1]; for (k = 2; k in f; k++) s = s "\t" f[k]; print s }
}
