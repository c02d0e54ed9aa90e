#!/usr/bin/env bash
# Configures and builds Airtrap (Release) into build/, executables in build/bin. Installs nothing:
# run.sh and test.sh call deps.sh first. With CI set, warnings are errors. Arguments name the
# targets to build (default: everything, tests included).
#
#   --no-unity   build file by file into build-nounity/ instead: a unity build compiles several
#                sources as one, so a file that forgets an include still compiles there; this
#                one catches it.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
options=(-DCMAKE_BUILD_TYPE=Release)
if [[ "${1:-}" == "--no-unity" ]]; then
    shift
    build="$root/build-nounity"
    options+=(-DAIRTRAP_UNITY_BUILD=OFF)
fi

# Ninja schedules every target's files in one queue, so the tests compile while the engine's
# longest files finish. A build folder keeps the generator it was made with.
if [[ ! -f "$build/CMakeCache.txt" ]]; then
    options+=(-G Ninja)
fi
if [[ -n "${CI:-}" ]]; then
    options+=(-DAIRTRAP_WERROR=ON)
fi

targets=()
if [[ $# -gt 0 ]]; then
    targets=(--target "$@")
fi

cmake -S "$root" -B "$build" "${options[@]}"
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"
