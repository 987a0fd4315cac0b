#!/usr/bin/env bash
# Fetches the wider test-mesh set (docs/test-meshes.md) and converts it to binary PLY, with DIR/MANIFEST.md.
#   scripts/test_meshes.sh [DIR]      DIR defaults to ../test-meshes beside the repository (never inside it)
# Each source is read from $IVIS_MIRROR/OWNER+NAME (a git dir holding the pinned commit; default /work/.mirror),
# else downloaded from raw.githubusercontent.com at the pinned commit; its sha256 must match the pinned one.
# Files already present with the pinned output sha256 are kept. Exit status 1 if any file failed.
set -uo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
DIR=${1:-$(cd "$HERE/../.." && pwd)/test-meshes}
MIRROR=${IVIS_MIRROR:-/work/.mirror}
PY=/usr/bin/python3
CONVERT="$HERE/test_meshes_convert.py"
CLI="$HERE/../build/app/inversevis"

# One mesh a line: file|kind|owner/name|commit|path|source sha256|output sha256|op|licence as the source states it|note
MESHES=$(cat <<'EOF'
lucy_100k.ply|statue with wings|pyvista/vtk-data|126ee906165a8b2f984f08259a4a2d32cf3b3409|Data/lucy.ply|c57a95174c3c24d87c1ce8b44f48cbf0a5fcab47ce938880ec2acd497a478eb3|ff43f11dc75f14795ebf4815d456ad062d0f415e819e187e1d00814bc55b456c|none|vtk-data Copyright.txt: BSD-3-Clause-style (Martin, Schroeder, Lorensen); no note of its own. Stanford Lucy (Stanford 3D Scanning Repository: research use, credit the Stanford Computer Graphics Laboratory), decimated by the source repo.|Closed. Stanford Lucy: an angel with spread wings.
sea_vase_scan.ply|deep cavity (vase, open scan)|pyvista/vtk-data|126ee906165a8b2f984f08259a4a2d32cf3b3409|Data/ivan-nikolov/seaVase_decimated.vtp|bb1c0f9f9d36f4d17fa396a486ada50c4d063d79a692667a1f6f0f8f9c259904|b1ae27b8a18426f91b88288118612cea815a041d828dfeea171c41b9e32baf14|none|vtk-data Copyright.txt (BSD-3-Clause-style); Data/ivan-nikolov/README.md: from GGG-BenchmarkSfM (Nikolov, Mendeley Data bzxk2n78s9 v4), decimated by the source repo; the dataset's own licence is not restated there.|Photogrammetry scan of a vase: open (unseen base, small holes; 21 non-manifold edges), the mouth leads into the scanned inside wall.
vented_case_thin_shell.ply|thin shell with slotted vents|pyvista/vtk-data|126ee906165a8b2f984f08259a4a2d32cf3b3409|Data/cad/4947746/Vented_Rear_Case_With_Pi_Supports.vtp|3445b4644d938f270442a3c5aa7baa68bbed46132c344bd7fae1bf557e7801bc|451033d84149c9dcfba1574f4994c361ae6f8b2c2cfbe2d8911e1843d3e42313|none|Data/cad/4947746/README.md and LICENSE.txt: "PiBoy DMG Custom Rear Case With Ventilation" by downerhouse, Thingiverse thing 4947746, "licensed under cc" (variant not named).|Closed, genus 24: thin walls with rows of through-slots. Point array Normals dropped (not a scalar field).
turbine_blade_199k.ply|thin plate (turbine blade)|pyvista/vtk-data|126ee906165a8b2f984f08259a4a2d32cf3b3409|Data/turbineblade.ply|c2850452c86e3076e0d70f77859bee942c096153f687c66b85549f3e52d809cb|5545f2e4b7c515bebfddef7466ee41ee0d86d3b17c5b9473056c10ee9225050b|none|vtk-data Copyright.txt (BSD-3-Clause-style); no note of its own.|Closed. A thin curved blade.
idgh_42400_part.ply|mechanical part, through-holes|pyvista/vtk-data|126ee906165a8b2f984f08259a4a2d32cf3b3409|Data/42400-IDGH.stl|943a3a869b92ed884c43c8f16d184468e24c69c197069adf73082ea5cb3df448|9d5e6bb60b6718cea823efe712aeb25d0a466dfdb48e2c41d1a123a96fff35c5|none|vtk-data Copyright.txt (BSD-3-Clause-style); a long-standing VTK test file (same bytes as vmtk-test-data input/fixture.stl).|Closed after merging STL corners, genus 10: flanges with bolt holes. 3 triangles have a repeated corner (kept; inversevis drops them and then counts 7 boundary edges).
gears.ply|mechanical parts, bores (7 components)|pyvista/vtk-data|126ee906165a8b2f984f08259a4a2d32cf3b3409|Data/gears.stl|efd5c90522e787ed72926033b98796f71ddb1c3bf99d21e379e7456deb0e0138|7164ce8deef344cdea927a0f5e79df24d8c59fa39242a7bb34a7f59c46e39b56|none|vtk-data Copyright.txt (BSD-3-Clause-style); no note of its own (OpenSCAD export).|7 separate closed gears (total genus 2).
fertility_genus4.ply|genus-4 sculpture|libigl/libigl-tutorial-data|c1f9ede366d02e3531ecbaec5e3769312f31cccd|fertility.off|145fdfb007c8d5d09ba60943f14f4ddc9edd4327c7956fe379c624adeb59dc5b|6e1b1af8f41620c4dfbda6c307d0013e42563e23a686290b971b388a387b683e|none|Repo has no LICENSE file; its README credits AIM@SHAPE for fertility.off.|Closed, genus 4.
brava_brain_arteries_tubes.ply|dense vessel tree (157 branches)|megdec/vascularmd|770feb8fbfb591d6d43f966db57b1465010b9a13|Data/P1_whole_brain_BraVa.swc|016214e4c943c62139a0b889c9daf3b84eb3b3be9035e8942043adb07bca090e|0dfb9b3e7905432eda54d5a696db27e61825fb86de4f6788439237e2dd056baa|none|vascularmd is GPL-3.0 (LICENSE); the SWC is a whole-brain arterial tree of the BraVa database (README: "existing databases of large cerebral vascular networks (e.g. BraVa)").|Surface generated here from the centre lines: one capped 16-sided tube per branch (bifurcation to bifurcation or tip, radius from the SWC), wound outward; tubes overlap at the 78 bifurcations (157 closed components, not a union).
gmsh_cerebral_open.ply|open artery tree, 9 boundary loops|live-clones/gmsh|6e0890bb1a5c21f35cfe13342cf90a10c0604795|benchmarks/centerlines/cerebral.stl|5755308df9553edb3b7d74e9eec685ec8956dcf1dd25455cbb6ae26ac4516259|1c145449e9944ec89ee49dd9b463a565f6509fc9d6bf1031501b98631ae79666|none|Gmsh: GPL-2.0-or-later with an exception (doc/LICENSE.txt); test file of Gmsh's centre-line benchmark (removed from Gmsh in 2017).|Cerebral arteries (the benchmark's "cerebral" case), cut open at 9 ends.
gmsh_patient_aorta_open.ply|open aorta with branches, 7 boundary loops|live-clones/gmsh|f53fb375fba1d96ef1f7ded5c260f931d3943cec|benchmarks/centerlines/patientBIG.stl|acb5384c6750fb431b47cda5c66a55d40d17c2211f51d87da3c21529e5e6ca88|4a5c34a78ea83adb67f2b3a9abcf22a428ea6058fb5178a5c0df02bde2bb570c|none|Gmsh: GPL-2.0-or-later with an exception (doc/LICENSE.txt); test file of Gmsh's centre-line benchmark (removed in 2017).|Aorta with branches (the benchmark's "patient" case), cut open at 7 ends.
aneurisk_c0015_open.ply|open artery, 3 boundary loops|KVSlab/VaMPy|9b4bd9de58e3ab6870cf7a87c5f0f5724a761707|models/artery/artery.vtp|475e8df73ecdd5be6d1284ae4077f16d444ef49723b6ded2812ba61f7539f1d9|702efa4d9a75947b1947ed733de53bf808a0ce059d9618bb29a530b585ef577f|none|VaMPy is GPL-3.0; models/artery/README.md: modified AneuRisk case C0015 (cite Sangalli et al. 2014, AneuRisk65).|Carotid artery model, cut open at 3 ends. Point array Normals dropped.
lucy_1m6_subdiv.ply|1M+ triangles (Lucy, subdivided)|pyvista/vtk-data|126ee906165a8b2f984f08259a4a2d32cf3b3409|Data/lucy.ply|c57a95174c3c24d87c1ce8b44f48cbf0a5fcab47ce938880ec2acd497a478eb3|e34777092b236a73f246c00aecb7218e8c643d800db87d0fe83698ab409da8b5|subdivide2|As lucy_100k.ply.|lucy_100k.ply after two flat 1-to-4 midpoint subdivisions (same surface, 16x the triangles): no public mesh of 1M+ triangles fits the 4 MiB file limit of the mirror this set was made from.
EOF
)

