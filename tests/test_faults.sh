#!/bin/bash
# Faults a week-long sweep meets: runs killed (SIGKILL) at random moments and resumed by the
# same command, a sweep's make killed and started again, and a disk that fills up.
#
# Kill and resume: three runs of the 2D shaker (500 time units) with a checkpoint every 2 time units are killed
# again and again at random moments (0.05-0.6 s after each start, so kills land in the event
# loop, in checkpoint writes and in their renames) and restarted with the same command until
# one completes; at least 50 kills in all.  After every kill the run file is absent or
# complete, and the checkpoint absent or readable; the finished run is byte-identical to an
# uninterrupted one.
#
# A sweep of six runs (a made-up experiment on experiments/common.mk) whose make is killed
# with its runs once two are done: make then has only the others to make, finishes the sweep,
# and leaves the finished runs' files untouched.
#
# Full disk: a run stopped after its first checkpoint is resumed on a small tmpfs that a filler
# has filled: it must fail with a message naming the file and the reason, a non-zero exit,
# and the checkpoint it started from unchanged; with the filler gone the same command
# completes, byte-identical to the uninterrupted run.  Without the right to mount a tmpfs
# the file-size limit (ulimit -f) plays the full disk (WG_FULL_DISK_ULIMIT=1 forces it).
# WG_TEST_SHORT: one run of 300 time units, kills 0.05-0.25 s after each start, at least 8 (the sanitizers' pass).
set -u
run=${WG_BIN:?}/wetgran-run
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"

args="t_end=500 dt_series=1 dt_snapshot=100 profile_start=250 dt_checkpoint=2 --no-volatile -q"
seeds="1 2 3" min_kills=50 window=0.55
if [ -n "${WG_TEST_SHORT:-}" ]; then # the sanitizers' pass: one shorter run, quicker kills
  args="t_end=300 dt_series=1 dt_snapshot=100 profile_start=150 dt_checkpoint=2 --no-volatile -q"
  seeds=1 min_kills=8 window=0.2
fi
RANDOM=4242
kills=0 bad_output=0 bad_ckpt=0
for seed in $seeds; do
  ref=$tmp/ref$seed kr=$tmp/kr$seed
  mkdir -p "$ref" "$kr"
  (cd "$ref" && "$run" "$scenes/shake2d.ini" seed=$seed $args -o run.h5 2> err)
  attempts=0
  while [ ! -e "$kr/run.h5" ] && [ $attempts -lt 200 ]; do
    attempts=$((attempts + 1))
    (cd "$kr" && exec "$run" "$scenes/shake2d.ini" seed=$seed $args -o run.h5 2>> err) &
    pid=$!
    sleep "$(awk -v r=$RANDOM -v w=$window 'BEGIN { printf "%.3f", 0.05 + w * r / 32767 }')"
    if kill -KILL $pid 2> /dev/null; then
      wait $pid 2> /dev/null
      kills=$((kills + 1))
      # the run file appears only complete (renamed from its temporary at the end)
      if [ -e "$kr/run.h5" ] && ! cmp -s "$kr/run.h5" "$ref/run.h5"; then bad_output=$((bad_output + 1)); fi
      if [ -e "$kr/run.h5.ckpt" ] && ! h5ls "$kr/run.h5.ckpt" > /dev/null 2>&1; then bad_ckpt=$((bad_ckpt + 1)); fi
    else
      wait $pid 2> /dev/null
    fi
  done
  check "seed $seed: killed and resumed until complete ($attempts starts): byte-identical to the uninterrupted run" \
    cmp -s "$kr/run.h5" "$ref/run.h5"
  check "seed $seed: no temporary or checkpoint left behind" bash -c "! ls '$kr'/run.h5.* 2> /dev/null | grep -q ."
done
check "at least $min_kills kills in all ($kills)" test $kills -ge $min_kills
check "after every kill the run file was absent or complete ($bad_output incomplete)" test $bad_output -eq 0
check "after every kill the checkpoint was absent or readable ($bad_ckpt unreadable)" test $bad_ckpt -eq 0

# ---- a sweep killed: make finishes it without redoing finished points ----
top=$(cd "$(dirname "$0")/.." && pwd)
ex=$tmp/sweep
mkdir -p "$ex"
echo "seeds = 1 2 3 4 5 6" > "$ex/quick.conf"
cat > "$ex/Makefile" <<MK
include $top/experiments/common.mk
RUNS := \$(foreach s,\$(call conf,seeds),\$(RUNDIR)/seed\$(s).h5)
runs: \$(RUNS)
.PHONY: runs
\$(RUNDIR)/seed%.h5: \$(CONF) \$(ENGINE) | \$(RUNDIR)
	\$(WGRUN) \$(SCENES)/shake2d.ini t_end=40 profile_start=0 dt_checkpoint=5 seed=\$* -o \$@
