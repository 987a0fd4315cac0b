"""Writes docs/performance.md from the measurements scripts/bench.sh keeps (stdout: Markdown).

    python3 bench/performance_report.py RESULTS_DIR MINUTES"""
import datetime
import json
import os
import pathlib
import sys

results, minutes = pathlib.Path(sys.argv[1]), sys.argv[2]


def load(name):
    return json.loads((results / f"{name}.json").read_text())


def mib(n):
    return f"{n / 2**20:,.0f} MiB"


def gib(n):
    return f"{n / 2**30:.2f} GiB"


def verdict(ok):
    return "met" if ok else "**not met**"


def cpu_model():
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return "unknown CPU"


sdf = {n: load(f"sdf-{n}") for n in (200, 1000, 2000)}
render = load("render")
methods = {m["method"]: m for m in render["methods"]}
wrap, faithful = methods["inversevis-wrap"], methods["inversevis"]
read = load("read")
print_run = load("print")
optimize_run, optimize_report = load("optimize"), load("optimize-report")
paper = {stem: (load(f"paper-{stem}"), load(f"paper-{stem}-report")) for stem in ("armadillo_50k", "cow", "neptune_30k")}
python = load("python")
viewer = (results / "viewer.md").read_text().strip()
viewer_rows = {}
for line in viewer.splitlines():
    cells = [c.strip() for c in line.strip("|").split("|")]
    if len(cells) == 6 and cells[1] in ("cpu", "gpu"):
        viewer_rows[(cells[0], cells[1])] = cells
wrap_cpu = viewer_rows[("inversevis-wrap", "cpu")]
moving_fps = float(wrap_cpu[4].split()[0])
rest_seconds = float(wrap_cpu[5].split()[0])
paper_worst = max(report["seconds"] for _, report in paper.values())

measured = datetime.datetime.fromtimestamp(max(f.stat().st_mtime for f in results.iterdir()), datetime.timezone.utc)

print(f"""# Performance

Measured on {measured.date().isoformat()} (UTC) by `scripts/bench.sh` (this run: {minutes} minute{"" if minutes == "1" else "s"}) on a
machine with {os.cpu_count()} cores ({cpu_model()}), Release build:

```sh
scripts/bench.sh            # ../shared/meshes and ../test-meshes (scripts/test_meshes.sh fetches it)
```

Every figure is measured against a reference in the same run where one exists; nothing is
asserted on time in the tests. Each measurement is kept in `build/bench-results/` (a second run
measures only what is missing; `--fresh` measures all again).

## Targets

| what | target | measured | |
|---|---|---|---|
| default method's frame (armadillo, volume 1000, 1000 x 1000) | 0.5 s | {wrap['frame_seconds']:.2f} s | {verdict(wrap['frame_seconds'] <= 0.5)} |
| the faithful model's frame (same) | 0.5 s | {faithful['frame_seconds']:.2f} s | {verdict(faithful['frame_seconds'] <= 0.5)} |
| viewer without a GPU, 1024 x 768, default method, moving | 10 frames/s | {moving_fps:.1f} | {verdict(moving_fps >= 10)} |
| the same, full picture after the camera stops | 1 s | {rest_seconds:.2f} s | {verdict(rest_seconds <= 1)} |
| print, 4000 x 3000 at volume 2000, volume cached: wall | 10 s | {print_run['wall_seconds']:.1f} s | {verdict(print_run['wall_seconds'] <= 10)} |
| the same: peak memory | 2 GiB | {gib(print_run['peak_rss_bytes'])} | {verdict(print_run['peak_rss_bytes'] <= 2 * 2**30)} |
| `optimize` of a 100k-triangle statue, wall, volume cached | 10 s | {optimize_run['wall_seconds']:.1f} s | {verdict(optimize_run['wall_seconds'] <= 10)} |
| `optimize --opt-res 1000`, search, per mesh (armadillo, cow, Neptune) | 120 s | at most {paper_worst:.0f} s | {verdict(paper_worst <= 120)} |
| volume build at 1000^3 against bare OpenVDB | 2.0x | {sdf[1000]['ratio']:.2f}x | {verdict(sdf[1000]['ratio'] <= 2.0)} |
| volume build's peak memory at 2000^3 | 1.5 GiB | {gib(sdf[2000]['peak_rss_bytes'])} | {verdict(sdf[2000]['peak_rss_bytes'] <= 1.5 * 2**30)} |
| Python's `render()` against the C++ render inside it | 1.05x | {python['ratio']:.2f}x | {verdict(python['ratio'] <= 1.05)} |
| compressed .vtp (inline base64) against binary PLY | 2x | {read['ratio_inline']:.2f}x | {verdict(read['ratio_inline'] <= 2)} |

## Volume build (`inversevis-bench sdf`)

`inversevis-bench sdf ../shared/meshes/armadillo_50k.ply --volume-res N --json`. Ours: the full
build ([volume.md](volume.md)): OpenVDB's band, the exact closest point, triangle
and gradient of every band voxel, and the far field with the exact distance and gradient of every
far voxel. Reference: a bare `openvdb::tools::meshToVolume` with a 3-voxel band on each side and a
polygon-index grid. Each runs in a forked child of its own, so its time and peak resident memory
are its alone. The armadillo ({sdf[1000]['triangles']:,} triangles):

| N | ours | OpenVDB | ratio | our peak memory | OpenVDB's peak memory | active voxels (ours) |
|---|---|---|---|---|---|---|""")
for n, s in sdf.items():
    print(f"| {n} | {s['ours_seconds']:.2f} s | {s['openvdb_seconds']:.2f} s | **{s['ratio']:.2f}** | "
          f"{mib(s['peak_rss_bytes'])} | {mib(s['openvdb_peak_rss_bytes'])} | {s['active_voxels']:,} |")
