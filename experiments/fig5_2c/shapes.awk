# Fig. 5.2c's numbers from a wetgran-interface ag table (with --ends): the ends, the jump,
# the drop-to-strip boundary a_D/S, the order of the shapes (by their mean a_g).
/^# ends from the scan/ {
  split($0, w, " "); ef = w[8]; efe = w[10]; eg = w[13]; ege = w[15]; sub(",", "", efe); next
}
/^#/ { next }
$1 == "file" { for (i = 1; i <= NF; i++) c[$i] = i; next }
{
  n++; et[n] = $c["estar_tilde"]; ag[n] = $c["a_g"]; er[n] = $c["a_g_err"]; sh[n] = $c["shape"]
}
END {
  # sort the runs by E~* (insertion sort: a scan has tens of runs)
  for (i = 2; i <= n; i++)
    for (j = i; j > 1 && et[j] < et[j - 1]; j--) {
      t = et[j]; et[j] = et[j - 1]; et[j - 1] = t; t = ag[j]; ag[j] = ag[j - 1]; ag[j - 1] = t
      t = er[j]; er[j] = er[j - 1]; er[j - 1] = t; t = sh[j]; sh[j] = sh[j - 1]; sh[j - 1] = t
    }
  print "key\tvalue\terror"
  printf "estar_f_fgc\t%s\t%s\nestar_fgc_g\t%s\t%s\n", ef, efe, eg, ege
  first = 0; first_ii = 0; rank["I"] = 1; rank["II"] = 2; rank["III"] = 3
  coex = 0; drop_over = 0
  for (i = 1; i <= n; i++) if (sh[i] == "I") last_i = i
  for (i = 1; i <= n; i++) {
    if (!(sh[i] in rank)) continue
    coex++
    if (!first) first = i
    sum[sh[i]] += ag[i]; num[sh[i]]++
    if (sh[i] == "I" && ag[i] > 1 / 3.14159265358979) drop_over = 1
    if (sh[i] == "II" && !first_ii && last_i && i > last_i) first_ii = i
  }
  # the shapes' order: the mean a_g of the gas drops below the strips' below the fluid drops'
  # (metastable drops may outlive the first strip along E~*, as in the thesis's Fig. 5.2c)
  order = 1; prev = -1; classes = 0
  for (k = 1; k <= 3; k++) {
    s = k == 1 ? "I" : k == 2 ? "II" : "III"
    if (!num[s]) continue
    classes++
    m = sum[s] / num[s]
    printf "ag_mean_%s\t%.4g\tnan\n", s, m
    if (m <= prev) order = 0
    prev = m
  }
  if (classes < 2) order = 0 # one shape alone orders nothing
  printf "coexisting_runs\t%d\tnan\n", coex
  for (i = 1; i <= n; i++) if (sh[i] in rank) lastc = i
  if (first) printf "ag_rises\t%d\tnan\n", (ag[lastc] - ag[first] > er[lastc] + er[first])
  if (first) printf "ag_first_coexisting\t%.4g\t%.3g\nestar_tilde_first_coexisting\t%.4g\tnan\n", ag[first], er[first], et[first]
  if (last_i && first_ii)
    printf "a_ds\t%.4g\t%.3g\n", (ag[last_i] + ag[first_ii]) / 2, (ag[first_ii] - ag[last_i]) / 2
  else
    printf "a_ds\tnan\tnan\n"
  printf "shape_order\t%d\tnan\nmetastable_drop\t%d\tnan\n", order, drop_over
}