# Prints the mirror git dir that holds COMMIT:PATH for OWNER/NAME, if any.
mirror_git_dir() {
  local base="$MIRROR/${1/\//+}" d
  for d in "$base/repo/.git" "$base/repo" "$base/.git" "$base"; do
    git --git-dir="$d" cat-file -e "$2:$3" 2>/dev/null && { echo "$d"; return 0; }
  done
  return 1
}

# Writes OWNER/NAME@COMMIT:PATH to OUT (mirror first, then download) and checks its sha256; errors name FILE.
fetch_source() {
  local file=$1 repo=$2 commit=$3 path=$4 sha=$5 out=$6 gd got rc
  if gd=$(mirror_git_dir "$repo" "$commit" "$path"); then
    git --git-dir="$gd" show "$commit:$path" >"$out" || { echo "test_meshes: $file: git show failed" >&2; return 1; }
  else
    curl -fsL --retry 2 -o "$out" "https://raw.githubusercontent.com/$repo/$commit/$path" 2>/dev/null
    rc=$?
    if [ $rc -ne 0 ]; then
      echo "test_meshes: $file: cannot fetch $repo@$commit:$path (not in $MIRROR; download failed, curl exit $rc)" >&2
      return 1
    fi
  fi
  got=$(sha256sum "$out" | cut -c1-64)
  [ "$got" = "$sha" ] && return 0
  echo "test_meshes: $file: sha256 mismatch for $repo@$commit:$path (got $got, pinned $sha)" >&2
  return 1
}

