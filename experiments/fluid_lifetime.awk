# How long the homogeneous fluid of an (E*, Gamma) sweep lasts before fluid-gas coexistence
# nucleates.  Input (whitespace-separated): file gamma estar label time T_g, one line per
# sample of each run's temperature series (wetgran-series RUN.h5 temperature), for the runs
# labelled f or fgc.  The gas bubble of a coexistence is hot: at the f-fgc line of Fig. 3.4a
# the mean T_g jumps by about a decade (3 to 20-35 E_cb).  Per row of Gamma the level is the
# geometric mean of the hottest f run's and the coldest fgc run's T_g over the second half of
# each run.  Runs start as a gas (T_g/E_cb = 20): a run's lifetime tau is the first time T_g
# climbs back above the level after the fluid has formed (fallen below it); "inf": never,
# 0: no fluid ever formed (the gas condensed straight into coexistence).  Both crossings must
# clear the level by half its log distance to either phase (a band of hysteresis), so that
# the instantaneous T_g of a fluid that cools through the level does not count as a jump.
# Output: gamma, estar, label, tau and the row's level per run.
{
  key = $1
  if (!(key in seen)) { seen[key] = 1; order[++nrun] = key; gam[key] = $2; est[key] = $3; lab[key] = $4 }
  n[key]++; t[key, n[key]] = $5; T[key, n[key]] = $6
}
END {
  for (i = 1; i <= nrun; i++) {
    k = order[i]; s = 0; c = 0
    for (j = int(n[k] / 2) + 1; j <= n[k]; j++) { s += T[k, j]; c++ }
    if (c == 0) continue
    late = s / c; g = gam[k]
    if (lab[k] == "f" && (!(g in hot_f) || late > hot_f[g])) hot_f[g] = late
    if (lab[k] == "fgc" && (!(g in cold_c) || late < cold_c[g])) cold_c[g] = late
  }
  print "gamma\testar\tlabel\ttau\tlevel"
  for (i = 1; i <= nrun; i++) {
    k = order[i]; g = gam[k]
    if (!(g in hot_f) || !(g in cold_c)) continue   # a row without both phases has no line
    level = sqrt(hot_f[g] * cold_c[g]); lo = sqrt(hot_f[g] * level); hi = sqrt(level * cold_c[g])
    tau = "inf"; formed = 0
    for (j = 1; j <= n[k]; j++) {
      if (T[k, j] < lo) formed = 1
      else if (formed && T[k, j] >= hi) { tau = t[k, j]; break }
    }
    if (!formed) tau = 0
    printf "%s\t%s\t%s\t%s\t%.4g\n", g, est[k], lab[k], tau, level
  }
}
