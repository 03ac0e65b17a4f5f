#!/bin/bash
# Runs every test program and test script, as many at once as there are cores (WG_TEST_JOBS
# to change that); prints their output in a fixed order and, last, the total
# "N passed, N failed" line that CI reads.  Usage: tests/run.sh TEST_BIN_DIR TOOL_BIN_DIR
set -u
testdir=${1:?test binary directory}
bindir=${2:?tool directory}
export WG_BIN=$(cd "$bindir" && pwd)
export WG_TESTS=$(cd "$(dirname "$0")" && pwd)
jobs=${WG_TEST_JOBS:-$(nproc)}
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
tests=()
for t in "$testdir"/test_* "$WG_TESTS"/test_*.sh; do [ -x "$t" ] && tests+=("$t"); done
for t in "${tests[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  name=$(basename "$t")
  ( start=$(date +%s); "$t" > "$logs/$name.log" 2>&1; echo "$? $(( $(date +%s) - start ))" > "$logs/$name.rc" ) &
done
wait
passed=0 failed=0 broken=""
for t in "${tests[@]}"; do
  name=$(basename "$t")
  echo "=== $name"
  cat "$logs/$name.log"
  read -r rc secs < "$logs/$name.rc"
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$logs/$name.log" | tail -n 1)
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
  echo "--- $name: $line ($secs s)"
done
[ -n "$broken" ] && echo "failing:$broken"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