MK
# the committed engine version stands for bin/wetgran-run.version, which `make test` does not make
eng="ENGINE=$top/sim/ENGINE_VERSION"
(cd "$ex" && exec setsid make -j1 "$eng" runs > /dev/null 2>&1) &
mpid=$!
for i in $(seq 100); do # until two runs are done
  [ "$(ls "$ex"/out/quick/runs/seed*.h5 2> /dev/null | wc -l)" -ge 2 ] && break
  sleep 0.1
done
kill -KILL -- -$mpid 2> /dev/null; wait $mpid 2> /dev/null
done_before=$(ls "$ex"/out/quick/runs/seed*.h5 2> /dev/null | wc -l)
cp -p "$ex"/out/quick/runs/seed*.h5 "$tmp/" 2> /dev/null
todo=$(make -n -C "$ex" "$eng" runs 2> /dev/null | grep -c scripts/record)
check "sweep killed after $done_before of 6 runs: make has only the other $todo to make" \
  test "$done_before" -ge 2 -a "$todo" -eq $((6 - done_before))
make -s -C "$ex" "$eng" runs > /dev/null 2>&1
same=0
for f in "$tmp"/seed*.h5; do cmp -s "$f" "$ex/out/quick/runs/$(basename "$f")" && [ ! "$ex/out/quick/runs/$(basename "$f")" -nt "$f" ] && same=$((same + 1)); done
check "make finishes the sweep ($(ls "$ex"/out/quick/runs/seed*.h5 | wc -l) runs) and leaves the $done_before finished ones as they were ($same)" \
  test "$(ls "$ex"/out/quick/runs/seed*.h5 | wc -l)" -eq 6 -a "$same" -eq "$done_before"

# ---- full disk ----
fd=$tmp/disk
mkdir -p "$fd"
short="t_end=60 dt_series=1 dt_snapshot=20 profile_start=30 dt_checkpoint=10 --no-volatile -q"
(cd "$tmp/ref1" && "$run" "$scenes/shake2d.ini" $short -o short.h5 2> /dev/null)
mode=tmpfs
if [ -n "${WG_FULL_DISK_ULIMIT:-}" ] || ! mount -t tmpfs -o size=3m wgtest "$fd" 2> /dev/null; then mode=ulimit; fi
cleanup_disk() { [ $mode = tmpfs ] && umount "$fd" 2> /dev/null; }
trap 'cleanup_disk; rm -rf "$tmp"' EXIT
echo "# full disk played by: $mode"
(cd "$fd" && "$run" "$scenes/shake2d.ini" $short --abort-after-checkpoint 1 -o short.h5 2> /dev/null)
cp "$fd/short.h5.ckpt" "$tmp/ckpt.before"
if [ $mode = tmpfs ]; then
  dd if=/dev/zero of="$fd/filler" bs=64k 2> /dev/null # until the tmpfs is full
  (cd "$fd" && "$run" "$scenes/shake2d.ini" $short -o short.h5 2> "$tmp/err.full"); rc=$?
else
  # files may not grow beyond 64 kB: the next checkpoint's write fails as on a full disk
  (cd "$fd" && trap '' XFSZ && ulimit -f 64 && "$run" "$scenes/shake2d.ini" $short -o short.h5 2> "$tmp/err.full"); rc=$?
fi
check "full disk: the run fails (exit $rc)" test $rc -ne 0
check "full disk: one message names the file and the reason" \
  grep -qE "short\.h5[^ ]*: .*(No space left on device|File too large)" "$tmp/err.full"
check "full disk: the checkpoint it resumed from is unchanged" cmp -s "$fd/short.h5.ckpt" "$tmp/ckpt.before"
check "full disk: no run file" test ! -e "$fd/short.h5"
rm -f "$fd/filler" "$fd"/short.h5.ckpt.tmp "$fd"/short.h5.tmp
(cd "$fd" && "$run" "$scenes/shake2d.ini" $short -o short.h5 2> /dev/null)
check "space again: the same command completes, byte-identical to the uninterrupted run" \
  cmp -s "$fd/short.h5" "$tmp/ref1/short.h5"
sed 's/^/# /' "$tmp/err.full" | head -n 5
summary
