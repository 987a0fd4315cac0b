#include "python_mesh.h"

#include "python_errors.h"

#include <ivis/core/errors.h>
#include <ivis/core/show_array.h>
#include <ivis/core/surface_source.h>
#include <ivis/vdb/cache_folder.h>
#include <ivis/vdb/volume_cache.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace py = pybind11;

namespace ivis::python {
namespace {

/// "float64 (5, 3)": an array's dtype and shape, for messages.
std::string described(const py::array& array)
{
    std::ostringstream text;
    text << py::str(array.dtype()).cast<std::string>() << " (";
    for (py::ssize_t k = 0; k < array.ndim(); ++k) text << (k ? ", " : "") << array.shape(k);
    text << (array.ndim() == 1 ? ",)" : ")");
    return text.str();
}

/// @a array in the machine's byte order (a copy where numpy holds it swapped, as '>f8'), which the
/// copies below read.
py::array nativeOrder(const py::array& array)
{
    if (array.dtype().attr("isnative").cast<bool>()) return array;
    return array.attr("astype")(array.dtype().attr("newbyteorder")("="));
}

/// @a given as an array: a numpy array as it is; a nested list or tuple, or an object numpy reads
/// as an array (`__array__`), converted (to float64 when @a floating). TypeError naming @a what
/// and @a expected for anything else (None, a string, a number), ValueError for a ragged list.
py::array arrayOf(const py::object& given, const std::string& what, const std::string& expected, bool floating)
{
    if (py::isinstance<py::array>(given)) return py::reinterpret_borrow<py::array>(given);
    const bool sequence = py::isinstance<py::list>(given) || py::isinstance<py::tuple>(given);
    if (!sequence && !py::hasattr(given, "__array__"))
        throw py::type_error(what + " must be " + expected + ", got " +
                             py::str(py::type::handle_of(given).attr("__name__")).cast<std::string>());
    const py::array array = floating && sequence ? py::array_t<double, py::array::forcecast>::ensure(given)
                                                 : py::array::ensure(given);
    if (!array) throw py::value_error(what + " must be " + expected + ", got a sequence numpy cannot read as one");
    return array;
}

/// The value type of a numeric dtype; throws TypeError naming @a what for any other.
core::ValueType valueType(const py::array& array, const std::string& what)
{
    const char kind = array.dtype().kind();
    const py::ssize_t size = array.itemsize();
    if (kind == 'f' && (size == 4 || size == 8)) return size == 4 ? core::ValueType::Float32 : core::ValueType::Float64;
    if (kind == 'i' || kind == 'u') {
        const bool sign = kind == 'i';
        switch (size) {
        case 1: return sign ? core::ValueType::Int8 : core::ValueType::UInt8;
        case 2: return sign ? core::ValueType::Int16 : core::ValueType::UInt16;
        case 4: return sign ? core::ValueType::Int32 : core::ValueType::UInt32;
        case 8: return sign ? core::ValueType::Int64 : core::ValueType::UInt64;
        }
    }
    throw py::type_error(what + " must hold numbers (integers or float32/float64), got " + described(array));
}

/// The elements of @a array (any numeric dtype, any strides) converted to Out, row-major: the one
/// copy of the data into the engine.
template <typename In, typename Out>
void copyInto(const py::array& array, Out* out)
{
    const py::ssize_t n = array.ndim() == 1 ? array.shape(0) : array.shape(0) * array.shape(1);
    const char* base = static_cast<const char*>(array.data());
    const py::ssize_t columns = array.ndim() == 1 ? 1 : array.shape(1);
    for (py::ssize_t i = 0; i < n; ++i) {
        const py::ssize_t row = i / columns, column = i % columns;
        const char* at = base + row * array.strides(0) + (array.ndim() == 1 ? 0 : column * array.strides(1));
        In value;
        std::memcpy(&value, at, sizeof(In));
        out[i] = Out(value);
    }
}

/// flattened()'s copy into @a out, which holds the array's elements.
template <typename Out>
void flattenInto(const py::array& array, Out* out)
{
    const char kind = array.dtype().kind();
    const py::ssize_t size = array.itemsize();
    if (kind == 'f' && size == 4) copyInto<float>(array, out);
    else if (kind == 'f' && size == 8) copyInto<double>(array, out);
    else if (kind == 'i' && size == 1) copyInto<std::int8_t>(array, out);
    else if (kind == 'i' && size == 2) copyInto<std::int16_t>(array, out);
    else if (kind == 'i' && size == 4) copyInto<std::int32_t>(array, out);
    else if (kind == 'i' && size == 8) copyInto<std::int64_t>(array, out);
    else if (kind == 'u' && size == 1) copyInto<std::uint8_t>(array, out);
    else if (kind == 'u' && size == 2) copyInto<std::uint16_t>(array, out);
    else if (kind == 'u' && size == 4) copyInto<std::uint32_t>(array, out);
    else if (kind == 'u' && size == 8) copyInto<std::uint64_t>(array, out);
    else throw py::type_error("an array of " + described(array) + " holds no numbers the engine reads");
}

/// The elements of a one- or two-dimensional numeric array as Out, row-major.
template <typename Out>
std::vector<Out> flattened(const py::array& array)
{
    const py::ssize_t n = array.ndim() == 1 ? array.shape(0) : array.shape(0) * array.shape(1);
    std::vector<Out> out(std::size_t(std::max<py::ssize_t>(n, 0)));
    flattenInto(array, out.data());
    return out;
}

/// Each array of @a data (name -> n or n x k values) as a DataArray of @a association with @a tuples tuples.
std::vector<core::DataArray> dataArrays(const py::dict& data, core::Association association, py::ssize_t tuples)
{
    const std::string where = association == core::Association::Point ? "point_data" : "cell_data";
    const std::string per = association == core::Association::Point ? "vertex" : "face";
    std::vector<core::DataArray> arrays;
    for (const auto& [key, value] : data) {
        if (!py::isinstance<py::str>(key)) throw py::type_error(where + " keys must be array names (str)");
        const std::string name = key.cast<std::string>();
        if (name.empty()) throw py::value_error(where + ": an array needs a name");
        py::array array = py::array::ensure(value);
        if (!array) throw py::type_error(where + "['" + name + "'] must be a numpy array");
        array = nativeOrder(array);
        core::DataArray data;
        data.name = name;
        data.association = association;
        data.type = valueType(array, where + "['" + name + "']");
        if ((array.ndim() != 1 && array.ndim() != 2) || array.shape(0) != tuples)
            throw py::value_error(where + "['" + name + "'] must have shape (" + std::to_string(tuples) + ",) or (" +
                                  std::to_string(tuples) + ", k), one tuple per " + per + ", got " + described(array));
        data.components = array.ndim() == 1 ? 1 : int(array.shape(1));
        if (data.components < 1) throw py::value_error(where + "['" + name + "'] has no components");
        data.values = flattened<double>(array);
        arrays.push_back(std::move(data));
    }
    return arrays;
}

/// Volume options as a key: every field that names a cache file.
std::string volumeKey(const vdb::VolumeOptions& o)
{
    std::ostringstream key;
    key << o.resolution << '/' << o.farFieldResolution << '/' << o.farFieldReach << '/' << o.bandVoxels << '/'
        << int(o.sign);
    return key.str();
}

}  // namespace

std::shared_ptr<Mesh> Mesh::read(const std::string& source)
{
    auto mesh = std::make_shared<Mesh>();
    mesh->mSource = source;
    if (source.rfind(core::kScenePrefix, 0) == 0) {
        mesh->mRaw = core::loadSurface(source);  // generated: its own scalar, already normalised
    } else {
        if (core::isTimeSeries(source))
            throw InputError(source + ": a time series; read one step's file (its steps are listed by `inversevis info`)");
        mesh->mRaw = core::readMesh(source, {}, &mesh->mReport);
    }
    return mesh;
}

std::shared_ptr<Mesh> Mesh::fromArrays(const py::object& givenVertices, const py::object& givenFaces,
                                       const py::dict& pointData, const py::dict& cellData)
{
    const std::string vertexArray = "a float32 or float64 array of shape (n, 3)";
    const std::string faceArray = "an int32 or int64 array of shape (m, 3) (vertex indices from 0)";
    const py::array vertices = nativeOrder(arrayOf(givenVertices, "vertices", vertexArray, true));
    const py::array faces = nativeOrder(arrayOf(givenFaces, "faces", faceArray, false));
    const char vertexKind = vertices.dtype().kind();
    if (vertices.ndim() != 2 || vertices.shape(1) != 3 || vertexKind != 'f' ||
        (vertices.itemsize() != 4 && vertices.itemsize() != 8))
        throw py::value_error("vertices must be " + vertexArray + ", got " + described(vertices));
    const char faceKind = faces.dtype().kind();
    if (faces.ndim() != 2 || faces.shape(1) != 3 || (faceKind != 'i' && faceKind != 'u') || faces.itemsize() < 4)
        throw py::value_error("faces must be " + faceArray + ", got " + described(faces));
    std::vector<glm::dvec3> positions(std::size_t(vertices.shape(0)));
    static_assert(sizeof(glm::dvec3) == 3 * sizeof(double));
    flattenInto(vertices, reinterpret_cast<double*>(positions.data()));
    if (faceKind == 'u' && faces.itemsize() == 8) {  // an index above int64's range would wrap to a negative one
        const std::vector<std::uint64_t> indices = flattened<std::uint64_t>(faces);
        const auto count = std::uint64_t(vertices.shape(0));
        const auto beyond =
            std::find_if(indices.begin(), indices.end(), [count](std::uint64_t i) { return i >= count; });
        if (beyond != indices.end())
            throw InputError("Mesh: face " + std::to_string((beyond - indices.begin()) / 3) + " references vertex " +
                             std::to_string(*beyond) + " but the mesh has " + std::to_string(vertices.shape(0)) +
                             " vertices");
    }
    std::vector<std::int64_t> triangles = flattened<std::int64_t>(faces);
    std::vector<core::DataArray> arrays = dataArrays(pointData, core::Association::Point, vertices.shape(0));
    for (core::DataArray& array : dataArrays(cellData, core::Association::Cell, faces.shape(0)))
        arrays.push_back(std::move(array));
    auto mesh = std::make_shared<Mesh>();
    mesh->mSource = "Mesh";
    mesh->mRaw = core::meshFromArrays(mesh->mSource, std::move(positions), std::move(triangles), std::move(arrays),
                                       &mesh->mReport);
    return mesh;
}

py::array Mesh::vertices() const
{
    // In the given units: a mesh far from its origin is kept relative to its centre (readMesh).
    const auto& positions = mRaw.mesh.positions;
    py::array_t<float> out({py::ssize_t(positions.size()), py::ssize_t(3)});
    glm::vec3* data = reinterpret_cast<glm::vec3*>(out.mutable_data());
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    for (const glm::vec3& p : positions) *data++ = glm::vec3(mRaw.normalization.meshFromNormalized(glm::dvec3(p)));
    return std::move(out);
}

py::array Mesh::faces() const
{
    const auto& triangles = mRaw.mesh.triangles;
    py::array_t<std::int64_t> out({py::ssize_t(triangles.size()), py::ssize_t(3)});
    std::int64_t* data = out.mutable_data();
    for (const auto& t : triangles)
        for (std::uint32_t v : t) *data++ = std::int64_t(v);
    return std::move(out);
}

std::vector<core::ArrayInfo> Mesh::arrays() const
{
    if (!generated() || !mRaw.hasScalar()) return core::describeArrays(mRaw);
    core::SurfaceField own;  // a scene's scalar as the one point array of a file
    own.arrays = {{mRaw.name, core::Association::Point, core::ValueType::Float32, 1,
                   std::vector<double>(mRaw.values.begin(), mRaw.values.end())}};
    return core::describeArrays(own);
}

py::dict Mesh::data(core::Association association) const
{
    py::dict out;
    const bool point = association == core::Association::Point;
    if (generated()) {  // a scene carries its scalar, not arrays
        if (point && mRaw.hasScalar()) {
            py::array_t<double> values(py::ssize_t(mRaw.values.size()));
            std::copy(mRaw.values.begin(), mRaw.values.end(), values.mutable_data());
            out[decodedText(mRaw.name)] = values;
        }
        return out;
    }
    const std::size_t rows = point ? mRaw.mesh.positions.size() : mRaw.mesh.dataTriangleCount;
    for (const core::DataArray& array : mRaw.arrays) {
        if (array.association != association) continue;
        const std::size_t k = std::size_t(array.components);
        py::array_t<double> values = k == 1 ? py::array_t<double>(py::ssize_t(rows))
                                            : py::array_t<double>({py::ssize_t(rows), py::ssize_t(k)});
        double* at = values.mutable_data();
        for (std::size_t row = 0; row < rows; ++row) {
            const std::size_t tuple = point ? row : mRaw.triangleCells[row];
            std::copy_n(array.values.begin() + std::ptrdiff_t(tuple * k), k, at + row * k);
        }
        out[decodedText(array.name)] = values;
    }
    return out;
}

core::SurfaceField Mesh::shown(const core::SurfaceLoadOptions& load) const
{
    const std::string& scalar = load.read.scalarName;
    if (load.hotSpots > 0 && !scalar.empty())
        throw ValueError("scalar= and hotspots= exclude each other: the hot spots are the scalar shown");
    if (load.hotSpots > 0 && load.read.cellToPoint)
        throw ValueError("cell_to_point= and hotspots= exclude each other: hot spots are one value per vertex");
    if (generated()) {
        if (!scalar.empty() && scalar != mRaw.name)  // its own by name, as point_data and arrays list it
            throw InputError(mSource + ": generated scenes carry their own scalar" +
                             (mRaw.hasScalar() ? " ('" + mRaw.name + "')" : std::string()) +
                             "; other names of scalar= apply to mesh files only");
        if (load.read.cellToPoint)
            throw InputError(mSource + ": generated scenes carry their own point scalar; cell_to_point= applies to mesh "
                                       "files only");
        if (load.hotSpots == 0 && !load.capHoles) return mRaw;
        core::SurfaceLoadOptions generate;  // generated again, so that caps and hot spots come as `render` makes them
        generate.capHoles = load.capHoles;
        generate.hotSpots = load.hotSpots;
        return core::loadSurface(mSource, generate);
    }
    try {
        core::SurfaceField field = mRaw;
        if (!scalar.empty()) core::showArray(field, scalar, load.read.cellToPoint);
        return core::loadReadSurface(mSource, std::move(field), mReport, load);
    } catch (const InputError& e) {  // the reader's message names the options, said here as keywords
        throw InputError(asKeywords(e.what(), {"--cell-to-point", "--scalar"}));
    }
}

std::shared_ptr<const Scene> Mesh::scene(const core::SurfaceLoadOptions& load, const vdb::VolumeOptions& options,
                                         core::Interrupter* interrupter)
{
    std::lock_guard<std::mutex> lock(mMutex);
    // Capped holes change the geometry, so its volumes too.
    const std::string volumeName = volumeKey(options) + (load.capHoles ? "/capped" : "");
    const std::string sceneName = load.read.scalarName + '\n' + std::to_string(load.read.cellToPoint) + '/' +
                                  std::to_string(load.hotSpots) + '\n' + volumeName;
    if (auto found = mScenes.find(sceneName); found != mScenes.end()) return found->second;
    auto scene = std::make_shared<Scene>();
    scene->field = shown(load);
    Volume& volume = mVolumes[volumeName];
    if (!volume.volume) {
        volume.path = vdb::defaultVolumePath(vdb::optionalCacheFolder(""), mSource, scene->field.mesh, options);
        volume.volume = std::make_shared<const vdb::SurfaceVolume>(
            vdb::loadOrBuildVolume(scene->field.mesh, options, volume.path, interrupter));
    }
    scene->volume = volume.volume;
    scene->volumePath = volume.path;
    scene->render = std::make_unique<render::RenderScene>(scene->field, *scene->volume);
    return mScenes[sceneName] = scene;
}

}  // namespace ivis::python