print(f"""
What costs the build beyond OpenVDB's: the far field's exact closest points, one bounded BVH
query per far voxel, which the smooth curved rays need (exact gradients everywhere), and the band
reaching one far voxel outside the surface, which keeps landings continuous where rays pass close to
it. At N = 200 the fine grid carries the whole far field itself, so the ratio there is large by
design. The build is cached: a picture or an optimisation pays it once per mesh and resolution.
What was tried to cut it: [decisions/volume-build-cost.md](decisions/volume-build-cost.md).

## Rendering (`inversevis-bench render`)

`inversevis-bench render ../shared/meshes/armadillo_50k.ply --volume-res 1000 --image 1000x1000 --json`:
the armadillo at volume 1000, 1000 x 1000 pixels, theta 90 phi 0, the default field of view
(75 degrees, not framed), shadows on, each method at its defaults, each frame the faster of two.
Per method: its frame under adaptive image sampling (the default, [rendering.md](rendering.md),
"Adaptive image sampling") and under `--full-trace`, the rays it traced, and the steps per second
of its drawn rays on our sampler (fine band in bricks, dense far field, both blending exact
per-voxel gradients) against the same rays on a plain dense float array of the distance at the
fine voxel size ({mib(render['reference_bytes'])}), the memory-bound ceiling. The front view alone:
{render['front_seconds']:.2f} s.

| method | frame | full trace | indirect pixels | rays traced | seeds sought near the lattice's | ours (M steps/s) | dense (M steps/s) | ratio |
|---|---|---|---|---|---|---|---|---|""")
for m in render["methods"]:
    print(f"| `{m['method']}`{' (default)' if m is wrap else ''} | **{m['frame_seconds']:.2f} s** | "
          f"{m['full_trace_seconds']:.2f} s | {m['pixels_indirect']:,} | {m['rays_traced']:,} | "
          f"{m['seeds_interpolated']:,} | {m['steps_per_second'] / 1e6:.1f} | "
          f"{m['reference_steps_per_second'] / 1e6:.1f} | {m['ratio']:.2f} |")
