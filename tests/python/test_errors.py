"""Every bad array and bad argument is a ValueError or TypeError with a clear message, never a crash;
nothing is written where the picture cannot be made."""
import numpy as np
import pytest

import inversevis
from conftest import run_cli, uv_sphere


@pytest.fixture(scope="module")
def sphere():
    return uv_sphere(8, 12)


@pytest.mark.parametrize("vertices, faces, error, words", [
    (np.zeros((4, 2)), np.array([[0, 1, 2]]), ValueError, "vertices must be a float32 or float64 array of shape (n, 3), got float64 (4, 2)"),
    (np.zeros((4, 3), dtype=np.int64), np.array([[0, 1, 2]]), ValueError, "vertices must be"),
    (np.zeros(12), np.array([[0, 1, 2]]), ValueError, "got float64 (12,)"),
    (np.eye(3), np.array([[0.0, 1.0, 2.0]]), ValueError, "faces must be an int32 or int64 array of shape (m, 3)"),
    (np.eye(3), np.array([[0, 1, 2, 0]]), ValueError, "got int64 (1, 4)"),
    (np.eye(3), np.array([[0, 1, 3]]), inversevis.InputError, "face 0 references vertex 3 but the mesh has 3 vertices"),
    (np.eye(3), np.array([[0, 1, -1]]), inversevis.InputError, "references vertex -1"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]]), np.array([[0, 1, 2]]), inversevis.InputError,
     "vertex 2 has a non-finite coordinate"),
    (np.eye(3), np.array([[0, 1, 1]]), inversevis.InputError, "mesh has no triangles"),
    # uint64 above int64's range was read as -1
    (np.eye(3), np.array([[0, 1, 2**64 - 1]], dtype=np.uint64), inversevis.InputError,
     "face 0 references vertex 18446744073709551615 but the mesh has 3 vertices"),
    # not arrays: the messages held pybind11's repr of every argument (megabytes for a real mesh)
    (None, [[0, 1, 2]], TypeError, "vertices must be a float32 or float64 array of shape (n, 3), got NoneType"),
    ("mesh.ply", [[0, 1, 2]], TypeError, "vertices must be a float32 or float64 array of shape (n, 3), got str"),
    (np.eye(3), 7, TypeError, "faces must be an int32 or int64 array of shape (m, 3) (vertex indices from 0), got int"),
    ([[0, 0], [1, 0, 0]], [[0, 1, 2]], ValueError, "got a sequence numpy cannot read as one"),
    (np.eye(3), [[0.0, 1.0, 2.0]], ValueError, "faces must be an int32 or int64 array of shape (m, 3)"),
])
def test_bad_arrays_are_refused_with_a_clear_message(vertices, faces, error, words):
    with pytest.raises(error) as refused:
        inversevis.Mesh(vertices, faces)
    assert words in str(refused.value)


def test_bad_point_and_cell_data_are_refused(sphere):
    v, f, h = sphere
    with pytest.raises(ValueError, match=r"point_data\['h'\] must have shape \(86,\) or \(86, k\), one tuple per vertex"):
        inversevis.Mesh(v, f, point_data={"h": h[:-1]})
    with pytest.raises(ValueError, match=r"cell_data\['c'\] must have shape \(168,\)"):
        inversevis.Mesh(v, f, cell_data={"c": np.zeros(3)})
    with pytest.raises(TypeError, match=r"point_data\['s'\] must hold numbers"):
        inversevis.Mesh(v, f, point_data={"s": np.array(["a"] * len(v))})
    with pytest.raises(TypeError, match="point_data must be a dict"):
        inversevis.Mesh(v, f, point_data=[h])
    with pytest.raises(TypeError, match="keys must be array names"):
        inversevis.Mesh(v, f, point_data={1: h})


