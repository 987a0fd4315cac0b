#!/usr/bin/env bash
# Shared set-up for scripts/demo.sh and scripts/test.sh: installs missing Debian packages (when
# root), configures and builds Release into build/. Source it; it defines IVIS_BUILD.
set -euo pipefail

IVIS_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
IVIS_BUILD=${IVIS_BUILD:-$IVIS_ROOT/build}
IVIS_PACKAGES=(
  build-essential cmake ccache pkg-config
  libopenvdb-dev libboost-iostreams-dev libtbb-dev libopenmesh-dev libopenexr-dev
  libglm-dev libpng-dev libfreetype-dev fonts-dejavu-core nlohmann-json3-dev libcli11-dev libgtest-dev libembree-dev libpugixml-dev zlib1g-dev
  libglfw3-dev libepoxy-dev libimgui-dev xvfb libgl1-mesa-dri xauth
  python3-dev pybind11-dev python3-numpy python3-pytest
  ffmpeg  # for the tests only: the MP4 of a rendered series (the tool runs without it)
)

# scripts/fuzz.sh needs these too (clang and its libFuzzer and sanitizer runtimes).
IVIS_FUZZ_PACKAGES=(clang libclang-rt-14-dev)

# The packages named in the arguments (default IVIS_PACKAGES) that are not installed.
ivis_missing_packages() {
  local missing=() wanted=("$@")
  [ ${#wanted[@]} -eq 0 ] && wanted=("${IVIS_PACKAGES[@]}")
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  echo "${missing[@]:-}"
}

# Installs the packages named in the arguments (default IVIS_PACKAGES) that are missing.
ivis_install_packages() {
  local missing
  missing=$(ivis_missing_packages "$@")
  [ -z "$missing" ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "inversevis: missing Debian packages: $missing" >&2
    echo "inversevis: install them with: sudo apt-get install $missing" >&2
    exit 1
  fi
  echo "inversevis: installing $missing" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  # shellcheck disable=SC2086
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
}

# Configures build/ (cmake arguments in "$@") and builds it: every target, or only the targets
# named in IVIS_TARGETS (space-separated).
ivis_build() {
  local jobs targets=()
  jobs=$(nproc 2>/dev/null || echo 2)
  cmake -S "$IVIS_ROOT" -B "$IVIS_BUILD" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  for t in ${IVIS_TARGETS:-}; do targets+=(--target "$t"); done
  cmake --build "$IVIS_BUILD" -j "$jobs" "${targets[@]}"
}

# Sets SHARED (the shared meshes: $1, else ../shared/meshes) and WIDER (the wider test set: $2,
# else ../test-meshes, fetched by scripts/test_meshes.sh when missing), each an absolute path.
ivis_mesh_folders() {
  SHARED=$(cd "${1:-$IVIS_ROOT/../shared/meshes}" && pwd)
  WIDER=${2:-$IVIS_ROOT/../test-meshes}
  [ -f "$WIDER/MANIFEST.md" ] || "$IVIS_ROOT/scripts/test_meshes.sh" "$WIDER"
  WIDER=$(cd "$WIDER" && pwd)
}

ivis_install_packages