print(f"""
What a frame of the default method costs: every indirect pixel traces its own ray (a landing
interpolated between neighbours misses the landings' sub-voxel detail:
[decisions/interpolated-landings.md](decisions/interpolated-landings.md)), seeks its own seed (the
centre of its view ray's valley, sought near the bottom interpolated from the lattice), and where
its neighbours do not show it stable, the stability rule traces two probes: in the frame above
(counted with `--fov 75 --stable-shift 0.1` on 2026-11-29) 309,000 pixels' own rays took 29.5 M
steps and 175,000 probes of 87,000 pixels 24.5 M, 45% of the steps (which pixels are probed since:
[decisions/stability-probes-cost.md](decisions/stability-probes-cost.md)). A fifth of the steps
creep through the last half voxel to the landing. The drawn rays' flights with the front picture
alone take about what the 0.5 s target allows the whole frame
([decisions/frame-floor.md](decisions/frame-floor.md)). What makes the frames as fast as they are:
- **Adaptive image sampling** of the wrap ([rendering.md](rendering.md)): seeds sought near the
  lattice's valley bottoms, the lattice's own searches started from their blocks' corners' bottoms
  (volumes above 200), background blocks skipped, the stability rule's probes only where needed.
- **Four rays in lockstep** (`CurvedRayMap::traceMany`): a ray's steps are a chain of dependent
  memory reads; four rays stepping in turn overlap them (more lanes, a brick cache per lane and
  prefetching did not help: [decisions/lockstep-lanes.md](decisions/lockstep-lanes.md)). The
  stability rule's probes of a tile are traced together too (`CurvedRayMap::areStable`).
- **The blend in SSE2** (`detail::blend`, `render/include/ivis/render/dense_grid.h`): a sample's
  eight (phi, gradient) corners summed four components at a time, read where they lie, with the
  bits of the formula summed one component at a time; the corners summed in pairs and the pairs
  in pairs, so that a sample waits on three additions, not eight (the faithful model's frame about
  7% faster, the default method's 3-5%: [decisions/simd-blend.md](decisions/simd-blend.md)).
- **phi along a view ray from quartics** (`render/include/ivis/render/line_sampler.h`): the seed
  search's samples of one far cell after its first come from the quartic the blend is along the
  ray there, a few multiply-adds each, equal to the blend up to rounding (volumes above 200);
  the marches skip the rest of a cell whose quartic is bounded below by the least phi found so far.
  What the seed search costs and what these two change:
  [decisions/seed-search-cost.md](decisions/seed-search-cost.md).
- **Tangent planes near the landing** ([rendering.md](rendering.md)): above volume 200, below a
  fine voxel of phi one sample serves the next 16 steps as the field's tangent plane, checked
  where they end and stepped again where it fails: 14% fewer samples and about 4% of the frame on
  the armadillo, nothing lost or gained on the thin vessels of the tree
  ([decisions/tangent-planes.md](decisions/tangent-planes.md)).
- **Band bricks** (`render/include/ivis/render/band_bricks.h`): the fine band copied into bricks of
  9^3 interleaved (phi, gradient) voxels, a cell's eight corners four cache lines of one brick.
- **Fresh memory faulted in on both cores** (`core/include/ivis/core/large_block.h`) for the
  image, its layers, the far copy and the bricks, in 4 KiB pages: on this machine transparent huge
  pages made the first touch slower and the frames no faster
  ([decisions/page-size.md](decisions/page-size.md)).
- **The hull search** in groups of 8 view rays cleared by one cone, refined by regula falsi.
- **Shadow rays** end where they leave the surface's box for good.

## A print

`inversevis render scene:vessel-tree --volume-res 2000 --res 4000x3000`, the default method, its
volume cached before (`inversevis sdf scene:vessel-tree --volume-res 2000`): **{print_run['wall_seconds']:.1f} s**
wall, peak memory **{gib(print_run['peak_rss_bytes'])}**. Its memory: what the scene samples (the band in
bricks, the far field), the volume's triangle grid (`render` frees its phi and gradient
grids once the scene has copied them: [volume.md](volume.md), "Memory"), the picture
with its eight layers (12 M pixels; the coherence every render reports reads the landing layers)
and the figure with its colour bar. Where its seconds go (most are the frame itself):
[decisions/print-cost.md](decisions/print-cost.md).

## `optimize` as a user runs it

`inversevis optimize lucy_100k.ply` (the wider test set's statue, {optimize_report['mesh'].split('/')[-1]}: the
default method, the visibility energy, volume 200 cached, the readable rule, the 1000 x 1000
picture and its measures): **{optimize_run['wall_seconds']:.1f} s** wall, of it the search (the
readable rule included) {optimize_report['seconds']:.1f} s.

The paper's set-up, every view evaluated on 1000^2 rays (`inversevis optimize MESH --opt-res 1000`,
volume 200 cached; the paper reports 35-120 s on a GPU). The default method ascends no parameter
([decisions/fixed-parameters.md](decisions/fixed-parameters.md)), so each view is one evaluation:

| mesh | search | wall | evaluations |
|---|---|---|---|""")
for stem, (run, report) in paper.items():
    print(f"| {stem} | {report['seconds']:.0f} s | {run['wall_seconds']:.0f} s | {report['evaluations']:,} |")
