#!/usr/bin/env bash
# Regenerates docs/results.md: every method at its own optimum on the shared meshes and on the
# wider test set (docs/test-meshes.md), measured as docs/measures.md says, with the pictures of
# the shared meshes in docs/images/results.
#   scripts/results.sh [SHARED_MESHES [TEST_MESHES]]   defaults: ../shared/meshes, ../test-meshes
# The evaluations' JSON is kept in build/results/: run it again after an interruption to go on.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
IVIS_TARGETS=inversevis ivis_build
ivis_mesh_folders "${1:-}" "${2:-}"
cli="$IVIS_BUILD/app/inversevis"
work="$IVIS_BUILD/results"
mkdir -p "$work"
methods=front,neugebauer,mirror,inversevis,inversevis-adaptive,inversevis-wrap
evaluate=("$cli" evaluate --opt-res 100 --display-res 1000 --methods "$methods" --resume)
pictures=(--pictures "$IVIS_ROOT/docs/images/results" --picture-res 240)
start=$(date +%s)

# The shared set: the artery with its pressure, the generated tree with its wall shear stress and
# every other mesh with two generated hot spots, so that every picture is coloured.
"${evaluate[@]}" "${pictures[@]}" --hotspots 2 --json "$work/shared-hotspots.json" \
  "$SHARED"/{armadillo_50k,cow,rocker_arm,neptune_30k,sphere_ico5,stanford_bunny,vmtk_aorta_segment,lasc2013_b003_left_atrium}.ply
"${evaluate[@]}" "${pictures[@]}" --scalar pressure_t200 --json "$work/shared-artery.json" \
  "$SHARED/vampy_artery_cfd_pressure.ply"
