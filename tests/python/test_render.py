"""A render from Python is the command line's picture, byte for byte; a mesh given as numpy arrays
renders as its file does; the picture's arrays are what its files hold."""
import numpy as np
import pytest

import inversevis
from conftest import run_cli, uv_sphere


@pytest.mark.parametrize("method", ["inversevis-wrap", "inversevis", "mirror"])
def test_a_python_render_is_the_cli_png_byte_for_byte(tmp_path, method):
    cli_png, py_png = tmp_path / "cli.png", tmp_path / "py.png"
    done = run_cli("render", "scene:vessel-tree", "--method", method, "--res", "320x240", "--theta", "70",
                   "--phi", "30", "-o", str(cli_png))
    assert done.returncode == 0, done.stderr
    picture = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), method, size=(320, 240), theta=70, phi=30)
    picture.save(str(py_png))
    assert py_png.read_bytes() == cli_png.read_bytes()
    assert picture._repr_png_() == cli_png.read_bytes()


def test_a_file_with_a_chosen_scalar_and_parameters_renders_as_the_cli(tmp_path, sphere_file):
    cli_png, cli_exr = tmp_path / "cli.png", tmp_path / "cli.exr"
    done = run_cli("render", sphere_file, "--scalar", "height", "--res", "200x200", "--stable-shift", "0.3",
                   "--theta", "100", "--colormap", "magma", "-o", str(cli_png), "--exr", str(cli_exr))
    assert done.returncode == 0, done.stderr
    picture = inversevis.render(inversevis.Mesh.read(sphere_file), scalar="height", size=(200, 200), stable_shift=0.3,
                                theta=100, colormap="magma")
    picture.save(str(tmp_path / "py.png"))
    assert (tmp_path / "py.png").read_bytes() == cli_png.read_bytes()
    assert picture.method["stable_shift"] == pytest.approx(0.3)
    assert "readable_rule" not in picture.measures  # the rule was given


def test_numpy_arrays_render_as_the_same_mesh_read_from_its_file(sphere_file):
    vertices, faces, height = uv_sphere()
    from_file = inversevis.render(inversevis.Mesh.read(sphere_file), size=(160, 160), theta=60, phi=20)
    # The file holds float32 coordinates and values: the arrays given as the file holds them.
    given = inversevis.Mesh(vertices.astype(np.float32), faces.astype(np.int32),
                            point_data={"height": height.astype(np.float32)})
    from_arrays = inversevis.render(given, size=(160, 160), theta=60, phi=20)
    assert np.array_equal(from_arrays.rgba, from_file.rgba)
    for name, layer in from_file.layers.items():
        assert np.array_equal(from_arrays.layers[name], layer, equal_nan=True), name


def test_the_pictures_arrays_are_its_files(tmp_path):
    picture = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), "inversevis", size=(120, 90))
    # The PNG's pixels: the picture and the colour bar's margin beside it.
    assert picture.rgba.shape[0] >= 90 and picture.rgba.shape[1] > 120 and picture.rgba.shape[2] == 4
    assert picture.rgba.dtype == np.uint8
    region = picture.layers["region"]
    assert region.shape == (90, 120) and region.dtype == np.float32
    assert set(np.unique(region)) <= {0.0, 1.0, 2.0} and (region == 2.0).sum() > 100
    assert picture.measures["pixels_indirect"] == int((region == 2.0).sum())
    indirect = region == 2.0
    assert np.isfinite(picture.layers["P.X"][indirect]).all()
    assert np.isnan(picture.layers["P.X"][region == 0.0]).all()
    assert 0.9 < picture.measures["coherence"] <= 1.0
    with pytest.raises(ValueError, match="read-only"):  # a write changed them but not what probe() reads
        picture.layers["depth"][0, 0] = 1.0
    # The camera reproduces the picture: fixed, not framed again.
    again = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), "inversevis", size=(120, 90),
                              camera=picture.camera)
    assert np.array_equal(again.rgba, picture.rgba)
    picture.save(str(tmp_path / "p.exr"))
    assert (tmp_path / "p.exr").stat().st_size > 0


def test_the_mesh_lists_its_arrays_as_info_does(sphere_file):
    mesh = inversevis.Mesh.read(sphere_file)
    [height] = mesh.arrays
    assert height["name"] == "height" and height["association"] == "point" and height["components"] == 1
    assert height["min"] == pytest.approx(0.0, abs=1e-6) and height["max"] == pytest.approx(1.0)
    assert mesh.vertices.shape[1] == 3 and mesh.faces.shape[1] == 3
    assert inversevis.methods()[0] == "inversevis-wrap"