print(f"""
Each evaluation maps the view's 1000^2 pixels as the method's 1000 x 1000 picture does (adaptive
image sampling, `ViewSamples`): it costs about what that picture costs. For a method with
parameters to ascend, `--ascent-res 100` ascends them on 100^2 rays and measures the views on
1000^2 rays ([optimisation.md](optimisation.md)).

## The viewer without a GPU (`bench/viewer_frame_rates.sh`)

`inversevis-view --benchmark` under Xvfb with Mesa's llvmpipe, the vessel tree at volume 200,
N frames orbiting 360 degrees of azimuth at theta 90, each drawn as the window draws it while the
camera moves and shown (glFinish, swap), then the seconds from the last move to the full picture
shown. Where OpenGL is software the CPU renderer traces the picture (`--tracer auto`, the `cpu`
rows): smaller while the camera moves, sized to keep 12 frames per second, and whole once it rests.
The `gpu` rows are the shaders on llvmpipe, tracing a quarter of the pixels while moving.
"Traced size" is the mean size drawn while moving ([viewer.md](viewer.md), "Frame rate").

{viewer}

On a GPU the shaders are the tracer; the project's machines have none, so that frame rate is not
measured here (the aim: 60 frames per second at 1920 x 1080). To measure it:
`inversevis-view scene:vessel-tree --benchmark --tracer gpu --width 1920 --height 1080` on a
machine whose `glxinfo -B` names a hardware renderer (the benchmark line names the renderer).

## The Python module's overhead (`bench/python_overhead.py`)

`PYTHONPATH=build/python python3 bench/python_overhead.py scene:vessel-tree --repeat 3`: `render()`
of the generated tree at 1000 x 1000 from Python (its volume and scene built once before), the wall
seconds of each call with the pixels taken out as `picture.rgba` against the C++ renderer's own
seconds inside it (`measures["seconds"]`): {min(python['wall_seconds']):.2f}-{max(python['wall_seconds']):.2f} s against
{min(python['render_seconds']):.2f}-{max(python['render_seconds']):.2f} s, ratio **{python['ratio']:.2f}** (the median). What the call
adds: the framing's probe of the picture's extent (which `render` does too) and the one copy of the
pixels into numpy; the layers are views, not copies.

## Reading VTK files (`inversevis-bench read`)

`inversevis-bench read ../shared/meshes/neptune_30k.ply --subdivide 3 --repeat 3 --json`: the
Neptune subdivided three times at edge midpoints ({read['vertices']:,} points, {read['triangles']:,}
triangles) with one Float32 point array, written as binary PLY ({read['ply_bytes'] / 1e6:.1f} MB), as a
zlib-compressed .vtp with inline base64 data and Int64 connectivity as VMTK writes it
({read['vtp_inline_bytes'] / 1e6:.1f} MB), and as a zlib-compressed .vtp with raw appended data as ParaView
writes it ({read['vtp_appended_bytes'] / 1e6:.1f} MB); each read by `core::readMesh` with the array chosen, in a
child process of its own, the best of 3 reads:

| PLY | .vtp inline base64 | ratio | .vtp appended raw | ratio | peak memory PLY | peak memory .vtp inline |
|---|---|---|---|---|---|---|
| {read['ply_seconds']:.3f} s | {read['vtp_inline_seconds']:.3f} s | {read['ratio_inline']:.2f} | {read['vtp_appended_seconds']:.3f} s | {read['ratio_appended']:.2f} | {mib(read['ply_peak_rss_bytes'])} | {mib(read['vtp_inline_peak_rss_bytes'])} |""")
