# Reads wetgran-transitions' table (combo pair x err ...), combo = the position in the list
# combos (-v combos='F_B:s_crit ...'), and writes results.tsv: the f-fgc E* of each combo;
# for each bridge energy E_cb = F_B s_crit, in increasing order k = 1, 2, ..., its value and
# the mean E* of its combos (error: the mean of the members' errors, since they share one
# grid); the ratio of the largest energy's mean to the smallest's; and the largest relative
# spread (max - min over mean) among combos of equal E_cb and among combos of equal F_B.
BEGIN { split(combos, list, " ") }
$1 == "combo" || $2 != "f_fgc" { next }
{
  split(list[$1], p, ":"); fb = p[1]; s = p[2]
  e = sprintf("%.4g", fb * s)
  printf "f_fgc_F%s_S%s\t%.4g\t%.3g\n", fb, s, $3, $4
  n[e]++; sum[e] += $3; esum[e] += $4
  if (!(e in elo) || $3 < elo[e]) elo[e] = $3
  if (!(e in ehi) || $3 > ehi[e]) ehi[e] = $3
  nf[fb]++; fsum[fb] += $3
  if (!(fb in flo) || $3 < flo[fb]) flo[fb] = $3
  if (!(fb in fhi) || $3 > fhi[fb]) fhi[fb] = $3
}
END {
  ne = 0
  for (e in n) order[++ne] = e
  if (ne < 2) { print "compare.awk: expected at least two bridge energies, found " ne > "/dev/stderr"; exit 1 }
  for (i = 2; i <= ne; i++)
    for (j = i; j > 1 && order[j] + 0 < order[j - 1] + 0; j--) { t = order[j]; order[j] = order[j - 1]; order[j - 1] = t }
  se = 0
  for (k = 1; k <= ne; k++) {
    e = order[k]; m[k] = sum[e] / n[e]; me[k] = esum[e] / n[e]
    printf "ecb_%d\t%s\tnan\nf_fgc_ecb_%d\t%.4g\t%.3g\nf_fgc_ecb_%d_n\t%d\tnan\n", k, e, k, m[k], me[k], k, n[e]
    if ((ehi[e] - elo[e]) / m[k] > se) se = (ehi[e] - elo[e]) / m[k]
  }
  r = m[ne] / m[1]
  printf "f_fgc_ratio_ecb\t%.4g\t%.3g\n", r, r * sqrt((me[1] / m[1])^2 + (me[ne] / m[ne])^2)
  sf = 0; kf = 0
  for (f in nf) if (nf[f] > 1) { kf++; if ((fhi[f] - flo[f]) / (fsum[f] / nf[f]) > sf) sf = (fhi[f] - flo[f]) / (fsum[f] / nf[f]) }
  printf "f_fgc_spread_same_ecb\t%.4g\tnan\n", se
  if (kf) printf "f_fgc_spread_same_fb\t%.4g\tnan\n", sf
}
