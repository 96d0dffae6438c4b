#!/usr/bin/env bash
# A one-node Slurm cluster from Debian 12's packages (slurmctld, slurmd, munge), for the tests of
# `--executor slurm`: everything (the munge key and socket, slurm.conf, state, spool, logs) lives
# in DIR, nothing under /etc or /var is touched, and `stop` ends what `start` began.
#   scripts/slurm-cluster.sh start DIR   installs the packages if needed, starts munged,
#                                        slurmctld and slurmd, waits for the node to be idle,
#                                        and prints `export SLURM_CONF=DIR/slurm.conf`
#   scripts/slurm-cluster.sh stop DIR
# What it proves and does not: docs/simulator.md, "Sweeps on a cluster".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cmd=${1:?usage: slurm-cluster.sh start|stop DIR}
dir=$(mkdir -p "${2:?usage: slurm-cluster.sh start|stop DIR}" && cd "$2" && pwd)

stop() {
  # The PIDs first: a daemon removes its own PID file as it begins to shut down.
  local pids=() p pid
  for p in slurmd slurmctld munged; do
    pid=$(cat "$dir/$p.pid" 2>/dev/null || true)
    [ -n "$pid" ] && kill "$pid" 2>/dev/null && pids+=("$pid")
    rm -f "$dir/$p.pid"
  done
  for pid in "${pids[@]}"; do
    for _ in $(seq 100); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  done
}

if [ "$cmd" = stop ]; then
  stop
  exit 0
fi
[ "$cmd" = start ] || { echo "slurm-cluster: unknown command '$cmd' (start or stop)" >&2; exit 2; }
[ "$(id -u)" -eq 0 ] || { echo "slurm-cluster: the daemons run as root here (SlurmUser=root)" >&2; exit 2; }
"$root/scripts/apt-install.sh" slurm-cluster slurmctld slurmd munge slurm-client >&2
stop
mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/logs"
chmod 700 "$dir/munge"
[ -s "$dir/munge/munge.key" ] || mungekey --create --keyfile="$dir/munge/munge.key" >&2
chmod 600 "$dir/munge/munge.key"
munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
  --pid-file="$dir/munged.pid" --log-file="$dir/logs/munged.log" \
  --seed-file="$dir/munge/munge.seed" >&2
host=$(hostname -s)
cpus=$(nproc)
mem_mb=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 1024))
# Ports away from the standard 6817/6818, so a site's own Slurm is never reached.
cat >"$dir/slurm.conf" <<CONF
ClusterName=planter-test
SlurmctldHost=$host
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/logs/slurmctld.log
SlurmdLogFile=$dir/logs/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
# Batch jobs scheduled when submitted or when a task ends: the default delays them up to 3 s,
# a high-throughput site's setting that made this cluster's short tasks wait about 3 s each.
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MinJobAge=3600
MaxArraySize=100001
NodeName=$host CPUs=$cpus RealMemory=$mem_mb State=UNKNOWN
PartitionName=planter Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -i >&2
slurmd >&2
for _ in $(seq 100); do
  state=$(sinfo -h -n "$host" -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "$state" = idle ] || {
  echo "slurm-cluster: the node did not come up (state '$state'); logs in $dir/logs" >&2
  tail -5 "$dir/logs/"*.log >&2
  exit 1
}
echo "slurm-cluster: one node ($host, $cpus CPUs, $mem_mb MB) idle in partition planter" >&2
echo "export SLURM_CONF=$dir/slurm.conf"
