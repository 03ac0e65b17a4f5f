# The domains tables of the seeds (wetgran-interface domains) -> key value error, the seeds'
# means with their standard error (with ../seed_means.awk; nan for one seed).  Keys: n_d_max and t_max (the most
# domains and when, in driving periods), area_final (the crystalline share of the box in the
# last frame), crystallizes (the share of seeds where it exceeds 5 %), beta (the fit's exponent; error: the fit's, for one seed), area_ratio (the
# crystalline area at the fit window's end over its start: 1 when the area is conserved).
FNR == 1 { if (f++) flush(); m = -1 }
function flush() { add("n_d_max", m); add("t_max", tm); add("area_final", a); add("crystallizes", a > 0.05) }
!/^#/ && $1 != "file" { if ($4 > m) { m = $4; tm = $3 }; a = $5 }
/^# .*fit n_d = / {
  match($0, /beta = [^ ]* \+- [^;]*/); split(substr($0, RSTART + 7, RLENGTH - 7), b, / \+- /)
  add("beta", b[1]); one_err["beta"] = b[2]
  match($0, /area fraction [^ ]* -> [^ ]*/); split(substr($0, RSTART + 14, RLENGTH - 14), r, / -> /)
  add("area_ratio", r[1] > 0 ? r[2] / r[1] : "nan")
}
END {
  flush()
  print_means("n_d_max t_max area_final crystallizes beta area_ratio")
  printf "seeds\t%d\tnan\n", f
}
