# wetgran — build, test, benchmark and regenerate the figures.
#   make            build every tool into bin/
#   make demo       the main job: a small real figure (thesis Fig. 3.2, event-driven)
#   make test       build and run the tests (SANITIZE=1: under ASan + UBSan)
#   make bench      benchmarks (numbers go to tests/bench/out/; EDMD_SRC=<EDMD Single/> adds EDMD)
#   make stress     the stress matrix: extreme drives, eps, densities, time steps (about a minute)
#   make bench-large  free cooling of 2.5e6 wet spheres (minutes, ~0.7 GB; not in CI)
#   make docs-figures  the pictures of docs/ (docs/figures/<id>.png)
# make, demo, test, bench and the figures first install the Debian packages they need
# (scripts/install-deps.sh; nothing is done when all are there).

SHELL := /bin/bash
CC ?= gcc
OPT ?= -O2 -g
HDF5_CFLAGS := $(shell pkg-config --cflags hdf5-serial 2>/dev/null)
HDF5_LIBS := $(shell pkg-config --libs hdf5-serial 2>/dev/null)
GIT_VERSION := $(shell git describe --always --dirty 2>/dev/null || echo unknown)
WARN := -Wall -Wextra
NPROC := $(shell nproc 2>/dev/null || echo 2)
# -ffp-contract=off: no FMA contraction, so results are bit-identical across builds
BASE_CFLAGS := -std=c11 -D_GNU_SOURCE $(OPT) $(WARN) -ffp-contract=off

ifeq ($(SANITIZE),1)
  BUILD := build/san
  BASE_CFLAGS += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
  LDSAN := -fsanitize=address,undefined
  BIN := build/san/bin
else
  BUILD := build/rel
  BIN := bin
endif

# sim/: common/ (below both engines), ed/ and td/ (each engine's modules), run/ (run files,
# observers, the run tool); headers are found by name
SIM_DIRS := common ed td run
ALL_CFLAGS := $(BASE_CFLAGS) $(patsubst %,-Isim/%,$(SIM_DIRS)) $(HDF5_CFLAGS) -DWG_CFLAGS='"$(BASE_CFLAGS)"'
LIBS := $(HDF5_LIBS) -lgsl -lgslcblas -lm $(LDSAN)

