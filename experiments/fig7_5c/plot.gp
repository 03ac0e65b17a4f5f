# Fig. 7.5c look (../shear_sweep.gp): F_scrit L_x / d against F_B, the fitted line, and the
# thesis's fit 3.7 mg + 1.4 F_B.
val(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $2 }' %s", k, res)))
err(k) = real(system(sprintf("awk -F'\t' '$1 == \"%s\" { print $3 }' %s", k, res)))
a = val("line_a"); ae = err("line_a"); b = val("line_b"); be = err("line_b")
ttl = sprintf("fluidization boundary against F_B: L_x = %g d (%s profile): F_{scrit} L_x / d = (%.1f {/Symbol \261} %.1f) mg + (%.2f {/Symbol \261} %.2f) F_B", lx, profile, a, ae, b, be)
xl = "F_B / mg"; yl = "F_{smax} L_x / (mg d)"; keypos = "top left"
xrun(v) = v; yrun(v, f) = f * lx; xcol = 1
ref1(x) = 3.7 + 1.4 * x; ref1_t = "thesis: 3.7 mg + 1.4 F_B"
ref2(x) = NaN; ref2_t = ""
load "../shear_sweep.gp"
