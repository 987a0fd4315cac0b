"""Shared fixtures of the Python module's tests: a private volume cache, the command-line
program, and a small sphere mesh written by the test itself (no shared data needed)."""
import os
import struct
import subprocess
import zlib

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


def read_png(path):
    """The pixels of an 8-bit RGB or RGBA PNG without interlacing (as the program writes them), as a
    (height, width, channels) uint8 array: the PNG format decoded with zlib alone."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    at, idat = 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, path
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    channels = 3 if colour == 2 else 4
    stride = width * channels
    raw = zlib.decompress(idat)
    rows, up = [], [0] * stride
    for y in range(height):
        kind, line = raw[y * (stride + 1)], raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)]
        row = [0] * stride
        for x in range(stride):
            left = row[x - channels] if x >= channels else 0
            corner = up[x - channels] if x >= channels else 0
            if kind == 0:
                predicted = 0
            elif kind == 1:
                predicted = left
            elif kind == 2:
                predicted = up[x]
            elif kind == 3:
                predicted = (left + up[x]) // 2
            else:  # Paeth
                p = left + up[x] - corner
                pa, pb, pc = abs(p - left), abs(p - up[x]), abs(p - corner)
                predicted = left if pa <= pb and pa <= pc else (up[x] if pb <= pc else corner)
            row[x] = (line[x] + predicted) & 255
        rows.append(row)
        up = row
    return np.array(rows, dtype=np.uint8).reshape(height, width, channels)