def test_notes_and_warnings_are_said_in_python(tmp_path, monkeypatch, capsys):
    """What the engine says reaches sys.stderr and the warnings module, where a notebook shows them and
    a script can catch them (it was written to file descriptor 2, past both)."""
    v, f, h = uv_sphere(8, 12)
    with_degenerate = np.vstack([f, [[0, 1, 1]]])
    mesh = inversevis.Mesh(v, with_degenerate, point_data={"h": h})
    inversevis.render(mesh, "front", size=(40, 40), volume_resolution=48)
    said = capsys.readouterr().err
    assert "inversevis: Mesh: dropped 1 degenerate triangles" in said
    assert "inversevis: Mesh: showing the point array 'h'" in said
    blocked = tmp_path / "not-a-folder"
    blocked.write_text("a file where the cache folder would be")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocked))
    with pytest.warns(RuntimeWarning, match="the volume is built for this run and not kept"):
        inversevis.render(inversevis.Mesh(v, f), "front", size=(40, 40), volume_resolution=48)


def test_point_and_cell_data_give_the_arrays_values_row_for_row(tmp_path):
    """As PyVista's point_data and cell_data: each array's values aligned with vertices and faces."""
    v, f, h = uv_sphere(8, 12)
    velocity = np.column_stack([h, 2 * h, 3 * h])
    cells = np.arange(len(f), dtype=np.int32) * 3
    mesh = inversevis.Mesh(v, f, point_data={"h": h, "velocity": velocity}, cell_data={"c": cells})
    assert np.array_equal(mesh.point_data["h"], h)
    assert np.array_equal(mesh.point_data["velocity"], velocity)
    assert np.array_equal(mesh.cell_data["c"], cells.astype(np.float64))
    assert set(mesh.cell_data) == {"c"}
    # Polygons: a file's quad gives its value to both of its triangles, row for row with faces.
    quad = tmp_path / "quad.vtk"
    quad.write_text("# vtk DataFile Version 3.0\nq\nASCII\nDATASET POLYDATA\nPOINTS 5 float\n0 0 0 1 0 0 1 1 0 0 1 0 "
                    "2 0 0\nPOLYGONS 2 9\n4 0 1 2 3\n3 1 4 2\nCELL_DATA 2\nSCALARS id float 1\nLOOKUP_TABLE default\n"
                    "7 9\nPOINT_DATA 5\nSCALARS p float 1\nLOOKUP_TABLE default\n0 1 2 3 4\n")
    read = inversevis.Mesh.read(quad)
    assert len(read.faces) == 3 and np.array_equal(read.cell_data["id"], [7.0, 7.0, 9.0])
    assert np.array_equal(read.point_data["p"], [0.0, 1.0, 2.0, 3.0, 4.0])
    tree = inversevis.Mesh.read("scene:vessel-tree")
    assert list(tree.point_data) == ["wss"] and len(tree.point_data["wss"]) == len(tree.vertices)


def test_a_scenes_own_scalar_is_listed_and_may_be_named():
    tree = inversevis.Mesh.read("scene:vessel-tree")
    assert [(a["name"], a["association"], a["shown_by_default"]) for a in tree.arrays] == [("wss", "point", True)]
    assert tree.arrays[0]["max"] == pytest.approx(tree.point_data["wss"].max())
    named = inversevis.render(tree, "front", scalar="wss", size=(40, 40), volume_resolution=48)
    assert np.array_equal(named.rgba, inversevis.render(tree, "front", size=(40, 40), volume_resolution=48).rgba)
    own = r"scene:vessel-tree: generated scenes carry their own scalar \('wss'\)"
    with pytest.raises(inversevis.InputError, match=own):
        inversevis.render(tree, "front", scalar="pressure", size=(40, 40), volume_resolution=48)


@pytest.mark.parametrize("keywords, flags", [
    (dict(hotspots=2), ["--hotspots", "2"]),
    (dict(hotspots=1, cap_holes=True, theta=40), ["--hotspots", "1", "--cap-holes", "--theta", "40"]),
    (dict(ortho=True, range_percentile=(5, 95), theta=60),
     ["--ortho", "--range-percentile", "5", "95", "--theta", "60"]),
    (dict(symmetric=True, colormap="coolwarm", phi=120), ["--symmetric", "--colormap", "coolwarm", "--phi", "120"]),
])
def test_what_a_picture_shows_and_its_scale_are_chosen_as_on_the_command_line(tmp_path, keywords, flags):
    cli_png = tmp_path / "cli.png"
    done = run_cli("render", "scene:vessel-tree", "--res", "200x150", "--volume-res", "64", *flags, "-o", str(cli_png))
    assert done.returncode == 0, done.stderr
    picture = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), size=(200, 150), volume_resolution=64,
                                **keywords)
    assert picture._repr_png_() == cli_png.read_bytes()
    if keywords.get("cap_holes"):  # the tree is open at its four ends: the caps show
        open_ends = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), size=(200, 150), volume_resolution=64,
                                      **{**keywords, "cap_holes": False})
        assert not np.array_equal(open_ends.rgba, picture.rgba)


