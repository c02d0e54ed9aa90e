#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, everything in one scratch folder: its own munge key and
# socket, slurm.conf, state, spool and logs; nothing outside the folder changes and `stop` leaves
# no daemon behind. For the farm tests (label farm) and for trying `airtrap-cli farm` by hand:
#
#   scripts/slurm-local.sh start DIR    starts munged, slurmctld and slurmd; prints the SLURM_CONF
#                                       line to export before sbatch, squeue, sacct and scancel
#   scripts/slurm-local.sh stop DIR     stops them
#
# Needs root (the daemons run as SlurmUser=root) and Debian's slurm-wlm, slurm-client and munge
# (scripts/deps.sh). Exits 77, the tests' "skipped", when either is missing.
set -euo pipefail

usage() {
    echo "usage: $0 start|stop DIR" >&2
    exit 2
}
[[ $# -eq 2 ]] || usage
action="$1"
mkdir -p "$2"
dir="$(cd "$2" && pwd)"
conf="$dir/slurm.conf"
socket="$dir/munge/munge.socket"

skip() {
    echo "slurm-local: $1" >&2
    exit 77
}

write_config() {
    local host ports
    host="$(hostname -s)"
    # Ports from the folder's name, so that clusters in two folders do not meet.
    ports=$((20000 + $(printf '%s' "$dir" | cksum | cut -d' ' -f1) % 20000 * 2))
    cat >"$conf" <<EOF
# A one-node cluster for Airtrap's farm tests (scripts/slurm-local.sh); accounting is off.
ClusterName=airtrap-local
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
SlurmctldPort=$ports
SlurmdPort=$((ports + 1))
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
# Jobs start as soon as what they wait for ends: a test waits for chains of short jobs.
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0,bf_interval=1
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=main Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
}

start_munge() {
    mkdir -p "$dir/munge" "$dir/log"
    chmod 700 "$dir/munge"
    if [[ ! -f "$dir/munge/munge.key" ]]; then
        head -c 1024 /dev/urandom >"$dir/munge/munge.key"
        chmod 400 "$dir/munge/munge.key"
    fi
    munged --force --socket="$socket" --key-file="$dir/munge/munge.key" \
        --log-file="$dir/log/munged.log" --pid-file="$dir/munge/munged.pid" \
        --seed-file="$dir/munge/munged.seed"
}

wait_for_idle_node() {
    local state
    for _ in $(seq 60); do
        state="$(SLURM_CONF="$conf" sinfo -h -o %T 2>/dev/null || true)"
        if [[ "$state" == idle* || "$state" == mixed* || "$state" == allocated* ]]; then
            return 0
        fi
        sleep 0.5
    done
    echo "slurm-local: the node did not come up (state '${state}'); logs in $dir/log" >&2
    return 1
}

start() {
    [[ $(id -u) -eq 0 ]] || skip "needs root: the daemons run as SlurmUser=root"
    for tool in munged slurmctld slurmd sbatch sinfo scontrol; do
        command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/deps.sh installs it)"
    done
    stop_daemons
    mkdir -p "$dir/state" "$dir/spool" "$dir/log"
    write_config
    start_munge
    # -c: a fresh cluster, no jobs from an earlier run of this folder.
    slurmctld -c -f "$conf"
    slurmd -f "$conf"
    wait_for_idle_node
    echo "export SLURM_CONF=$conf"
}

# Waits up to 10 s for the process in pid file $1 to end, then kills it.
end_process() {
    local pid
    [[ -f "$1" ]] || return 0
    pid="$(cat "$1")"
    for _ in $(seq 20); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.5
    done
    kill -9 "$pid" 2>/dev/null || true
    rm -f "$1"
}

stop_daemons() {
    if [[ -f "$conf" && -f "$dir/slurmctld.pid" ]]; then
        SLURM_CONF="$conf" scontrol shutdown 2>/dev/null || true
    fi
    end_process "$dir/slurmd.pid"
    end_process "$dir/slurmctld.pid"
    if [[ -f "$dir/munge/munged.pid" ]]; then
        munged --stop --socket="$socket" 2>/dev/null || true
        end_process "$dir/munge/munged.pid"
    fi
}

case "$action" in
start) start ;;
stop) stop_daemons ;;
*) usage ;;
esac
