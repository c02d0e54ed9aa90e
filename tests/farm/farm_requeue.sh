#!/usr/bin/env bash
# Two bake jobs interrupted mid-bake on a real one-node Slurm: one requeued by the scheduler
# (`scontrol requeue`, as a preemption does), one sent the warning of its time limit
# (`scancel --signal=USR1 --batch`, what --signal=B:USR1@120 sends): the bake stops after its
# step with exit 75 and the job requeues itself. Both run again from their last good frame and
# end with every frame bit-identical in state to an undisturbed local bake.
source "$(dirname "$0")/farm_support.sh"
start_cluster

write_scene scene.json 100 0.02
for how in requeue signal; do
    "$cli" farm submit scene.json --out "$how" --stages bake --threads 1 >/dev/null ||
        fail "submit into $how"
done
requeue_id="$(job_ids requeue)"
signal_id="$(job_ids signal)"

frames_in() { find "$1/base" -name 'frame_*.atf' 2>/dev/null | wc -l; }
for _ in $(seq 600); do
    (($(frames_in requeue) >= 15 && $(frames_in signal) >= 15)) && break
    sleep 0.1
done
echo "interrupting at $(frames_in requeue) and $(frames_in signal) of 100 frames"
(($(frames_in requeue) < 100 && $(frames_in signal) < 100)) ||
    fail "a bake ended before it could be interrupted"
scontrol requeue "$requeue_id"
scancel --signal=USR1 --batch "$signal_id"

# A requeued job may start again only after a delay the controller sets (BeginTime); the test
# lifts it rather than wait two minutes. Right after the requeue (and while the signalled job
# requeues itself) squeue may show the first run's end (CANCELLED) before the job is pending
# again: the wait ends when both jobs look ended and both records hold a run that ended with 0
# (the checks below then say what went wrong if the two minutes run out).
ids="$requeue_id,$signal_id"
both_finished() {
    grep -q '^exit=0$' requeue/farm/records/bake-0.txt 2>/dev/null &&
        grep -q '^exit=0$' signal/farm/records/bake-0.txt 2>/dev/null
}
for _ in $(seq 240); do
    waiting="$(unfinished "$ids")"
    [[ -z "$waiting" ]] && both_finished && break
    if grep -q 'PENDING BeginTime' <<<"$waiting"; then
        for id in "$requeue_id" "$signal_id"; do
            scontrol update JobId="$id" StartTime=now 2>/dev/null || true
        done
    fi
    sleep 0.5
done
[[ -z "$(unfinished "$ids")" ]] || fail "the bakes did not end within 120 s: $(squeue)"
"$cli" farm status requeue
"$cli" farm status signal

for how in requeue signal; do
    id="$(job_ids "$how")"
    restarts="$(scontrol show job "$id" | grep -o 'Restarts=[0-9]*' | cut -d= -f2)"
    [[ "${restarts:-0}" -ge 1 ]] || fail "$how: the job was not requeued (Restarts=${restarts:-?})"
    grep -q '^exit=0$' "$how/farm/records/bake-0.txt" || fail "$how: the last run did not end with exit 0"
    grep -q 'continuing from frame' "$how"/farm/logs/bake-0-*.log ||
        fail "$how: the requeued run did not continue the cache"
done
grep -q 'SIGUSR1' signal/farm/logs/bake-0-*.log || fail "signal: the bake did not see SIGUSR1"

"$cli" bake scene.json --out reference --threads 1 -q >/dev/null 2>&1
# Every fifth frame: each continues all before it, and a frame's state holds its time and step.
for frame in $(seq 5 5 100); do
    expected="$(state_of reference "$frame")"
    for how in requeue signal; do
        [[ "$(state_of "$how/base" "$frame")" == "$expected" ]] ||
            fail "$how: frame $frame differs from the undisturbed bake"
    done
done
echo "both interrupted bakes equal the undisturbed bake in every fifth frame up to 100"
