#!/usr/bin/env bash
# A 2×2 wedge of a tiny scene through bake → post → export on a real one-node Slurm: every job
# ends COMPLETED, each wedge's last frame equals a local bake of the same values, the post and
# export jobs of a wedge start only after the jobs they wait for have ended, export.json and
# post.json list every frame once the last jobs ran, and a wedged string full of shell syntax
# reaches Airtrap as literal text (no file `pwned` appears; the manifest holds the text).
source "$(dirname "$0")/farm_support.sh"
start_cluster

write_scene scene.json 12 0.04
# The contact sheet needs the editor beside airtrap-cli (built unless AIRTRAP_BUILD_EDITOR=OFF).
sheet=()
[[ -x "$(dirname "$cli")/airtrap" ]] && sheet=(--contact-sheet 12)
nasty=$'$(touch pwned) `touch pwned` \'quoted\' "double"\nsecond line'
"$cli" farm submit scene.json --out out --threads 1 --chunk 5 --export obj,ply \
    --wedge solver.viscosity_alpha=0.05 --wedge solver.viscosity_alpha=0.2 \
    --wedge "name=Tank" --wedge "name=$nasty" "${sheet[@]}" >submit.txt || fail "submit: $(cat submit.txt)"
cat submit.txt
[[ "$(json out/wedges.json 'len(d["wedges"])')" == 4 ]] || fail "wedges.json lists not 4 wedges"
wait_for_jobs out 150
"$cli" farm status out
"$cli" farm status out --json >status.json

python3 - status.json <<'CHECK' || fail "a job did not complete, or ran before what it waits for"
import json, sys
status = json.load(open(sys.argv[1]))
for wedge in status["wedges"]:
    ended = {}
    for job in wedge["jobs"]:
        tasks = job.get("tasks", [job])
        for task in tasks:
            assert task["state"] == "COMPLETED", (wedge["name"], job["stage"], task)
        ended[job["stage"]] = max(float(t["ended"]) for t in tasks)
        started = min(float(t["started"]) for t in tasks)
        before = {"post": "bake", "post-merge": "post", "export": "post-merge",
                  "export-listing": "export"}.get(job["stage"])
        assert before is None or started >= ended[before], (wedge["name"], job["stage"])
    assert wedge["frames_cached"] == 12, wedge
for job in status["final_jobs"]:
    assert job["state"] == "COMPLETED", job
    last = max(float(t["ended"]) for w in status["wedges"] for j in w["jobs"]
               for t in j.get("tasks", [j]))
    assert float(job["started"]) >= last, "the contact sheet started before the last wedge job ended"
print("every job completed, each after the jobs it waits for")
CHECK

for index in 0 1 2 3; do
    folder="$(json out/wedges.json "d['wedges'][$index]['folder']")"
    # NUL-separated: a value may hold a newline.
    mapfile -d '' -t sets < <(python3 -c 'import json, sys
w = json.load(open("out/wedges.json"))["wedges"][int(sys.argv[1])]
sys.stdout.write("".join("--set\0" + k + "=" + v + "\0" for k, v in zip(w["keys"], w["values"])))' "$index")
    "$cli" bake scene.json --out "local$index" --threads 1 -q "${sets[@]}" >/dev/null 2>&1
    [[ "$(state_of "$folder" 12)" == "$(state_of "local$index" 12)" ]] ||
        fail "wedge $index: frame 12 differs from a local bake with ${sets[*]}"
    [[ "$(json "$folder/export/export.json" 'd["sequences"]["water.obj"]["frames"]')" == "$(seq -s ', ' 1 12 | sed 's/^/[/; s/$/]/')" ]] ||
        fail "wedge $index: export.json does not list water.obj frames 1–12"
    [[ "$(json "$folder/post/post.json" 'len(d["frames"])')" == 12 ]] ||
        fail "wedge $index: post.json does not list 12 frames"
    [[ ! -e "$folder/post/parts" ]] || fail "wedge $index: the post part lists were not merged"
done
echo "each wedge's frame 12 equals a local bake of its values; post.json and export.json are whole"

# The jobs run in the submitting folder ($work); a shell would have made the file there, or at /.
if [[ -e /pwned ]] || find "$work" -name pwned | grep -q .; then
    fail "a wedged value was run by the shell"
fi
found=0
for folder in out/*/; do
    [[ -f "$folder/manifest.json" ]] || continue
    if [[ "$(json "$folder/manifest.json" 'd["scene"]["name"]')" == "$nasty" ]]; then
        found=1
    fi
done
[[ $found == 1 ]] || fail "no wedge's manifest holds the wedged name as literal text"
echo "the wedged name with \$(…), backquotes, quotes and a newline reached Airtrap as text"

if ((${#sheet[@]})); then
    size="$(python3 -c 'import struct, sys; d = open(sys.argv[1], "rb").read(24); print(*struct.unpack(">II", d[16:24]))' out/contact_sheet.png)"
    # Four tiles of 640 × 360 in two rows, each above a 34-pixel label, with 6-pixel gaps.
    [[ "$size" == "1298 806" ]] || fail "contact_sheet.png is $size, not 1298 806"
    for picture in out/farm/sheet/*.png; do
        [[ $(stat -c %s "$picture") -gt 10000 ]] || fail "$picture is (nearly) empty"
    done
    echo "contact_sheet.png tiles the four wedges' frame 12"
fi
