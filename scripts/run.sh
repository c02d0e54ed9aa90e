#!/usr/bin/env bash
# Installs what is missing, builds, then starts the editor when there is a display; without one it
# bakes samples/dam_break.json into cache/dam_break headless and shows the bake's progress line.
# Running it again on an existing bake resumes it instead of starting over. Extra arguments go to
# the editor or to the bake.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

bash scripts/deps.sh

# Build only the program about to run: quicker, and it does not wait on the test suite.
if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
    bash scripts/build.sh airtrap
    # With no arguments the dam-break sample opens, so there is something to look at and bake.
    if [[ $# -eq 0 ]]; then
        set -- samples/dam_break.json
    fi
    exec build/bin/airtrap "$@"
fi

bash scripts/build.sh airtrap-cli
echo "run: no display, baking samples/dam_break.json into cache/dam_break"
bake=(build/bin/airtrap-cli bake samples/dam_break.json --out cache/dam_break)
if [[ -f cache/dam_break/manifest.json ]]; then
    # A previous run left a bake here: continue it rather than refuse to overwrite it.
    bake+=(--resume)
fi
exec "${bake[@]}" "$@"
