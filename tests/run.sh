#!/bin/bash
# Runs every test program and test script; prints their output and, last, the total
# "N passed, N failed" line that CI reads.  Usage: tests/run.sh TEST_BIN_DIR TOOL_BIN_DIR
set -u
testdir=${1:?test binary directory}
bindir=${2:?tool directory}
export WG_BIN=$(cd "$bindir" && pwd)
export WG_TESTS=$(cd "$(dirname "$0")" && pwd)
passed=0 failed=0 broken=""
log=$(mktemp)
for t in "$testdir"/test_* "$WG_TESTS"/test_*.sh; do
  [ -x "$t" ] || continue
  name=$(basename "$t")
  echo "=== $name"
  start=$(date +%s)
  "$t" > "$log" 2>&1
  rc=$?
  cat "$log"
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
  if [ -z "$line" ]; then
    echo "!!! $name ended (exit $rc) without a summary line"
    failed=$((failed + 1)); broken="$broken $name"
    continue
  fi
  p=${line%% passed*}; f=${line#*passed, }; f=${f%% failed*}
  passed=$((passed + p)); failed=$((failed + f))
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    echo "!!! $name exited $rc"; failed=$((failed + 1)); broken="$broken $name"
  fi
  [ "$f" -gt 0 ] && broken="$broken $name"
  echo "--- $name: $line ($(( $(date +%s) - start )) s)"
done
rm -f "$log"
[ -n "$broken" ] && echo "failing:$broken"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
