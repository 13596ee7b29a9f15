#!/usr/bin/env bash
# The real-Slurm test (CTest `slurm_sweep`, label slurm): starts a single-node Slurm on this
# machine (munged, slurmctld and slurmd from Debian's munge and slurm-wlm; a generated munge key
# and slurm.conf for localhost; every file in a temporary folder; run as the current user),
# runs a 20-point sweep locally and through `mechsim sweep --slurm` (a throttled job array and a
# dependent collect job) with one point crashing, resubmits the failed task alone (--resume),
# checks `mechsim sweep status` and that the collected table equals the local run's (but for the
# measured wall_time column), and stops everything it started.
# Cgroups are not needed: proctrack/linuxproc and task/none track the tasks as plain processes.
# Usage: slurm_sweep_test.sh MECHSIM_EXE SWEEP_FILE
set -euo pipefail
exe=$1
sweep=$2
for tool in munged slurmctld slurmd sbatch squeue sinfo; do
  if ! command -v "$tool" >/dev/null; then
    echo "SKIP: $tool is not installed (scripts/install-deps.sh installs munge and slurm-wlm)"
    exit 77
  fi
done

work=$(mktemp -d /tmp/mechsim_slurm_test.XXXXXX)
chmod 755 "$work"  # munged wants its socket's folder searchable by all
pids=()
cleanup() {
  for f in slurmd slurmctld munged; do
    [[ -f $work/$f.pid ]] && kill "$(cat "$work/$f.pid")" 2>/dev/null || true
  done
  for _ in $(seq 50); do
    alive=0
    for f in slurmd slurmctld munged; do
      [[ -f $work/$f.pid ]] && kill -0 "$(cat "$work/$f.pid")" 2>/dev/null && alive=1
    done
    ((alive)) || break
    sleep 0.1
  done
  for f in slurmd slurmctld munged; do
    [[ -f $work/$f.pid ]] && kill -9 "$(cat "$work/$f.pid")" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  for log in "$work"/log/*.log; do echo "--- $log"; tail -n 20 "$log"; done
  exit 1
}

# Free ports for slurmctld and slurmd, on loopback.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
host=$(hostname -s)
user=$(id -un)
mkdir -p "$work/state" "$work/spool" "$work/log"
head -c 1024 /dev/urandom > "$work/munge.key"
chmod 600 "$work/munge.key"
munged --key-file="$work/munge.key" --socket="$work/munge.sock" --pid-file="$work/munged.pid" \
  --log-file="$work/log/munged.log" --seed-file="$work/munge.seed" --force || fail "munged did not start"

cat > "$work/slurm.conf" <<CONF
ClusterName=mechsimtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$work/munge.sock
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
MaxArraySize=1001
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -f "$SLURM_CONF" -i || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" || fail "slurmd did not start"
for _ in $(seq 150); do
  [[ $(sinfo -h -o %T 2>/dev/null) == idle ]] && break
  sleep 0.2
done
[[ $(sinfo -h -o %T) == idle ]] || fail "the node did not become idle: $(sinfo -h -o '%T %E')"

# The same sweep locally, then on Slurm: 10 array tasks of 2 points, 2 running at once; point 5
# (task 2) crashes there (the test-only fault, passed to the jobs in sbatch's environment).
"$exe" sweep "$sweep" -o "$work/local" -j 2 --no-plots > "$work/local.out" 2>&1 || { cat "$work/local.out"; fail "local sweep"; }
MECHSIM_SWEEP_TEST_FAULT=crash@5 "$exe" sweep "$sweep" -o "$work/slurm" --slurm --array-limit 2 --points-per-task 2 \
  > "$work/submit.out" 2>&1 || { cat "$work/submit.out"; fail "submission"; }
cat "$work/submit.out"
grep -q -- "--array=0-9%2" "$work/submit.out" || fail "expected a 10-task array throttled to 2"
"$exe" sweep status "$work/slurm" > "$work/status.out" 2>&1 || { cat "$work/status.out"; fail "status"; }
grep -q "slurm array job" "$work/status.out" || { cat "$work/status.out"; fail "status names no array job"; }
wait_for_collect() {
  local job
  job=$(sed -n 's/.*collect job \([0-9]*\).*/\1/p' "$1")
  [[ -n $job ]] || fail "no collect job id in $1"
  for _ in $(seq 900); do
    [[ -z $(squeue -h -j "$job" 2>/dev/null) && -f $work/slurm/slurm/logs/collect_$job.out ]] && break
    sleep 0.2
  done
  [[ -z $(squeue -h -j "$job" 2>/dev/null) ]] || fail "collect job $job still queued; squeue: $(squeue -h)"
  [[ -f $work/slurm/slurm/logs/collect_$job.out ]] || fail "collect job $job left no log"
}
wait_for_collect "$work/submit.out"
grep -q "^5,crashed,0," "$work/slurm/results.csv" || fail "point 5 is not recorded as crashed: $(sed -n 7p "$work/slurm/results.csv")"
"$exe" sweep status "$work/slurm" > "$work/status.out" 2>&1
cat "$work/status.out"
grep -q "20 points: 1 crashed" "$work/status.out" || fail "status does not count the crash"
grep -q "array tasks with points crashed, timed out or not run: 2 " "$work/status.out" || fail "status does not name task 2"

# Only the failed task goes again.
"$exe" sweep "$sweep" -o "$work/slurm" --slurm --resume --array-limit 2 --points-per-task 2 > "$work/resubmit.out" 2>&1 ||
  { cat "$work/resubmit.out"; fail "resubmission"; }
cat "$work/resubmit.out"
grep -q -- "--array=2%2" "$work/resubmit.out" || fail "expected task 2 alone"
wait_for_collect "$work/resubmit.out"
"$exe" sweep status "$work/slurm" > "$work/status.out" 2>&1
cat "$work/status.out"
grep -q "20 points: 5 failed, 15 passed" "$work/status.out" || fail "status after the resubmission"

# Tables equal but for the measured column (wall_time: the sweep file's metrics hold no other).
strip() { python3 -c '
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, c in enumerate(rows[0]) if c not in ("wall_time", "real_time_factor")]
for r in rows: print(",".join(r[i] for i in keep))' "$1"; }
strip "$work/local/results.csv" > "$work/local.csv"
strip "$work/slurm/results.csv" > "$work/slurm.csv"
[[ $(wc -l < "$work/local.csv") -eq 21 ]] || fail "the local table has $(wc -l < "$work/local.csv") lines, expected 21"
if ! diff "$work/local.csv" "$work/slurm.csv"; then fail "the Slurm table differs from the local one"; fi
grep -q ",passed,1," "$work/local.csv" || fail "no point passed"
grep -q ",failed,0," "$work/local.csv" || fail "no point failed (0.1 m/s drives too short a distance)"
echo "PASS: 20 points on Slurm ($(ls "$work"/slurm/slurm/logs | wc -l) job logs), table equal to the local run's"
