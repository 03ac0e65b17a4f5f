# Shared by the sweeps of thesis Fig. 7.5 (fig7_5a, fig7_5c): for each value of one scene key
# (SWEEP_KEY, conf `values`), a sweep in F_smax (conf `fsmax`) of sim/scenes/shear3d.ini; a run
# is fluidized when its mean coordination (bridges per grain) over t >= avg_from is below
# coord_cut; per value, F_scrit is the midpoint of the strongest solid and the weakest
# fluidized field (error: half their gap) and y = F_scrit L_x / d, divided by F_B when
# PER_FB = 1; a line y = a + b x fitted through them (wetgran-fit), x = value * X_SCALE.  The
# including Makefile sets SWEEP_KEY, PREFIX (runs are PREFIX<value>_F<fsmax>.h5), PER_FB, may set
# X_SCALE (default 1) and SWEEP_ARGS (the runs' arguments for the value $$V, default
# SWEEP_KEY=$$V) and may add lines to results.tsv through EXTRA_RESULTS (a shell command).
include ../common.mk

SCENE := $(SCENES)/shear3d.ini
VALUES := $(call conf,values)
FS := $(call conf,fsmax)
RUNS := $(foreach v,$(VALUES),$(foreach f,$(FS),$(RUNDIR)/$(PREFIX)$(v)_F$(f).h5))
# a parameter of the runs, read from a run's /parameters
param = $$(h5dump -a /parameters/$(1) $(2) | awk '/\(0\)/ { print $$2 }')

runs: $(RUNS)
.PHONY: runs

# the swept value's scene arguments, from the shell variable V (default: SWEEP_KEY=V)
SWEEP_ARGS ?= $(SWEEP_KEY)=$$V
$(RUNDIR)/$(PREFIX)%.h5: $(SCENE) $(CONF) $(ENGINE) | $(RUNDIR)
	v=$*; V=$${v%%_F*}; $(WGRUN) $(SCENE) $(call conf,run) $(SWEEP_ARGS) shear_force=$${v#*_F} -q -o $@

# one row per run: the swept value, F_smax, mean e_perp [m g d], coordination (2 B / N) over
# t >= avg_from, the state, L_x and F_B of the run
$(OUT)/sweep.tsv: $(RUNS) $(BIN)/wetgran-series | $(OUT)
	{ echo -e "$(SWEEP_KEY)\tfsmax\te_perp\tcoordination\tstate\tlx\tf_b"; for v in $(VALUES); do for f in $(FS); do \
	  r=$(RUNDIR)/$(PREFIX)$${v}_F$$f.h5; \
	  $(BIN)/wetgran-series $$r e_perp bridges | awk -F'\t' -v v=$$v -v f=$$f -v t0=$(call conf,avg_from) \
	    -v n=$(call param,n,$$r) -v lx=$(call param,lx,$$r) -v fb=$(call param,f_b,$$r) -v cut=$(call conf,coord_cut) \
	    'NR > 1 && $$1 >= t0 { k++; e += $$2; b += $$3 } END { z = 2 * b / k / n; \
	      printf "%s\t%s\t%.4g\t%.4g\t%s\t%s\t%s\n", v, f, e / k, z, (z < cut ? "fluidized" : "solid"), lx, fb }'; \
	done; done; } > $@.tmp && mv $@.tmp $@

X_SCALE ?= 1
# per value: F_scrit, its error, y and its error, x
$(OUT)/boundary.tsv: $(OUT)/sweep.tsv
	awk -F'\t' -v per_fb=$(PER_FB) -v xs=$(X_SCALE) 'NR == 1 { print $$1 "\tfscrit\tfscrit_err\ty\ty_err\tx"; next } \
	  { v = $$1; if (!(v in seen)) { order[++m] = v; seen[v] = 1 }; scale[v] = $$6 / (per_fb ? $$7 : 1) } \
	  $$5 == "solid" && (!(v in s) || $$2 > s[v]) { s[v] = $$2 } \
	  $$5 == "fluidized" && (!(v in f) || $$2 < f[v]) { f[v] = $$2 } \
	  END { for (k = 1; k <= m; k++) { v = order[k]; \
	    if ((v in s) && (v in f) && s[v] < f[v]) printf "%s\t%.4g\t%.4g\t%.4g\t%.4g\t%.4g\n", v, (s[v] + f[v]) / 2, (f[v] - s[v]) / 2, \
	      (s[v] + f[v]) / 2 * scale[v], (f[v] - s[v]) / 2 * scale[v], v * xs; \
	    else printf "%s\tnan\tnan\tnan\tnan\t%.4g\n", v, v * xs } }' $< > $@.tmp && mv $@.tmp $@

# The line's errors: the fit's (scaled by its scatter) and the brackets' (each F_scrit uniform
# within its bracket, standard deviation half-gap / sqrt 3, carried through the least-squares
# weights) added in quadrature: on a coarse grid the midpoints can fall exactly on a line.
$(OUT)/results.tsv: $(OUT)/boundary.tsv $(BIN)/wetgran-fit $(BIN)/wetgran-theory
	{ echo -e "key\tvalue\terror"; \
	  awk -F'\t' 'NR > 1 && $$4 == $$4 + 0 { print $$6 "\t" $$4 }' $< | \
	    { echo -e "x\ty"; cat; } | $(BIN)/wetgran-fit --model line --x x --y y --prefix line - | awk -F'\t' '$$1 != "key"' | \
	    awk -F'\t' -v OFS='\t' 'NR == FNR { if (FNR > 1 && $$4 == $$4 + 0) { n++; x[n] = $$6; e[n] = $$5 / sqrt(3); sx += $$6; sxx += $$6 * $$6 }; next } \
	      FNR == 1 { d = n * sxx - sx * sx; for (i = 1; i <= n; i++) { va += (e[i] * (sxx - x[i] * sx) / d) ^ 2; vb += (e[i] * (n * x[i] - sx) / d) ^ 2 } } \
	      $$1 == "line_a" { $$3 = sqrt($$3 * $$3 + va) } $$1 == "line_b" { $$3 = sqrt($$3 * $$3 + vb) } { print }' $< -; \
	  awk -F'\t' 'NR > 1 { n++; ok += $$4 == $$4 + 0 } END { printf "bracketed\t%d\tnan\n", (n > 0 && ok == n) }' $<; \
	  $(EXTRA_RESULTS) \
	} > $@.tmp && mv $@.tmp $@
