# The f-fgc line as an observer who stops after a time t_w would place it: per row of Gamma in a
# lifetime table (fluid_lifetime.awk), the geometric midpoint between the largest E* still
# fluid at t_w (tau > t_w) and the next one, the smallest whose coexistence has nucleated by
# t_w; rows that coexist from their smallest E* or have not nucleated by t_w give none.
# The same on a table of fluid_lifetime.awk -v lower=fgc -v upper=g: the fgc-g line, between
# the largest E* still coexisting at t_w and the next.
# -v waits="T1 T2 ..."  -v prefix=KEY: rows KEY_t<T> (mean over rows, its standard error) and
# KEY_t<T>_n (rows averaged), as in results.tsv.  -v table=1 instead: one line per wait and
# row, "wait row estar estar_err" (the error half the E* step, as wetgran-transitions), rows
# in increasing order.
# A run shows the lower phase at t_w if it had formed by then (column 6 of the table, when
# given) and not yet given way (tau).
/^#/ || $1 == "gamma" { next }
{
  r = ++m[$1]; e[$1, r] = $2; tau[$1, r] = ($4 == "inf") ? -1 : $4 + 0; rows[$1] = 1
  fm[$1, r] = ($6 == "") ? 0 : ($6 == "nan") ? -1 : $6 + 0
}
function gone(g, i, w) { return (tau[g, i] >= 0 && tau[g, i] <= w) || fm[g, i] < 0 || fm[g, i] > w }
END {
  nw = split(waits, w, " ")
  for (g in rows)   # sort each row by E*
    for (i = 2; i <= m[g]; i++)
      for (j = i; j > 1 && e[g, j - 1] + 0 > e[g, j] + 0; j--) {
        x = e[g, j]; e[g, j] = e[g, j - 1]; e[g, j - 1] = x
        x = tau[g, j]; tau[g, j] = tau[g, j - 1]; tau[g, j - 1] = x
        x = fm[g, j]; fm[g, j] = fm[g, j - 1]; fm[g, j - 1] = x
      }
  if (table) {
    nr = 0
    for (g in rows) rl[++nr] = g
    for (i = 2; i <= nr; i++)
      for (j = i; j > 1 && rl[j - 1] + 0 > rl[j] + 0; j--) { x = rl[j]; rl[j] = rl[j - 1]; rl[j - 1] = x }
    print "wait\trow\testar\testar_err"
    for (a = 1; a <= nw; a++)
      for (r = 1; r <= nr; r++) {
        g = rl[r]
        for (i = 1; i <= m[g]; i++)
          if (gone(g, i, w[a] + 0)) {
            if (i > 1) printf "%s\t%s\t%.6g\t%.3g\n", w[a], g, sqrt(e[g, i - 1] * e[g, i]), (e[g, i] - e[g, i - 1]) / 2
            break
          }
      }
    exit
  }
  for (a = 1; a <= nw; a++) {
    s = 0; s2 = 0; c = 0
    for (g in rows)
      for (i = 1; i <= m[g]; i++)
        if (gone(g, i, w[a] + 0)) {
          if (i > 1) { x = sqrt(e[g, i - 1] * e[g, i]); s += x; s2 += x * x; c++ }
          break
        }
    mean = c ? sprintf("%.6g", s / c) : "nan"
    v = (c > 1) ? (s2 - s * s / c) / (c - 1) / c : -1
    if (c > 1 && v < 1e-12 * s * s / (c * c)) v = 0   # rows agreeing, up to round-off
    err = (v >= 0) ? sprintf("%.3g", sqrt(v)) : "nan"
    printf "%s_t%s\t%s\t%s\n%s_t%s_n\t%d\tnan\n", prefix, w[a], mean, err, prefix, w[a], c
  }
}
