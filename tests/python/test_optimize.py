"""optimize() finds the view `inversevis optimize` finds and draws its picture byte for byte; the
same seed gives the same result; bad settings are refused before anything runs."""
import json

import pytest

import inversevis
from conftest import run_cli

SMALL = dict(volume_resolution=64, opt_res=24, steps=2, finalists=0, size=(200, 160))


def test_optimize_finds_and_draws_what_the_cli_does(tmp_path):
    cli_png, cli_json = tmp_path / "cli.png", tmp_path / "cli.json"
    done = run_cli("optimize", "scene:vessel-tree", "--volume-res", "64", "--opt-res", "24", "--steps", "2",
                   "--finalists", "0", "--res", "200x160", "--energy", "scalar", "--hot-spot-views", "2", "-o",
                   str(cli_png), "--json", str(cli_json))
    assert done.returncode == 0, done.stderr
    picture = inversevis.optimize(inversevis.Mesh.read("scene:vessel-tree"), energy="scalar", hot_spot_views=2, **SMALL)
    picture.save(str(tmp_path / "py.png"))
    assert (tmp_path / "py.png").read_bytes() == cli_png.read_bytes()
    cli = json.loads(cli_json.read_text())
    assert picture.optimization["theta"] == cli["theta"] and picture.optimization["phi"] == cli["phi"]
    assert picture.optimization["energy_value"] == cli["energy_value"]
    assert len(picture.optimization["visited"]) == len(cli["visited"])
    assert picture.method == cli["params"]
    assert picture.optimization["hot_spot_rule"] == cli["hot_spot_rule"]
    for key, value in cli["measures"].items():
        assert picture.measures[key] == value, key
    # The best view's camera draws the same picture again with render().
    again = inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), camera=picture.camera, size=(200, 160),
                              volume_resolution=64, min_coherence=0, **{k: v for k, v in picture.method.items()
                                                                         if k != "method"})
    assert (again.rgba == picture.rgba).all()


def test_optimize_takes_renders_choice_of_scalar_and_look(tmp_path):
    cli_png, cli_json = tmp_path / "cli.png", tmp_path / "cli.json"
    done = run_cli("optimize", "scene:vessel-tree", "--volume-res", "64", "--opt-res", "24", "--steps", "2",
                   "--finalists", "0", "--res", "200x160", "--hotspots", "2", "--energy", "scalar", "--invert",
                   "--units", "a.u.", "--legend", "bottom", "--no-outline", "--unshaded-indirect", "--range-percentile",
                   "10", "90", "--hot-spot-views", "2", "-o", str(cli_png), "--json", str(cli_json))
    assert done.returncode == 0, done.stderr
    picture = inversevis.optimize(inversevis.Mesh.read("scene:vessel-tree"), hotspots=2, energy="scalar", invert=True,
                                  units="a.u.", legend_side="bottom", outline=False, shade_indirect=False,
                                  range_percentile=(10, 90), hot_spot_views=2, **SMALL)
    assert picture._repr_png_() == cli_png.read_bytes()
    cli = json.loads(cli_json.read_text())
    assert picture.optimization["theta"] == cli["theta"] and picture.optimization["phi"] == cli["phi"]
    assert len(picture.measures["reveal"]["per_region"]) == 2
    assert picture.measures["reveal"] == cli["measures"]["reveal"]


def test_several_views_are_those_the_cli_chooses_and_draws(tmp_path):
    cli_png, cli_json = tmp_path / "cli.png", tmp_path / "cli.json"
    done = run_cli("optimize", "scene:vessel-tree", "--volume-res", "64", "--opt-res", "24", "--steps", "2",
                   "--finalists", "0", "--res", "200x160", "--views", "2", "-o", str(cli_png), "--json", str(cli_json))
    assert done.returncode == 0, done.stderr
    picture = inversevis.optimize(inversevis.Mesh.read("scene:vessel-tree"), views=2, **SMALL)
    picture.save_views(str(tmp_path / "py.png"))
    assert (tmp_path / "py.png").read_bytes() == cli_png.read_bytes()
    cli = json.loads(cli_json.read_text())["several_views"]
    assert picture.optimization["several_views"] == cli
    assert len(picture.views) == 2
    assert (picture.views[0].rgba == picture.rgba).all(), "the best view first"
    for view, measured in zip(picture.views, cli["views"]):
        assert view.measures == measured
        assert view.method == measured["params"]
    assert cli["union"]["visibility"] > max(v["visibility"] for v in cli["views"])
    # The second view's file draws it again with the command line.
    picture.views[1].save_view(str(tmp_path / "second.json"))
    again = run_cli("render", "scene:vessel-tree", "--volume-res", "64", "--view", str(tmp_path / "second.json"),
                    "-o", str(tmp_path / "again.png"))
    assert again.returncode == 0, again.stderr
    picture.views[1].save(str(tmp_path / "second.png"))
    assert (tmp_path / "again.png").read_bytes() == (tmp_path / "second.png").read_bytes()
    with pytest.raises(ValueError, match="no several views"):
        inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), "front", size=(40, 40),
                          volume_resolution=64).save_views(str(tmp_path / "none.png"))


