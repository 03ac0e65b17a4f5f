# Fig. 7.5b look (../shear_sweep.gp): F_scrit L_x / d against L_x, the fitted line, and the
# thesis's constant 3.7 mg + 1.4 F_B.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
a = val("line_a"); ae = err("line_a"); b = val("line_b"); be = err("line_b")
ttl = sprintf("boundary against the width, F_B = %g mg (%s): F_{scrit} L_x / d = (%.1f {/Symbol \261} %.1f) mg + (%.2f {/Symbol \261} %.2f) mg L_x / d", fb, profile, a, ae, b, be)
xl = "L_x / d"; yl = "F_{smax} L_x / (mg d)"; keypos = "top left"
xrun(v) = v; yrun(v, f) = f * v; xcol = 6
ref1(x) = 3.7 + 1.4 * fb; ref1_t = "thesis: 3.7 mg + 1.4 F_B, independent of L_x"
ref2(x) = NaN; ref2_t = ""
load "../shear_sweep.gp"
