# Figs. 5.9-5.11's numbers: first file preps.tsv (wetgran-interface ag --ends auto on the
# preps: its '# ends' line, nan where the scan does not bracket an end), second strips.tsv
# (one row per sheared run).  Per sheared E*: the line A~_d = s F_smax through the origin
# over the forces F_smax L_x / E_cb <= fitmax (least squares weighted by the fits' errors, the
# slope's error scaled by sqrt(chi^2/dof)), N_p's mean, sigma = N_p / ((2 pi)^2 s) (Eq. 5.9,
# m g), sigma / gamma with gamma = F_B / (pi d) = E_cb / (s_crit pi) (Eq. 2.8), Eq. 5.10's mean.
FNR == NR && /^# ends from the scan/ {
  split($0, w, " "); ef = w[8]; efe = w[10]; eg = w[13]; ege = w[15]; sub(",", "", efe); next
}
FNR == NR { next }
FNR == 1 { next }
{
  e = $1; if (!(e in seen)) { seen[e] = 1; order[++ne] = e }
  NP[e] += $6; Q[e] += $7; QL[e] += $8; nall[e]++
  if (fitmax != "" && $2 > fitmax + 0) { big[e] = $4; bigf[e] = $3; next } # beyond the small-slope range
  k = ++cnt[e]; F[e, k] = $3; A[e, k] = $4; S[e, k] = ($5 > 1e-4 ? $5 : 1e-4)
}
END {
  pi = 3.14159265358979; gam = ecb / (scrit * pi)
  print "key\tvalue\terror"
  printf "estar_f_fgc\t%s\t%s\nestar_fgc_g\t%s\t%s\n", ef, efe, eg, ege
  falls = 1; npfalls = 1; prev = ""
  for (i = 1; i <= ne; i++) {
    e = order[i]; sxx = 0; sxy = 0
    for (k = 1; k <= cnt[e]; k++) { wt = 1 / (S[e, k] * S[e, k]); sxx += wt * F[e, k] * F[e, k]; sxy += wt * F[e, k] * A[e, k] }
    s = sxy / sxx; chi = 0
    for (k = 1; k <= cnt[e]; k++) { r = (A[e, k] - s * F[e, k]) / S[e, k]; chi += r * r }
    ds = sqrt(1 / sxx) * (cnt[e] > 1 && chi > cnt[e] - 1 ? sqrt(chi / (cnt[e] - 1)) : 1)
    np = NP[e] / nall[e]; sig = np / (4 * pi * pi * s); dsig = sig * ds / s
    et = (ef != "nan" && eg != "nan") ? (e - ef) / (eg - ef) : "nan"
    printf "estar_tilde_E%s\t%.4g\tnan\n", e, et
    printf "ad_slope_E%s\t%.5g\t%.3g\n", e, s, ds
    printf "ad_chi2_dof_E%s\t%.3g\tnan\n", e, (cnt[e] > 1 ? chi / (cnt[e] - 1) : 0)
    printf "n_p_E%s\t%.6g\tnan\n", e, np
    printf "sigma_E%s\t%.5g\t%.3g\n", e, sig, dsig
    printf "sigma_over_gamma_E%s\t%.5g\t%.3g\n", e, sig / gam, dsig / gam
    printf "eq5_10_sigma_over_gamma_E%s\t%.4g\tnan\n", e, Q[e] / nall[e]
    printf "eq5_10_lateral_sigma_over_gamma_E%s\t%.4g\tnan\n", e, QL[e] / nall[e]
    # the strongest force beyond the fit, over the line's value there: > 1 where the small-slope
    # approximation of Eq. 5.7 fails (a steep interface costs less than its square)
    if (e in big) printf "ad_beyond_fit_over_line_E%s\t%.4g\tnan\n", e, big[e] / (s * bigf[e])
    # with A_d in d instead of A~_d = A_d / L_x in Eq. 5.9 (sigma / L_x): the reading under
    # which the thesis's 0.15-0.40 fall (docs/chapter5.md)
    printf "sigma_ad_in_d_over_gamma_E%s\t%.5g\t%.3g\n", e, sig / (gam * lx), dsig / (gam * lx)
    if (prev != "" && !(sig < prevsig)) falls = 0
    if (prev != "" && !(np < prevnp)) npfalls = 0
    prev = e; prevsig = sig; prevnp = np
  }
  printf "sigma_falls\t%d\tnan\n", (ne > 1 ? falls : 0)
  printf "n_p_falls\t%d\tnan\n", (ne > 1 ? npfalls : 0)
}