def test_bad_render_arguments_are_refused_before_anything_is_built(sphere, tmp_path):
    mesh = inversevis.Mesh(*sphere[:2], point_data={"h": sphere[2]})
    cases = [
        (dict(method="nothing"), ValueError, "unknown method 'nothing'"),
        (dict(alpha=0.5), TypeError, "render() got an unexpected keyword argument 'alpha' (neither one of its "
                                     "arguments nor a parameter of inversevis-wrap: "),
        (dict(colourmap="magma"), TypeError, "unexpected keyword argument 'colourmap'"),
        (dict(scalar=3), TypeError, "scalar must be an array's name ('NAME', 'NAME:0', 'cell:NAME'), got int"),
        (dict(scalar=np.zeros(86)), TypeError, "got ndarray; to colour by your own values give them to Mesh("),
        (dict(camera={"eye": [0, 0, 2.5]}, theta=30), ValueError,
         "camera= is the whole view; theta, phi, fov and ortho"),
        (dict(camera={"eye": [0, 0, 2.5]}, fov=10), ValueError, "camera= is the whole view"),
        (dict(camera={"eye": [1e20, 0, 0]}), ValueError, "camera eye at 1e+20 normalised units from the object's centre "
                                                         "is out of range"),
        (dict(stable_shift=-1.0), ValueError, "inversevis-wrap stable_shift -1 is out of range (0.0001 to 10)"),
        (dict(stable_shift="a"), TypeError, "stable_shift must be a number"),
        (dict(size=(0, 10)), ValueError, "width and height must be 1 to 32768"),
        (dict(colormap="jet"), ValueError, "jet"),
        (dict(scalar="nope"), inversevis.InputError, "nope"),
        (dict(range=(1.0, 0.0)), ValueError, "range"),
        (dict(min_coherence=2.0), ValueError, "min_coherence"),
        (dict(min_coherence=float("nan")), ValueError, "min_coherence nan must lie in [0, 1]"),  # it turned the rule off
        (dict(theta=float("nan")), ValueError, "theta nan must be finite"),  # it named the camera's eye
        (dict(method="front", min_coherence=0.5), ValueError,  # it did nothing, as `render --method front
         "min_coherence: front has no rule for drawing rays to loosen"),  # --min-coherence 0.5` refuses
        (dict(spp=0), ValueError, "spp 0"),
        (dict(camera={"target": [0, 0, 0]}), ValueError, "camera"),
        (dict(volume_resolution=3), ValueError, "resolution"),
        (dict(progress=5), TypeError, "progress must be None or a callable"),
        (dict(hotspots=2, scalar="h"), ValueError, "scalar= and hotspots= exclude each other"),
        (dict(hotspots=1, cell_to_point=True), ValueError, "cell_to_point= and hotspots= exclude each other"),
        (dict(hotspots=7), ValueError, "hotspots 7 must be 0 to 6"),
        (dict(hotspots=True), TypeError, "hotspots must be a number of hot spots (0 to 6), got bool"),
        (dict(hotspots="2"), TypeError, "hotspots must be a number of hot spots (0 to 6), got str"),
        (dict(hotspots=np.bool_(True)), TypeError, "got bool"),
        (dict(hotspots=2**64), ValueError, "hotspots 18446744073709551616 must be 0 to 6"),
        (dict(hotspots=np.int64(-1)), ValueError, "hotspots -1 must be 0 to 6"),
        (dict(scalar="h", cell_to_point=True), inversevis.InputError,
         "cell_to_point averages a cell array; 'h' is a point array"),
        (dict(log=True, symmetric=True), ValueError, "log and symmetric exclude each other"),
        (dict(range=(0, 1), range_percentile=(5, 95)), ValueError, "range and range_percentile exclude each other"),
        (dict(range_percentile=(50, 10)), ValueError, "range_percentile [50, 10]: expected 0 <= LO < HI <= 100"),
        (dict(fov=30, ortho=True), ValueError, "fov= and ortho= exclude each other"),
        (dict(camera={"eye": [0, 0, 2.5]}, ortho=True), ValueError, "camera= is the whole view"),
        # it was nlohmann's parse error of Python's "NaN"
        (dict(camera={"eye": [float("nan"), 0, 2.5]}), ValueError, "not a camera (a camera file's JSON, as "
                                                                   "Picture.camera): its numbers must be finite"),
        (dict(method="front", alpha=1), TypeError, "nor a parameter of front, which has none)"),
    ]
    for arguments, error, words in cases:
        with pytest.raises(error) as refused:
            inversevis.render(mesh, **{"size": (40, 40), **arguments})
        assert words in str(refused.value), arguments
    with pytest.raises(TypeError):
        inversevis.render(mesh, size="big")
    assert inversevis.render(mesh, "front", hotspots=np.int64(2), size=(40, 40)).measures["pixels_direct"] > 0


