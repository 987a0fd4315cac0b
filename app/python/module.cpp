// The Python module `inversevis`: PYBIND11_MODULE and the docstrings users read with help().
#include "python_errors.h"
#include "python_json.h"
#include "python_mesh.h"
#include "python_optimize.h"
#include "python_picture.h"
#include "python_render.h"
#include "python_view.h"

#include <ivis/core/camera_json.h>
#include <ivis/core/data_array.h>
#include <ivis/core/errors.h>
#include <ivis/core/hot_spots.h>
#include <ivis/optimize/readable_rule.h>
#include <ivis/render/method_registry.h>

#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace py = pybind11;
using namespace ivis;

namespace {

/// One array as a dict, the keys `inversevis info --json` uses.
py::dict arrayDict(const core::ArrayInfo& a)
{
    py::dict d;
    d["name"] = python::decodedText(a.name);
    d["association"] = core::associationName(a.association);
    d["type"] = core::valueTypeName(a.type);
    d["components"] = a.components;
    d["min"] = std::isnan(a.min) ? py::object(py::none()) : py::object(py::float_(a.min));  // None: no finite value
    d["max"] = std::isnan(a.max) ? py::object(py::none()) : py::object(py::float_(a.max));
    d["nan_count"] = a.nanCount;
    d["shown_by_default"] = a.shownByDefault;
    return d;
}

/// @a result, once what the call logged is said in Python (python::sayLogged).
template <typename T>
T said(T result)
{
    python::sayLogged();
    return result;
}

/// A path given as str or os.PathLike (pathlib.Path), as Python's own file functions take it.
std::string pathText(const py::object& path)
{
    const py::object text = py::module_::import("os").attr("fspath")(path);  // a TypeError for anything else
    if (!py::isinstance<py::str>(text)) throw py::type_error("path must be a str or an os.PathLike of str, not bytes");
    return text.cast<std::string>();
}

/// The array named by scalar= (None: the file's default); a TypeError for anything but a name.
std::string scalarName(const py::object& scalar)
{
    if (scalar.is_none()) return {};
    if (!py::isinstance<py::str>(scalar))
        throw py::type_error("scalar must be an array's name ('NAME', 'NAME:0', 'cell:NAME'), got " +
                             py::str(scalar.get_type().attr("__name__")).cast<std::string>() +
                             "; to colour by your own values give them to Mesh(..., point_data={'NAME': values})");
    return scalar.cast<std::string>();
}

/// An integer argument as Python's operator.index takes it (an int, a numpy integer), clamped to
/// the range of long long beyond it (where the caller's range check refuses it); a bool, or
/// anything else, raises TypeError naming @a name and @a what it must be.
long long wholeNumber(const py::object& value, const std::string& name, const std::string& what)
{
    const bool isBool = py::isinstance<py::bool_>(value) ||
                        py::str(value.get_type().attr("__name__")).cast<std::string>().rfind("bool", 0) == 0;
    if (isBool || !PyIndex_Check(value.ptr()))
        throw py::type_error(name + " must be " + what + ", got " +
                             py::str(value.get_type().attr("__name__")).cast<std::string>());
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    if (!index) throw py::error_already_set();
    int overflow = 0;
    const long long number = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow > 0) return std::numeric_limits<long long>::max();
    if (overflow < 0) return std::numeric_limits<long long>::min();
    return number;
}

/// hotspots= as a count: a bool (hotspots=True would draw one) and anything but a whole number are refused.
int hotSpotCount(const py::object& hotSpots)
{
    const long long count =
        wholeNumber(hotSpots, "hotspots", "a number of hot spots (0 to " + std::to_string(core::kMaxHotSpots) + ")");
    if (count < 0 || count > core::kMaxHotSpots)
        throw ValueError("hotspots " + py::str(hotSpots).cast<std::string>() + " must be 0 to " +
                         std::to_string(core::kMaxHotSpots));
    return int(count);
}

