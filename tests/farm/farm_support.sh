# Sourced by the farm tests (label farm), run by ctest as  TEST.sh SCRIPTS_DIR WORK_DIR CLI
# Starts the one-node cluster of scripts/slurm-local.sh in WORK_DIR/cluster and stops it on exit;
# exits 77 (skipped) where a cluster cannot start: not root, or Slurm not installed.
set -euo pipefail
scripts="$1"
work="$2"
cli="$3"
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
    echo "FAIL: $*"
    exit 1
}

start_cluster() {
    local status=0 started
    started="$("$scripts/slurm-local.sh" start "$work/cluster")" || status=$?
    [[ $status -eq 77 ]] && exit 77
    [[ $status -eq 0 ]] || fail "the cluster did not start (exit $status); logs in $work/cluster/log"
    trap '"$scripts/slurm-local.sh" stop "$work/cluster"' EXIT
    eval "$started"
}

# A scene of a few hundred particles, with bubbles, that bakes `end` frames in about `end`/10 s
# per core at spacing 0.02 (0.04: a few frames per hundredth of a second).
write_scene() {
    local path="$1" end="$2" spacing="$3"
    cat >"$path" <<SCENE
{
    "format_version": 1,
    "name": "Farm test",
    "solver": {"particle_spacing": $spacing, "max_speed": 3.5},
    "frames": {"fps": 60.0, "end_frame": $end},
    "container": {"min": [0, 0, 0], "max": [0.3, 0.3, 0.3], "headroom": 0.2},
    "fluid_blocks": [{"name": "Water", "min": [0, 0, 0], "max": [0.2, 0.2, 0.2]}],
    "bubbles": {"enabled": true}
}
SCENE
}

# json FILE EXPRESSION: the Python expression evaluated with `d` the file's JSON.
json() {
    python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}

# The job ids of a submission, from its wedges.json.
job_ids() {
    json "$1/wedges.json" '",".join([j["id"] for w in d["wedges"] for j in w["jobs"]] + [j["id"] for j in d["final_jobs"]])'
}

# The states of the jobs and array tasks $1 (comma-separated ids) that have not ended yet; Slurm
# lists ended jobs for MinJobAge (300 s) after their end.
unfinished() {
    squeue -h -t all -j "$1" -o '%T %r' 2>/dev/null |
        grep -vE '^(COMPLETED|FAILED|CANCELLED|TIMEOUT|OUT_OF_MEMORY|NODE_FAIL|BOOT_FAIL|DEADLINE) ' || true
}

# Waits until every job of the submission in $1 has ended (at most $2 seconds).
wait_for_jobs() {
    local dir="$1" limit="$2" ids
    ids="$(job_ids "$dir")"
    for _ in $(seq $((limit * 2))); do
        [[ -z "$(unfinished "$ids")" ]] && return 0
        sleep 0.5
    done
    fail "jobs of $dir still queued after $limit s: $(squeue)"
}

# The state CRC-32 of frame $2 of the cache $1 (airtrap-cli info --json), timings aside.
state_of() {
    "$cli" info "$1" --frame "$2" --json | python3 -c 'import json, sys; print(json.load(sys.stdin)["state_crc32"])'
}
