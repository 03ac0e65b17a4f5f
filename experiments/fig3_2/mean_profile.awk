# Mean lateral profile over seeds (wetgran-profiles files, one per seed), for the figures.
# Each seed's plug sits at a different x, so every profile is first turned periodically so
# that its density-weighted centre sits mid-box: the centre is the circular mean of x on the
# periodic axis (angle 2 pi x / L weighted by the number density), rounded to a bin.
# Output: x, then for every column of the input its mean over seeds and the standard error
# of that mean (nan with one seed), named <column> and <column>_se.
# Usage: awk -f mean_profile.awk seed1.profiles.tsv seed2.profiles.tsv ...
BEGIN { FS = OFS = "\t"; pi = atan2(0, -1) }
FNR == 1 { nf++; if (nf == 1) { ncol = NF; for (c = 1; c <= NF; c++) head[c] = $c }
           else if (NF != ncol) { print FILENAME ": " NF " columns, expected " ncol > "/dev/stderr"; bad = 1; exit 1 }
           next }
{ nb[nf] = FNR - 1; for (c = 1; c <= NF; c++) v[nf, FNR - 1, c] = $c }
END {
  if (bad) exit 1
  if (nf == 0) { print "mean_profile.awk: no input" > "/dev/stderr"; exit 1 }
  n = nb[1]
  for (f = 2; f <= nf; f++) if (nb[f] != n) { print "mean_profile.awk: seed file " f " has " nb[f] " bins, the first " n > "/dev/stderr"; exit 1 }
  dx = v[1, 2, 1] - v[1, 1, 1]; L = n * dx
  for (f = 1; f <= nf; f++) {
    C = 0; S = 0
    for (i = 1; i <= n; i++) { a = 2 * pi * v[f, i, 1] / L; C += v[f, i, 2] * cos(a); S += v[f, i, 2] * sin(a) }
    xc = L * atan2(S, C) / (2 * pi); if (xc < 0) xc += L
    # bins to move by (positive: towards larger x) so that xc lands at L / 2
    sh[f] = int((L / 2 - xc) / dx + (L / 2 - xc >= 0 ? 0.5 : -0.5))
  }
  printf "%s", head[1]
  for (c = 2; c <= ncol; c++) printf "\t%s\t%s_se", head[c], head[c]
  printf "\n"
  for (i = 1; i <= n; i++) {
    printf "%s", v[1, i, 1]
    for (c = 2; c <= ncol; c++) {
      s = 0; s2 = 0
      for (f = 1; f <= nf; f++) { j = ((i - 1 - sh[f]) % n + n) % n + 1; y = v[f, j, c]; s += y; s2 += y * y }
      m = s / nf
      var = nf > 1 ? (s2 - nf * m * m) / (nf - 1) : 0
      se = (nf > 1) ? sprintf("%.3g", sqrt((var > 0) ? var : 0) / sqrt(nf)) : "nan"
      printf "\t%.6g\t%s", m, se
    }
    printf "\n"
  }
}
