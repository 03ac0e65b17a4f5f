# Reads wetgran-transitions' table (combo pair x err ...), combo = the position in the list
# combos (-v combos='F_B:s_crit ...'), and writes results.tsv: the f-fgc E* of each combo;
# for the smaller and the larger bridge energy E_cb = F_B s_crit, their value and the mean
# E* of their combos (error: the mean of the members' errors, since they share one grid);
# the ratio of the two means; and the largest relative spread (max - min over mean) among
# combos of equal E_cb and among combos of equal F_B.
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
  for (e in n) { ne++; if (ne == 1 || e + 0 < lo + 0) lo = e; if (ne == 1 || e + 0 > hi + 0) hi = e }
  if (ne != 2) { print "compare.awk: expected two bridge energies, found " ne > "/dev/stderr"; exit 1 }
  m_lo = sum[lo] / n[lo]; e_lo = esum[lo] / n[lo]; m_hi = sum[hi] / n[hi]; e_hi = esum[hi] / n[hi]
  printf "ecb_lo\t%s\tnan\nf_fgc_ecb_lo\t%.4g\t%.3g\nf_fgc_ecb_lo_n\t%d\tnan\n", lo, m_lo, e_lo, n[lo]
  printf "ecb_hi\t%s\tnan\nf_fgc_ecb_hi\t%.4g\t%.3g\nf_fgc_ecb_hi_n\t%d\tnan\n", hi, m_hi, e_hi, n[hi]
  r = m_hi / m_lo
  printf "f_fgc_ratio_ecb\t%.4g\t%.3g\n", r, r * sqrt((e_lo / m_lo)^2 + (e_hi / m_hi)^2)
  se = 0; for (e in n) if ((ehi[e] - elo[e]) / (sum[e] / n[e]) > se) se = (ehi[e] - elo[e]) / (sum[e] / n[e])
  sf = 0; kf = 0
  for (f in nf) if (nf[f] > 1) { kf++; if ((fhi[f] - flo[f]) / (fsum[f] / nf[f]) > sf) sf = (fhi[f] - flo[f]) / (fsum[f] / nf[f]) }
  printf "f_fgc_spread_same_ecb\t%.4g\tnan\n", se
  if (kf) printf "f_fgc_spread_same_fb\t%.4g\tnan\n", sf
}
