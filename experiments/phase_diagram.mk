# A phase diagram in the (E*, Gamma) plane (thesis Ch. 3), shared by the figures that differ
# only in parameters.  The including Makefile includes
# ../common.mk first; its <profile>.conf gives estars, gammas and run (scene overrides: the
# physics of the figure and the run lengths).  Each grid point is one run, a make target, so
# `make -j` runs them in parallel and an interrupted sweep resumes.  The phase of each comes
# from wetgran-orderparam with thresholds calibrated on the sweep, the fluid-gas cut per row of
# Gamma (the gas's T_g/E_cb moves by decades with Gamma, so one cut for the sweep can call a
# cool gas fluid); boundaries are midpoints of Delaunay edges between phases; the f-fgc line
# is fitted as vertical.
SCENE ?= $(SCENES)/shake2d.ini
# a row may list its own E* values (estars_<gamma> = ...), refined where its boundaries lie
row_estars = $(or $(call conf,estars_$(1)),$(call conf,estars))
POINTS := $(call made,$(foreach g,$(call conf,gammas),$(foreach e,$(call row_estars,$(g)),$(RUNDIR)/G$(g)_E$(e).h5)))
gamma_of = $(word 1,$(subst _E, ,$(1)))
estar_of = $(word 2,$(subst _E, ,$(1)))
# the A = s_crit line of the plot: Gamma = 2 E* E_cb / (m g s_crit)
SCRIT := $(call conf,s_crit)
ECB := $(call conf,e_cb)

$(RUNDIR)/G%.h5: $(SCENE) $(CONF) $(ENGINE) | $(RUNDIR)
	$(WGRUN) $(SCENE) $(call conf,run) gamma=$(call gamma_of,$*) estar=$(call estar_of,$*) -q -o $@

$(OUT)/orderparam.tsv: $(POINTS) $(BIN)/wetgran-orderparam | $(OUT)
	$(BIN)/wetgran-orderparam --calibrate --per-scan --relative-contrast $(POINTS) > $@.tmp && mv $@.tmp $@

$(OUT)/boundary.tsv: $(OUT)/orderparam.tsv $(BIN)/wetgran-boundary
	$(BIN)/wetgran-boundary --x estar --y gamma --label label --logx $< > $@.tmp && mv $@.tmp $@

# The f-fgc line is where the fluid turns coexisting as E* rises: the fit takes the midpoints
# with f at the smaller E* ("f<fgc"), not those where a coexistence gives way to a fluid again
# at larger E* (Gamma <= 1.5, and at Gamma = 8 in fig3_9).  Over all rows it also takes the
# low-Gamma rows' line (near E* = 0.7, below the bulge); the thesis's vertical line is where
# gravity no longer matters, so it is fitted again over the rows Gamma >= vertical_gamma_min
# (conf; default 8): key vertical_f_fgc_hi_gamma.
# Where the including Makefile sets FGC_G_BULGE, also the bulge of the fgc-g line at A = s_crit
# (Figs. 3.4a/b): keys fgc_g_bulge_estar, _gamma and _a_over_scrit (fgc_g_bulge.awk).
VGMIN := $(or $(call conf,vertical_gamma_min),8)
WAITS := $(call conf,fluid_waits)
$(OUT)/results.tsv: $(OUT)/orderparam.tsv $(BIN)/wetgran-boundary $(if $(WAITS),$(OUT)/lifetimes.tsv ../fluid_line_after.awk) $(if $(FGC_G_BULGE),../fgc_g_bulge.awk)
	{ $(BIN)/wetgran-boundary --x estar --y gamma --label label --logx --fit-vertical "f<fgc" $< && \
	  awk -F'\t' -v g=$(VGMIN) '/^#/ || $$1 == "file" || $$2 >= g' $< | \
	    $(BIN)/wetgran-boundary --x estar --y gamma --label label --logx --fit-vertical "f<fgc" - | \
	    awk -F'\t' -v OFS='\t' 'NR > 1 { sub(/^vertical_f_fgc/, "vertical_f_fgc_hi_gamma", $$1); print }'; \
	  $(if $(WAITS),awk -f ../fluid_line_after.awk -v waits="$(WAITS)" -v prefix=vertical_f_fgc_hi_gamma $(OUT)/lifetimes.tsv;) \
	  $(if $(FGC_G_BULGE),awk -f ../fgc_g_bulge.awk -v ecb=$(ECB) -v scrit=$(SCRIT) $<;) } > $@.tmp && mv $@.tmp $@

# The f-fgc line against the time one watches (conf fluid_waits = T1 T2 ...): near the line the
# fluid is metastable, and coexistence nucleates after a lifetime that grows steeply as E*
# falls.  lifetimes.tsv: per run of the rows Gamma >= vertical_gamma_min, when its T_g jumped
# to the bubble's (fluid_lifetime.awk); results: the line as placed by someone who stopped
# each run at T (fluid_line_after.awk), keys vertical_f_fgc_hi_gamma_t<T>.
$(OUT)/lifetimes.tsv: $(OUT)/orderparam.tsv $(BIN)/wetgran-series ../fluid_lifetime.awk
	awk -F'\t' -v g=$(VGMIN) '$$1 !~ /^#/ && $$1 != "file" && $$2 >= g && ($$NF == "f" || $$NF == "fgc") { print $$1, $$2, $$3, $$NF }' $< | \
	  while read -r run gamma estar label; do \
	    $(BIN)/wetgran-series $$run temperature | awk -v r=$$run -v g=$$gamma -v e=$$estar -v l=$$label 'NR > 1 { print r, g, e, l, $$1, $$2 }'; \
	  done | awk -f ../fluid_lifetime.awk > $@.tmp && mv $@.tmp $@

$(FIGURE): $(OUT)/results.tsv $(OUT)/boundary.tsv ../phase_diagram.gp | $(FIGDIR)
	$(call gnuplot,../phase_diagram.gp,op='$(OUT)/orderparam.tsv'; bd='$(OUT)/boundary.tsv'; res='$(OUT)/results.tsv'; scrit=$(SCRIT); ecb=$(ECB))