"${evaluate[@]}" "${pictures[@]}" --json "$work/shared-tree.json" scene:vessel-tree
# The wider set: every method, two generated hot spots on every mesh.
"${evaluate[@]}" --hotspots 2 \
  --json "$work/wider.json" "$WIDER"/*.ply

# Two views of the default method on every mesh (optimize --views 2), each kept once made.
mkdir -p "$work/views"
two_views() {  # STEM MESH [FLAGS...]
  local stem=$1 mesh=$2
  shift 2
  [ -f "$work/views/$stem.json" ] && return 0
  "$cli" -q optimize "$mesh" "$@" --views 2 -o "$work/views/$stem.png" --json "$work/views/$stem.json"
}
for stem in armadillo_50k cow rocker_arm neptune_30k sphere_ico5 stanford_bunny vmtk_aorta_segment lasc2013_b003_left_atrium; do
  two_views "$stem" "$SHARED/$stem.ply" --hotspots 2
done
two_views vampy_artery_cfd_pressure "$SHARED/vampy_artery_cfd_pressure.ply" --scalar pressure_t200
two_views vessel-tree scene:vessel-tree
for mesh in "$WIDER"/*.ply; do two_views "$(basename "$mesh" .ply)" "$mesh" --hotspots 2; done

# The default method at the scalar energy's optimum, two generated hot spots on every mesh (the
# artery and the tree too), each kept once made.
mkdir -p "$work/hot-spots"
for mesh in "$SHARED"/*.ply scene:vessel-tree "$WIDER"/*.ply; do
  stem=$(basename "${mesh#scene:}" .ply)
  [ -f "$work/hot-spots/$stem.json" ] && continue
  "$cli" -q optimize "$mesh" --hotspots 2 --energy scalar -o "$work/hot-spots/$stem.png" \
    --json "$work/hot-spots/$stem.json"
done
minutes=$(( ($(date +%s) - start + 59) / 60 ))

# A row per mesh of the optimize reports in folder $1: "views" (the two views' figures) or
# "hot-spots" (the hot spots at the scalar energy's optimum).
report_table() {
  /usr/bin/python3 - "$work/$1" "$1" <<'PY'
import json, pathlib, sys
folder, kind = pathlib.Path(sys.argv[1]), sys.argv[2]
if kind == "views":
    print("| Surface | best view: visibility / coherence | second view: visibility / coherence "
          "| together: visibility (by voxel count) | seconds |")
else:
    print("| Surface | hot spots seen, percent of each | share in one place / outline ratio, each "
          "| surface visibility / coherence | seconds |")
print("|---|---|---|---|---|")
for path in sorted(p for p in folder.glob("*.json") if ".png." not in p.name):
    report = json.loads(path.read_text())
    if kind == "views":
        several = report["several_views"]
        views = [f'{100 * v["visibility"]:.1f} / {v["coherence"]:.3f}' for v in several["views"]] + ["-"]
        together = several["union"]
        cells = [views[0], views[1], f'{100 * together["visibility"]:.1f} ({100 * together["voxel_visibility"]:.1f})']
    else:
        measures = report["measures"]
        reveal = measures["reveal"]
        cells = [", ".join(f"{100 * r:.1f}" for r in reveal["per_region"]),
                 ", ".join(f'{s["largest_share"]:.2f} / {s["outline_ratio"]:.2f}' for s in reveal["shapes"]),
                 f'{100 * measures["visibility"]:.1f} / {measures["coherence"]:.3f}']
    print(f'| {path.stem} | {" | ".join(cells)} | {report["seconds"]:.1f} |')
PY
}

"$cli" -q merge "$work"/shared-{hotspots,artery,tree}.json --markdown "$work/shared.md" >/dev/null
"$cli" -q merge "$work/wider.json" --markdown "$work/wider.md" >/dev/null

# Pictures of the shared set, a row per mesh.
picture_table() {
  local stems=(armadillo_50k cow rocker_arm neptune_30k sphere_ico5 stanford_bunny vampy_artery_cfd_pressure
               vmtk_aorta_segment lasc2013_b003_left_atrium vessel-tree)
  echo "| Surface | ${methods//,/ | } |"
  echo "|---|---|---|---|---|---|---|"
  for stem in "${stems[@]}"; do
    printf '| %s |' "$stem"
    for m in ${methods//,/ }; do printf ' ![](images/results/%s-%s.png) |' "$stem" "$m"; done
    echo
  done
}

out="$IVIS_ROOT/docs/results.md"
{
  cat <<HEADER
# The paper's evaluation, measured here

Every method at its own optimum (the best view and parameters its visibility energy finds:
\`evaluate --opt-res 100\`), measured at that view on 1000 x 1000 pixels and the 200^3 grid as
[measures.md](measures.md) says: surface visibility by area, by voxel count and read literally,
mapping coherence, hot-spot reveal and how each hot spot reads in the picture; Table 2 the
optimisation's seconds. Generated on $(date -u +%Y-%m-%d) on a machine with $(nproc) cores (this
run: ${minutes} minutes; from nothing the whole takes 20-45 minutes on 2 cores, and a run
interrupted goes on where it stopped; the seconds are that machine's, whose speed varies by up to
a factor of two between the project's machines and days) by

\`\`\`sh
scripts/results.sh            # ../shared/meshes and ../test-meshes (scripts/test_meshes.sh fetches it)
\`\`\`

which runs \`inversevis evaluate --opt-res 100 --display-res 1000 --methods $methods\`
on the shared meshes (the artery with \`--scalar pressure_t200\`, the generated vessel tree with its
wall shear stress, every other mesh with \`--hotspots 2\`) and on the wider set
([test-meshes.md](test-meshes.md), \`--hotspots 2\`), joins the runs with
\`inversevis merge\`, runs \`inversevis optimize --views 2\` on every mesh, and
\`inversevis optimize --hotspots 2 --energy scalar\` on every mesh.

The paper's own figures (surface visibility in percent, front-only in brackets), for comparison:

| Surface | Neugebauer | Mirror | InverseVis |
|---|---|---|---|
| Armadillo | 79 (46) | 88 (47) | 97 (45) |
| Cow | 91 (38) | 95 (38) | 98 (47) |
| Fertility (here: fertility_genus4 in the wider set) | 71 (41) | 86 (34) | 96 (43) |
| Gargoyle | 84 (42) | 88 (39) | 95 (37) |
| Neptune | 72 (43) | 95 (53) | 96 (53) |
| Rocker arm | 84 (55) | 97 (47) | 98 (46) |
| Sphere | 100 (43) | 75 (43) | 100 (43) |
| Aneurysms 1-3 | 65-84 (37-41) | 84-92 (42-44) | 96-100 (42-44) |
| Carotids 5, 11 | 68-78 (36-44) | 93-97 (45-46) | 98-100 (49) |
| Vessel tree | 73 (47) | 84 (48) | 98 (45) |

# The shared meshes (../shared/meshes)

HEADER
  cat "$work/shared.md"
  printf '\n# The wider test set (docs/test-meshes.md)\n\n'
  cat "$work/wider.md"
  printf '\n# Two views of the default method (optimize --views 2)\n\n'
  printf 'The best view and the visited view that adds the most surface to it (docs/optimisation.md,\n'
  printf '"Several views"), each at its readable rule; "together" is the area their pictures show.\n\n'
  report_table views
  printf '\n# Hot spots at the scalar energy'"'"'s optimum (the default method)\n\n'
  printf 'Two generated hot spots at the ends of each mesh'"'"'s thinnest axis (`--hotspots 2`, the artery and\n'
  printf 'the tree too), the view `optimize --energy scalar` chooses (its hot-spot rule included:\n'
  printf 'docs/optimisation.md) with its readable rule, measured on its 1000 x 1000 picture\n'
  printf '(docs/measures.md, 3 and 4): how much of each hot spot is seen, and how each reads in the picture.\n\n'
  report_table hot-spots
  printf '\n# Pictures of the shared meshes at each method'"'"'s optimum (240 x 240)\n\n'
  picture_table
} >"$out.tmp"
mv "$out.tmp" "$out"
echo "results: wrote $out ($minutes minutes)"