# Makes DIR/FILE from its source unless it is already there with the pinned sha256.
make_mesh() {
  local file=$1 repo=$2 commit=$3 path=$4 sha=$5 outsha=$6 op=$7 src tmp got
  [ -f "$DIR/$file" ] && [ "$(sha256sum "$DIR/$file" | cut -c1-64)" = "$outsha" ] && return 0
  src="$WORK/src.${path##*.}"
  tmp="$DIR/.$file.tmp"
  fetch_source "$file" "$repo" "$commit" "$path" "$sha" "$src" || return 1
  if ! "$PY" "$CONVERT" "$src" "$tmp" --op "$op" --comment "source github.com/$repo @ $commit : $path"; then
    echo "test_meshes: $file: conversion failed" >&2
    rm -f "$tmp"
    return 1
  fi
  mv -f "$tmp" "$DIR/$file"
  got=$(sha256sum "$DIR/$file" | cut -c1-64)
  [ "$got" = "$outsha" ] || echo "test_meshes: note: $file has sha256 $got, not the pinned $outsha (another numpy?)" >&2
}

# Prints MANIFEST.md for the files made (rows from the converter's --stats).
write_manifest() {
  cat <<'EOF'
# Mesh set: test-meshes (wider shapes)

Made by `scripts/test_meshes.sh`; shapes the shared set lacks (docs/test-meshes.md). Same format as the shared set:
binary little-endian PLY; vertex `float x y z` (+ extra `float` properties = real scalar point fields, original names),
faces `list uchar int vertex_indices`, triangles only (polygons fan-triangulated), coordinates as in the source,
unreferenced vertices removed, STL corners with bit-identical coordinates merged; nothing else repaired.

Columns: V = vertices, T = triangles, bnd = boundary edges (one incident triangle), loops = boundary loops, nm =
non-manifold edges (>2 triangles), inc = interior edges traversed the same way by both triangles, cc = connected
components, genus = total genus (closed manifold meshes only), vol = signed volume (closed meshes: >0 = outward),
bbox = [min] .. [max].

| file | kind | source (repo @ commit : path) | licence / terms as stated by source | V | T | bnd | loops | nm | inc | cc | genus | vol | bbox | scalar properties (min..max) |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
EOF
  local file kind repo commit path sha outsha op lic note
  while IFS='|' read -r file kind repo commit path sha outsha op lic note; do
    [ -f "$DIR/$file" ] || continue
    IFS=$'\t' read -r v t bnd loops nm inc cc genus vol bbox sc < <("$PY" "$CONVERT" --stats "$DIR/$file")
    echo "| $file | $kind | github.com/$repo @ \`${commit:0:12}\` : \`$path\` | $lic | $v | $t | $bnd | $loops | $nm | $inc | $cc | $genus | $vol | $bbox | $sc |"
  done <<<"$MESHES"
  echo
  echo "Total size: $(du -ch "$DIR"/*.ply 2>/dev/null | tail -1 | cut -f1)"
  echo
  echo "## Notes per file"
  echo
  while IFS='|' read -r file kind repo commit path sha outsha op lic note; do
    [ -f "$DIR/$file" ] || continue
    echo "- **$file** ($(stat -c %s "$DIR/$file") bytes; full commit \`$commit\`; source sha256 \`$sha\`): $note"
  done <<<"$MESHES"
}

mkdir -p "$DIR" || exit 1
WORK=$(mktemp -d) || exit 1
trap 'rm -rf "$WORK"' EXIT
status=0
while IFS='|' read -r file kind repo commit path sha outsha op lic note; do
  if ! make_mesh "$file" "$repo" "$commit" "$path" "$sha" "$outsha" "$op" </dev/null; then
    status=1
  elif [ -x "$CLI" ] && ! "$CLI" -q info "$DIR/$file" </dev/null >/dev/null; then
    echo "test_meshes: $file: inversevis info cannot read it" >&2
    status=1
  fi
done <<<"$MESHES"
write_manifest >"$DIR/.MANIFEST.md.tmp" && mv -f "$DIR/.MANIFEST.md.tmp" "$DIR/MANIFEST.md" || status=1
echo "test_meshes: $(ls "$DIR"/*.ply 2>/dev/null | wc -l) meshes and MANIFEST.md in $DIR" >&2
exit $status
