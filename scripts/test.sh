#!/usr/bin/env bash
# Builds everything (installing what is missing) and runs the whole test suite with ctest.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
ivis_build
cd "$IVIS_BUILD"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "$@"
