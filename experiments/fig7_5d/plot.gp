# Fig. 7.5d look (../shear_sweep.gp): F_scrit L_x / d against the filling height h_f, the
# fitted line, and the thesis's picture at this F_B: the gravity term of its fit, 3.7 mg at
# h_f = 5 d, growing as h_f (3.7 h_f / 5 + 1.4 F_B).
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
a = val("line_a"); ae = err("line_a"); b = val("line_b"); be = err("line_b")
ttl = sprintf("boundary against the filling height, L_x = %g d, F_B = %g mg (%s): F_{scrit} L_x / d = (%.1f {/Symbol \261} %.1f) mg + (%.2f {/Symbol \261} %.2f) mg h_f / d", lx, fb, profile, a, ae, b, be)
xl = "h_f / d"; yl = "F_{smax} L_x / (mg d)"; keypos = "top left"
xrun(v) = v * xs; yrun(v, f) = f * lx; xcol = 6
ref1(x) = 3.7 * x / 5 + 1.4 * fb; ref1_t = "thesis: 3.7 mg h_f / 5 d + 1.4 F_B"
ref2(x) = NaN; ref2_t = ""
load "../shear_sweep.gp"
