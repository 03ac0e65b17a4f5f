# Per profile file (one seed): T_g contrast max/min, the plug's peak packing fraction and
# the gas's, the peak bridge density.  Output: key, value (mean over seeds), error (standard
# error of the mean over seeds).
FNR == 1 { nf++; next }
{
  tg = $5; pf = $3; nb = $6
  if (FNR == 2 || tg > tgmax[nf]) tgmax[nf] = tg
  if (FNR == 2 || tg < tgmin[nf]) tgmin[nf] = tg
  if (FNR == 2 || pf > pfmax[nf]) pfmax[nf] = pf
  if (FNR == 2 || pf < pfmin[nf]) pfmin[nf] = pf
  if (FNR == 2 || nb > nbmax[nf]) nbmax[nf] = nb
}
function report(key, arr,   i, s, s2, m, e) {
  s = 0; s2 = 0
  for (i = 1; i <= nf; i++) { s += arr[i]; s2 += arr[i] * arr[i] }
  m = s / nf
  e = nf > 1 ? sqrt((s2 / nf - m * m) * nf / (nf - 1) / nf) : "nan"
  printf "%s\t%.6g\t%.3g\n", key, m, e
}
END {
  for (i = 1; i <= nf; i++) { ratio[i] = tgmax[i] / tgmin[i]; lr[i] = log(ratio[i]) / log(10) }
  print "key\tvalue\terror"
  report("tg_contrast_decades", lr)
  report("tg_ecb_max", tgmax)
  report("tg_ecb_min", tgmin)
  report("packing_fraction_max", pfmax)
  report("packing_fraction_min", pfmin)
  report("bridge_density_max", nbmax)
}
