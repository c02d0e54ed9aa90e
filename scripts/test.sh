#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test. All of ctest runs inside a virtual X server
# because the GUI tests need a real OpenGL context: the offscreen platform crashes QOpenGLWidget.
#
#   scripts/test.sh [ctest options]
#   scripts/test.sh --sanitize address,undefined [ctest options]
#   scripts/test.sh --sanitize thread [ctest options]
#
# --sanitize builds everything with clang and those sanitizers into build-sanitize-<names>/
# (docs/TESTING.md "Sanitizers") and runs the tests they are for: address,undefined the unit,
# physics and cli tests; thread the tests of the code that runs threads (the bake and render
# controllers, the frame loader, post on two threads stopped and failing) and its own check that
# a race in a loop is reported. Any report fails the test that caused it.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sanitize=""
if [[ "${1:-}" == "--sanitize" ]]; then
    sanitize="${2:?--sanitize needs a list: address,undefined or thread}"
    shift 2
fi

bash "$root/scripts/deps.sh"

export QT_QPA_PLATFORM=xcb
# Mesa's software rasteriser: the same OpenGL 3.3 core on every machine, with or without a GPU.
export LIBGL_ALWAYS_SOFTWARE=1

if [[ -z "$sanitize" ]]; then
    bash "$root/scripts/build.sh"
    # ctest exits non-zero when any test fails; set -e passes that on.
    xvfb-run -a -s "-screen 0 1280x1024x24" \
        ctest --test-dir "$root/build" --output-on-failure -j 2 "$@"
    exit 0
fi

build="$root/build-sanitize-${sanitize//,/-}"
options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-16
    "-DAIRTRAP_SANITIZE=$sanitize")
if [[ ! -f "$build/CMakeCache.txt" ]]; then
    options+=(-G Ninja)
fi
if [[ -n "${CI:-}" ]]; then
    options+=(-DAIRTRAP_WERROR=ON)
fi
cmake -S "$root" -B "$build" "${options[@]}"
cmake --build "$build" --parallel "$(nproc)"

suppressions="$root/tests/sanitizers"
# The sanitizers find llvm-symbolizer on the PATH, where Debian's link names LLVM 14's.
export PATH="/usr/lib/llvm-16/bin:$PATH"
# allocator_may_return_null: an allocation too large to make throws std::bad_alloc, as it does
# without ASan, instead of stopping the process (a damaged VDB file read on its own, with no
# checksum of ours in front of it, makes OpenVDB ask for terabytes; docs/TESTING.md).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:allocator_may_return_null=1"
export LSAN_OPTIONS="suppressions=$suppressions/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# ignore_noninstrumented_modules: memory functions (malloc, free, memcpy) called from libraries
# built without TSan (Qt, oneTBB, OpenVDB) are not checked as accesses; their locks still order.
export TSAN_OPTIONS="suppressions=$suppressions/tsan.supp:halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1"
if [[ "$sanitize" == *thread* ]]; then
    selection=(-R "^(TestSimulationController|TestRenderOutputController|TestRenderSession|TestFrameLoader|TestPostThreads|TestPostStore|TsanSeesARaceInALoop)$")
else
    selection=(-L "^(unit|physics|cli)$")
fi
xvfb-run -a -s "-screen 0 1280x1024x24" \
    ctest --test-dir "$build" --output-on-failure -j 2 "${selection[@]}" "$@"
