#!/bin/bash
# experiments/common.mk on a made-up experiment: switching PROFILE makes that profile's
# results and redraws the shared figure (a missing results.tsv must be made even when the
# figure is newer than everything it came from), a second make does nothing; and no run of
# any real experiment is an intermediate file (make would delete it once drawn from).
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"
ex=$tmp/ex
mkdir -p "$ex"
echo "runs = 1 2" > "$ex/quick.conf"
echo "runs = 1 2 3" > "$ex/full.conf"
cat > "$ex/Makefile" <<MK
include $top/experiments/common.mk
\$(RUNDIR)/r%.h5: \$(CONF) | \$(RUNDIR)
	echo run \$* > \$@
\$(OUT)/results.tsv: \$(foreach r,\$(call conf,runs),\$(RUNDIR)/r\$(r).h5.txt) | \$(OUT)
	echo "\$(PROFILE) \$(words \$^)" > \$@
\$(RUNDIR)/%.h5.txt: \$(RUNDIR)/%.h5
	cp \$< \$@
\$(FIGURE): \$(OUT)/results.tsv | \$(FIGDIR)
	cp \$< \$@
MK
mk() { make -s -C "$ex" FIGDIR="$tmp/fig" "$@" > "$tmp/make.out" 2>&1; }
fig=$tmp/fig/ex.png
mk
check "quick: results and figure from the quick runs" grep -qx 'quick 2' "$fig"
mk PROFILE=full
check "full after quick: the full results are made though the figure is newer" \
  test -f "$ex/out/full/results.tsv"
check "full after quick: the figure is redrawn from them" grep -qx 'full 3' "$fig"
mk
check "quick after full: the figure is redrawn from the quick results" grep -qx 'quick 2' "$fig"
touch "$tmp/ref"
mk
check "a second make leaves the figure alone" test ! "$fig" -nt "$tmp/ref"
rm "$ex/out/quick/results.tsv"
mk
check "a results.tsv removed is made again" grep -qsx 'quick 2' "$ex/out/quick/results.tsv"
mk PARTIAL=1 PROFILE=full
check "PARTIAL=1 draws its own figure" test -f "$tmp/fig/ex-partial.png"
# PARTIAL=1 draws the runs made here and those filed in the archive (restored from it), and
# does not start the others
ex2=$tmp/ex2
mkdir -p "$ex2/out/full/runs" "$tmp/archive"
echo "runs = 1 2 3" > "$ex2/full.conf"
cat > "$ex2/Makefile" <<MK
include $top/experiments/common.mk
RUNS := \$(call made,\$(foreach r,\$(call conf,runs),\$(RUNDIR)/r\$(r).h5))
\$(RUNDIR)/r%.h5: | \$(RUNDIR)
	cp \$(ARCHIVE)/r\$*.h5 \$@ 2> /dev/null || echo run \$* > \$@
\$(OUT)/results.tsv: \$(RUNS) | \$(OUT)
	echo \$(notdir \$^) > \$@
\$(FIGURE): \$(OUT)/results.tsv | \$(FIGDIR)
	cp \$< \$@
MK
echo made here > "$ex2/out/full/runs/r1.h5"
echo filed > "$tmp/archive/r2.h5"
make -s -C "$ex2" FIGDIR="$tmp/fig" PROFILE=full PARTIAL=1 ARCHIVE="$tmp/archive" > "$tmp/make.out" 2>&1
check "PARTIAL=1: the runs made here and the runs filed in the archive, no other" \
  grep -qx 'r1.h5 r2.h5' "$ex2/out/full-partial/results.tsv"
check "PARTIAL=1: a filed run is restored from the archive" grep -qx filed "$ex2/out/full/runs/r2.h5"
check "PARTIAL=1: a run neither made nor filed is not started" test ! -e "$ex2/out/full/runs/r3.h5"
# every experiment, both profiles: the dry run succeeds, and make's database after it lists
# no intermediate file (the tools under test stand in for bin/, a stamp for the fingerprint)
bin=${WG_BIN:-$top/bin}
touch "$tmp/engine"
inter= broken= broken_partial= partial_runs=
for e in "$top"/experiments/fig*/; do
  for p in quick full; do
    [ -f "$e$p.conf" ] || continue
    make -C "$e" -n -p PROFILE=$p BIN="$bin" ENGINE="$tmp/engine" > "$tmp/db" 2> /dev/null ||
      broken="$broken $(basename "$e")/$p"
    f=$(grep -B4 '^#  File is an intermediate prerequisite' "$tmp/db" | grep -E '^[^#][^:]*:' | sed 's/:.*//')
    [ -n "$f" ] && inter="$inter $(basename "$e")/$p ($(echo "$f" | wc -l), e.g. $(echo "$f" | grep -m1 h5 || echo "$f" | head -n 1))"
    # PARTIAL=1 reaches the lenders too: a borrower must ask them for their partial outputs
    # (or for their complete ones with PARTIAL=), which have rules there; runs stay in
    # out/<profile>/runs under PARTIAL=1, so no command may name out/<profile>-partial/runs
    make -C "$e" -n PROFILE=$p PARTIAL=1 BIN="$bin" ENGINE="$tmp/engine" > "$tmp/dry" 2>&1 ||
      broken_partial="$broken_partial $(basename "$e")/$p"
    grep -q -- "-partial/runs" "$tmp/dry" && partial_runs="$partial_runs $(basename "$e")/$p"
  done
done
check "every experiment's dry run succeeds (${broken:-all})" test -z "$broken"
check "every experiment's dry run with PARTIAL=1 succeeds (${broken_partial:-all})" test -z "$broken_partial"
check "with PARTIAL=1 every run is looked for in out/<profile>/runs (${partial_runs:-all})" test -z "$partial_runs"
check "no file of any experiment is intermediate (${inter:-none})" test -z "$inter"

# the top Makefile: `make fig3_4atd` (or make -j2 fig3_3 fig3_4atd) makes the figures whose
# runs it borrows first, so no run is started twice at once
db=$(make -C "$top" -p -q .wg-no-such-goal 2> /dev/null)
check "make fig3_4atd waits for fig3_3 and fig3_4a, whose runs it borrows" \
  grep -qx 'figure-fig3_4atd: figure-fig3_3 figure-fig3_4a | figure-tools' <<< "$db"
check "make fig3_4atd goes through that rule" grep -qx 'fig3_4atd: figure-fig3_4atd' <<< "$db"
summary