/// What a picture shows of its mesh: scalar=, cell_to_point=, hotspots= and cap_holes=, as `render`'s
/// --scalar, --cell-to-point, --hotspots and --cap-holes (checked against each other by Mesh::shown).
core::SurfaceLoadOptions shownBy(const py::object& scalar, bool cellToPoint, const py::object& hotSpots,
                                  bool capHoles)
{
    core::SurfaceLoadOptions load;
    load.read.scalarName = scalarName(scalar);
    load.read.cellToPoint = cellToPoint;
    load.hotSpots = hotSpotCount(hotSpots);
    load.capHoles = capHoles;
    return load;
}

/// Makes `Type.__new__(Type)` with no arguments raise TypeError @a message. pybind11 gives an object
/// made so, never passed to __init__, uninitialised memory as its value, which any method then reads.
/// With arguments (`Type(...)` of a subclass calls __new__ so, then __init__) it makes the object as
/// before; `Type(...)` itself calls the tp_new slot, which stays pybind11's.
void refuseBareNew(const py::handle& type, const char* message)
{
    auto* typeObject = reinterpret_cast<PyTypeObject*>(type.ptr());
    const newfunc make = typeObject->tp_new;
    py::cpp_function guarded(
        [typeObject, make, message](const py::handle& cls, const py::args& args,
                                    const py::kwargs& kwargs) -> py::object {
            if (args.empty() && kwargs.empty()) throw py::type_error(message);
            if (!PyType_Check(cls.ptr()) || !PyType_IsSubtype(reinterpret_cast<PyTypeObject*>(cls.ptr()), typeObject))
                throw py::type_error(std::string("__new__'s first argument must be ") + typeObject->tp_name +
                                     " or a subclass of it");
            PyObject* made = make(reinterpret_cast<PyTypeObject*>(cls.ptr()), args.ptr(), kwargs.ptr());
            if (!made) throw py::error_already_set();
            return py::reinterpret_steal<py::object>(made);
        },
        py::name("__new__"));
    if (PyDict_SetItemString(typeObject->tp_dict, "__new__", py::staticmethod(guarded).ptr()) != 0)
        throw py::error_already_set();
    PyType_Modified(typeObject);
}

}  // namespace