def test_colours_of_a_scalar_the_mesh_does_not_show_are_refused_as_the_cli_refuses_them(sphere, tmp_path):
    mesh = inversevis.Mesh(*sphere[:2])  # geometry alone
    for keyword, value in [("symmetric", True), ("log", True), ("invert", True), ("units", "Pa"), ("colormap", "magma"),
                           ("range_percentile", (5, 95)), ("range", (0, 1)), ("legend_side", "left")]:
        with pytest.raises(inversevis.InputError, match=f"Mesh: {keyword}= colours a scalar, and the mesh shows none"):
            inversevis.render(mesh, size=(40, 40), volume_resolution=32, **{keyword: value})
    # The command line refuses the same flag on the same geometry.
    path = tmp_path / "plain.obj"
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in sphere[0]) +
                    "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in sphere[1]))
    done = run_cli("render", str(path), "--symmetric", "--res", "40x40", "--volume-res", "32", "-o",
                   str(tmp_path / "x.png"))
    assert done.returncode == 2 and "--symmetric colours a scalar, and the mesh shows none" in done.stderr


def test_bad_files_raise_the_cli_s_one_line(tmp_path):
    missing = tmp_path / "missing.ply"
    with pytest.raises(inversevis.InputError, match=f"^{missing}: "):
        inversevis.Mesh.read(str(missing))
    broken = tmp_path / "broken.ply"
    broken.write_text("ply\nformat ascii 1.0\nelement vertex 3\n")
    with pytest.raises(inversevis.InputError, match=f"^{broken}: "):
        inversevis.Mesh.read(str(broken))
    with pytest.raises(inversevis.InputError, match="unknown scene 'nothing'"):
        inversevis.Mesh.read("scene:nothing")
    with pytest.raises(inversevis.InputError, match=f"^{missing}: "):  # a pathlib.Path as well
        inversevis.Mesh.read(missing)
    with pytest.raises(TypeError):
        inversevis.Mesh.read(3)


def test_save_refuses_other_formats_and_writes_nothing(tmp_path):
    picture = inversevis.render(inversevis.Mesh.read("scene:sphere"), "front", size=(30, 30))
    with pytest.raises(ValueError, match=r"\.png or \.exr"):
        picture.save(str(tmp_path / "p.jpg"))
    with pytest.raises(inversevis.InputError):
        picture.save(str(tmp_path / "no" / "folder" / "p.png"))
    with pytest.raises(ValueError, match=r"view file is saved as \.json"):  # JSON in a .png replaced a figure
        picture.save_view(tmp_path / "figure.png")
    assert list(tmp_path.iterdir()) == []


def test_points_no_face_uses_are_left_out_with_their_data(sphere):
    """Unused points (as VTK files carry them) neither widen the framing nor the colour range."""
    v, f, h = sphere
    far = np.vstack([v, [[40.0, 40.0, 40.0]]])
    mesh = inversevis.Mesh(far, f, point_data={"h": np.append(h, 5.0)})
    assert np.array_equal(mesh.vertices, v.astype(np.float32))
    assert mesh.arrays[0]["max"] == pytest.approx(h.max())
    kept = inversevis.render(mesh, "front", size=(40, 40)).rgba
    assert np.array_equal(kept, inversevis.render(inversevis.Mesh(v, f, point_data={"h": h}), "front", size=(40, 40)).rgba)
    nan = inversevis.Mesh(np.vstack([v, [[np.nan, 0.0, 0.0]]]), f)  # refused only where a face uses it
    assert len(nan.vertices) == len(v)


