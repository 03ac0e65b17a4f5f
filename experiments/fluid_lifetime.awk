# How long the homogeneous fluid of an (E*, Gamma) sweep lasts before fluid-gas coexistence
# nucleates.  Input (whitespace-separated): file gamma estar label time T_g, one line per
# sample of each run's temperature series (wetgran-series RUN.h5 temperature), for the runs
# labelled f or fgc.  The gas bubble of a coexistence is hot: at the f-fgc line of Fig. 3.4a
# the mean T_g jumps by about a decade (3 to 20-35 E_cb).  Per row of Gamma the level is the
# geometric mean of the hottest f run's and the coldest fgc run's T_g over the second half of
# each run (-v late: another final fraction).  Runs start as a gas (T_g/E_cb = 20): a run's lifetime tau is the first time T_g
# climbs back above the level after the fluid has formed (fallen below it); "inf": never,
# 0: no fluid ever formed (the gas condensed straight into coexistence).  Both crossings must
# clear the level by half its log distance to either phase (a band of hysteresis), so that
# the instantaneous T_g of a fluid that cools through the level does not count as a jump.
# Output: gamma, estar, label, tau, the row's level and when the fluid formed, per run.
#
# -v lower=fgc -v upper=g -v falling=1, fed the bridge count (wetgran-series RUN.h5 bridges)
# of the fgc and g runs: the same for the coexistence and the gas beyond it (the fgc-g line),
# tau being when the coexistence evaporates.  falling: the upper phase has the smaller value
# (Gamma = 30, fig3_5 full: about 70 bridges in a gas, 200-1500 in a coexistence).  T_g does not
# serve here: a gas heats for thousands of time units (F_B = 2 mg, E* = 1.8: 270 m g d at
# t = 800, 3500 at 3300) with the bridge count of a gas from the start.  -v late=0.1: the
# phases' values from each run's last tenth instead of its second half: a run labelled g may
# have coexisted for most of that half (F_B = 16 mg, E* = 1: until t = 16 000 of 20 000, 807
# bridges over the second half, 73 over the last tenth).
BEGIN {
  if (lower == "") lower = "f"; if (upper == "") upper = "fgc"; if (late == "") late = 0.5
  s = falling ? -1 : 1
}
{
  key = $1
  if (!(key in seen)) { seen[key] = 1; order[++nrun] = key; gam[key] = $2; est[key] = $3; lab[key] = $4 }
  n[key]++; t[key, n[key]] = $5; T[key, n[key]] = $6
}
# x lies beyond y towards the upper phase
function beyond(x, y) { return s * (x - y) > 0 }
END {
  for (i = 1; i <= nrun; i++) {
    k = order[i]; sum = 0; c = 0
    for (j = int(n[k] * (1 - late)) + 1; j <= n[k]; j++) { sum += T[k, j]; c++ }
    if (c == 0) continue
    v = sum / c; g = gam[k]
    if (lab[k] == lower && (!(g in edge_lo) || beyond(v, edge_lo[g]))) edge_lo[g] = v
    if (lab[k] == upper && (!(g in edge_up) || beyond(edge_up[g], v))) edge_up[g] = v
  }
  print "gamma\testar\tlabel\ttau\tlevel\tformed"
  for (i = 1; i <= nrun; i++) {
    k = order[i]; g = gam[k]
    if (!(g in edge_lo) || !(g in edge_up)) continue   # a row without both phases has no line
    level = sqrt(edge_lo[g] * edge_up[g]); lo = sqrt(edge_lo[g] * level); hi = sqrt(level * edge_up[g])
    tau = "inf"; formed = "nan"
    for (j = 1; j <= n[k]; j++) {
      if (beyond(lo, T[k, j])) { if (formed == "nan") formed = t[k, j] }
      else if (formed != "nan" && !beyond(hi, T[k, j])) { tau = t[k, j]; break }
    }
    if (formed == "nan") tau = 0
    printf "%s\t%s\t%s\t%s\t%.4g\t%s\n", g, est[k], lab[k], tau, level, formed
  }
}
