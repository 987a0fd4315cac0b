#!/usr/bin/env bash
# Builds everything (installing what is missing) and runs the whole test suite with ctest.
#   scripts/test.sh [CTEST ARGS...]              Release build in build/ (what CI runs)
#   scripts/test.sh --sanitize [CTEST ARGS...]   AddressSanitizer + UBSan build in build-sanitize/
set -euo pipefail
SANITIZE=0
if [ "${1:-}" = "--sanitize" ]; then
  SANITIZE=1
  shift
  export IVIS_BUILD=${IVIS_BUILD:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build-sanitize}
fi
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
if [ "$SANITIZE" = 1 ]; then
  # No alignment check: oneTBB's concurrent_hash_map (in OpenVDB's trees) casts tagged pointers.
  ivis_build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIVIS_BUILD_BENCH=OFF \
    -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize=alignment -fno-sanitize-recover=undefined -fno-omit-frame-pointer" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
  # Leaks are checked by default (the viewer alone turns that off: app/viewer/main.cpp).
  export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
else
  ivis_build
fi
shared=${IVIS_SHARED_DIR:-$IVIS_ROOT/../shared}
if [ ! -d "$shared/meshes" ]; then
  echo "inversevis: $shared/meshes is missing (the project's shared meshes; IVIS_SHARED_DIR names another" \
    "folder): every test that reads them fails, naming the file" >&2
fi
cd "$IVIS_BUILD"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "$@"