def test_an_array_of_nan_only_has_no_range(sphere):
    """As `info --json` gives null: a range of 0 to 0 would read as a constant array."""
    v, f, h = sphere
    mesh = inversevis.Mesh(v, f, point_data={"h": h, "gone": np.full(len(v), np.nan)})
    gone = next(a for a in mesh.arrays if a["name"] == "gone")
    assert (gone["min"], gone["max"], gone["nan_count"]) == (None, None, len(v))


def test_arrays_in_either_byte_order_are_the_same_mesh(sphere):
    v, f, h = sphere
    native = inversevis.Mesh(v, f, point_data={"h": h}, cell_data={"c": np.arange(len(f), dtype=np.int32)})
    swapped = inversevis.Mesh(v.astype(">f8"), f.astype(">i8"), point_data={"h": h.astype(">f4")},
                              cell_data={"c": np.arange(len(f), dtype=">i4")})
    assert np.array_equal(native.vertices, swapped.vertices)
    assert np.array_equal(native.faces, swapped.faces)
    for a, b in zip(native.arrays, swapped.arrays):
        assert (a["min"], a["max"]) == pytest.approx((b["min"], b["max"]), rel=1e-6)


def test_a_message_holding_bytes_that_are_not_utf8_still_says_what_is_wrong(tmp_path):
    bad = tmp_path / "view.json"
    bad.write_bytes(b"\xff\xfe not json")
    with pytest.raises(inversevis.InputError) as refused:
        inversevis.read_view(str(bad))
    assert str(refused.value).startswith(f"{bad}: ")


def test_the_scalar_energy_of_a_scalar_without_values_is_refused(sphere):
    """Every value NaN: every view's energy was 0 and optimize() returned theta 0, phi 0 silently."""
    v, f, _ = sphere
    mesh = inversevis.Mesh(v, f, point_data={"z": np.full(len(v), np.nan)})
    with pytest.raises(inversevis.InputError, match="the scalar energy needs values of 'z', which has none"):
        inversevis.optimize(mesh, scalar="z", energy="scalar", opt_res=16, steps=1, size=(60, 60),
                            volume_resolution=48)


def test_a_picture_is_made_only_by_render_and_optimize():
    # Picture.__new__ made an object with nothing inside, whose methods then read garbage or crashed.
    with pytest.raises(TypeError, match="come from render"):
        inversevis.Picture()
    with pytest.raises(TypeError):  # Python's own check: the type's __new__ is not object's
        inversevis.Picture.__new__(inversevis.Picture)


def test_a_mesh_is_made_only_with_its_arrays_or_from_a_file():
    # Mesh.__new__ without __init__ made an object whose uninitialised memory crashed its first method.
    with pytest.raises(TypeError, match="come from Mesh"):
        inversevis.Mesh.__new__(inversevis.Mesh)

    class Named(inversevis.Mesh):  # a subclass is still made and initialised
        pass

    named = Named([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    assert isinstance(named, inversevis.Mesh) and named.faces.tolist() == [[0, 1, 2]]
    with pytest.raises(TypeError, match="come from Mesh"):
        Named.__new__(Named)


def test_nested_lists_are_read_as_arrays():
    listed = inversevis.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], ((0, 1, 2),))
    arrays = inversevis.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float64), np.array([[0, 1, 2]], np.int32))
    assert np.array_equal(listed.vertices, arrays.vertices)
    assert np.array_equal(listed.faces, arrays.faces)


def test_none_for_a_mesh_or_a_folder_for_a_view_file_is_refused(tmp_path):
    with pytest.raises(TypeError):  # it crashed the interpreter
        inversevis.render(None)
    with pytest.raises(TypeError):
        inversevis.optimize(None, "front")
    with pytest.raises(inversevis.InputError, match=str(tmp_path) + ": is a directory"):
        inversevis.read_view(tmp_path)  # a RuntimeError that did not name it
