# The droplets tables of the seeds (wetgran-interface droplets) -> key value error: per key
# the seeds' mean and its standard error (with ../seed_means.awk).  Keys: t0, t1 (ends of
# nucleation and coalescence), n_f_max, coalescence_ratio (N_f at t1 over N_f at t0),
# spacing_mean (of adjacent droplets at the nucleation maximum, d), nf_c and nf_exponent (N_f
# against T_g / E_cb over [t0, t1]: c of the -1/2 law and the free exponent), tg_rise (mean
# T_g at t1 over that at t0: the gas warms as the droplets merge) and tg_rises (the share of
# seeds where it does).
FNR == 1 { f++ }
/^# .*nucleation to t0 = / {
  match($0, /t0 = [^ ]*/); t0 = substr($0, RSTART + 5, RLENGTH - 5) + 0; add("t0", t0)
  match($0, /maximum [0-9]*/); nmax = substr($0, RSTART + 8, RLENGTH - 8); add("n_f_max", nmax)
  match($0, /t1 = [^ ]*/); t1 = substr($0, RSTART + 5, RLENGTH - 5) + 0; add("t1", t1)
  add("tg_rise", tg[f, t1] / tg[f, t0]); add("tg_rises", tg[f, t1] > tg[f, t0])
  match($0, /t1 = [^ ]* \(N_f [0-9]*/); split(substr($0, RSTART, RLENGTH), w, " "); add("coalescence_ratio", w[5] / nmax)
}
/^# .*coalescence frames .*N_f = / {
  match($0, /N_f = [^ ]*/); add("nf_c", substr($0, RSTART + 6, RLENGTH - 6))
  match($0, /\^-?[0-9.e+-]+ \+-/); add("nf_exponent", substr($0, RSTART + 1, RLENGTH - 4))
}
/^# .*spacing of adjacent droplets/ { match($0, /mean [^ ]*/); add("spacing_mean", substr($0, RSTART + 5, RLENGTH - 5)) }
!/^#/ && $1 != "file" { split($0, c, "\t"); tg[f, c[2] + 0] = c[7] }
END {
  print_means("t0 t1 n_f_max coalescence_ratio spacing_mean nf_c nf_exponent tg_rise tg_rises")
  printf "seeds\t%d\tnan\n", f
}
