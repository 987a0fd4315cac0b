#include <ivis/core/mesh_reader.h>

#include <ivis/core/errors.h>
#include <ivis/core/file_bytes.h>
#include <ivis/core/mesh_formats.h>
#include <ivis/core/mesh_layout_check.h>
#include <ivis/core/show_array.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string_view>

namespace ivis::core {
namespace {

using detail::failInput;
using detail::RawMesh;

struct LoadedMesh {
    const char* format = "";
    SurfaceField field;
    std::size_t points = 0;  ///< the file's points, used or not
    std::size_t cells = 0;
    std::vector<std::uint32_t> keptPoints;  ///< file point of each mesh vertex; empty when every point is kept
    MeshReadReport report;
};

/// The tuples @a kept (ascending) of @a values, @a components values each.
template <typename T>
void keepTuples(std::vector<T>& values, const std::vector<std::uint32_t>& kept, int components)
{
    const std::size_t k = std::size_t(components);
    for (std::size_t i = 0; i < kept.size(); ++i)
        std::copy_n(values.begin() + std::ptrdiff_t(kept[i] * k), k, values.begin() + std::ptrdiff_t(i * k));
    values.resize(kept.size() * k);
}

/// Drops the points no triangle of @a loaded uses, with their point data, as vtkCleanPolyData does
/// (VTK files often carry them: a clipped model's, a centreline's): they would widen the bounds the
/// picture is framed and normalised by, and the colour range.
void dropUnusedPoints(LoadedMesh& loaded)
{
    TriangleMesh& mesh = loaded.field.mesh;
    std::vector<char> used(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles)
        for (const std::uint32_t v : t) used[v] = 1;
    std::vector<std::uint32_t> index(used.size(), 0);
    for (std::size_t v = 0; v < used.size(); ++v)
        if (used[v]) index[v] = std::uint32_t(loaded.keptPoints.size()), loaded.keptPoints.push_back(std::uint32_t(v));
    if (loaded.keptPoints.size() == mesh.positions.size()) {
        loaded.keptPoints.clear();
        return;
    }
    for (auto& t : mesh.triangles)
        for (std::uint32_t& v : t) v = index[v];
    keepTuples(mesh.positions, loaded.keptPoints, 1);
    for (DataArray& array : loaded.field.arrays)
        if (array.association == Association::Point) keepTuples(array.values, loaded.keptPoints, array.components);
    loaded.report.unusedPointsDropped = loaded.points - loaded.keptPoints.size();
}

bool isDegenerate(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t)
{
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
    const glm::dvec3 a(mesh.positions[t[0]]);
    const glm::dvec3 n =
        glm::cross(glm::dvec3(mesh.positions[t[1]]) - a, glm::dvec3(mesh.positions[t[2]]) - a);
    return glm::dot(n, n) == 0.0;
}

/// Where the positions of @a raw are kept from (their indices checked first): the file's origin,
/// or, when the box of the finite points its faces use lies further from the origin than it is
/// long, its centre rounded to a multiple of the largest power of two within its longest side, so
/// that a mesh far from its origin keeps its shape in single precision. The rounding keeps a
/// single-precision file's points exact relative to it, and so their normalised positions the
/// bits they had unshifted.
glm::dvec3 positionsOrigin(const std::string& path, const RawMesh& raw, bool oneBased)
{
    const std::size_t vertexCount = raw.positions.size();
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::size_t f = 0; f < raw.faceCount(); ++f) {
        const auto [begin, end] = raw.face(f);
        for (const std::int64_t* c = begin; c != end; ++c) {
            if (*c < 0 || std::size_t(*c) >= vertexCount) {
                failInput(path, "face " + std::to_string(f + oneBased) + " references vertex " +
                                    std::to_string(*c + oneBased) + " but the mesh has " +
                                    std::to_string(vertexCount) + " vertices");
            }
            const glm::dvec3& p = raw.positions[std::size_t(*c)];
            if (end - begin < 3 || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    if (!(lo.x <= hi.x)) return glm::dvec3(0.0);
    const glm::dvec3 centre = 0.5 * (lo + hi), size = hi - lo;
    const double longest = std::max({size.x, size.y, size.z});
    const double offset = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    if (!(offset > longest) || !(longest > 0.0)) return glm::dvec3(0.0);
    const double step = std::ldexp(1.0, std::ilogb(longest));
    return glm::round(centre / step) * step;
}

/// Positions (from positionsOrigin(), field.normalization's centre), fan-triangulated faces with
/// their file cells, and the arrays, validated.
LoadedMesh collect(const std::string& path, RawMesh raw, bool oneBased)
{
    LoadedMesh out;
    const std::size_t vertexCount = raw.positions.size();
    if (vertexCount >= std::size_t(UINT32_MAX)) failInput(path, "has more points than can be indexed (2^32 - 1)");
    const glm::dvec3 origin = positionsOrigin(path, raw, oneBased);
    out.field.normalization.center = origin;
    TriangleMesh& mesh = out.field.mesh;
    mesh.positions.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) mesh.positions[v] = glm::vec3(raw.positions[v] - origin);

    out.report.degenerateDropped = raw.skippedFaces;
    for (std::size_t f = 0; f < raw.faceCount(); ++f) {
        const auto [begin, end] = raw.face(f);
        if (end - begin < 3) {
            ++out.report.degenerateDropped;
            continue;
        }
        const std::uint32_t cell = raw.faceCells.empty() ? std::uint32_t(f) : raw.faceCells[f];
        for (const std::int64_t* c = begin + 1; c + 1 != end; ++c) {
            const std::array<std::uint32_t, 3> t{std::uint32_t(begin[0]), std::uint32_t(c[0]), std::uint32_t(c[1])};
            if (isDegenerate(mesh, t)) {
                ++out.report.degenerateDropped;
            } else {
                mesh.triangles.push_back(t);
                out.field.triangleCells.push_back(cell);
            }
        }
    }
    if (mesh.triangles.empty()) failInput(path, "mesh has no triangles");
    mesh.dataTriangleCount = mesh.triangles.size();
    for (const auto& t : mesh.triangles)
        for (const std::uint32_t v : t) {
            const glm::dvec3& given = raw.positions[v];
            if (!std::isfinite(given.x) || !std::isfinite(given.y) || !std::isfinite(given.z))
                failInput(path, "vertex " + std::to_string(v + oneBased) + " has a non-finite coordinate");
            const glm::vec3& p = mesh.positions[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                failInput(path, "vertex " + std::to_string(v + oneBased) + " lies beyond single precision (3.4e38) "
                                "from the others");
        }

    for (const DataArray& array : raw.arrays) {
        IVIS_CHECK(array.tuples() == (array.association == Association::Point ? vertexCount : raw.cellCount));
    }
    out.field.arrays = std::move(raw.arrays);
    out.points = vertexCount;
    out.cells = raw.cellCount;
    out.report.notes = std::move(raw.notes);
    dropUnusedPoints(out);
    return out;
}

/// Reads the file with the reader its extension names and converts it.
LoadedMesh loadMesh(const std::string& path)
{
    std::string data = detail::readFileBytes(path);
    const detail::MeshFileFormat& format = detail::meshFileFormat(path);
    LoadedMesh loaded = collect(path, format.read(path, std::move(data)), format.extension == std::string_view(".obj"));
    loaded.format = format.name;
    loaded.field.sourcePath = path;
    return loaded;
}

}  // namespace

SurfaceField readMesh(const std::string& path, const MeshReadOptions& options, MeshReadReport* report)
{
    if (!options.scalarName.empty() && !options.scalarFile.empty()) {
        failInput(path, "choose either a scalar name or a scalar file, not both");
    }
    if (options.cellToPoint && !options.scalarFile.empty()) {
        failInput(path, "--cell-to-point averages a cell array; a scalar file gives one value per vertex");
    }
    LoadedMesh loaded = loadMesh(path);
    SurfaceField& field = loaded.field;
    if (!options.scalarName.empty()) {
        showArray(field, options.scalarName, options.cellToPoint);
    } else if (!options.scalarFile.empty()) {
        field.values = readScalarFile(options.scalarFile, loaded.points);
        if (!loaded.keptPoints.empty()) keepTuples(field.values, loaded.keptPoints, 1);
        field.name = std::filesystem::path(options.scalarFile).stem().string();
    }
    if (report != nullptr) *report = std::move(loaded.report);
    return std::move(field);
}

SurfaceField meshFromArrays(const std::string& name, std::vector<glm::dvec3> positions,
                            std::vector<std::int64_t> triangles, std::vector<DataArray> arrays,
                            MeshReadReport* report)
{
    if (triangles.size() % 3 != 0) failInput(name, "the triangles' indices are not three per triangle");
    RawMesh raw;
    raw.positions = std::move(positions);
    raw.cellCount = triangles.size() / 3;
    raw.corners = std::move(triangles);
    for (std::size_t f = 1; f <= raw.cellCount; ++f) raw.faceEnds.push_back(3 * f);
    for (const DataArray& array : arrays) {
        const std::size_t tuples = array.association == Association::Point ? raw.positions.size() : raw.cellCount;
        if (array.components < 1 || array.values.size() != tuples * std::size_t(array.components))
            failInput(name, std::string(associationName(array.association)) + " array '" + array.name + "' holds " +
                                std::to_string(array.values.size()) + " values, not " + std::to_string(tuples) +
                                " tuples of " + std::to_string(array.components));
    }
    raw.arrays = std::move(arrays);
    LoadedMesh loaded = collect(name, std::move(raw), false);
    loaded.field.sourcePath = name;
    if (report != nullptr) *report = std::move(loaded.report);
    return std::move(loaded.field);
}

MeshInfo describeMesh(const std::string& path)
{
    LoadedMesh loaded = loadMesh(path);
    const TriangleMesh& mesh = loaded.field.mesh;
    MeshInfo info;
    info.path = path;
    info.format = loaded.format;
    info.vertices = loaded.points;
    info.cells = loaded.cells;
    info.triangles = mesh.triangles.size();
    info.bounds = bounds(mesh);  // in the file's units
    info.bounds.lo += loaded.field.normalization.center;
    info.bounds.hi += loaded.field.normalization.center;
    info.boundaryEdges = boundaryEdgeCount(mesh);
    info.components = componentCount(mesh);
    info.report = std::move(loaded.report);
    info.arrays = describeArrays(loaded.field);
    return info;
}

std::vector<ArrayInfo> describeArrays(const SurfaceField& field)
{
    // The cells a triangle comes from: a line or vertex cell's value, or a volume's inner cell's, is never drawn.
    std::vector<char> cellDrawn;
    for (const std::uint32_t cell : field.triangleCells) {
        if (cell >= cellDrawn.size()) cellDrawn.resize(std::size_t(cell) + 1, 0);
        cellDrawn[cell] = 1;
    }
    const std::vector<char> everyTuple;  // a point array's: its unused points are dropped already
    std::vector<ArrayInfo> infos;
    const DataArray* shown = field.arrays.empty() ? nullptr : &defaultArray(field);
    for (const DataArray& array : field.arrays) {
        ArrayInfo a{array.name, array.association, array.type, array.components, 0.0, 0.0, 0, &array == shown};
        const std::vector<char>& drawn = array.association == Association::Cell ? cellDrawn : everyTuple;
        std::tie(a.min, a.max) = finiteRange(array, array.defaultComponent(), drawn);
        for (std::size_t t = 0; t < array.tuples(); ++t)
            if (drawn.empty() || (t < drawn.size() && drawn[t])) a.nanCount += std::isnan(array.at(t, kMagnitude)) ? 1 : 0;
        infos.push_back(a);
    }
    return infos;
}

std::vector<float> readScalarFile(const std::string& path, std::size_t expectedCount)
{
    return detail::parseScalarFile(path, detail::readFileBytes(path), expectedCount);
}

std::vector<float> detail::parseScalarFile(const std::string& path, const std::string& data, std::size_t expectedCount)
{
    std::vector<float> values;
    detail::TextCursor in(data);
    for (std::string_view token = in.token(); !token.empty(); token = in.token()) {
        // Named only on error: the token's line, its number and its text, quoted in full up to 40
        // characters (a comma-separated file's line is one token).
        const auto where = [&] {
            const std::size_t line = 1 + std::count(data.data(), token.data(), '\n');
            const std::string quoted =
                token.size() <= 40 ? std::string(token) : std::string(token.substr(0, 37)) + "...";
            return "line " + std::to_string(line) + ": value " + std::to_string(values.size()) + " '" + quoted + "'";
        };
        const detail::FloatToken number = detail::parseFloatToken(token);
        if (number.kind == detail::FloatToken::NotANumber)
            failInput(path, where() + " is not a number" +
                                (token.find(',') != std::string_view::npos
                                     ? " (values are separated by spaces or lines, not commas)"
                                     : ""));
        if (number.kind == detail::FloatToken::NonFinite && std::isfinite(number.value))
            failInput(path, where() + " is beyond the largest a 32-bit float holds (3.4e+38)");
        if (number.kind == detail::FloatToken::NonFinite && !std::isnan(number.value)) {
            failInput(path, where() + " is not finite (only nan is allowed)");
        }
        values.push_back(float(number.value));
    }
    if (values.size() != expectedCount) {
        failInput(path, "expected " + std::to_string(expectedCount) + " scalar values (one per vertex), found " +
                            std::to_string(values.size()));
    }
    return values;
}

}  // namespace ivis::core
