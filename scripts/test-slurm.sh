#!/usr/bin/env bash
# make test-slurm: a one-node Slurm on this host (munged, slurmctld and slurmd on 127.0.0.1, all
# state in a temporary folder), the ring's fy × ky sweep submitted as a job array over jobs.txt,
# merged, and compared with the same sweep run in-process. Daemons are stopped by their PIDs.
# Usage: scripts/test-slurm.sh PLASTICA_BINARY SOURCE_DIR
set -euo pipefail
plastica=$(realpath "$1")
source_dir=$(realpath "$2")
work=$(mktemp -d /tmp/plastica-slurm.XXXXXX)
chmod 755 "$work" # munged runs as munge and must reach its folder
host=$(hostname -s)
pids=()
cleanup() {
  for f in "$work"/slurmd.pid "$work"/slurmctld.pid; do [ -f "$f" ] && kill "$(cat "$f")" 2>/dev/null || true; done
  [ -f "$work/munged.pid" ] && kill "$(cat "$work/munged.pid")" 2>/dev/null || true
  sleep 0.5
  rm -rf "$work"
}
trap cleanup EXIT

# munged refuses to run as root: as the munge user, with its socket and pid in the work folder.
mkdir -p "$work/munge"
chown munge:munge "$work/munge"
runuser -u munge -- munged --socket="$work/munge/munge.socket" --pid-file="$work/munged.pid" \
  --log-file="$work/munge/munged.log" --seed-file="$work/munge/seed"
export MUNGE_SOCKET="$work/munge/munge.socket"

mkdir -p "$work/state" "$work/spool"
cat > "$work/slurm.conf" <<CONF
ClusterName=plastica
SlurmctldHost=$host(127.0.0.1)
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SchedulerParameters=batch_sched_delay=0
MailProg=/bin/true
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ReturnToService=2
CONF
export SLURM_CONF="$work/slurm.conf"
start=$(date +%s.%N)
slurmctld -D > "$work/slurmctld.out" 2>&1 &
slurmd -D > "$work/slurmd.out" 2>&1 &
for i in $(seq 1 100); do
  if sinfo -h -o %t 2>/dev/null | grep -qx idle; then break; fi
  sleep 0.1
done
sinfo -h -o %t | grep -qx idle || { echo "test-slurm: the node did not come up"; cat "$work"/slurm*.log; exit 1; }
echo "test-slurm: one-node Slurm up in $(echo "$(date +%s.%N) - $start" | bc) s"

scene="$source_dir/models/ring_inelastic.toml"
vary=(--vary 'material[steel].fy=20000,30000,36518' --vary 'foundation[1].ky=600,1200,2400' --at 50,100)
"$plastica" sweep "$scene" "${vary[@]}" -o "$work/in_process" --no-charts > /dev/null
"$plastica" sweep "$scene" "${vary[@]}" -o "$work/slurm" --emit jobs > /dev/null
job=$(sbatch --parsable "$work/slurm/sweep.sbatch")
submitted=$(date +%s.%N)
while squeue -h -j "$job" 2>/dev/null | grep -q .; do sleep 0.2; done
echo "test-slurm: the 9-task array ran in $(echo "$(date +%s.%N) - $submitted" | bc) s"
"$plastica" merge "$work/slurm" --at 50,100 > /dev/null || true
# Identical rows up to the timings (the last column, seconds).
strip() { sed 's/,[^,]*$//' "$1"; }
if diff <(strip "$work/in_process/sweep.csv") <(strip "$work/slurm/sweep.csv"); then
  echo "test-slurm: the Slurm array and the in-process sweep give the same sweep.csv ($(($(wc -l < "$work/slurm/sweep.csv") - 1)) runs)"
else
  echo "test-slurm: sweep.csv differs"; exit 1
fi

# Values a shell would run, and a sweep folder with a space and a quote in its name: each run is
# one line of jobs.txt and one argument vector, so the array runs the values as titles and no
# command of theirs.
hostile="$work/it's a sweep"
marker="$work/injected"
"$plastica" sweep "$scene" --vary "scene.title=\"\$(touch $marker-1)\",\"; touch $marker-2\",\"\`touch $marker-3\`\"" \
  -o "$hostile" --emit jobs > /dev/null
job=$(sbatch --parsable "$hostile/sweep.sbatch")
while squeue -h -j "$job" 2>/dev/null | grep -q .; do sleep 0.2; done
if ls "$marker"-* > /dev/null 2>&1; then
  echo "test-slurm: a sweep value ran as a command"; exit 1
fi
for id in r0001 r0002 r0003; do
  grep -q '"status": "completed"' "$hostile/runs/$id/run.json" || { echo "test-slurm: hostile run $id did not complete"; cat "$hostile/logs/"*; exit 1; }
done
grep -qF '"title": "$(touch' "$hostile/runs/r0001/run.json" || { echo "test-slurm: the title is not the value given"; exit 1; }
echo "test-slurm: values that a shell would run ran as text, from a folder with a space and a quote (3 tasks)"
