#!/usr/bin/env bash
# Renders the embedded default scene (a generated vessel tree with an aneurysm) with the default
# method (the wrapped InverseVis) to a PNG and says where it is.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
IVIS_TARGETS=inversevis ivis_build  # the command-line tool alone: no tests, viewer or benchmarks
out="$IVIS_ROOT/demo"
mkdir -p "$out"
"$IVIS_BUILD/app/inversevis" render scene:vessel-tree --res 1000x1000 \
  -o "$out/vessel-tree.png" --exr "$out/vessel-tree.exr" --stats-json "$out/vessel-tree.json"
echo "demo: picture written to $out/vessel-tree.png"
