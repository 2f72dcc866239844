#!/bin/bash
# A one-node Slurm cluster in a scratch folder runs a study of examples/slurm: a job array of
# slices and the merge that waits for them; the merged results must equal the unsharded run's.
#   tests/slurm/one_node.sh ROTBENCH SLICES RUN_ARGUMENTS...
# Needs root (slurmd launches the jobs) and the Debian packages slurmctld, slurmd,
# slurm-client and munge. No systemd: munged and the daemons run in the foreground, in the
# background of this script, with their keys, sockets, state and logs in the scratch folder
# (the packaged paths are refused as insecure there).
set -euo pipefail
rotbench=$(realpath "$1") slices=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
scratch=$(mktemp -d)
chmod 755 "$scratch"  # munged wants its socket's folder open to all
pids=()
stop() {  # the daemons get 5 s to go after a TERM (slurmd can linger for a minute), then KILL
  SLURM_CONF="$scratch/slurm.conf" scontrol shutdown > /dev/null 2>&1 || true
  for pid in "${pids[@]}"; do kill "$pid" 2> /dev/null || true; done
  for _ in $(seq 50); do
    alive=0
    for pid in "${pids[@]}"; do kill -0 "$pid" 2> /dev/null && alive=1; done
    [ "$alive" = 0 ] && break
    sleep 0.1
  done
  for pid in "${pids[@]}"; do kill -KILL "$pid" 2> /dev/null || true; done
  wait 2> /dev/null || true
  rm -rf "$scratch"
}
trap stop EXIT

mungekey --create --keyfile "$scratch/munge.key"
munged -F --key-file="$scratch/munge.key" --socket="$scratch/munge.socket" --pid-file="$scratch/munged.pid" \
  --seed-file="$scratch/munge.seed" --log-file="$scratch/munged.log" > "$scratch/munged.out" 2>&1 &
pids+=($!)
mkdir -p "$scratch/state" "$scratch/spool"
# Ports apart from the packaged defaults, so a Slurm already on the machine is left alone.
cat > "$scratch/slurm.conf" << CONF
ClusterName=rotbench
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$scratch/munge.socket
CredType=cred/munge
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$scratch/spool
SlurmctldPidFile=$scratch/slurmctld.pid
SlurmdPidFile=$scratch/slurmd.pid
SlurmctldLogFile=$scratch/slurmctld.log
SlurmdLogFile=$scratch/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
NodeName=localhost CPUs=$(nproc) State=UNKNOWN
PartitionName=batch Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$scratch/slurm.conf"
for _ in $(seq 50); do [ -S "$scratch/munge.socket" ] && break; sleep 0.1; done
slurmctld -D -i -f "$SLURM_CONF" > "$scratch/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" > "$scratch/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do sinfo -h -o %t 2> /dev/null | grep -q idle && break; sleep 0.2; done
sinfo -h -o %t | grep -q idle || { tail -20 "$scratch"/*.log "$scratch"/*.out; exit 1; }

read -r array merge < <("$root/examples/slurm/submit.sh" "$rotbench" "$scratch/study" "$slices" "$@")
# Awaited by polling: sacct needs accounting, and a merge whose array failed stays pending.
state=""
for _ in $(seq 3000); do
  state=$(scontrol show job "$merge" | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
  case "$state" in PENDING | RUNNING | CONFIGURING | COMPLETING) ;; *) break ;; esac
  if scontrol show job "$array" | grep -q 'JobState=\(FAILED\|CANCELLED\|TIMEOUT\|NODE_FAIL\)'; then state=array-failed; break; fi
  sleep 0.2
done
if [ "$state" != COMPLETED ]; then
  echo "slurm: the merge job ended $state" >&2
  cat "$scratch/study/logs/"*.txt >&2 || true
  exit 1
fi
"$rotbench" run "$@" --quiet --out "$scratch/whole" > /dev/null
"$root/tests/same_results.py" "$rotbench" "$scratch/whole" "$scratch/study/merged"
echo "slurm: $slices slices (job $array) merged (job $merge) equal the unsharded run"
