#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer and UBSan on) into build-fuzz/ and
# runs one, or each in turn, for SECONDS (docs/TESTING.md "Fuzzing"):
#
#   scripts/fuzz.sh TARGET [SECONDS]   TARGET: scene frame manifest post-results mesh, or all
#
# The build compiles the engine file by file (no unity batches), so it also catches a file that
# forgets an include, which CI relies on. The corpus grows in build-fuzz/fuzz/corpus/TARGET
# between runs; it starts from the seeds: the samples' scenes (scene), the test meshes (mesh),
# and frames, a manifest and post result files written by this build's own writers
# (airtrap-fuzz-seeds). A crash is saved as build-fuzz/fuzz/crashes/TARGET-crash-<hash>; rerun it
# with   build-fuzz/fuzz/airtrap-fuzz-TARGET build-fuzz/fuzz/crashes/TARGET-crash-<hash>
# The exit status is libFuzzer's: 0 when the time ran out with nothing found.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
target="${1:?usage: scripts/fuzz.sh scene|frame|manifest|post-results|mesh|all [SECONDS]}"
seconds="${2:-60}"
all_targets=(scene frame manifest post-results mesh)
case "$target" in
scene | frame | manifest | post-results | mesh) targets=("$target") ;;
all) targets=("${all_targets[@]}") ;;
*)
    echo "fuzz: unknown target '$target' (${all_targets[*]} or all)" >&2
    exit 1
    ;;
esac

bash "$root/scripts/deps.sh"
build="$root/build-fuzz"
options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-16 -DAIRTRAP_FUZZ=ON
    -DAIRTRAP_BUILD_EDITOR=OFF -DAIRTRAP_UNITY_BUILD=OFF)
if [[ ! -f "$build/CMakeCache.txt" ]]; then
    options+=(-G Ninja)
fi
if [[ -n "${CI:-}" ]]; then
    options+=(-DAIRTRAP_WERROR=ON)
fi
cmake -S "$root" -B "$build" "${options[@]}" >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target airtrap-fuzz-seeds airtrap_engine_layers \
    "${targets[@]/#/airtrap-fuzz-}"

fuzz="$build/fuzz"
seeds="$fuzz/seeds"
"$fuzz/airtrap-fuzz-seeds" "$seeds" >/dev/null
mkdir -p "$seeds/scene" "$seeds/mesh" "$fuzz/crashes" "$fuzz/work/meshes"
cp "$root"/samples/*.json "$root"/samples/bench/*.json "$seeds/scene/"
cp "$root"/tests/data/*.obj "$seeds/mesh/"
for mesh in "$root"/samples/meshes/*.obj; do
    cp "$mesh" "$seeds/mesh/sample_$(basename "$mesh")"
done
# Scenes name meshes relative to the working folder: give them the test meshes there.
cp "$root"/tests/data/*.obj "$fuzz/work/"
cp "$root"/samples/meshes/*.obj "$fuzz/work/meshes/"

cd "$fuzz/work"
for one in "${targets[@]}"; do
    mkdir -p "$fuzz/corpus/$one"
    echo "fuzz: $one for $seconds s"
    # One input may take at most 10 s (a scene whose bodies are sampled finely is slow, not
    # stuck) and 2 GB; beyond either is a finding.
    "$fuzz/airtrap-fuzz-$one" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$fuzz/crashes/$one-" \
        "$fuzz/corpus/$one" "$seeds/$one"
done
