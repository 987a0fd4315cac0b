"""What a picture shows, asked from Python as the command line asks it: a pixel probed, the tear
map and the unseen map are those of `render --probe`, `--tear-map` and `--unseen-map`."""
import json

import numpy as np
import pytest

import inversevis
from conftest import read_png, run_cli

VIEW = ["--res", "200x150", "--theta", "70", "--phi", "30"]


@pytest.fixture(scope="module")
def tree():
    """The vessel tree's picture from Python, at the command line's view."""
    return inversevis.render(inversevis.Mesh.read("scene:vessel-tree"), size=(200, 150), theta=70, phi=30)


def test_a_probed_pixel_says_what_render_probe_says(tmp_path, tree):
    region = tree.layers["region"]
    pixels = [tuple(int(c) for c in np.argwhere(region == kind)[len(np.argwhere(region == kind)) // 2][::-1])
              for kind in (0, 1, 2)]  # (x, y) of a background, a direct and an indirect pixel
    stats = tmp_path / "s.json"
    probes = [arg for x, y in pixels for arg in ("--probe", f"{x},{y}")]
    done = run_cli("render", "scene:vessel-tree", *VIEW, *probes, "-o", str(tmp_path / "t.png"),
                   "--stats-json", str(stats))
    assert done.returncode == 0, done.stderr
    expected = json.loads(stats.read_text())["probes"]
    probed = [tree.probe(x, y) for x, y in pixels]
    assert [p["region"] for p in probed] == ["background", "direct", "indirect"]
    assert probed == expected
    assert probed[2]["launch"]["drawn"] and probed[2]["view"] is not None


def test_a_pixel_outside_the_picture_is_refused(tree):
    with pytest.raises(ValueError, match=r"probe\(200, 0\): outside the 200x150 picture \(x 0 to 199, y 0 to 149\)"):
        tree.probe(200, 0)
    with pytest.raises(ValueError, match="outside"):
        tree.probe(0, -1)
    with pytest.raises(ValueError, match=r"probe\(2147483648, 0\): outside"):
        tree.probe(2**31, 0)
    with pytest.raises(ValueError, match=r"probe\(1180591620717411303424, -1180591620717411303424\): outside"):
        tree.probe(2**70, -2**70)  # it named the pixel as clamped to 64 bits
    with pytest.raises(TypeError, match="x must be a pixel's column \\(an integer\\), got float"):
        tree.probe(1.5, 0)
    assert tree.probe(np.int64(10), np.int32(10))["pixel"] == [10, 10]  # numpy integers, as indices are


def test_the_tear_and_unseen_maps_are_the_command_lines(tmp_path, tree):
    tears, unseen = tmp_path / "tears.png", tmp_path / "unseen.png"
    done = run_cli("render", "scene:vessel-tree", *VIEW, "-o", str(tmp_path / "t.png"), "--tear-map", str(tears),
                   "--unseen-map", str(unseen))
    assert done.returncode == 0, done.stderr
    torn = tree.tear_map()
    assert torn.shape == (150, 200, 3) and torn.dtype == np.uint8
    assert np.array_equal(torn, read_png(tears))
    red = (torn[..., 0] > 200) & (torn[..., 1] < 80)
    assert 0 < red.sum() < (tree.layers["region"] == 2).sum()  # some tears, among the indirect pixels only
    assert np.array_equal(tree.unseen_map(), read_png(unseen))
    assert tree.unseen_map().shape == (150, 300, 3)
