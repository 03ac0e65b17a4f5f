# Time averages of a wetgran-series table with their errors from block means: the rows with
# time >= from are cut into `blocks` consecutive blocks (10), and each chosen column's mean is
# printed with the standard error of its block means (blocks longer than the series'
# correlation time make them independent).  One line: NAME MEAN ERR for each column of
# `cols` (space-separated names from the header), tab-separated.
# Usage: wetgran-series RUN.h5 A B | awk -v from=100 -v cols="A B" -f block_means.awk
BEGIN { FS = OFS = "\t"; if (blocks == "") blocks = 10; nc = split(cols, want, " ") }
NR == 1 { for (i = 1; i <= NF; i++) at[$i] = i
          for (c = 1; c <= nc; c++) if (!(want[c] in at)) { print "block_means: no column " want[c] > "/dev/stderr"; bad = 1; exit 1 }
          next }
$1 + 0 >= from + 0 { n++; for (c = 1; c <= nc; c++) x[c, n] = $(at[want[c]]) }
END {
  if (bad) exit 1
  if (n < blocks) { print "block_means: " n " rows after time " from ", fewer than " blocks " blocks" > "/dev/stderr"; exit 1 }
  per = int(n / blocks); line = ""
  for (c = 1; c <= nc; c++) {
    s = s2 = 0
    for (b = 0; b < blocks; b++) {
      m = 0; for (k = 1; k <= per; k++) m += x[c, b * per + k]; m /= per
      s += m; s2 += m * m
    }
    mean = s / blocks; var = (s2 - blocks * mean * mean) / (blocks - 1)
    line = line (c > 1 ? OFS : "") want[c] OFS sprintf("%.6g", mean) OFS sprintf("%.3g", sqrt(var > 0 ? var : 0) / sqrt(blocks))
  }
  print line
}
