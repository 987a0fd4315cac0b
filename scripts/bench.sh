#!/usr/bin/env bash
# Regenerates docs/performance.md: every benchmark of bench/ on this machine, each against its
# reference measured in the same run, and the targets each meets or misses.
#   scripts/bench.sh [--fresh] [SHARED_MESHES [TEST_MESHES]]   defaults: ../shared/meshes, ../test-meshes
# Each measurement is kept in build/bench-results/ as it is made: a second run measures only what
# is missing (an interrupted run goes on), --fresh measures everything again.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
fresh=0
if [ "${1:-}" = --fresh ]; then fresh=1; shift; fi
IVIS_TARGETS="inversevis inversevis-bench inversevis-view inversevis_python" ivis_build
ivis_mesh_folders "${1:-}" "${2:-}"
cli="$IVIS_BUILD/app/inversevis"
bench="$IVIS_BUILD/bench/inversevis-bench"
timer=(/usr/bin/python3 "$IVIS_ROOT/bench/timed_run.py")
work="$IVIS_BUILD/bench-results"
[ "$fresh" = 1 ] && rm -rf "$work"
mkdir -p "$work"
start=$(date +%s)
armadillo="$SHARED/armadillo_50k.ply"

# measure NAME COMMAND...: the command's standard output into NAME.json, unless that is there.
measure() {
  local name=$1
  shift
  [ -f "$work/$name.json" ] && return 0
  echo "bench: $name" >&2
  "$@" >"$work/$name.json.tmp"
  mv "$work/$name.json.tmp" "$work/$name.json"
}
# timed NAME COMMAND...: the command's wall seconds and peak memory into NAME.json, unless there.
timed() {
  local name=$1
  shift
  [ -f "$work/$name.json" ] && return 0
  echo "bench: $name" >&2
  "${timer[@]}" "$work/$name.json" "$@"
}

for n in 200 1000 2000; do measure "sdf-$n" "$bench" sdf "$armadillo" --volume-res "$n" --json; done
measure render "$bench" render "$armadillo" --volume-res 1000 --image 1000x1000 --json
measure read "$bench" read "$SHARED/neptune_30k.ply" --subdivide 3 --repeat 3 --json

# A print, its volume cached first (as a user's second print of one scene finds it).
"$cli" -q sdf scene:vessel-tree --volume-res 2000 >/dev/null
timed print "$cli" -q render scene:vessel-tree --volume-res 2000 --res 4000x3000 -o "$work/print.png"

# optimize as a user runs it on a statue of 100k triangles, its volume cached.
lucy="$WIDER/lucy_100k.ply"
"$cli" -q sdf "$lucy" >/dev/null
timed optimize "$cli" -q optimize "$lucy" -o "$work/optimize.png" --json "$work/optimize-report.json"
# The paper's set-up: every view evaluated on 1000^2 rays.
for stem in armadillo_50k cow neptune_30k; do
  "$cli" -q sdf "$SHARED/$stem.ply" >/dev/null
  timed "paper-$stem" "$cli" -q optimize "$SHARED/$stem.ply" --opt-res 1000 -o "$work/paper-$stem.png" \
    --json "$work/paper-$stem-report.json"
done

measure python env PYTHONPATH="$IVIS_BUILD/python" /usr/bin/python3 "$IVIS_ROOT/bench/python_overhead.py" \
  scene:vessel-tree --repeat 3
if [ ! -f "$work/viewer.md" ]; then
  echo "bench: viewer" >&2
  "$IVIS_ROOT/bench/viewer_frame_rates.sh" --shaders --frames 30 "$IVIS_BUILD" >"$work/viewer.md.tmp"
  mv "$work/viewer.md.tmp" "$work/viewer.md"
fi

minutes=$(( ($(date +%s) - start + 59) / 60 ))
out="$IVIS_ROOT/docs/performance.md"
/usr/bin/python3 "$IVIS_ROOT/bench/performance_report.py" "$work" "$minutes" >"$out.tmp"
mv "$out.tmp" "$out"
echo "bench: wrote $out ($minutes minutes)"
