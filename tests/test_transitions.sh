#!/bin/bash
# wetgran-transitions places a phase change of a one-dimensional scan between the right two
# samples, per group, tolerates a stray label, and refuses bad input naming file and line.
set -u
tr_=${WG_BIN:?}/wetgran-transitions
. "$(dirname "$0")/checks.sh"
row() { awk -F'\t' -v g="$1" -v p="$2" '$1 == g && $2 == p { print $3, $4, $7 }' "$3"; }
printf 'estar\te_cb\tlabel\n' > "$tmp/scan.tsv"
# E_cb = 1: f f fgc(stray) f f fgc fgc g g ; E_cb = 2: f fgc, no gas
printf '1\t1\tf\n1.2\t1\tf\n1.4\t1\tfgc\n1.6\t1\tf\n1.7\t1\tf\n1.8\t1\tfgc\n2.2\t1\tfgc\n2.6\t1\tg\n3\t1\tg\n' >> "$tmp/scan.tsv"
printf '4\t2\tfgc\n1\t2\tf\n2\t2\tf\n' >> "$tmp/scan.tsv"
"$tr_" --x estar --group e_cb --pair f:fgc --pair fgc:g "$tmp/scan.tsv" > "$tmp/out" 2> "$tmp/err"
check "header names the group column" bash -c "head -1 '$tmp/out' | grep -q '^e_cb	pair	x	err'"
check "f-fgc of E_cb = 1 between 1.7 and 1.8, one point misplaced" \
  test "$(row 1 f_fgc "$tmp/out")" = "1.75 0.05 1"
check "fgc-g of E_cb = 1 between 2.2 and 2.6" test "$(row 1 fgc_g "$tmp/out")" = "2.4 0.2 0"
check "rows of a group are sorted in x first (E_cb = 2: 3 after 2)" \
  test "$(row 2 f_fgc "$tmp/out")" = "3 1 0"
check "a pair absent from a group is reported on stderr" grep -q "e_cb = 2: no fgc:g" "$tmp/err"
"$tr_" --x estar --group e_cb --pair f:fgc --logx "$tmp/scan.tsv" > "$tmp/log"
read -r x e m < <(row 2 f_fgc "$tmp/log")
check "--logx: geometric midpoint sqrt(2 * 4) = $x" awk -v x="$x" 'BEGIN { exit !(x > 2.828 && x < 2.829) }'
check "--logx: error x ln(2) / 2 = $e" awk -v x="$x" -v e="$e" 'BEGIN { d = e - x * log(2) / 2; exit !(d < 1e-3 && d > -1e-3) }'
printf 'estar\tlabel\n1\tf\nx\tg\n' > "$tmp/bad.tsv"
"$tr_" --x estar --pair f:g "$tmp/bad.tsv" > /dev/null 2> "$tmp/err2"; rc=$?
check "a bad number: exit 1, file and line 3 named" bash -c "[ $rc -eq 1 ] && grep -q 'bad.tsv:3' '$tmp/err2'"
"$tr_" --x gamma --pair f:g "$tmp/bad.tsv" > /dev/null 2> "$tmp/err3"; rc=$?
check "a missing column: exit 1, column named" bash -c "[ $rc -eq 1 ] && grep -q \"'gamma'\" '$tmp/err3'"
"$tr_" --x estar "$tmp/bad.tsv" > /dev/null 2>&1; rc=$?
check "no --pair: exit 2" test "$rc" -eq 2
check "--help answers" bash -c "'$tr_' --help | grep -q Usage"
summary
