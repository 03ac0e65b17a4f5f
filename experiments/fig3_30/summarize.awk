# wetgran-orderparam's table (one row per run) to key, value, error: Delta n_cb and
# Delta n_area (Eq. 3.3) as mean and standard error over the runs, and the fraction of runs
# labelled fluid-gas coexistence.
BEGIN { FS = OFS = "\t" }
/^#/ { next }
$1 == "file" { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
  n++
  cb[n] = $col["dn_cb"]; ar[n] = $col["dn_area"]
  if ($col["label"] == "fgc") nfgc++
}
function report(key, x,   i, s, s2, m, e) {
  s = s2 = 0
  for (i = 1; i <= n; i++) { s += x[i]; s2 += x[i] * x[i] }
  m = s / n
  e = (n > 1) ? sprintf("%.3g", sqrt((s2 / n - m * m) / (n - 1))) : "nan"
  printf "%s\t%.6g\t%s\n", key, m, e
}
END {
  if (n == 0) { print "summarize.awk: no runs in the table" > "/dev/stderr"; exit 1 }
  print "key", "value", "error"
  report("dn_cb", cb)
  report("dn_area", ar)
  printf "fgc_fraction\t%.6g\tnan\n", nfgc / n
}
