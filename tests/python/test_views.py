"""View files pass between the command line and Python: a view `render --view-out` wrote draws
the same picture from Python, a Python picture's view draws it on the command line; measure=True
measures what `render --measure` measures."""
import json

import pytest

import inversevis
from conftest import run_cli


def test_a_cli_view_draws_the_same_picture_from_python(tmp_path):
    view, cli_png = tmp_path / "v.view.json", tmp_path / "cli.png"
    done = run_cli("render", "scene:vessel-tree", "--res", "240x180", "--theta", "60", "--phi", "40", "--colormap",
                   "plasma", "--log", "--invert", "--units", "Pa", "--legend", "left", "--no-outline",
                   "--unshaded-indirect", "--volume-res", "64", "-o", str(cli_png), "--view-out", str(view))
    assert done.returncode == 0, done.stderr
    arguments = inversevis.read_view(view)
    assert arguments["size"] == (240, 180) and arguments["log"] and arguments["invert"]
    assert arguments["legend_side"] == "left" and arguments["units"] == "Pa" and not arguments["outline"]
    written = json.loads(view.read_text())["mesh_units"]  # the tree's own transform, not an identity
    assert arguments["camera"]["mesh_units"]["scale"] == written["scale"] != 1.0
    assert arguments["camera"]["mesh_units"]["center"] == written["center"]
    picture = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), volume_resolution=64, **arguments)
    picture.save(str(tmp_path / "py.png"))
    again = run_cli("render", "scene:vessel-tree", "--view", str(view), "--volume-res", "64", "-o",
                    str(tmp_path / "again.png"))
    assert again.returncode == 0, again.stderr
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "again.png").read_bytes()
    assert (tmp_path / "py.png").read_bytes() == cli_png.read_bytes()


def test_a_python_pictures_view_draws_it_on_the_command_line(tmp_path):
    mesh = inversevis.Mesh.read("scene:vessel-tree")
    picture = inversevis.render(mesh, "mirror", size=(200, 150), theta=120, phi=-30, colormap="coolwarm",
                                range=(0.2, 0.8), volume_resolution=64, mirror_w=[0.4, 0.3, 0.0, 0.1, 0.0])
    picture.save(tmp_path / "py.png")  # a pathlib.Path, as Python's own file functions take
    picture.save_view(tmp_path / "p.view.json")
    done = run_cli("render", "scene:vessel-tree", "--view", str(tmp_path / "p.view.json"), "--volume-res", "64",
                   "-o", str(tmp_path / "cli.png"))
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "cli.png").read_bytes() == (tmp_path / "py.png").read_bytes()
    # An optimised picture's view too: its method carries the rule the search chose.
    best = inversevis.optimize(mesh, volume_resolution=64, opt_res=24, steps=1, finalists=0, size=(200, 150))
    best.save_view(str(tmp_path / "best.view.json"))
    assert inversevis.read_view(str(tmp_path / "best.view.json"))["stable_shift"] == best.method["stable_shift"]


def test_bad_views_are_refused_naming_the_file(tmp_path):
    broken = tmp_path / "broken.view.json"
    broken.write_text("{\"inversevis_view\": 1, \"camera\": ")
    with pytest.raises(inversevis.InputError, match="broken.view.json"):
        inversevis.read_view(str(broken))
    scalar_file = tmp_path / "values.txt"
    scalar_file.write_text("\n".join(["1.0"] * 8))
    cube = tmp_path / "cube.obj"
    cube.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                    "f 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\nf 3 7 4\nf 4 7 8\n"
                    "f 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n")
    filed = tmp_path / "filed.view.json"
    done = run_cli("render", str(cube), "--scalar-file", str(scalar_file), "--res", "80x60", "--volume-res", "32",
                   "-o", str(tmp_path / "filed.png"), "--view-out", str(filed))
    assert done.returncode == 0, done.stderr
    with pytest.raises(inversevis.InputError, match="filed.view.json: the view colours by a scalar file"):
        inversevis.read_view(str(filed))


def test_a_view_of_hot_spots_draws_the_same_picture_from_python(tmp_path):
    hot, cli_png = tmp_path / "hot.view.json", tmp_path / "cli.png"
    done = run_cli("render", "scene:vessel-tree", "--hotspots", "2", "--res", "160x120", "--volume-res", "64",
                   "-o", str(cli_png), "--view-out", str(hot))
    assert done.returncode == 0, done.stderr
    arguments = inversevis.read_view(str(hot))
    assert arguments["hotspots"] == 2 and not arguments["cell_to_point"]
    picture = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), volume_resolution=64, **arguments)
    assert picture._repr_png_() == cli_png.read_bytes()
    picture.save_view(tmp_path / "again.view.json")
    assert json.loads((tmp_path / "again.view.json").read_text())["hotspots"] == 2


def test_a_view_of_capped_holes_caps_them_again_on_either_side(tmp_path):
    mesh = inversevis.Mesh.read("scene:vessel-tree")  # open at its four ends
    picture = inversevis.render(mesh, cap_holes=True, size=(160, 120), theta=40, volume_resolution=64)
    picture.save_view(tmp_path / "capped.view.json")
    arguments = inversevis.read_view(tmp_path / "capped.view.json")
    assert arguments["cap_holes"]
    assert inversevis.render(mesh, volume_resolution=64, **arguments)._repr_png_() == picture._repr_png_()
    done = run_cli("render", "scene:vessel-tree", "--view", str(tmp_path / "capped.view.json"), "--volume-res", "64",
                   "-o", str(tmp_path / "cli.png"))
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "cli.png").read_bytes() == picture._repr_png_()


def test_measure_measures_what_render_measure_does(tmp_path):
    stats = tmp_path / "s.json"
    done = run_cli("render", "scene:vessel-tree", "--res", "200x150", "--measure", "--volume-res", "64",
                   "--stats-json", str(stats), "-o", str(tmp_path / "cli.png"))
    assert done.returncode == 0, done.stderr
    measured = json.loads(stats.read_text())["measures"]
    picture = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), size=(200, 150), volume_resolution=64,
                                measure=True)
    for key, value in measured.items():
        assert picture.measures[key] == value, key
    assert 0.0 < picture.measures["visibility"] <= 1.0
    assert "visibility" not in inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), size=(200, 150),
                                                 volume_resolution=64).measures
