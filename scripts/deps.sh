#!/usr/bin/env bash
# Installs the Debian 12 packages Airtrap needs to build, run and test. Only missing packages are
# installed, so a second run is a quick no-op that never touches the network.
set -euo pipefail

packages=(
    # toolchain
    cmake g++ make ninja-build pkg-config
    # engine
    libeigen3-dev libtbb-dev libopenvdb-dev libboost-iostreams-dev zlib1g-dev libassimp-dev
    nlohmann-json3-dev libcli11-dev
    # editor
    qt6-base-dev libqt6opengl6-dev libgl-dev
    # GUI tests without a screen: virtual X server and Mesa's software OpenGL
    xvfb xauth libgl1-mesa-dri
    # fuzzing and sanitizer builds (scripts/fuzz.sh, test.sh --sanitize): clang with libFuzzer
    # and the sanitizers' runtimes, and LLVM 16's symbolizer for readable reports (Debian's
    # llvm-symbolizer link points at LLVM 14)
    clang-16 libclang-rt-16-dev llvm-16
    # the Blender add-on's tests (tools/blender, label blender): Blender 3.4, run headless
    blender
    # the farm's tests (label farm): a one-node Slurm cluster (scripts/slurm-local.sh), and
    # Python to read the JSON the farm writes
    slurm-wlm slurm-client munge python3
)

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    if [[ "$status" != "install ok installed" ]]; then
        missing+=("$package")
    fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
    echo "deps: all ${#packages[@]} packages already installed, nothing to do"
    exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
    if ! command -v sudo >/dev/null; then
        echo "deps: missing ${missing[*]}; run as root or install sudo" >&2
        exit 1
    fi
    sudo=(sudo)
fi

# env rather than export: sudo drops the caller's environment.
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "deps: installed ${#missing[@]} missing packages: ${missing[*]}"