def test_the_same_seed_gives_the_same_view_and_another_start_is_taken():
    mesh = inversevis.Mesh.read("scene:vessel-tree")
    first = inversevis.optimize(mesh, "inversevis", seed=7, **SMALL)
    second = inversevis.optimize(mesh, "inversevis", seed=7, **SMALL)
    seconds = lambda picture: {k: v for k, v in picture.optimization.items() if k != "seconds"}
    assert seconds(first) == seconds(second)
    assert (first.rgba == second.rgba).all()
    started = inversevis.optimize(mesh, "inversevis", seed=7, start=(45.0, 120.0), **SMALL)
    assert started.optimization["visited"][0]["theta"] == pytest.approx(45.0)
    assert started.optimization["visited"][0]["phi"] == pytest.approx(120.0)
    # A start beyond the pole is the command line's: theta -30 is 30 on the other side (it was taken as given).
    over = inversevis.optimize(mesh, "inversevis", seed=7, start=(-30.0, 10.0), **SMALL)
    assert over.optimization["visited"][0]["theta"] == pytest.approx(30.0)
    assert over.optimization["visited"][0]["phi"] == pytest.approx(-170.0)
    # A render() picture carries no search.
    assert inversevis.render(mesh, "front", size=(40, 40), volume_resolution=64).optimization is None


@pytest.mark.parametrize("arguments, message", [
    (dict(energy="area"), "energy 'area': visibility or scalar"),
    (dict(opt_res=2), "opt_res 2 is out of range"),
    (dict(opt_res=24, ascent_res=24), "ascent_res 24 must lie from 4 to below opt_res"),
    (dict(seed=-1), "seed -1 must be a whole number from 0"),
    (dict(opt_res=24, ascent_res=2), "ascent_res 2 must lie from 4"),
    (dict(steps=-1), "steps -1 is out of range"),
    (dict(gamma=2.0), "gamma weights the directly visible part of the scalar energy; energy is visibility"),
    (dict(energy="scalar", gamma=-1.0), "gamma -1"),
    (dict(finalists=-2), "finalists -2 is out of range"),
    (dict(min_coherence=1.5), "min_coherence"),
    (dict(method="inversevis", min_coherence=0.5), "min_coherence: inversevis has no rule for drawing rays"),
    (dict(start=(float("inf"), 0.0)), "start .inf, 0.*: theta and phi must be finite"),
    (dict(size=(4, 100)), "needs a wider picture"),
    (dict(views=0), "views 0 is out of range"),
    (dict(views=2, energy="scalar"), "need energy='visibility'"),
    (dict(hot_spot_views=3), "hot_spot_views: the hot-spot rule chooses among views by the scalar energy; energy is "
                             "visibility"),
])
def test_bad_settings_are_refused_with_a_clear_message(arguments, message):
    mesh = inversevis.Mesh.read("scene:vessel-tree")
    with pytest.raises(ValueError, match=message):
        inversevis.optimize(mesh, **{**SMALL, **arguments})


def test_a_keyword_neither_argument_nor_parameter_is_a_type_error():
    mesh = inversevis.Mesh.read("scene:vessel-tree")
    for keyword in ("alpha", "fov", "measure"):  # a paper-model parameter, and render()'s own arguments
        with pytest.raises(TypeError, match=f"optimize\\(\\) got an unexpected keyword argument '{keyword}'"):
            inversevis.optimize(mesh, **{**SMALL, keyword: 0.5})


def test_the_scalar_energy_needs_a_scalar():
    import numpy as np
    mesh = inversevis.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float32),
                           np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))
    with pytest.raises(inversevis.InputError, match="the scalar energy needs a scalar"):
        inversevis.optimize(mesh, energy="scalar", **SMALL)
    # Colours of a scalar the mesh does not show are refused, as `optimize --log` refuses them.
    with pytest.raises(inversevis.InputError, match="log= colours a scalar, and the mesh shows none"):
        inversevis.optimize(mesh, log=True, **SMALL)


def test_ctrl_c_stops_a_search_within_a_second():
    import os
    import subprocess
    import sys
    import textwrap
    script = textwrap.dedent("""
        import os, signal, threading, time, inversevis
        mesh = inversevis.Mesh.read("scene:vessel-tree")
        inversevis.render(mesh, "front", size=(20, 20), volume_resolution=64)
        threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        start = time.monotonic()
        try:
            inversevis.optimize(mesh, volume_resolution=64, steps=100000)
        except KeyboardInterrupt:
            print("interrupted after", time.monotonic() - start)
        else:
            print("finished")
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=dict(os.environ),
                          timeout=300)
    assert done.returncode == 0, done.stderr
    words = done.stdout.split()
    assert words[0] == "interrupted", done.stdout
    assert float(words[-1]) < 2.5  # the signal at 1 s, the search stopped within a second or so