PYBIND11_MODULE(inversevis, m)
{
    m.doc() = "InverseVis: both sides of a surface in one picture. Read a mesh (or give it as numpy arrays), "
              "render it with a method, get the picture's pixels and layers as numpy arrays. The pictures are "
              "those of `inversevis render` with the same arguments (docs/python.md).";
    python::registerErrors(m);

    py::class_<python::Mesh, std::shared_ptr<python::Mesh>> mesh(m, "Mesh",
                                                                 R"(A surface mesh with its point and cell arrays.

Mesh(vertices, faces, point_data=None, cell_data=None): vertices an (n, 3) float32 or float64
array, faces an (m, 3) int32 or int64 array of vertex indices from 0, point_data and cell_data
dicts of arrays with n (or m) rows: (n,) for a scalar, (n, k) for k components; nested lists are read
as numpy.asarray reads them (the vertices as float64). Mesh.read(path)
reads a file instead. Renders of one mesh share its volumes (and the command line's cache).)");
    refuseBareNew(mesh, "inversevis.Mesh objects come from Mesh(vertices, faces, ...) and Mesh.read(path)");
    mesh.def(py::init([](const py::object& vertices, const py::object& faces, const py::object& pointData,
                         const py::object& cellData) {
                 auto dictOf = [](const py::object& o, const char* name) {
                     if (o.is_none()) return py::dict();
                     if (!py::isinstance<py::dict>(o)) throw py::type_error(std::string(name) + " must be a dict of arrays");
                     return o.cast<py::dict>();
                 };
                 return said(python::Mesh::fromArrays(vertices, faces, dictOf(pointData, "point_data"),
                                                      dictOf(cellData, "cell_data")));
             }),
             py::arg("vertices"), py::arg("faces"), py::arg("point_data") = py::none(), py::arg("cell_data") = py::none())
        .def_static("read", [](const py::object& path) { return said(python::Mesh::read(pathText(path))); },
                    py::arg("path"),
                    "Reads a mesh file (.obj .off .ply .stl .vtk .vtp .vtu, as `inversevis render` does) or a "
                    "generated scene ('scene:vessel-tree'); raises InputError naming the file and the problem.")
        .def_property_readonly("source", &python::Mesh::source, "The file read, 'scene:<name>', or 'Mesh' for arrays.")
        .def_property_readonly("vertices", &python::Mesh::vertices, "(n, 3) float32 copy of the vertices, in the mesh's own units.")
        .def_property_readonly("faces", &python::Mesh::faces, "(m, 3) int64 copy of the triangles (polygons fan-triangulated).")
        .def_property_readonly(
            "point_data", [](const python::Mesh& mesh) { return mesh.data(core::Association::Point); },
            "The point arrays' values by name, one row per vertex (as vertices; float64, (n,) or (n, k)), "
            "copied; a generated scene's own scalar.")
        .def_property_readonly(
            "cell_data", [](const python::Mesh& mesh) { return mesh.data(core::Association::Cell); },
            "The cell arrays' values by name, one row per face (as faces: each triangle its polygon's value; "
            "float64, (m,) or (m, k)), copied.")
        .def_property_readonly(
            "arrays",
            [](const python::Mesh& mesh) {
                py::list list;
                for (const core::ArrayInfo& a : mesh.arrays()) list.append(arrayDict(a));
                return list;
            },
            "The point and cell arrays, as `inversevis info` lists them: dicts with name, association, type, "
            "components, min, max, nan_count, shown_by_default.")
        .def("__repr__", [](const python::Mesh& mesh) {
            return python::decodedText("<inversevis.Mesh " + mesh.source() + ": " + std::to_string(mesh.vertexCount()) +
                                       " vertices, " + std::to_string(mesh.triangleCount()) + " triangles, " +
                                       std::to_string(mesh.arrays().size()) + " arrays>");
        });

    py::class_<python::Picture, std::shared_ptr<python::Picture>> picture(m, "Picture", "A rendered picture (render()).");
    // A Picture comes from render() or optimize(): one from Picture.__new__ would hold nothing a method can read.
    reinterpret_cast<PyTypeObject*>(picture.ptr())->tp_new = [](PyTypeObject*, PyObject*, PyObject*) -> PyObject* {
        PyErr_SetString(PyExc_TypeError, "inversevis.Picture objects come from render() and optimize()");
        return nullptr;
    };
    PyType_Modified(reinterpret_cast<PyTypeObject*>(picture.ptr()));
    picture
        .def_property_readonly("rgba", &python::Picture::rgba,
                               "(height, width, 4) uint8: the PNG's pixels, sRGB, with the colour bar's margin.")
        .def_property_readonly(
            "layers", [](const py::object& self) { return self.cast<const python::Picture&>().layers(self); },
            "The EXR's layers by name ('depth', 'region' (0 background, 1 direct, 2 indirect), 'triangle', 'P.X', "
            "'P.Y', 'P.Z' (normalised units), 'scalar', 'steps'): (height, width) float32 read-only views of the "
            "picture.")
        .def_property_readonly("camera", [](const python::Picture& p) { return python::fromJson(core::cameraFileJson(p.camera, p.meshUnits)); },
                               "The camera, as the camera file `render` writes (render(camera=...) takes it back).")
        .def_property_readonly("method", [](const python::Picture& p) { return python::fromJson(p.method); },
                               "The method and its parameters as drawn (the readable rule chosen where it ran).")
        .def_property_readonly("measures", [](const python::Picture& p) { return python::fromJson(p.measures); },
                               "The mapping coherence, what the readable rule chose, timing and pixel counts; with measure=True "
                               "(and of optimize()) the surface visibility and the other measures of docs/measures.md.")
        .def_property_readonly(
            "optimization",
            [](const python::Picture& p) { return p.optimization.is_null() ? py::object(py::none()) : python::fromJson(p.optimization); },
            "Of optimize(): the best view's theta and phi, its energy and front energy at opt_res, the search's "
            "seconds and evaluations, the readable rule chosen and every visited view (as `optimize --json`); None "
            "for render().")
        .def("save", [](const python::Picture& p, const py::object& path) { p.save(pathText(path)); }, py::arg("path"),
             "Writes the picture as PNG (.png, with its colour bar) or the multi-layer EXR (.exr), as `render -o` "
             "and `--exr` write them.")
        .def("save_view", [](const python::Picture& p, const py::object& path) { p.saveView(pathText(path)); },
             py::arg("path"),
             "Writes the picture's view file (camera, method and parameters, scalar, colours, look), as `render "
             "--view-out` writes one: `inversevis render MESH --view FILE` and the viewer's --view show the picture, "
             "read_view(FILE) gives it back to render().")
        .def_property_readonly("views", [](const python::Picture& p) { return p.views; },
                               "Of optimize(views=N > 1): each view's Picture, the best first (its measures: "
                               "visibility, coherence; its camera and method, save_view() as for any picture); "
                               "an empty list otherwise.")
        .def("save_views", [](const python::Picture& p, const py::object& path) { p.saveViews(pathText(path)); },
             py::arg("path"),
             "Of optimize(views=N > 1): writes the views side by side with one colour bar as PNG, as `inversevis "
             "optimize --views N -o` writes it.")
        .def(
            "probe",
            [](const python::Picture& p, const py::object& x, const py::object& y) {
                const long long column = wholeNumber(x, "x", "a pixel's column (an integer)");
                const long long row = wholeNumber(y, "y", "a pixel's row (an integer)");
                try {
                    return python::fromJson(p.probe(column, row));
                } catch (const ValueError& e) {  // the message names the pixel as given, not as clamped
                    const std::string clamped = "probe(" + std::to_string(column) + ", " + std::to_string(row) + ")";
                    std::string message = e.what();
                    if (message.rfind(clamped, 0) == 0)
                        message = "probe(" + py::str(x).cast<std::string>() + ", " + py::str(y).cast<std::string>() +
                                  ")" + message.substr(clamped.size());
                    throw ValueError(message);
                }
            },
            py::arg("x"), py::arg("y"),
            "What pixel (x, y) shows, x a column and y a row of the layers from the top left (rgba's colour bar "
            "margin not counted), as `render --probe X,Y` reports it: a dict with pixel, region ('background', "
            "'direct', 'indirect'), and for a surface point its position (the mesh's units), cell, scalar and "
            "view (a theta and phi that show it directly); a curved ray's pixel also its launch (seed, ring, "
            "speed, bend, drawn, refusal). Raises ValueError for a pixel outside the picture.")
        .def("tear_map", &python::Picture::tearMap,
             "(height, width, 3) uint8: the picture in grey with its tears in red (the indirect pixels whose "
             "neighbour's surface point lies further than the coherence measure's 0.1), as `render --tear-map`.")
        .def("unseen_map", &python::Picture::unseenMap,
             "(height, 2 * height, 3) uint8: the surface seen from the picture's side (left) and the opposite "
             "side (right), red where no pixel of the picture shows it, as `render --unseen-map` (it measures the "
             "picture again, as measure=True does).")
        .def("_repr_png_", &python::Picture::png)
        .def("__repr__", [](const python::Picture& p) {
            return "<inversevis.Picture " + std::to_string(p.result.image.width()) + "x" +
                   std::to_string(p.result.image.height()) + " " + p.method.value("method", std::string()) + ">";
        });

    m.def(
        "render",
        [](const std::shared_ptr<python::Mesh>& mesh, const std::string& method, const py::object& scalar,
           bool cellToPoint, const py::object& hotSpots, bool capHoles,
           const std::optional<double>& theta, const std::optional<double>& phi, const std::optional<double>& fov,
           bool ortho, const std::optional<py::dict>& camera, const std::pair<int, int>& size,
           const std::string& colormap,
           const std::optional<std::pair<double, double>>& range,
           const std::optional<std::pair<double, double>>& rangePercentile, bool symmetric, bool log, bool invert,
           const std::string& units, int volumeResolution, double minCoherence, bool fullTrace, bool legend,
           const std::string& legendSide, bool outline, bool shadows, bool shadeIndirect, bool transparent, int spp,
           bool measure, const py::object& progress, const py::kwargs& parameters) {
            python::RenderRequest request;
            request.method = method;
            request.load = shownBy(scalar, cellToPoint, hotSpots, capHoles);
            if (camera && (theta || phi || fov || ortho))
                throw ValueError("camera= is the whole view; theta, phi, fov and ortho beside it would be ignored (as "
                                 "`render --camera` refuses --theta, --phi, --fov and --ortho)");
            if (fov && ortho)
                throw ValueError("fov= and ortho= exclude each other (an orthographic view has no field of view)");
            request.theta = theta.value_or(90.0);
            request.phi = phi.value_or(0.0);
            request.fov = fov;
            request.orthographic = ortho;
            request.camera = camera;
            request.size = size;
            request.colormap = colormap;
            request.range = range;
            request.rangePercentile = rangePercentile;
            request.symmetric = symmetric;
            request.log = log;
            request.invert = invert;
            request.units = units;
            request.volumeResolution = volumeResolution;
            request.minCoherence = minCoherence;
            request.fullTrace = fullTrace;
            request.legend = legend;
            request.legendSide = legendSide;
            request.outline = outline;
            request.shadows = shadows;
            request.shadeIndirect = shadeIndirect;
            request.transparent = transparent;
            request.samplesPerPixel = spp;
            request.measure = measure;
            request.parameters = parameters;
            return said(python::renderMesh(mesh, request, progress));
        },
        py::arg("mesh").none(false), py::arg("method") = render::defaultMethod()->name(), py::kw_only(),
        py::arg("scalar") = py::none(), py::arg("cell_to_point") = false, py::arg("hotspots") = 0,
        py::arg("cap_holes") = false, py::arg("theta") = py::none(), py::arg("phi") = py::none(),
        py::arg("fov") = py::none(), py::arg("ortho") = false,
        py::arg("camera") = py::none(), py::arg("size") = std::pair<int, int>(1000, 1000),
        py::arg("colormap") = "viridis", py::arg("range") = py::none(), py::arg("range_percentile") = py::none(),
        py::arg("symmetric") = false, py::arg("log") = false,
        py::arg("invert") = false, py::arg("units") = "", py::arg("volume_resolution") = 200,
        py::arg("min_coherence") = optimize::kDefaultMinCoherence, py::arg("full_trace") = false,
        py::arg("legend") = true, py::arg("legend_side") = "right", py::arg("outline") = true,
        py::arg("shadows") = true, py::arg("shade_indirect") = true, py::arg("transparent") = false,
        py::arg("spp") = 1, py::arg("measure") = false, py::arg("progress") = py::none(),
        R"(A picture of mesh, as `inversevis render MESH` makes it with the same arguments.

method: a method's name (methods() lists them); its parameters as keywords by their keys
(stable_shift=0.2, alpha=0.5, mirror_w=[0.3, 0.3, 0, 0, 0]). scalar: the array to colour by
('NAME', 'NAME:0' for a component, 'cell:NAME'; None: the file's default). cell_to_point: a cell
array averaged onto the vertices (area-weighted); hotspots: N (1 to 6) generated hot spots as the
scalar instead, the first two at the ends of the thinnest axis; cap_holes: close open boundary
loops (caps are never coloured). theta, phi: the camera on the sphere of radius 2.5 (None: 90 and
0), the field of view framed to the picture unless fov (degrees) fixes it; ortho: an orthographic
view (framed by its half height); or camera (a Picture.camera) fixes the whole view instead. size:
(width, height). range: (lo, hi) of the colour scale (None: the data's); range_percentile: (LO, HI)
percentiles of the data as the range instead (0 to 100); symmetric: the range centred on 0, for
signed data; log, invert, units, legend, legend_side ('right', 'left', 'bottom'),
outline, shadows, shade_indirect, transparent, spp: render's --log, --invert, --units,
--no-legend, --legend, --no-outline, --no-shadows, --unshaded-indirect, --transparent, --spp
(each keyword is the option of the same name: hotspots=2 is --hotspots 2).
read_view(path) gives the arguments of a view file's picture: render(mesh, **read_view(path)). volume_resolution: the volume's N (cached as the command line caches it).
min_coherence: the readable rule (`render --min-coherence`): where the method's rule for drawing rays
is not given (inversevis-wrap: stable_shift), the loosest rule whose picture keeps at least this
estimated coherence; 0 keeps the method's default rule; a method without such a rule refuses other values.
full_trace: trace every pixel's ray (no adaptive image sampling). measure: also measure what the
picture shows, as `render --measure` (measures: visibility, voxel_visibility, paper_literal, front_visibility,
surface_pixels, even_bound, reveal with a scalar; docs/measures.md). progress: None or a callable
(stage, percent). The GIL is released while it renders; Ctrl-C raises KeyboardInterrupt.)");

    m.def(
        "optimize",
        [](const std::shared_ptr<python::Mesh>& mesh, const std::string& method, const py::object& scalar,
           bool cellToPoint, const py::object& hotSpots, bool capHoles, const std::string& energy,
           const std::optional<float>& gamma, int optRes, int ascentRes, int steps, const py::int_& seed,
           int finalists, const std::optional<int>& hotSpotViews,
           const std::optional<std::pair<double, double>>& start, int views, const std::pair<int, int>& size,
           const std::string& colormap, const std::optional<std::pair<double, double>>& range,
           const std::optional<std::pair<double, double>>& rangePercentile, bool symmetric, bool log, bool invert,
           const std::string& units, int volumeResolution, double minCoherence, bool legend,
           const std::string& legendSide, bool outline, bool shadows, bool shadeIndirect, bool transparent, int spp,
           const py::object& progress, const py::kwargs& parameters) {
            python::OptimizeRequest request;
            request.look.method = method;
            request.look.load = shownBy(scalar, cellToPoint, hotSpots, capHoles);
            request.look.size = size;
            request.look.colormap = colormap;
            request.look.range = range;
            request.look.rangePercentile = rangePercentile;
            request.look.symmetric = symmetric;
            request.look.log = log;
            request.look.invert = invert;
            request.look.units = units;
            request.look.volumeResolution = volumeResolution;
            request.look.minCoherence = minCoherence;
            request.look.legend = legend;
            request.look.legendSide = legendSide;
            request.look.outline = outline;
            request.look.shadows = shadows;
            request.look.shadeIndirect = shadeIndirect;
            request.look.transparent = transparent;
            request.look.samplesPerPixel = spp;
            request.look.parameters = parameters;
            request.look.function = "optimize";
            request.energy = energy;
            request.gamma = gamma;
            request.optResolution = optRes;
            request.ascentResolution = ascentRes;
            request.steps = steps;
            try {
                request.seed = seed.cast<std::uint64_t>();
            } catch (const py::cast_error&) {
                throw ValueError("seed " + std::string(py::repr(seed)) + " must be a whole number from 0 to 2**64 - 1");
            }
            request.finalists = finalists;
            request.hotSpotViews = hotSpotViews;
            request.start = start;
            request.views = views;
            return said(python::optimizeMesh(mesh, request, progress));
        },
        py::arg("mesh").none(false), py::arg("method") = render::defaultMethod()->name(), py::kw_only(),
        py::arg("scalar") = py::none(), py::arg("cell_to_point") = false, py::arg("hotspots") = 0,
        py::arg("cap_holes") = false, py::arg("energy") = "visibility", py::arg("gamma") = py::none(),
        py::arg("opt_res") = 100, py::arg("ascent_res") = 0, py::arg("steps") = 20, py::arg("seed") = 1,
        py::arg("finalists") = 5, py::arg("hot_spot_views") = py::none(), py::arg("start") = py::none(), py::arg("views") = 1,
        py::arg("size") = std::pair<int, int>(1000, 1000),
        py::arg("colormap") = "viridis", py::arg("range") = py::none(), py::arg("range_percentile") = py::none(),
        py::arg("symmetric") = false, py::arg("log") = false, py::arg("invert") = false, py::arg("units") = "",
        py::arg("volume_resolution") = 200, py::arg("min_coherence") = optimize::kDefaultMinCoherence,
        py::arg("legend") = true, py::arg("legend_side") = "right", py::arg("outline") = true, py::arg("shadows") = true,
        py::arg("shade_indirect") = true, py::arg("transparent") = false, py::arg("spp") = 1,
        py::arg("progress") = py::none(),
        R"(The best view of mesh for a method and its picture, as `inversevis optimize MESH` finds and draws it
with the same arguments (the same picture, byte for byte).

energy: 'visibility' (the share of the surface some pixel shows) or 'scalar' (the scalar shown,
gamma weighting the direct part, 1 by default). opt_res: rays per side while searching (the paper: 100 or
1000); ascent_res: rays per side of each view's parameter ascent (0: opt_res); steps: annealing
proposals after the start; seed: the search's seed (the same seed, the same result); finalists:
best views measured again at 200 rays per side (0: none); hot_spot_views: with the scalar energy, the
hot-spot rule's views (as `optimize --hot-spot-views`; None: 8, 0: none); start: (theta, phi) to start from (None:
the best of 26 views from a cube's faces, edges and corners, as `optimize` starts); views: with N > 1,
also the visited views that show the most surface
with the best one (as `optimize --views N`: Picture.views, save_views(), optimization['several_views']
with their union's visibility; the visibility energy). The method's parameters as keywords start its ascent (a readable
rule given, e.g. stable_shift=0.1, is kept; otherwise the rule keeping min_coherence is chosen).
scalar, cell_to_point, hotspots, cap_holes: what it shows, as render(). size, colormap, range,
range_percentile, symmetric, log, invert, units, volume_resolution, legend, legend_side, outline,
shadows, shade_indirect, transparent, spp: the picture's, as render().
Returns a Picture whose camera and method are the best view's, whose measures are its surface
visibility, voxel_visibility, paper_literal, front_visibility, coherence (and reveal with a scalar), and whose
optimization holds the search's result. The GIL is released; Ctrl-C raises KeyboardInterrupt.)");

    m.def("read_view", [](const py::object& path) { return python::readView(pathText(path)); }, py::arg("path"),
          "The keyword arguments of render() that draw a view file's picture (`render --view-out`, the viewer's "
          "'save view', Picture.save_view): render(mesh, **read_view(path)) is `inversevis render MESH --view path`; "
          "update the dict to change one. Raises InputError naming the file for a bad view.");

    m.def(
        "methods", [] {
            std::vector<std::string> names{render::defaultMethod()->name()};
            for (const render::MethodInfo* info : render::methodRegistry())
                if (info->name != names.front()) names.push_back(info->name);
            return names;
        },
        "The methods' names, the default first.");
}
