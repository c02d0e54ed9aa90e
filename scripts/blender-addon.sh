#!/usr/bin/env bash
# Packs the Blender add-on (tools/blender/airtrap_importer, docs/BLENDER.md) into a zip that
# Blender installs from Edit > Preferences > Add-ons > Install:
#
#   scripts/blender-addon.sh [OUT.zip]      (default build/airtrap_importer.zip)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/build/airtrap_importer.zip}"
mkdir -p "$(dirname "$out")"
python3 - "$root/tools/blender" "$out" <<'PY'
import os, sys, zipfile
source, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
    for folder, _, files in os.walk(os.path.join(source, "airtrap_importer")):
        for name in sorted(files):
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                archive.write(path, os.path.relpath(path, source))
print(out)
PY
