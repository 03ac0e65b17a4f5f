#!/bin/bash
# The engine fingerprint that keys the run archive (scripts/engine-fingerprint): blind to
# comments and layout, changed by any change of code or flags; and scripts/rekey-archive, which
# renames a fingerprint in the keys of an archive.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"
fp() { "$top/scripts/engine-fingerprint" gcc "${flags:--O2}" "$tmp/src/evqueue.c" "$tmp/src/wg.h"; }
reset() { rm -rf "$tmp/src"; mkdir -p "$tmp/src"; cp "$top/sim/evqueue.c" "$top/sim/wg.h" "$tmp/src/"; }
reset
base=$(fp) || base=failed
check "the fingerprint is a sha256" bash -c "[[ '$base' =~ ^[0-9a-f]{64}$ ]]"
check "the same sources give the same fingerprint" test "$(fp)" = "$base"
sed -i '1i /* a new comment, with code in it: x = 1; */' "$tmp/src/evqueue.c"
sed -i 's|^\(.*;\)$|\1 // a trailing comment|' "$tmp/src/evqueue.c"
sed -i 's/^  /\t/' "$tmp/src/wg.h"
sed -i 's/$/   /' "$tmp/src/wg.h"
check "comments added and layout changed: the same fingerprint" test "$(fp)" = "$base"
check "(the files did change)" bash -c "! cmp -s '$tmp/src/evqueue.c' '$top/sim/evqueue.c' && ! cmp -s '$tmp/src/wg.h' '$top/sim/wg.h'"
reset
echo 'int wg_fingerprint_probe;' >> "$tmp/src/evqueue.c"
check "a line of code added: another fingerprint" test "$(fp)" != "$base"
reset
sed -i "s/q->size \*= 2;/q->size *= 3;/" "$tmp/src/evqueue.c"
check "a constant changed: another fingerprint" test "$(fp)" != "$base"
check "(the constant did change)" grep -q 'q->size \*= 3;' "$tmp/src/evqueue.c"
reset
flags=-O3
check "other compiler flags: another fingerprint" test "$(fp)" != "$base"
unset flags
check "a missing source is an error" bash -c "! '$top/scripts/engine-fingerprint' gcc -O2 '$tmp/src/nothing.c' 2> /dev/null"

# rekey-archive
old=$(printf a%.0s $(seq 64)) new=$(printf b%.0s $(seq 64)) other=$(printf c%.0s $(seq 64))
mkdir -p "$tmp/arch/partial"
printf '%s\nargs1\n' "$old" > "$tmp/arch/r1.h5.key"
printf '%s\nargs2\n' "$old" > "$tmp/arch/partial/r2.h5.key"
printf '%s\nargs3\n' "$other" > "$tmp/arch/r3.h5.key"
"$top/scripts/rekey-archive" "$old" "$new" "$tmp/arch" 2> "$tmp/err"
check "rekey-archive renames the fingerprint in keys, checkpoints' too" \
  bash -c "test \"\$(cat '$tmp/arch/r1.h5.key')\" = \"$new
args1\" && test \"\$(cat '$tmp/arch/partial/r2.h5.key')\" = \"$new
args2\""
check "and leaves keys of another engine alone" test "$(head -n 1 "$tmp/arch/r3.h5.key")" = "$other"
check "and says how many it rekeyed" grep -q '2 keys now name' "$tmp/err"
check "rekey-archive refuses a fingerprint that is not a sha256" \
  bash -c "! '$top/scripts/rekey-archive' xyz '$new' '$tmp/arch' 2> /dev/null"
summary
