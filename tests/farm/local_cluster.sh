#!/usr/bin/env bash
# Run by ctest (label farm) as  local_cluster.sh SCRIPTS_DIR WORK_DIR
# The one-node cluster of scripts/slurm-local.sh starts, runs a job and, after it and only after
# it (--dependency=afterok), a two-task array, then stops with no daemon left. Exits 77 (skipped)
# where a cluster cannot start: not root, or Slurm not installed.
set -euo pipefail
scripts="$1"
work="$2"
cluster="$work/cluster"
rm -rf "$work"
mkdir -p "$work"

fail() {
    echo "FAIL: $*"
    exit 1
}

status=0
started="$("$scripts/slurm-local.sh" start "$cluster")" || status=$?
[[ $status -eq 77 ]] && exit 77
[[ $status -eq 0 ]] || fail "the cluster did not start (exit $status); logs in $cluster/log"
trap '"$scripts/slurm-local.sh" stop "$cluster"' EXIT
eval "$started"

cat >"$work/job.sh" <<'JOB'
#!/bin/sh
sleep 1
echo "task ${SLURM_ARRAY_TASK_ID:-first} $(date +%s.%N)"
JOB
first="$(sbatch --parsable -o "$work/first.out" "$work/job.sh")"
array="$(sbatch --parsable --array=1-2 --dependency="afterok:$first" \
    -o "$work/array_%a.out" "$work/job.sh")"
echo "submitted job $first and array $array"
for _ in $(seq 120); do
    [[ -z "$(squeue -h -j "$first,$array" 2>/dev/null)" ]] && break
    sleep 0.5
done
[[ -z "$(squeue -h -j "$first,$array")" ]] || fail "jobs still queued after 60 s: $(squeue)"
for out in first array_1 array_2; do
    [[ -s "$work/$out.out" ]] || fail "$out.out is missing or empty"
done
first_end="$(awk '{print $3}' "$work/first.out")"
for task in 1 2; do
    grep -q "^task $task " "$work/array_$task.out" || fail "array_$task.out: $(cat "$work/array_$task.out")"
    # Each array task prints after its one-second sleep; it must have started after the first
    # job printed.
    task_end="$(awk '{print $3}' "$work/array_$task.out")"
    awk -v a="$first_end" -v b="$task_end" 'BEGIN { exit !(b - a >= 1.0) }' ||
        fail "array task $task ended at $task_end, less than a second after the first job ($first_end)"
done
echo "job, then its dependent array of two, ran on the local cluster"

"$scripts/slurm-local.sh" stop "$cluster"
trap - EXIT
for pidfile in slurmctld.pid slurmd.pid munge/munged.pid; do
    [[ ! -f "$cluster/$pidfile" ]] || fail "$pidfile left after stop"
done
if pgrep -f "$cluster/(slurm.conf|munge)" >/dev/null; then
    fail "a daemon of $cluster is still running: $(pgrep -af "$cluster/")"
fi
echo "PASS"
