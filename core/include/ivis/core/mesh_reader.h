/// @file mesh_reader.h
/// @brief Reads OBJ, OFF, PLY (ASCII and binary) and STL meshes with an optional per-vertex scalar.
/// @note Every failure throws InputError whose message is one line "<path>: <problem>". Vertex and
///       face numbers in messages count from 0, except for OBJ files, which count from 1 as OBJ
///       indices do.
/// @note Files are parsed by OpenMesh 9.0 through an importer that keeps raw faces, so
///       non-manifold and open meshes lose no triangle. Its readers trust counts and tokens, so
///       each file's layout is checked first; layouts OpenMesh would misread (binary OFF, ASCII
///       PLY with 8-bit custom properties or nan/inf values, list properties other than in the
///       vertex element or after a face's vertex_indices) are rejected with a message.
#pragma once

#include <ivis/core/surface_field.h>

#include <cstddef>
#include <string>
#include <vector>

namespace ivis::core {

/// @brief Which scalar to attach while reading.
struct MeshReadOptions {
    std::string scalarName;  ///< per-vertex float/double PLY property; "" = none
    std::string scalarFile;  ///< sidecar text file, one value per vertex; "" = none
};

/// @brief Summary of one scalar property found in a file.
struct ScalarInfo {
    std::string name;
    float min = 0.0f;  ///< finite minimum (NaN ignored)
    float max = 0.0f;
    std::size_t nanCount = 0;
};

/// @brief What `inversevis info` prints about a mesh file.
struct MeshInfo {
    std::string path;
    std::string format;  ///< "obj", "off", "ply", "stl"
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::size_t degenerateDropped = 0;
    std::size_t boundaryEdges = 0;
    std::size_t components = 0;
    Bounds3 bounds;  ///< in the file's own units
    std::vector<ScalarInfo> scalars;
};

/// @brief Reads a mesh in its own units (not normalised), polygons fan-triangulated, degenerate
///        triangles (repeated index or zero area) dropped and counted in @a degenerateDropped.
/// @param path mesh file; format chosen by extension (.obj .off .ply .stl, case-insensitive)
/// @param options scalar selection (at most one of name / file)
/// @param degenerateDropped optional output: number of dropped degenerate triangles
/// @throw InputError (missing/unreadable file, unknown format, not a mesh, zero triangles,
///        non-finite coordinates, out-of-range indices, bad sidecar, unknown scalar name listing
///        the names that exist)
/// @warning Thread-safe; the OpenMesh part of concurrent reads runs one at a time.
SurfaceField readMesh(const std::string& path, const MeshReadOptions& options = {},
                      std::size_t* degenerateDropped = nullptr);

/// @brief Reads a mesh and reports its counts, bounds and every per-vertex scalar property.
/// @throw InputError as readMesh
MeshInfo describeMesh(const std::string& path);

/// @brief Reads a sidecar scalar file: whitespace/newline separated numbers ("nan" allowed).
/// @param expectedCount number of vertices; a different count is an error
/// @throw InputError naming the file and the first bad token (numbered from 0, like vertices)
///        or the count mismatch
std::vector<float> readScalarFile(const std::string& path, std::size_t expectedCount);

}  // namespace ivis::core
