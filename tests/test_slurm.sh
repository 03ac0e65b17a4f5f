#!/bin/bash
# SCHED=slurm on a real single-node Slurm that this test starts (munged, slurmctld, slurmd from
# Debian slurm-wlm and munge: scripts/install-deps.sh --cluster) in a scratch folder, on ports
# of its own, and stops at the end.  A made-up experiment of three short runs: scripts/slurm-sweep
# submits them as one job array and waits; afterwards make has no run left to make and finishes
# the figure, whose results equal those of a plain local make; a second sweep submits nothing;
# a sweep whose run fails fails.  The top Makefile's `make <figure> SCHED=slurm` calls the sweep.
# Without the Slurm daemons installed the test says so and checks only the last point.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
. "$(dirname "$0")/checks.sh"

check "make fig3_2 SCHED=slurm sweeps with Slurm first, then makes the figure" \
  bash -c "make -s -n -C '$top' fig3_2 SCHED=slurm 2> /dev/null | grep -q 'scripts/slurm-sweep experiments/fig3_2 PROFILE=quick'"
check "without SCHED nothing of Slurm" \
  bash -c "! make -s -n -C '$top' fig3_2 2> /dev/null | grep -q slurm-sweep"

for c in munged slurmctld slurmd sbatch sinfo scontrol; do
  if ! command -v $c > /dev/null; then
    echo "# Slurm not installed (scripts/install-deps.sh --cluster): the job-array checks are not run"
    summary
    exit $?
  fi
done

# ---- a single-node Slurm of our own ----
S=$tmp/slurm
mkdir -p "$S"/{etc,spool,state,log,run,munge}
chmod 700 "$S/munge"
dd if=/dev/urandom bs=1 count=1024 of="$S/munge/munge.key" 2> /dev/null
chmod 400 "$S/munge/munge.key"
sock=$S/munge/munge.socket.2
munged -f --key-file="$S/munge/munge.key" --socket="$sock" --pid-file="$S/munge/munged.pid" \
  --log-file="$S/munge/munged.log" --seed-file="$S/munge/munged.seed"
port=$((20000 + RANDOM % 20000))
host=$(hostname)
cat > "$S/etc/slurm.conf" <<EOF
ClusterName=wetgran-test
SlurmctldHost=$host
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
AuthInfo=socket=$sock
CredType=cred/munge
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$S/state
SlurmdSpoolDir=$S/spool
SlurmctldPidFile=$S/run/slurmctld.pid
SlurmdPidFile=$S/run/slurmd.pid
SlurmctldLogFile=$S/log/slurmctld.log
SlurmdLogFile=$S/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=wgtest Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$S/etc/slurm.conf
stop_slurm() {
  scontrol shutdown > /dev/null 2>&1
  sleep 1
  for p in "$S/run/slurmd.pid" "$S/run/slurmctld.pid" "$S/munge/munged.pid"; do
    [ -s "$p" ] && kill "$(cat "$p")" 2> /dev/null
  done
}
trap 'stop_slurm; rm -rf "$tmp"' EXIT
slurmctld -f "$SLURM_CONF" && slurmd -f "$SLURM_CONF"
up=0
for i in $(seq 30); do
  sinfo -h -o %T 2> /dev/null | grep -q idle && { up=1; break; }
  sleep 1
done
check "a single-node Slurm of our own is up (sinfo: idle)" test $up = 1
[ $up = 1 ] || { tail -n 5 "$S/log/slurmctld.log" "$S/log/slurmd.log"; summary; exit 1; }

# ---- a made-up experiment of three short runs ----
mkexp() { # mkexp DIR [extra run args]
  mkdir -p "$1"
  echo "seeds = 1 2 3" > "$1/quick.conf"
  cat > "$1/Makefile" <<MK
include $top/experiments/common.mk
SEEDS := \$(call conf,seeds)
RUNS := \$(foreach s,\$(SEEDS),\$(RUNDIR)/seed\$(s).h5)
runs: \$(RUNS)
.PHONY: runs
\$(RUNDIR)/seed%.h5: \$(CONF) \$(ENGINE) | \$(RUNDIR)
	\$(WGRUN) \$(SCENES)/shake2d.ini n=100 lx=40 t_end=5 profile_start=0 dt_checkpoint=0 seed=\$* ${2:-} -o \$@
\$(OUT)/results.tsv: \$(RUNS) | \$(OUT)
	for r in \$(RUNS); do \$(BIN)/wetgran-series \$\$r temperature | tail -n 1; done > \$@
\$(FIGURE): \$(OUT)/results.tsv | \$(FIGDIR)
	cp \$< \$@
MK
}
# the committed engine version stands for bin/wetgran-run.version, which `make test` does not make
eng="ENGINE=$top/sim/ENGINE_VERSION"
mkexp "$tmp/local"
mkexp "$tmp/ex"
make -s -C "$tmp/local" FIGDIR="$tmp/fig" "$eng" > /dev/null 2>&1
check "before the sweep make has three runs to make" \
  test "$(make -n -C "$tmp/ex" FIGDIR="$tmp/fig" "$eng" 2> /dev/null | grep -c scripts/record)" -eq 3
"$top/scripts/slurm-sweep" "$tmp/ex" FIGDIR="$tmp/fig" "$eng" > "$tmp/sweep.out" 2>&1; rc=$?
logs=$(ls "$tmp"/ex/out/slurm/*/task-*.log 2> /dev/null | wc -l)
check "the sweep ran the three runs as one job array (exit $rc, $logs task logs)" \
  bash -c "[ $rc -eq 0 ] && [ $logs -eq 3 ] && grep -q '3 runs as one job array' '$tmp/sweep.out'"
check "every task ran on the Slurm node and its run ended" \
  bash -c "[ \$(grep -l '^summary: events=' '$tmp'/ex/out/slurm/*/task-*.log | wc -l) -eq 3 ]"
check "afterwards make has no run left to make" \
  bash -c "! make -n -C '$tmp/ex' FIGDIR='$tmp/fig' '$eng' 2> /dev/null | grep -q scripts/record"
make -s -C "$tmp/ex" FIGDIR="$tmp/fig" "$eng" > /dev/null 2>&1
check "make finishes the figure; its results equal a local make's" \
  cmp -s "$tmp/ex/out/quick/results.tsv" "$tmp/local/out/quick/results.tsv"
"$top/scripts/slurm-sweep" "$tmp/ex" FIGDIR="$tmp/fig" "$eng" > "$tmp/sweep2.out" 2>&1
check "a second sweep submits nothing" grep -q 'no run to make' "$tmp/sweep2.out"
mkexp "$tmp/bad" "gama=15"
"$top/scripts/slurm-sweep" "$tmp/bad" FIGDIR="$tmp/fig" "$eng" > "$tmp/sweep3.out" 2>&1; rc=$?
check "a sweep whose runs fail fails (exit $rc) and says where the logs are" \
  bash -c "[ $rc -ne 0 ] && grep -q 'job array failed' '$tmp/sweep3.out'"
summary