def write_vtp_with_cell_data(path, vertices, faces, values):
    """An ASCII VTK XML PolyData file of the mesh with the cell array 'c'."""
    points = " ".join(f"{x!r} {y!r} {z!r}" for x, y, z in vertices.astype(np.float32))
    connectivity = " ".join(str(i) for f in faces for i in f)
    offsets = " ".join(str(3 * (k + 1)) for k in range(len(faces)))
    cells = " ".join(repr(v) for v in values.astype(np.float32))
    path.write_text(f"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
<PolyData><Piece NumberOfPoints="{len(vertices)}" NumberOfPolys="{len(faces)}">
<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">{points}</DataArray></Points>
<Polys><DataArray type="Int64" Name="connectivity" format="ascii">{connectivity}</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">{offsets}</DataArray></Polys>
<CellData><DataArray type="Float32" Name="c" format="ascii">{cells}</DataArray></CellData>
</Piece></PolyData></VTKFile>
""")


def test_cell_values_averaged_onto_the_vertices_are_the_command_lines(tmp_path):
    vertices, faces, _ = uv_sphere()
    centres = vertices[faces].mean(axis=1)
    values = np.where(centres[:, 0] > 0.3, 1.0, 0.0) + centres[:, 2]  # a step: averaging smooths it
    path = tmp_path / "cells.vtp"
    write_vtp_with_cell_data(path, vertices, faces, values)
    done = run_cli("render", str(path), "--scalar", "c", "--cell-to-point", "--res", "160x160", "--theta", "70",
                   "--volume-res", "64", "-o", str(tmp_path / "cli.png"))
    assert done.returncode == 0, done.stderr
    averaged = inversevis.render(inversevis.Mesh.read(path), scalar="c", cell_to_point=True, size=(160, 160), theta=70,
                                 volume_resolution=64)
    assert averaged._repr_png_() == (tmp_path / "cli.png").read_bytes()
    # The same values per cell given as arrays, and shown per cell: the averaged picture has values no cell has.
    given = inversevis.Mesh(vertices.astype(np.float32), faces, cell_data={"c": values.astype(np.float32)})
    assert np.array_equal(inversevis.render(given, scalar="c", cell_to_point=True, size=(160, 160), theta=70,
                                            volume_resolution=64).rgba, averaged.rgba)
    per_cell = inversevis.render(given, scalar="c", size=(160, 160), theta=70, volume_resolution=64)
    cell_values = set(np.float32(values).tolist())
    shown = averaged.layers["scalar"][averaged.layers["region"] > 0]
    assert any(v not in cell_values for v in shown.tolist())
    assert set(per_cell.layers["scalar"][per_cell.layers["region"] > 0].tolist()) <= cell_values


def test_the_stub_file_names_every_keyword_the_functions_take():
    import ast
    import pathlib
    import re
    stub = pathlib.Path(inversevis.__file__).with_name("inversevis.pyi")
    stubbed = {node.name: [a.arg for a in node.args.args + node.args.kwonlyargs]
               for node in ast.parse(stub.read_text()).body if isinstance(node, ast.FunctionDef)}
    for function in (inversevis.render, inversevis.optimize, inversevis.read_view):
        signature = function.__doc__.splitlines()[0]  # pybind11's "name(arg: type = default, *, ...) -> type"
        taken = re.findall(r"(?:\(|, )(\w+):", signature[:signature.rindex(") ->")])
        assert stubbed[function.__name__] == taken, function.__name__


def test_a_mesh_far_from_its_origin_renders_as_at_its_origin():
    """Coordinates given in double precision a million units away keep every triangle and the picture."""
    vertices, faces, height = uv_sphere()
    offset = np.array([1e6, -2e6, 5e5])
    near = inversevis.Mesh(vertices, faces, point_data={"height": height})
    far = inversevis.Mesh(vertices + offset, faces, point_data={"height": height})
    assert len(far.faces) == len(near.faces)
    assert np.allclose(far.vertices, (vertices + offset).astype(np.float32))
    a = inversevis.render(near, size=(160, 160), theta=60, phi=20).rgba
    b = inversevis.render(far, size=(160, 160), theta=60, phi=20).rgba
    differs = np.any(np.abs(a.astype(int) - b.astype(int)) > 2, axis=-1)
    assert differs.mean() < 0.01
