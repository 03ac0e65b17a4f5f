#!/bin/bash
# scripts/campaign-status on a made-up experiment: runs counted from the experiment's own
# make recipes (continued lines too), filed / resumable / unfiled told apart, borrowed runs
# left to their own experiment.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"
t=$tmp/top
mkdir -p "$t/scripts" "$t/experiments/ex/out/full/runs" "$t/data/records/ex/full/partial"
cp "$top/scripts/campaign-status" "$t/scripts/"
touch "$t/experiments/ex/full.conf"
cat > "$t/experiments/ex/Makefile" <<MK
RUNS := \$(foreach e,1 2 3 4 5,out/full/runs/E\$(e).h5)
all: \$(RUNS) borrowed
out/full/runs/E%.h5:
	scripts/record $t/data/records/ex/full stamp wetgran-run scene.ini \\
	  estar=\$* -q -o \$@
borrowed:
	scripts/record $t/data/records/other/full stamp wetgran-run scene.ini -q -o out/full/runs/B.h5
MK
for n in E1 E2; do touch "$t/data/records/ex/full/$n.h5" "$t/data/records/ex/full/$n.h5.rec"; done
touch "$t/data/records/ex/full/partial/E3.h5.ckpt"
touch "$t/experiments/ex/out/full/runs/E4.h5" "$t/experiments/ex/out/full/runs/E4.h5.rec"
mkdir -p "$t/experiments/ex/out/full/runs/whole"
touch "$t/experiments/ex/out/full/runs/whole/E5.h5.ckpt"
"$t/scripts/campaign-status" > "$tmp/out" 2> "$tmp/err"
check "campaign-status prints a header and one row" test "$(wc -l < "$tmp/out")" -eq 2
check "five runs, two filed, one resumable, one complete but unfiled (one still running)" \
  grep -qP '^ex\t5\t2\t1\t1$' "$tmp/out"
check "an unknown experiment is an error" bash -c "! '$t/scripts/campaign-status' full nosuch 2> /dev/null"
summary
