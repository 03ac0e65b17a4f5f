# The weighted least-squares scale c of y = c t over a table's rows (columns y, its error ye,
# t; t > 0.005 only, and column x <= xmax when both are given): c = sum(y t / s^2) /
# sum(t^2 / s^2) with error 1 / sqrt(sum(t^2 / s^2)), scaled by sqrt(chi^2/dof) when that
# exceeds 1.  Prints KEY c error.
BEGIN { FS = "\t" }
/^#/ { next }
!header++ { next }
$t > 0.005 && (xmax == "" || $x <= xmax + 0) && $ye > 0 {
  w = 1 / ($ye * $ye); sy += $y * $t * w; st += $t * $t * w; n++; Y[n] = $y; T[n] = $t; W[n] = w
}
END {
  if (!n) { printf "%s\tnan\tnan\n", key; exit }
  c = sy / st; e = 1 / sqrt(st)
  for (k = 1; k <= n; k++) chi += (Y[k] - c * T[k]) ^ 2 * W[k]
  if (n > 1 && chi / (n - 1) > 1) e *= sqrt(chi / (n - 1))
  printf "%s\t%.4g\t%.2g\n", key, c, e
}
