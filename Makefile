# wetgran — build, test, benchmark and regenerate the figures.
#   make            build every tool into bin/
#   make demo       the main job: a small real figure (thesis Fig. 3.2, event-driven)
#   make test       build and run the tests (SANITIZE=1: under ASan + UBSan)
#   make bench      benchmarks (numbers go to tests/bench/out/)
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

ALL_CFLAGS := $(BASE_CFLAGS) -Isim $(HDF5_CFLAGS) -DWG_CFLAGS='"$(BASE_CFLAGS)"'
LIBS := $(HDF5_LIBS) -lgsl -lgslcblas -lm $(LDSAN)

LIB_SRC := $(filter-out sim/run_main.c,$(wildcard sim/*.c))
LIB_OBJ := $(patsubst sim/%.c,$(BUILD)/sim/%.o,$(LIB_SRC))
LIB := $(BUILD)/libwetgran.a
ANALYSIS_SRC := $(wildcard analysis/*.c)
TOOLS := $(BIN)/wetgran-run $(patsubst analysis/%.c,$(BIN)/wetgran-%,$(ANALYSIS_SRC))
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
BENCH_SRC := $(wildcard tests/bench/bench_*.c)
BENCH_BIN := $(patsubst tests/bench/%.c,$(BUILD)/bench/%,$(BENCH_SRC))

.PHONY: all deps demo test bench clean tools tests-build
.DELETE_ON_ERROR:

all: deps
	$(MAKE) tools

deps:
	@./scripts/install-deps.sh

tools: $(TOOLS) $(BIN)/wetgran-run.engine

# A fingerprint of the simulator's physics (scripts/engine-fingerprint: sources without their
# comments and layout, compiler version, flags): experiments rerun their runs when it changes,
# not when the binary is merely relinked (a new commit changes the version string) or a comment
# is edited.  The time-driven engine's own modules (td, contact) are left out: event-driven runs
# do not use them.  Recomputed on every make (a fraction of a second); rewritten only if changed.
ED_SRC := $(sort $(filter-out sim/td.% sim/contact.% sim/friction.%,$(wildcard sim/*.c sim/*.h)))
$(BIN)/wetgran-run.engine: $(BIN)/wetgran-run FORCE
	@./scripts/engine-fingerprint $(CC) '$(BASE_CFLAGS)' $(ED_SRC) > $@.tmp
	@cmp -s $@.tmp $@ && rm $@.tmp || mv $@.tmp $@

$(BUILD)/sim/%.o: sim/%.c $(wildcard sim/*.h) | $(BUILD)/sim
	$(CC) $(ALL_CFLAGS) -c $< -o $@

# the version string alone is rebuilt when the git state changes
$(BUILD)/sim/wg_error.o: sim/wg_error.c sim/wg.h $(BUILD)/version.txt | $(BUILD)/sim
	$(CC) $(ALL_CFLAGS) -DWG_GIT_VERSION='"$(GIT_VERSION)"' -c $< -o $@

$(BUILD)/version.txt: FORCE | $(BUILD)/sim
	@echo '$(GIT_VERSION)' | cmp -s - $@ || echo '$(GIT_VERSION)' > $@
FORCE:

$(LIB): $(LIB_OBJ)
	ar rcs $@.tmp $^ && mv $@.tmp $@

$(BIN)/wetgran-run: $(BUILD)/sim/run_main.o $(LIB) | $(BIN)
	$(CC) $(ALL_CFLAGS) $^ $(LIBS) -o $@

$(BIN)/wetgran-%: analysis/%.c $(LIB) | $(BIN)
	$(CC) $(ALL_CFLAGS) $< $(LIB) $(LIBS) -o $@

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
	$(MAKE) tools $(BENCH_BIN)
	./tests/bench/run.sh $(BUILD)/bench $(BIN)

# Figures: make fig3_2 [PROFILE=quick|full]; each is experiments/<id>/.
PROFILE ?= quick
FIGURES := $(notdir $(wildcard experiments/fig*))
.PHONY: $(FIGURES) figures check-figures $(addprefix figure-,$(FIGURES)) figure-tools
# one build of the tools however many figures are asked for (make -j2 fig3_4a fig3_9), and a
# figure that borrows another's runs after that one (make -j2 fig3_3 fig3_4atd would otherwise
# start the same run twice at once)
figure-tools: deps
	$(MAKE) tools
$(FIGURES): %: figure-%

# All figures share one pool of job slots (-j per core), so no core idles while one figure
# finishes its last run; a figure that borrows another's runs or thresholds (borrow =,
# thresholds_from = in its conf) waits for that one, so no run is made twice at once.
# FIGURES_SKIP: ids left out (CI leaves out those too slow for it; see .ci/run).
FIGURES_SKIP ?=
figures: deps
	$(MAKE) -j$(NPROC) tools
	$(MAKE) -j$(NPROC) $(addprefix figure-,$(filter-out $(FIGURES_SKIP),$(FIGURES)))
$(addprefix figure-,$(FIGURES)): figure-%: | figure-tools
	$(MAKE) -C experiments/$* PROFILE=$(PROFILE)
borrowed = $(shell grep -E '^\s*(borrow|thresholds_from)\s*=' experiments/$(1)/$(PROFILE).conf 2>/dev/null | sed 's/^[^=]*=//')
$(foreach f,$(FIGURES),$(eval figure-$(f): $(addprefix figure-,$(call borrowed,$(f)))))

# Compare every figure's results.tsv with data/reference/<id>.tsv (after make figures).
check-figures:
	FIGURES_SKIP='$(FIGURES_SKIP)' ./scripts/check-figures.sh $(PROFILE)

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
