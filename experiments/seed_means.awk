# Per key, the seeds' mean and its standard error, for a figure's results.tsv.  add(KEY, V)
# once per seed (non-numbers are skipped); print_means("KEY KEY ...") writes the key, value,
# error table: the error is nan for one seed, unless one_err[KEY] gives that seed's own.
# Used with another script: awk -f ../seed_means.awk -f results.awk TABLE ...
function add(k, v) { if (v == v + 0) { s[k] += v; s2[k] += v * v; n[k]++ } }
function print_means(list,    keys, nk, i, k, m, e) {
  printf "key\tvalue\terror\n"
  nk = split(list, keys, " ")
  for (i = 1; i <= nk; i++) {
    k = keys[i]
    if (!n[k]) { printf "%s\tnan\tnan\n", k; continue }
    m = s[k] / n[k]
    e = n[k] > 1 ? sprintf("%.2g", sqrt((s2[k] - n[k] * m * m) / (n[k] - 1) / n[k])) : (k in one_err ? one_err[k] : "nan")
    printf "%s\t%.4g\t%s\n", k, m, e
  }
}
