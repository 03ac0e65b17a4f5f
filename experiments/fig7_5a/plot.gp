# Fig. 7.5a look (../shear_sweep.gp): F_scrit L_x / (F_B d) against s_crit, the fitted line and
# its intercept, and Eq. 7.9's two candidate bounds at s_crit -> 0.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
a = val("line_a"); ae = err("line_a"); b = val("line_b")
printed = val("eq7_9_bound_printed"); bound = val("eq7_9_bound")
ttl = sprintf("fluidization boundary against s_{crit}: L_x = %g d, F_B = %g mg (%s profile): intercept %.2f {/Symbol \261} %.2f", lx, fb, profile, a, ae)
xl = "s_{crit} / d"; yl = "F_{smax} L_x / (F_B d)"; keypos = "bottom right"
xrun(v) = v; yrun(v, f) = f * lx / fb; xcol = 1
ref1(x) = printed; ref1_t = "Eq. 7.9 as printed: 1/(4 F_{cmin}) = 0.923"
ref2(x) = bound; ref2_t = "1/F_{cmin} = 3.69"
load "../shear_sweep.gp"
