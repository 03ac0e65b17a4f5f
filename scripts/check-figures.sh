#!/bin/bash
# Compares every experiments/<id>/out/<profile>/results.tsv with data/reference/<id>.tsv:
# |value - reference| must lie within the profile's tolerance.  Names figure, key, value and
# band on failure; exits non-zero if any key fails or a results file is missing.  A tolerance
# written "xfail:BAND" marks a known discrepancy of that profile (documented in the reference
# file and the README): it is checked against BAND and reported as XFAIL, or XPASS if it meets
# it after all, and does not fail the run.  A tolerance "-" leaves the key unchecked at that
# profile (a point only the full scan has).
# Figures named in FIGURES_SKIP (space-separated ids; CI leaves out those too slow for it)
# are reported as SKIP and not checked.
# Usage: scripts/check-figures.sh [quick|full] [ID ...]   (IDs: only those figures)
set -u
profile=${1:-quick}
[ $# -gt 0 ] && shift
top=${WG_TOP:-$(cd "$(dirname "$0")/.." && pwd)}  # WG_TOP: another tree (tests)
refs=()
if [ $# -gt 0 ]; then
  for id in "$@"; do
    if [ ! -f "$top/data/reference/$id.tsv" ]; then
      if [ -d "$top/experiments/$id" ]; then echo "check-figures: $id has no reference numbers (data/reference/$id.tsv)" >&2
      else echo "check-figures: no figure '$id' (see make help)" >&2; fi
      exit 2
    fi
    refs+=("$top/data/reference/$id.tsv")
  done
else
  refs=("$top"/data/reference/*.tsv)
fi
col=3; [ "$profile" = full ] && col=4
status=0 checked=0 passed=0 failed=0 xfail=0
for ref in "${refs[@]}"; do
  id=$(basename "$ref" .tsv)
  case " ${FIGURES_SKIP:-} " in *" $id "*) echo "SKIP  $id: left out of this job (FIGURES_SKIP)"; continue;; esac
  res="$top/experiments/$id/out/$profile/results.tsv"
  if [ ! -e "$res" ]; then
    echo "FAIL  $id: no $res (run: make $id PROFILE=$profile)"; status=1; failed=$((failed + 1)); continue
  fi
  while IFS=$'\t' read -r key value tq tf _; do
    case "$key" in ''|\#*) continue;; esac
    tol=$tq; [ "$profile" = full ] && tol=$tf
    [ "$tol" = - ] && continue
    got=$(awk -F'\t' -v k="$key" '$1 == k { print $2; exit }' "$res")
    checked=$((checked + 1))
    if [ -z "$got" ]; then
      echo "FAIL  $id: key $key missing from $res"; status=1; failed=$((failed + 1)); continue
    fi
    known=0
    case "$tol" in xfail:*) known=1; tol=${tol#xfail:};; esac
    if awk -v g="$got" -v v="$value" -v t="$tol" 'BEGIN { d = g - v; if (d < 0) d = -d; exit !(g == g + 0 && d <= t) }'; then
      if [ $known -eq 1 ]; then echo "XPASS $id: $key = $got within $value +- $tol ($profile; a known discrepancy met after all)"; xfail=$((xfail + 1))
      else echo "ok    $id: $key = $got within $value +- $tol ($profile)"; passed=$((passed + 1)); fi
    elif [ $known -eq 1 ]; then
      echo "XFAIL $id: $key = $got outside $value +- $tol ($profile; known discrepancy, see data/reference/$id.tsv)"; xfail=$((xfail + 1))
    else
      echo "FAIL  $id: $key = $got outside $value +- $tol ($profile)"; status=1; failed=$((failed + 1))
    fi
  done < "$ref"
done
echo "check-figures ($profile): $checked keys checked, $xfail known discrepancies (XFAIL/XPASS)"
echo "$passed passed, $failed failed"
exit $status
