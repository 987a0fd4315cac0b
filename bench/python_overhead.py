"""The Python module's overhead: render() called from Python against the C++ render inside it.

    PYTHONPATH=build/python python3 bench/python_overhead.py MESH [--size N] [--repeat K]

The mesh's volume is built (or read) once first; each call then frames the view and renders.
Prints JSON: the wall seconds of each call, the C++ renderer's own seconds inside it
(measures["seconds"]), and their ratio (the median of the calls)."""
import argparse
import json
import statistics
import time

import inversevis

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh")
parser.add_argument("--size", type=int, default=1000)
parser.add_argument("--repeat", type=int, default=3)
parser.add_argument("--volume-res", type=int, default=200)
args = parser.parse_args()

mesh = inversevis.Mesh.read(args.mesh)
options = dict(size=(args.size, args.size), volume_resolution=args.volume_res, stable_shift=0.1)
inversevis.render(mesh, **dict(options, size=(64, 64)))  # the volume and scene, once
walls, inner = [], []
for _ in range(args.repeat):
    start = time.perf_counter()
    picture = inversevis.render(mesh, **options)
    rgba = picture.rgba  # the pixels out, as a user takes them
    walls.append(time.perf_counter() - start)
    inner.append(picture.measures["seconds"])
ratios = [w / s for w, s in zip(walls, inner)]
print(json.dumps({"mesh": args.mesh, "size": args.size, "wall_seconds": walls, "render_seconds": inner,
                  "ratio": statistics.median(ratios)}))