LIB_SRC := $(filter-out sim/run/run_main.c,$(wildcard $(patsubst %,sim/%/*.c,$(SIM_DIRS))))
LIB_OBJ := $(patsubst sim/%.c,$(BUILD)/sim/%.o,$(LIB_SRC))
SIM_HDR := $(wildcard $(patsubst %,sim/%/*.h,$(SIM_DIRS)))
LIB := $(BUILD)/libwetgran.a
ANALYSIS_SRC := $(wildcard analysis/*.c)
TOOLS := $(BIN)/wetgran-run $(patsubst analysis/%.c,$(BIN)/wetgran-%,$(ANALYSIS_SRC)) $(BIN)/wetgran-cahn-hilliard
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
BENCH_SRC := $(wildcard tests/bench/bench_*.c)
BENCH_BIN := $(patsubst tests/bench/%.c,$(BUILD)/bench/%,$(BENCH_SRC))

.PHONY: all deps demo test bench bench-large stress clean tools tests-build
.DELETE_ON_ERROR:

all: deps
	$(MAKE) tools

deps:
	@./scripts/install-deps.sh

tools: $(TOOLS)

# The simulator's behavioural version (scripts/engine-version: a hash of the bit-exact outputs
# of seven short canonical runs, about 5 s of CPU): figures' runs depend on it, so a rebuild
# that computes the same trajectories re-simulates nothing.  Computed when the simulator is
# rebuilt; the version file is rewritten only when the version changes.
$(BIN)/wetgran-run.version: $(BIN)/wetgran-run.vstamp ;
$(BIN)/wetgran-run.vstamp: $(BIN)/wetgran-run
	@./scripts/engine-version $(BIN)/wetgran-run > $(BIN)/wetgran-run.version.tmp
	@cmp -s $(BIN)/wetgran-run.version.tmp $(BIN)/wetgran-run.version && rm $(BIN)/wetgran-run.version.tmp || \
	  mv $(BIN)/wetgran-run.version.tmp $(BIN)/wetgran-run.version
	@touch $@

# `make engine-version`: today's version against the committed one (sim/ENGINE_VERSION).  A change
# that alters a canonical trajectory must commit the new version and say so in its message.
.PHONY: engine-version
engine-version: deps
	$(MAKE) tools
	@v=$$(./scripts/engine-version $(BIN)/wetgran-run) && c=$$(cat sim/ENGINE_VERSION) && \
	  if [ "$$v" = "$$c" ]; then echo "engine version $$v (as committed in sim/ENGINE_VERSION)"; \
	  else echo "engine version $$v, committed $$c: the engine's trajectories changed; write $$v to sim/ENGINE_VERSION and say so in the commit (records of $$c stay usable; make check-archive FIG=<id> tests them against today's engine)"; exit 1; fi

$(BUILD)/sim/%.o: sim/%.c $(SIM_HDR) | $(BUILD)/sim
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

# the version string alone is rebuilt when the git state changes
$(BUILD)/sim/common/wg_error.o: sim/common/wg_error.c sim/common/wg.h $(BUILD)/version.txt | $(BUILD)/sim
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -DWG_GIT_VERSION='"$(GIT_VERSION)"' -c $< -o $@

$(BUILD)/version.txt: FORCE | $(BUILD)/sim
	@echo '$(GIT_VERSION)' | cmp -s - $@ || echo '$(GIT_VERSION)' > $@
FORCE:

$(LIB): $(LIB_OBJ)
	ar rcs $@.tmp $^ && mv $@.tmp $@

$(BIN)/wetgran-run: $(BUILD)/sim/run/run_main.o $(LIB) | $(BIN)
	$(CC) $(ALL_CFLAGS) $^ $(LIBS) -o $@

$(BIN)/wetgran-%: analysis/%.c $(LIB) | $(BIN)
	$(CC) $(ALL_CFLAGS) $< $(LIB) $(LIBS) -o $@

# sim/continuum/: the advective Cahn-Hilliard solver of the layering paper, a tool of its own
# (FFTW; kept out of libwetgran.a, which needs no FFTW)
$(BUILD)/sim/continuum/ch.o $(BUILD)/sim/continuum/ch_main.o: sim/continuum/ch.h
$(BIN)/wetgran-cahn-hilliard: $(BUILD)/sim/continuum/ch_main.o $(BUILD)/sim/continuum/ch.o $(LIB) | $(BIN)
	$(CC) $(ALL_CFLAGS) $^ $(LIBS) -lfftw3 -o $@

# wetgran-boundary triangulates with qhull (reentrant library)
$(BIN)/wetgran-boundary: LIBS += -lqhull_r
$(BIN)/wetgran-delaunay-flc: LIBS += -lqhull_r

$(BUILD)/tests/%: tests/%.c tests/tharness.h $(LIB) | $(BUILD)/tests
	$(CC) $(ALL_CFLAGS) -Itests $< $(LIB) $(LIBS) -o $@

$(BUILD)/bench/%: tests/bench/%.c $(LIB) | $(BUILD)/bench
	$(CC) $(ALL_CFLAGS) -Itests $< $(LIB) $(LIBS) -o $@

$(BUILD)/sim $(BUILD)/tests $(BUILD)/bench $(BIN):
	mkdir -p $@

tests-build: $(TOOLS) $(TEST_BIN)

# The test command of the README (and of .ci/run).
test: deps
	$(MAKE) -j$(NPROC) tests-build
	./tests/run.sh $(BUILD)/tests $(BIN)

bench: deps
	@./scripts/install-deps.sh --bench
	$(MAKE) tools $(BENCH_BIN)
	EDMD_SRC="$(EDMD_SRC)" ./tests/bench/run.sh $(BUILD)/bench $(BIN)

# The stress matrix (tests/stress.sh; its quick subset runs in `make test`): about a minute.
stress: deps
	$(MAKE) tools
	./tests/stress.sh $(BIN)

# Free cooling of 2.5e6 wet spheres (thesis Fig. 2.6): rate, memory, cluster picture; not in CI.
bench-large: deps
	$(MAKE) tools
	./tests/bench/large.sh $(BIN)

# Figures: make fig3_2 [PROFILE=quick|full]; each is experiments/<id>/.
PROFILE ?= quick
FIGURES := $(notdir $(patsubst %/,%,$(wildcard experiments/fig*/)))
.PHONY: $(FIGURES) figures check-figures $(addprefix figure-,$(FIGURES)) figure-tools
# one build of the tools however many figures are asked for (make -j2 fig3_4a fig3_9), and a
# figure that borrows another's runs after that one (make -j2 fig3_3 fig3_4atd would otherwise
# start the same run twice at once)
figure-tools: deps
	$(MAKE) tools $(BIN)/wetgran-run.version
$(FIGURES): %: figure-%

