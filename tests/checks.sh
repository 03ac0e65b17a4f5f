# Sourced by the shell tests: a scratch directory removed on exit, check "what" command...
# counting ok / FAIL, and summary printing the "N passed, N failed" line (exit status 1 on
# any failure).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0
check() {
  local what=$1; shift
  if "$@"; then passed=$((passed + 1)); echo "ok    $what"
  else failed=$((failed + 1)); echo "FAIL  $what"; fi
}
summary() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
