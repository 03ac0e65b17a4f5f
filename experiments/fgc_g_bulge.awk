# The bulge of the fgc-g line (thesis Figs. 3.4a/b: "a bulge where A = s_crit", which moves with
# the A = s_crit line when E_cb changes).  Reads an orderparam table (wetgran-orderparam: gamma in
# column 2, E* in 3, the phase label last).  Per row of Gamma sorted by E*, the fgc-g line is
# the geometric midpoint between the largest E* labelled fgc that a g follows and that g (error
# half the step, as wetgran-transitions); rows without such a pair (f straight to g, or
# coexisting to the end of the scan) have none.  The bulge is the interior local maximum of
# that E* along Gamma (rows with a line on either side lower; a plateau of equal rows counts
# as one, at the geometric mean of its Gamma), the largest if several; a maximum at the first
# or last row with a line is not bracketed and gives no bulge.  There the amplitude is
# A = 2 E* E_cb / (m g Gamma) (units m = g = d = 1), reported against s_crit.  Its error
# combines the E* half-step with where between the neighbouring rows the bulge may lie
# (half-way to each, in log Gamma: ln(Gamma_hi / Gamma_lo) / 4).
# -v ecb=E_CB -v scrit=S_CRIT [-v prefix=KEY]: rows KEY_estar, KEY_gamma, KEY_a_over_scrit
# (value, error) as in results.tsv.  -v table=1 instead: the line per row, "gamma estar
# estar_err a_over_scrit".
BEGIN { FS = "\t"; OFS = "\t"; if (prefix == "") prefix = "fgc_g_bulge" }
/^#/ || $1 == "file" { next }
{ r = ++m[$2]; e[$2, r] = $3 + 0; lab[$2, r] = $NF; rows[$2] = 1 }
function a_over_scrit(estar, gamma) { return 2 * estar * ecb / (gamma * scrit) }
END {
  nr = 0
  for (g in rows) {
    for (i = 2; i <= m[g]; i++)   # sort the row by E*
      for (j = i; j > 1 && e[g, j - 1] > e[g, j]; j--) {
        x = e[g, j]; e[g, j] = e[g, j - 1]; e[g, j - 1] = x
        x = lab[g, j]; lab[g, j] = lab[g, j - 1]; lab[g, j - 1] = x
      }
    for (i = m[g] - 1; i >= 1; i--)
      if (lab[g, i] == "fgc" && lab[g, i + 1] == "g") {
        rl[++nr] = g + 0; line[nr] = sqrt(e[g, i] * e[g, i + 1]); err[nr] = (e[g, i + 1] - e[g, i]) / 2
        break
      }
  }
  for (i = 2; i <= nr; i++)   # rows with a line, in increasing Gamma
    for (j = i; j > 1 && rl[j - 1] > rl[j]; j--) {
      x = rl[j]; rl[j] = rl[j - 1]; rl[j - 1] = x
      x = line[j]; line[j] = line[j - 1]; line[j - 1] = x
      x = err[j]; err[j] = err[j - 1]; err[j - 1] = x
    }
  if (table) {
    print "gamma", "estar", "estar_err", "a_over_scrit"
    for (i = 1; i <= nr; i++) printf "%g\t%.6g\t%.3g\t%.4g\n", rl[i], line[i], err[i], a_over_scrit(line[i], rl[i])
    exit
  }
  best = 0
  for (i = 2; i < nr; i = k + 1) {   # plateaus [i, k] of equal E*
    for (k = i; k < nr && line[k + 1] == line[i]; k++) ;
    if (k < nr && line[i - 1] < line[i] && line[k + 1] < line[i] && (!best || line[i] > line[best])) { best = i; bk = k }
  }
  if (!best) { print "fgc_g_bulge.awk: no bracketed maximum of the fgc-g line along Gamma (" nr " rows with one)" > "/dev/stderr"; exit }
  lg = 0; for (i = best; i <= bk; i++) lg += log(rl[i])
  gb = exp(lg / (bk - best + 1)); eb = line[best]
  rel_e = err[best] / eb; rel_g = log(rl[bk + 1] / rl[best - 1]) / 4
  a = a_over_scrit(eb, gb)
  printf "%s_estar\t%.6g\t%.3g\n", prefix, eb, err[best]
  printf "%s_gamma\t%.6g\tnan\n", prefix, gb
  printf "%s_a_over_scrit\t%.6g\t%.3g\n", prefix, a, a * sqrt(rel_e * rel_e + rel_g * rel_g)
}
