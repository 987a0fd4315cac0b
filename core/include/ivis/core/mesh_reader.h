/// @file mesh_reader.h
/// @brief Reads meshes with all their arrays: OBJ, OFF, PLY (ASCII and binary), STL, VTK legacy
///        `.vtk` and VTK XML `.vtp`/`.vtu`; each format is one reader registered by its extension
///        (mesh_formats.h).
/// @note Every failure throws InputError whose message is one line "<path>: <problem>". Vertex and
///       face numbers in messages count from 0, except for OBJ files, which count from 1 as OBJ
///       indices do.
/// @note OBJ, OFF, PLY and STL are parsed by OpenMesh 9.0 through an importer that keeps raw
///       faces, so non-manifold and open meshes lose no triangle. Its readers trust counts and
///       tokens, so each file's layout is checked first; layouts OpenMesh would misread (binary
///       OFF, ASCII PLY with 8-bit custom properties or nan/inf values, list properties other than
///       in the vertex element or after a face's vertex_indices) are rejected with a message.
/// @note STL files carry no shared vertices: corners with bit-identical coordinates are merged,
///       and the vertices are numbered in the order each merged corner first appears in the file
///       (as VTK's STL reader numbers them), which is the order a --scalar-file follows.
#pragma once

#include <ivis/core/surface_field.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ivis::core {

/// @brief Which scalar to show while reading.
struct MeshReadOptions {
    std::string scalarName;    ///< a point or cell array: "NAME", "NAME:magnitude", "NAME:<k>"; "" = none
    std::string scalarFile;    ///< sidecar text file, one value per vertex; "" = none
    bool cellToPoint = false;  ///< show a cell array averaged onto the vertices (area-weighted)
};

/// @brief What reading a file left out or repaired, for the user to hear about.
struct MeshReadReport {
    std::size_t degenerateDropped = 0;  ///< triangles dropped (repeated index or zero area)
    std::size_t unusedPointsDropped = 0;  ///< points no triangle uses, dropped with their point data
    std::vector<std::string> notes;     ///< what the file holds that is not shown ("left out 3 line cells")
};

/// @brief Summary of one array found in a file.
struct ArrayInfo {
    std::string name;
    Association association = Association::Point;
    ValueType type = ValueType::Float32;
    int components = 1;
    /// The figures below are of the tuples a picture can draw: every point (the file's unused points
    /// are dropped), the cells some triangle comes from (not line or vertex cells, nor a volume's inner cells).
    double min = 0.0;  ///< finite minimum of the default component (DataArray::defaultComponent); NaN if none
    double max = 0.0;  ///< finite maximum of the same; NaN if none
    std::size_t nanCount = 0;  ///< tuples with a NaN component
    bool shownByDefault = false;  ///< the array shown when none is chosen (core::defaultArray)
};

/// @brief What `inversevis info` prints about a mesh file.
struct MeshInfo {
    std::string path;
    std::string format;  ///< "obj", "off", "ply", "stl", "vtk", "vtp", "vtu"
    std::size_t vertices = 0;  ///< points in the file, used by a triangle or not
    std::size_t cells = 0;  ///< faces or cells in the file (the tuples of a cell array)
    std::size_t triangles = 0;
    Bounds3 bounds;  ///< of the points some triangle uses, in the file's own units
    std::size_t boundaryEdges = 0;
    std::size_t components = 0;
    MeshReadReport report;
    std::vector<ArrayInfo> arrays;
};

/// @brief Reads a mesh in its own units (not normalised), polygons fan-triangulated, degenerate
///        triangles (repeated index or zero area) dropped, with every array of the file and the
///        file cell each triangle came from. A mesh whose box's centre lies further from the
///        origin than the box is long is kept relative to that centre, rounded to a power of two
///        within its longest side (field.normalization's centre), its points taken as precisely
///        as the file holds them (STL: single precision, through OpenMesh), so that it keeps its
///        shape in single precision.
/// @param path mesh file; format chosen by extension (case-insensitive)
/// @param options scalar to show (at most one of name / file; see showArray for names)
/// @param report optional output: dropped triangles and notes on what is not shown
/// @throw InputError (missing/unreadable file, unknown format, not a mesh, zero triangles,
///        non-finite coordinates, out-of-range indices, malformed data, bad sidecar, unknown
///        array name listing the names that exist)
/// @warning Thread-safe; the OpenMesh part of concurrent reads runs one at a time.
SurfaceField readMesh(const std::string& path, const MeshReadOptions& options = {},
                      MeshReadReport* report = nullptr);

/// @brief A mesh given as arrays (the Python module's Mesh(vertices, faces, ...)) as readMesh reads
///        the same mesh from a file: coordinates checked finite, indices in range, degenerate
///        triangles dropped (counted in @a report), the arrays attached (each checked to hold a
///        tuple per point or per triangle), no scalar shown.
/// @param name what messages call the mesh (one line "<name>: <problem>")
/// @param triangles three vertex indices per triangle
/// @throw InputError as readMesh; for an array of the wrong length, naming it
SurfaceField meshFromArrays(const std::string& name, std::vector<glm::dvec3> positions,
                            std::vector<std::int64_t> triangles, std::vector<DataArray> arrays,
                            MeshReadReport* report = nullptr);

/// @brief Reads a mesh and reports its counts, bounds and every array.
/// @throw InputError as readMesh
MeshInfo describeMesh(const std::string& path);

/// @brief What `inversevis info` says of each array of @a field's file.
std::vector<ArrayInfo> describeArrays(const SurfaceField& field);

/// @brief Reads a sidecar scalar file: whitespace/newline separated numbers ("nan" allowed).
/// @param expectedCount number of vertices; a different count is an error
/// @throw InputError naming the file, the first bad token's line and its number (from 0, like vertices)
///        or the count mismatch
std::vector<float> readScalarFile(const std::string& path, std::size_t expectedCount);

namespace detail {
/// @brief readScalarFile on the bytes @a data of the file @a path (the fuzz target's entry point).
std::vector<float> parseScalarFile(const std::string& path, const std::string& data, std::size_t expectedCount);
}  // namespace detail

}  // namespace ivis::core
