#!/bin/bash
# The behavioural engine version (scripts/engine-version): this build's must be the committed
# sim/ENGINE_VERSION -- a change that alters any canonical trajectory must bump it, and the
# commit say so --; it is blind to how the simulator is called, and sees a changed trajectory.
set -u
bin=${WG_BIN:?}
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"
v=$("$top/scripts/engine-version" --keep "$tmp/canon" "$bin/wetgran-run")
check "this build's engine version ($v) is the committed one, sim/ENGINE_VERSION ($(cat "$top/sim/ENGINE_VERSION")): if the engine's trajectories changed on purpose, write the new version there and say so in the commit" \
  test "$v" = "$(cat "$top/sim/ENGINE_VERSION")"
check "seven canonical runs: ED 2D wet and dry, ED 3D periodic and walled, TD 2D wet, with friction, TD 3D" \
  test "$(ls "$tmp"/canon/*.h5 | wc -l)" -eq 7
check "every canonical run has snapshots and a T_g series in the hash, four have profiles" \
  bash -c "[ \$(grep -c '^-- /particles/all/position/value' '$tmp/canon/dump.txt') -eq 7 ] && [ \$(grep -c '^-- /observables/temperature/value' '$tmp/canon/dump.txt') -eq 7 ] && [ \$(grep -c '^-- /observables/profiles/temperature' '$tmp/canon/dump.txt') -eq 4 ]"
check "bridge lists of the wet runs are in the hash" test "$(grep -c '^-- /bridges/pairs' "$tmp/canon/dump.txt")" -ge 5
if [ -z "${WG_TEST_SHORT:-}" ]; then
  printf '#!/bin/sh\nexec "%s" "$@" dt_checkpoint=0\n' "$bin/wetgran-run" > "$tmp/same"
  printf '#!/bin/sh\nexec "%s" "$@" eps_wall=0.999\n' "$bin/wetgran-run" > "$tmp/changed"
  chmod +x "$tmp/same" "$tmp/changed"
  check "a simulator called differently but computing the same trajectories has the same version" \
    test "$("$top/scripts/engine-version" "$tmp/same")" = "$v"
  check "one whose trajectories differ (walls with eps_wall = 0.999) has another" \
    test "$("$top/scripts/engine-version" "$tmp/changed")" != "$v"
fi
"$top/scripts/engine-version" "$tmp/nosuch" > /dev/null 2> "$tmp/err"
rc=$?
check "no simulator: exit 2 naming it ($rc)" bash -c "[ $rc -eq 2 ] && grep -q 'no simulator' '$tmp/err'"
summary
