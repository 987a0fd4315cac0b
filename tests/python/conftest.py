"""Shared fixtures of the Python module's tests: a private volume cache, the command-line
program, and a small sphere mesh written by the test itself (no shared data needed)."""
import os
import subprocess

import numpy as np
import pytest

import inversevis


@pytest.fixture(autouse=True)
def private_cache(tmp_path_factory, monkeypatch):
    """Every test's volumes in one cache of the session (both the module and the CLI read XDG_CACHE_HOME)."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path_factory.getbasetemp() / "cache"))


def run_cli(*args):
    """Runs the command-line program (IVIS_CLI) and returns its completed process."""
    return subprocess.run([os.environ["IVIS_CLI"], *args], capture_output=True, text=True)


def uv_sphere(rings=24, segments=48):
    """Vertices (float64) and faces (int64) of a unit UV sphere, and a height field on its vertices."""
    vertices = [(0.0, 0.0, 1.0)]
    for i in range(1, rings):
        theta = np.pi * i / rings
        for j in range(segments):
            phi = 2 * np.pi * j / segments
            vertices.append((np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)))
    vertices.append((0.0, 0.0, -1.0))
    v = np.array(vertices)
    faces = []
    last = len(vertices) - 1
    for j in range(segments):
        faces.append((0, 1 + j, 1 + (j + 1) % segments))
        base = 1 + (rings - 2) * segments
        faces.append((last, base + (j + 1) % segments, base + j))
    for i in range(rings - 2):
        for j in range(segments):
            a, b = 1 + i * segments + j, 1 + i * segments + (j + 1) % segments
            c, d = a + segments, b + segments
            faces += [(a, c, b), (b, c, d)]
    f = np.array(faces, dtype=np.int64)
    return v, f, (v[:, 2] + 1.0) * 0.5


def write_ply(path, vertices, faces, height):
    """An ASCII PLY of the mesh with the vertex property 'height'."""
    with open(path, "w") as out:
        out.write("ply\nformat ascii 1.0\n")
        out.write(f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n")
        out.write(f"property float height\nelement face {len(faces)}\nproperty list uchar int vertex_indices\n")
        out.write("end_header\n")
        for p, h in zip(vertices.astype(np.float32), height.astype(np.float32)):
            out.write(f"{p[0]!r} {p[1]!r} {p[2]!r} {h!r}\n")
        for f in faces:
            out.write(f"3 {f[0]} {f[1]} {f[2]}\n")


@pytest.fixture(scope="session")
def sphere_file(tmp_path_factory):
    """A PLY file of the sphere with its height array."""
    path = tmp_path_factory.mktemp("mesh") / "sphere.ply"
    write_ply(path, *uv_sphere())
    return str(path)
