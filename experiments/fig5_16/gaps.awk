# The gaps between adjacent droplets (periodic, -v lx=L_x) of the frames that the droplets
# table's spacing line names, one per line: the histogram of Fig. 5.16's inset.
# usage: awk -v lx=L -f gaps.awk TABLE TABLE (the table twice: the window, then the frames)
FNR == NR { if ($0 ~ /spacing of adjacent droplets over t in \[/) { s = $0; sub(/.*in \[/, "", s); split(s, w, /[],]/); a = w[1] + 0; b = w[2] + 0 }; next }
/^#/ || $1 == "file" { next }
{
  split($0, c, "\t")
  if (c[2] + 0 < a || c[2] + 0 > b || c[4] < 2) next
  n = split(c[9], p, ",")
  for (i = 1; i <= n; i++) print (i < n ? p[i + 1] - p[i] : p[1] + lx - p[i])
}
