#!/usr/bin/env bash
# What farm submit refuses, and what a failure looks like, on a real one-node Slurm: a wedge that
# does not validate or a broken wedge file (refused before anything is written, naming the key and
# value), a dry run kept apart, an output folder holding another submission (unless --overwrite)
# or one whose jobs still run, no sbatch on the PATH,
# a controller that does not answer, sbatch refusing a job halfway (the jobs already queued are
# cancelled), a task that fails (farm status shows it with its log tail, and the job waiting for
# it is cancelled rather than left waiting for ever), and farm cancel stopping a running bake with
# its cache consistent.
source "$(dirname "$0")/farm_support.sh"

write_scene scene.json 12 0.04

expect_exit() {
    local expected="$1" name="$2"
    shift 2
    local status=0
    "$@" >"$name.out" 2>"$name.err" || status=$?
    [[ $status -eq $expected ]] || fail "$name: exit $status, expected $expected: $(cat "$name.err")"
}

expect_exit 2 bad-wedge "$cli" farm submit scene.json --out bad --dry-run \
    --wedge solver.viscosity_alpha=0.1 --wedge solver.viscosity_alpha=7
grep -q 'solver.viscosity_alpha=7' bad-wedge.err && grep -q 'expected a number in \[0, 1\]' bad-wedge.err ||
    fail "bad-wedge: the message names neither key, value nor range: $(cat bad-wedge.err)"
[[ ! -e bad ]] || fail "bad-wedge: the refused submission wrote $(ls bad)"

echo '{"solver.viscosity_alpha": 0.1}' >wedges.json
expect_exit 2 bad-file "$cli" farm submit scene.json --out bad --dry-run --wedge-file wedges.json
grep -q 'wedges.json: "solver.viscosity_alpha": expected an array' bad-file.err ||
    fail "bad-file: $(cat bad-file.err)"

expect_exit 0 dry "$cli" farm submit scene.json --out dry --dry-run --wedge solver.viscosity_alpha=0.1
[[ -s dry/farm/dry-run/submit.sh && -s dry/farm/dry-run/jobs/bake-0.sh ]] ||
    fail "dry: no scripts in dry/farm/dry-run"
[[ ! -e dry/wedges.json ]] || fail "dry: a dry run wrote the submission's wedges.json"

expect_exit 7 no-sbatch env PATH=/nonexistent "$cli" farm submit scene.json --out nosbatch
grep -q 'sbatch is not on the PATH' no-sbatch.err || fail "no-sbatch: $(cat no-sbatch.err)"
[[ "$(wc -l <no-sbatch.err)" -eq 1 ]] || fail "no-sbatch: more than one line: $(cat no-sbatch.err)"
echo "refused: an out-of-range wedge, a wedge file without arrays, no sbatch; a dry run apart"

start_cluster

expect_exit 0 first "$cli" farm submit scene.json --out taken --stages bake --threads 1 \
    --wedge solver.viscosity_alpha=0.1
wait_for_jobs taken 60
expect_exit 2 other "$cli" farm submit scene.json --out taken --stages bake --threads 1 \
    --wedge solver.viscosity_alpha=0.2
grep -q -- '--overwrite' other.err || fail "other: $(cat other.err)"
expect_exit 0 overwrite "$cli" farm submit scene.json --out taken --stages bake --threads 1 \
    --overwrite --wedge solver.viscosity_alpha=0.2
[[ "$(json taken/wedges.json 'd["wedges"][0]["values"]')" == "['0.2']" ]] ||
    fail "overwrite: wedges.json is not the new submission's"
[[ ! -e taken/viscosity_alpha-0.1 ]] || fail "overwrite: the replaced wedge's folder is still there"
wait_for_jobs taken 60
echo "refused: a folder holding another submission, unless --overwrite"

sed 's/^SlurmctldPort=.*/SlurmctldPort=1/' "$SLURM_CONF" >dead.conf
expect_exit 7 dead env SLURM_CONF="$work/dead.conf" "$cli" farm submit scene.json --out dead
grep -q 'Unable to contact slurm controller' dead.err || fail "dead: $(cat dead.err)"

# An sbatch that refuses the third job: the two queued before it are cancelled.
mkdir -p fake
cat >fake/sbatch <<FAKE
#!/bin/bash
count=\$(( \$(cat "$work/fake/count" 2>/dev/null || echo 0) + 1 ))
echo \$count >"$work/fake/count"
if [[ \$count -eq 3 ]]; then
    echo "sbatch: error: Batch job submission failed: refused by the test" >&2
    exit 1
fi
exec $(command -v sbatch) "\$@"
FAKE
chmod +x fake/sbatch
expect_exit 7 halfway env PATH="$work/fake:$PATH" "$cli" farm submit scene.json --out halfway
grep -q 'refused by the test; cancelled the 2 job(s) already queued' halfway.err ||
    fail "halfway: $(cat halfway.err)"
sleep 1
[[ -z "$(squeue -h -t PENDING,RUNNING 2>/dev/null)" ]] || fail "halfway: jobs left queued: $(squeue)"
echo "refused: a controller that does not answer; a submission sbatch refused halfway was cancelled"

# Export without post: every OBJ export task fails (post has made no frame).
"$cli" farm submit scene.json --out failing --threads 1 --chunk 4 --stages bake,export \
    --export obj >/dev/null || fail "submit failing"
for _ in $(seq 120); do
    [[ -z "$(unfinished "$(job_ids failing)")" ]] && break
    sleep 0.5
done
"$cli" farm status failing --lines 3 | tee status.txt
grep -q 'export [0-9]*: 3 FAILED' status.txt || fail "status does not show 3 failed export tasks"
grep -q '| airtrap-cli: .*post' status.txt || fail "status shows no log tail naming post"
"$cli" farm status failing --json >status.json
[[ "$(json status.json 'd["wedges"][0]["jobs"][1]["tasks"][0]["exit"]')" == 2 ]] ||
    fail "status --json gives no exit 2 for the failed task"
[[ "$(json status.json 'd["wedges"][0]["jobs"][2]["state"], d["wedges"][0]["jobs"][2]["reason"]')" == "('CANCELLED', 'DependencyNeverSatisfied')" ]] ||
    fail "the listing job after the failed export is not cancelled for its dependency"
echo "a failed task shows in farm status with its log tail; the job after it is cancelled"

write_scene long.json 100 0.02
"$cli" farm submit long.json --out cancelled --threads 1 --stages bake >/dev/null || fail "submit long"
for _ in $(seq 300); do
    (($(find cancelled/base -name 'frame_*.atf' 2>/dev/null | wc -l) >= 5)) && break
    sleep 0.1
done
expect_exit 2 busy "$cli" farm submit long.json --out cancelled --threads 1 --stages bake
grep -q 'still queued or running' busy.err || fail "busy: $(cat busy.err)"
"$cli" farm cancel cancelled | grep -q 'cancelled the 1 job' || fail "cancel said nothing"
for _ in $(seq 60); do
    [[ -z "$(unfinished "$(job_ids cancelled)")" ]] && break
    sleep 0.5
done
"$cli" farm status cancelled | tee cancelled.txt
grep -q 'bake [0-9]*: CANCELLED' cancelled.txt || fail "the cancelled bake does not show as ended"
grep -q '^exit=130$' cancelled/farm/records/bake-0.txt ||
    fail "the bake did not stop as asked: $(cat cancelled/farm/records/bake-0.txt)"
"$cli" check cancelled/base >/dev/null || fail "the cancelled bake left a damaged cache"
echo "a folder whose bake still runs is refused; farm cancel stopped it after its step, cache whole"