# All figures share one pool of job slots (-j per core), so no core idles while one figure
# finishes its last run; a figure that borrows another's runs or thresholds (borrow =,
# thresholds_from = in its conf) waits for that one, so no run is made twice at once.
# FIGURES_SKIP: ids left out (CI leaves out those too slow for it; see .ci/run).
FIGURES_SKIP ?=
figures: deps
	$(MAKE) -j$(NPROC) tools
	$(MAKE) -j$(NPROC) $(addprefix figure-,$(filter-out $(FIGURES_SKIP),$(FIGURES)))
# SCHED=slurm: the figure's runs first as one Slurm job array (scripts/slurm-sweep), then make
# finishes the figure from them
$(addprefix figure-,$(FIGURES)): figure-%: | figure-tools
	$(if $(filter slurm,$(SCHED)),./scripts/slurm-sweep experiments/$* PROFILE=$(PROFILE))
	$(MAKE) -C experiments/$* PROFILE=$(PROFILE)
borrowed = $(shell grep -E '^\s*(borrow|thresholds_from)\s*=' experiments/$(1)/$(PROFILE).conf 2>/dev/null | sed 's/^[^=]*=//')
$(foreach f,$(FIGURES),$(eval figure-$(f): $(addprefix figure-,$(call borrowed,$(f)))))

# Compare figures' results.tsv with data/reference/<id>.tsv (after make figures): every figure,
# or those named (make check-figures FIGURES="fig3_4a fig3_9", or make check-fig3_4a).
check-figures:
	FIGURES_SKIP='$(FIGURES_SKIP)' ./scripts/check-figures.sh $(PROFILE) $(filter-out all,$(FIGURES_ASKED))
FIGURES_ASKED := $(if $(filter command line,$(origin FIGURES)),$(FIGURES))
check-fig%:
	FIGURES_SKIP='$(FIGURES_SKIP)' ./scripts/check-figures.sh $(PROFILE) fig$*

# `make help`: the targets, and every figure with what it shows, whether CI makes it and the
# CPU its profiles took (experiments/figures.tsv; scripts/figure-costs measures them).
.PHONY: help
help:
	@sed -n '2,5p' Makefile | sed 's/^# //'
	@echo "  make <id> [PROFILE=quick|full]   one figure; make figures: all; make check-figures [FIGURES=...]"
	@echo "  make engine-version               the behavioural engine version against sim/ENGINE_VERSION"
	@echo "  make check-archive FIG=<id> [SAMPLE=k SEED=s MAX_CPU=s PROFILE=full]   re-simulate archived points"
	@echo "  make archive [FIGURES=...] [PROFILE=full]   file records into data/records (for the next clone)"
	@echo "  make docs-figures                 redraw docs/figures from the archive"
	@echo
	@awk -F'\t' 'NR == 1 { next } { printf "%-10s %-3s quick %8s  full %9s  %s\n", $$1, ($$3 == "yes" ? "CI" : "-"), $$4, $$5, $$2 }' experiments/figures.tsv
	@echo "(CPU: seconds of simulation summed over the profile's records; CI: made and checked by .ci/run)"

# Re-simulate SAMPLE randomly chosen archived points of FIG and compare them with the archive
# (scripts/check-archive; outcome in experiments/<FIG>/out/<PROFILE>/check-archive.tsv).
SAMPLE ?= 3
SEED ?= 1
MAX_CPU ?= 0
.PHONY: check-archive archive
check-archive: figure-tools
	@[ -n "$(FIG)" ] || { echo "make check-archive: name the figure, FIG=<id>" >&2; exit 2; }
	./scripts/check-archive $(FIG) $(SAMPLE) $(SEED) $(MAX_CPU) $(if $(filter command line,$(origin PROFILE)),$(PROFILE),full)

# File the records of the figures named (default: all) into data/records/<id>/<profile>/.
archive:
	@for f in $(FIGURES); do \
	  [ -d experiments/$$f/out/$(PROFILE)/runs ] && $(MAKE) -s -C experiments/$$f PROFILE=$(PROFILE) archive || true; done

# The main job: thesis Fig. 3.2 (event-driven curves) at CI scale.
demo: fig3_2

# The docs pages' pictures, docs/figures/<id>.png: every figure drawn from the run archive at
# the thesis's scale where it is filed (nothing simulated), else at CI scale, and shrunk
# (scripts/docs-figures; DOCS_FIGURES="fig3_2 fig4_1" for some only).
.PHONY: docs-figures
docs-figures: deps
	./scripts/docs-figures $(DOCS_FIGURES)

clean:
	rm -rf build bin
