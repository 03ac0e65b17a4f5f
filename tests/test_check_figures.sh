#!/bin/bash
# scripts/check-figures.sh: a value inside its band passes, outside fails naming figure, key,
# value and band, a missing key or results file fails, a figure in FIGURES_SKIP is skipped,
# and an xfail:BAND tolerance reports
# XFAIL (or XPASS) without failing the run.
set -u
. "$(dirname "$0")/checks.sh"
script=$(cd "$(dirname "$0")/.." && pwd)/scripts/check-figures.sh
mkdir -p "$tmp/data/reference" "$tmp/experiments/figA/out/quick" "$tmp/experiments/figB/out/quick"
ref() { printf '# key\tvalue\ttol_quick\ttol_full\tsource\n%s\n' "$2" > "$tmp/data/reference/$1.tsv"; }
res() { printf 'key\tvalue\terror\n%s\n' "$2" > "$tmp/experiments/$1/out/quick/results.tsv"; }
ref figA $'x\t1.0\t0.2\t0.1\tsource A'
ref figB $'y\t2.0\txfail:0.1\t0.1\tknown'
res figA $'x\t1.15\t0.01'
res figB $'y\t2.5\t0.01'
WG_TOP=$tmp "$script" quick > "$tmp/out1"; rc=$?
check "inside the band and a known discrepancy: exit 0 ($rc)" test "$rc" -eq 0
check "the known discrepancy is reported as XFAIL" grep -q '^XFAIL figB: y = 2.5 outside 2.0 +- 0.1' "$tmp/out1"
check "the last line counts 1 passed, 0 failed" test "$(tail -n 1 "$tmp/out1")" = "1 passed, 0 failed"
res figB $'y\t2.05\t0.01'
WG_TOP=$tmp "$script" quick > "$tmp/out2"
check "a known discrepancy met after all is XPASS" grep -q '^XPASS figB: y = 2.05' "$tmp/out2"
res figA $'x\t1.3\t0.01'
WG_TOP=$tmp "$script" quick > "$tmp/out3"; rc=$?
check "outside the band: non-zero exit" test "$rc" -ne 0
check "the failure names figure, key, value and band" grep -q '^FAIL  figA: x = 1.3 outside 1.0 +- 0.2 (quick)' "$tmp/out3"
WG_TOP=$tmp "$script" full > "$tmp/out4"; rc=$?
check "the full profile's band applies with PROFILE=full (no full results: fails)" \
  bash -c "[ $rc -ne 0 ] && grep -q 'FAIL  figA: no .*out/full/results.tsv' '$tmp/out4'"
res figA $'z\t1.0\t0.01'
WG_TOP=$tmp "$script" quick > "$tmp/out5"; rc=$?
check "a key missing from results.tsv fails" bash -c "[ $rc -ne 0 ] && grep -q 'key x missing' '$tmp/out5'"
FIGURES_SKIP="figA" WG_TOP=$tmp "$script" full > "$tmp/out6"; rc=$?
check "a figure in FIGURES_SKIP is reported SKIP, not checked (only figB fails here)" \
  bash -c "grep -q '^SKIP  figA' '$tmp/out6' && ! grep -q 'FAIL  figA' '$tmp/out6' && grep -q 'FAIL  figB' '$tmp/out6'"
# a tolerance "-": the key is not checked at that profile (the quick scan has no such point)
ref figA $'x\t1.0\t0.2\t0.1\tsource A\nw\t3.0\t-\t0.1\tfull only'
res figA $'x\t1.1\t0.01'
WG_TOP=$tmp FIGURES_SKIP=figB "$script" quick > "$tmp/out7"; rc=$?
check "a key whose quick tolerance is '-' is not checked at quick (missing, still exit 0)" \
  bash -c "[ $rc -eq 0 ] && ! grep -q 'key w' '$tmp/out7' && [ \"\$(tail -n 1 '$tmp/out7')\" = '1 passed, 0 failed' ]"
# one figure at a time: only those named are checked
res figB $'y\t2.9\t0.01'
WG_TOP=$tmp "$script" quick figA > "$tmp/out8"; rc=$?
check "naming figA checks figA alone (figB, failing, is not looked at)" \
  bash -c "[ $rc -eq 0 ] && ! grep -q figB '$tmp/out8' && [ \"\$(tail -n 1 '$tmp/out8')\" = '1 passed, 0 failed' ]"
WG_TOP=$tmp "$script" quick figA figB > "$tmp/out9"; rc=$?
check "naming both checks both" bash -c "grep -q '^ok    figA' '$tmp/out9' && grep -q 'figB: y = 2.9' '$tmp/out9'"
WG_TOP=$tmp "$script" quick figZ > "$tmp/out10" 2>&1; rc=$?
check "an unknown figure: exit 2 naming it" bash -c "[ $rc -eq 2 ] && grep -q \"no figure 'figZ'\" '$tmp/out10'"
summary
