#!/usr/bin/env bash
# Renders the embedded default scene (a generated vessel tree with an aneurysm) with InverseVis
# to a PNG and says where it is.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
ivis_build
out="$IVIS_ROOT/demo"
mkdir -p "$out"
"$IVIS_BUILD/app/inversevis" render scene:vessel-tree --method inversevis --res 1000x1000 \
  -o "$out/vessel-tree-inversevis.png" --exr "$out/vessel-tree-inversevis.exr" \
  --stats-json "$out/vessel-tree-inversevis.json"
echo "demo: picture written to $out/vessel-tree-inversevis.png"
