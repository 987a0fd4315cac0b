#!/usr/bin/env bash
# The viewer's frame rates without a GPU: `inversevis-view --benchmark` under Xvfb (Mesa llvmpipe)
# for every method, at 512x512 and 1024x768, traced by the CPU (--tracer cpu, the default on
# software GL) and, with --shaders, by the shaders as well. Prints a Markdown table of frames per
# second while the camera moves and seconds to the full picture at rest.
#
# usage: bench/viewer_frame_rates.sh [--shaders] [--frames N] [BUILD_DIR]
set -euo pipefail

shaders=0
frames=60
build=build
while [ $# -gt 0 ]; do
    case "$1" in
        --shaders) shaders=1 ;;
        --frames) frames="$2"; shift ;;
        -h|--help) sed -n '2,7p' "$0"; exit 0 ;;
        *) build="$1" ;;
    esac
    shift
done
viewer="$build/app/inversevis-view"
[ -x "$viewer" ] || { echo "viewer_frame_rates.sh: $viewer is not built (scripts/test.sh builds it)" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "viewer_frame_rates.sh: xvfb-run is missing (scripts/setup.sh installs xvfb)" >&2; exit 2; }

methods="inversevis-wrap inversevis inversevis-adaptive mirror neugebauer front"
tracers="cpu"
[ "$shaders" = 1 ] && tracers="cpu gpu"

# One benchmark run: "<fps> | <seconds>" from the viewer's benchmark line.
measure() {
    local line
    line=$(xvfb-run -a -s "-screen 0 1280x1024x24" "$viewer" scene:vessel-tree --benchmark \
        --benchmark-frames "$frames" "$@" 2>&1 | grep "inversevis-view: benchmark:")
    sed -E 's/.*moving ([0-9.]+) fps.*mean traced size ([0-9x]+)\); at rest the full [0-9x]+ picture in ([0-9.]+) s/\1 fps (\2) | \3 s/' <<<"$line"
}

echo "\`bench/viewer_frame_rates.sh --frames $frames\`, $(date -u +%Y-%m-%d), $(nproc) cores:"
echo
echo "| method | tracer | 512x512 moving (traced size) | at rest | 1024x768 moving (traced size) | at rest |"
echo "|---|---|---|---|---|---|"
for method in $methods; do
    for tracer in $tracers; do
        small=$(measure --method "$method" --tracer "$tracer" --width 512 --height 512)
        large=$(measure --method "$method" --tracer "$tracer" --width 1024 --height 768)
        echo "| $method | $tracer | $small | $large |"
    done
done
