#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test. All of ctest runs inside a virtual X server
# because the GUI tests need a real OpenGL context: the offscreen platform crashes QOpenGLWidget.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

bash "$root/scripts/deps.sh"
bash "$root/scripts/build.sh"

export QT_QPA_PLATFORM=xcb
# Mesa's software rasteriser: the same OpenGL 3.3 core on every machine, with or without a GPU.
export LIBGL_ALWAYS_SOFTWARE=1
# ctest exits non-zero when any test fails; set -e passes that on.
xvfb-run -a -s "-screen 0 1280x1024x24" \
    ctest --test-dir "$root/build" --output-on-failure -j 2 "$@"
