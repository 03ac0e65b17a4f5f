# Weighted least squares through the transitions of gamma_b.tsv (columns: omega pair x err):
# Gamma_b = a + b omega and Gamma_b = b omega, each point weighted by 1/err^2 (err: half the
# grid step around the transition), errors from the covariance, and chi^2 per degree of
# freedom.  The slope through the origin gives E* = b^2 / (2 E_cb) (Eq. 2.18-2.19).
# Usage: awk -v ecb=E_CB -f lines.awk gamma_b.tsv
BEGIN { FS = OFS = "\t" }
NR > 1 { n++; x[n] = $1; y[n] = $3; w[n] = 1 / ($4 * $4)
         S += w[n]; Sx += w[n] * x[n]; Sy += w[n] * y[n]; Sxx += w[n] * x[n]^2; Sxy += w[n] * x[n] * y[n] }
END {
  D = S * Sxx - Sx^2
  a = (Sxx * Sy - Sx * Sxy) / D; b = (S * Sxy - Sx * Sy) / D
  bp = Sxy / Sxx
  for (i = 1; i <= n; i++) { c2 += w[i] * (y[i] - a - b * x[i])^2; c2p += w[i] * (y[i] - bp * x[i])^2 }
  print "line_a", a, sqrt(Sxx / D)
  print "line_b", b, sqrt(S / D)
  print "line_chi2_dof", (n > 2 ? c2 / (n - 2) : "nan"), "nan"
  print "prop_b", bp, sqrt(1 / Sxx)
  print "prop_chi2_dof", (n > 1 ? c2p / (n - 1) : "nan"), "nan"
  print "estar_f_fgc", bp^2 / (2 * ecb), bp * sqrt(1 / Sxx) / ecb
  print "n_omega", n, "nan"
}
