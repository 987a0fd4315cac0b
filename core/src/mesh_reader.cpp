#include <ivis/core/mesh_reader.h>

#include <ivis/core/mesh_layout_check.h>
#include <ivis/core/raw_mesh_import.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>
#include <tuple>

namespace ivis::core {
namespace {

namespace fs = std::filesystem;
using detail::failInput;
using detail::MeshFormat;
using detail::NamedValues;

/// "Permission denied" -> "permission denied".
std::string systemMessage(int code)
{
    std::string text = std::generic_category().message(code);
    if (!text.empty()) text[0] = char(std::tolower(static_cast<unsigned char>(text[0])));
    return text;
}

/// Whole file as bytes; missing, directory and unreadable paths are InputErrors.
std::string readFileBytes(const std::string& path)
{
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory) {
        failInput(path, "cannot read file (" + systemMessage(ec.value()) + ")");
    }
    if (!fs::exists(status)) failInput(path, "file not found");
    if (fs::is_directory(status)) failInput(path, "is a directory, not a file");

    std::ifstream in(path, std::ios::binary);
    if (!in) failInput(path, "cannot read file (" + systemMessage(errno) + ")");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) failInput(path, "cannot read file (not a regular file)");
    in.seekg(0);
    std::string data(std::size_t(size), '\0');
    if (!in.read(data.data(), size)) failInput(path, "cannot read file (read error)");
    return data;
}

struct LoadedMesh {
    MeshFormat format = MeshFormat::Ply;
    TriangleMesh mesh;
    std::size_t degenerateDropped = 0;
    std::vector<NamedValues> scalars;  ///< every per-vertex float/double property, file order
};

bool isDegenerate(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t)
{
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
    const glm::dvec3 a(mesh.positions[t[0]]);
    const glm::dvec3 n =
        glm::cross(glm::dvec3(mesh.positions[t[1]]) - a, glm::dvec3(mesh.positions[t[2]]) - a);
    return glm::dot(n, n) == 0.0;
}

/// Positions, fan-triangulated faces and scalar properties from the raw import, validated.
LoadedMesh collect(const std::string& path, detail::RawMesh raw, bool oneBased, std::size_t facesInFile)
{
    LoadedMesh out;
    const std::size_t vertexCount = raw.positions.size();
    for (std::size_t i = 0; i < vertexCount; ++i) {
        const glm::vec3& p = raw.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            failInput(path, "vertex " + std::to_string(i + oneBased) + " has a non-finite coordinate");
        }
    }
    out.mesh.positions = std::move(raw.positions);

    // Faces OpenMesh skipped itself (OBJ/STL faces with repeated corners) count as degenerate.
    out.degenerateDropped = facesInFile > raw.faceCount() ? facesInFile - raw.faceCount() : 0;
    for (std::size_t f = 0; f < raw.faceCount(); ++f) {
        const auto [begin, end] = raw.face(f);
        for (const int* c = begin; c != end; ++c) {
            if (*c < 0 || std::size_t(*c) >= vertexCount) {
                failInput(path, "face " + std::to_string(f + oneBased) + " references vertex " +
                                    std::to_string(std::int64_t(*c) + oneBased) + " but the mesh has " +
                                    std::to_string(vertexCount) + " vertices");
            }
        }
        if (end - begin < 3) {
            ++out.degenerateDropped;
            continue;
        }
        for (const int* c = begin + 1; c + 1 != end; ++c) {
            const std::array<std::uint32_t, 3> t{std::uint32_t(begin[0]), std::uint32_t(c[0]),
                                                 std::uint32_t(c[1])};
            if (isDegenerate(out.mesh, t)) {
                ++out.degenerateDropped;
            } else {
                out.mesh.triangles.push_back(t);
            }
        }
    }
    if (out.mesh.triangles.empty()) failInput(path, "mesh has no triangles");
    out.mesh.dataTriangleCount = out.mesh.triangles.size();

    out.scalars = std::move(raw.scalars);
    return out;
}

/// Validates the file's layout, reads it with OpenMesh and converts it.
LoadedMesh loadMesh(const std::string& path)
{
    std::string data = readFileBytes(path);
    const MeshFormat format = detail::meshFormat(path);
    const detail::MeshLayout layout = detail::checkMeshLayout(path, format, data);
    detail::RawMesh raw = detail::importRawMesh(path, format, layout.binaryStl, std::move(data));
    LoadedMesh loaded = collect(path, std::move(raw), format == MeshFormat::Obj, layout.facesInFile);
    loaded.format = format;
    return loaded;
}

}  // namespace

SurfaceField readMesh(const std::string& path, const MeshReadOptions& options,
                      std::size_t* degenerateDropped)
{
    if (!options.scalarName.empty() && !options.scalarFile.empty()) {
        failInput(path, "choose either a scalar name or a scalar file, not both");
    }
    LoadedMesh loaded = loadMesh(path);
    SurfaceField field;
    field.mesh = std::move(loaded.mesh);
    field.sourcePath = path;
    if (!options.scalarName.empty()) {
        const auto it = std::find_if(loaded.scalars.begin(), loaded.scalars.end(),
                                     [&](const NamedValues& s) { return s.name == options.scalarName; });
        if (it == loaded.scalars.end()) {
            std::string available;
            for (const NamedValues& s : loaded.scalars) available += (available.empty() ? "" : ", ") + s.name;
            failInput(path, "no per-vertex scalar '" + options.scalarName + "'; available: " +
                                (available.empty() ? "none" : available));
        }
        field.values = std::move(it->values);
        field.name = options.scalarName;
    } else if (!options.scalarFile.empty()) {
        field.values = readScalarFile(options.scalarFile, field.mesh.positions.size());
        field.name = fs::path(options.scalarFile).stem().string();
    }
    if (degenerateDropped != nullptr) *degenerateDropped = loaded.degenerateDropped;
    return field;
}

MeshInfo describeMesh(const std::string& path)
{
    const LoadedMesh loaded = loadMesh(path);
    MeshInfo info;
    info.path = path;
    info.format = detail::formatName(loaded.format);
    info.vertices = loaded.mesh.positions.size();
    info.triangles = loaded.mesh.triangles.size();
    info.degenerateDropped = loaded.degenerateDropped;
    info.boundaryEdges = boundaryEdgeCount(loaded.mesh);
    info.components = componentCount(loaded.mesh);
    info.bounds = bounds(loaded.mesh);
    for (const NamedValues& s : loaded.scalars) {
        ScalarInfo scalar;
        scalar.name = s.name;
        std::tie(scalar.min, scalar.max) = finiteRange(s.values);
        scalar.nanCount = std::size_t(std::count_if(s.values.begin(), s.values.end(),
                                                    [](float v) { return std::isnan(v); }));
        info.scalars.push_back(scalar);
    }
    return info;
}

std::vector<float> readScalarFile(const std::string& path, std::size_t expectedCount)
{
    const std::string data = readFileBytes(path);
    std::vector<float> values;
    detail::TextCursor in(data);
    for (std::string_view token = in.token(); !token.empty(); token = in.token()) {
        const std::string where = "value " + std::to_string(values.size()) + " '" + std::string(token) + "'";
        const detail::FloatToken number = detail::parseFloatToken(token);
        if (number.kind == detail::FloatToken::NotANumber) failInput(path, where + " is not a number");
        if (number.kind == detail::FloatToken::NonFinite && !std::isnan(number.value)) {
            failInput(path, where + " is not finite (only nan is allowed)");
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
