# Shared by every experiments/<id>/Makefile: where the tools are and where outputs go.
# PROFILE=quick (CI scale, minutes) or PROFILE=full (the thesis's scale).
PROFILE ?= quick
TOP := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
BIN := $(TOP)/bin
# runs depend on the simulator's behavioural version (scripts/engine-version, rewritten only
# when a trajectory changes), not on its binary or sources
ENGINE := $(BIN)/wetgran-run.version
# PARTIAL=1 draws a sweep from the runs made so far (a campaign under way): runs stay in
# out/<profile>/runs, everything drawn from them goes to out/<profile>-partial/ and
# figures/<id>-partial.png, apart from the complete profile's
RUNDIR := out/$(PROFILE)/runs
OUT := out/$(PROFILE)$(if $(PARTIAL),-partial)
# $(call made,RUNS): the runs of a sweep, or under PARTIAL only those already made, here or
# filed in this experiment's run archive (so a fresh clone draws a campaign's progress)
comma := ,
made = $(if $(PARTIAL),$(foreach r,$(1),$(if $(or $(wildcard $(r)),$(and $(filter $(RUNDIR)/%,$(r)),$(wildcard $(ARCHIVE)/$(notdir $(r))))),$(r))),$(1))
FIGDIR := $(TOP)/figures
SCENES := $(TOP)/sim/scenes
SHELL := /bin/bash
.SHELLFLAGS := -e -o pipefail -c
.DELETE_ON_ERROR:
# No run may be an intermediate file, which make deletes once what was drawn from it is made
# (runs are borrowed by other figures, filed into the archive and worth hours of CPU): every
# experiment names its runs as prerequisites, which tests/test_experiment_make.sh checks.
# (Not .SECONDARY without prerequisites: that makes every target intermediate, and a missing
# results.tsv is then not made while the figure is newer than the runs.)

# parameters of the profile: one file of key=value words, a prerequisite of every run.
# Read once, into the variables conf.<key> ($(call conf,KEY) is their value, empty when the
# conf has no such key): one shell per lookup made a dry run of a full sweep take seconds.
CONF := $(PROFILE).conf
$(foreach kv,$(shell awk '/^[ \t]*\#/ { next } match($$0, /^[ \t]*[A-Za-z0-9_.]+[ \t]*=/) { \
    k = substr($$0, 1, RLENGTH - 1); gsub(/[ \t]/, "", k); v = substr($$0, RLENGTH + 1); \
    gsub(/^[ \t]+|[ \t]+$$/, "", v); gsub(/[ \t]+/, "^", v); print k ":=" v }' $(CONF)),$(eval conf.$(subst ^, ,$(kv))))
conf = $(conf.$(strip $(1)))

# runs of a sweep are independent: use the machine's cores unless told otherwise (a make
# started by another one, e.g. for borrowed runs, shares its parent's job slots)
ifeq ($(filter -j%,$(MAKEFLAGS) $(shell printenv MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc)
endif

# The figure id is the folder's name; every experiment makes figures/<id>.png and .pdf.
ID := $(notdir $(CURDIR))
FIGNAME := $(ID)$(if $(PARTIAL),-partial)
FIGURE := $(FIGDIR)/$(FIGNAME).png

# The simulator, through the record archive (scripts/record): each run's file in $(RUNDIR) is
# its record, the run cut down to what the figure is drawn from (conf record_snapshots:
# none, last, all or K,K...; record_series: the time series kept, or all; record_heights: the
# fields of the height maps kept, when not all); the whole run goes
# to $(RUNDIR)/whole.  A record already in data/records/<id>/<profile>/ made from the same scene
# and arguments is copied instead of simulated, whatever engine version made it (RERUN=1
# simulates those of another version again).  `make archive` files this profile's records.
ARCHIVE := $(TOP)/data/records/$(ID)/$(PROFILE)
RECORD := --snapshots $(or $(call conf,record_snapshots),none) --series $(or $(call conf,record_series),temperature$(comma)bridges)$(if $(call conf,record_heights), --heights $(call conf,record_heights))
WGRUN := $(TOP)/scripts/record $(ARCHIVE) $(ENGINE) '$(RECORD)' $(BIN)/wetgran-run

# results.tsv ends with the engine versions that made its points (scripts/stamp-engines; the
# file keeps its time, so nothing is redrawn for it)
all: $(FIGURE)
	@$(TOP)/scripts/stamp-engines $(OUT)/results.tsv $(RUNDIR) $(foreach b,$(call conf,borrow),$(TOP)/experiments/$(b)/$(RUNDIR))
	@echo "$(ID) ($(PROFILE)$(if $(PARTIAL),$(comma) runs made so far)): results in $(CURDIR)/$(OUT)/results.tsv, figure in $(FIGURE) and .pdf"

# $(call gnuplot,SCRIPT,VARIABLES): draw the figure as png and pdf, each renamed when complete
gnuplot = gnuplot -e "$(2); png='$(FIGURE).tmp.png'; pdf='$(FIGDIR)/$(FIGNAME).pdf.tmp'" $(1) && \
  mv $(FIGDIR)/$(FIGNAME).pdf.tmp $(FIGDIR)/$(FIGNAME).pdf && mv $(FIGURE).tmp.png $(FIGURE)

$(OUT) $(RUNDIR) $(FIGDIR):
	mkdir -p $@

# figures/<id>.png is shared by the profiles: it is redrawn when it was last drawn from
# another profile (or from the partial runs), whatever the times of the files
DRAWN := out/$(FIGNAME).drawn
$(DRAWN): FORCE
	@mkdir -p $(@D); echo '$(PROFILE)$(if $(PARTIAL), partial)' | cmp -s - $@ || echo '$(PROFILE)$(if $(PARTIAL), partial)' > $@
$(FIGURE): $(DRAWN)
FORCE:
.PHONY: FORCE

archive:
	$(TOP)/scripts/archive-records $(RUNDIR) $(ARCHIVE)

.PHONY: all archive
