/// @file raw_mesh.h
/// @brief A mesh as a reader took it from its file: points, polygon faces, the file cell of each
///        face, and every point and cell array, before validation and triangulation.
/// @note Internal to readMesh: coordinates may be non-finite and indices out of range here;
///       readMesh checks them.
#pragma once

#include <ivis/core/data_array.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core::detail {

/// Everything one reader found in one file, in the file's own units.
struct RawMesh {
    std::vector<glm::dvec3> positions;     ///< the file's points, as precise as the file holds them
    std::vector<std::int64_t> corners;     ///< corner indices of every face, 0-based, in face order
    std::vector<std::size_t> faceEnds;     ///< end of each face's corners in @a corners
    std::vector<std::uint32_t> faceCells;  ///< file cell of each face; empty: face f is cell f
    std::size_t cellCount = 0;             ///< cells in the file (the tuples of a cell array)
    std::vector<DataArray> arrays;         ///< point and cell arrays, file order
    std::size_t skippedFaces = 0;          ///< faces the parser dropped itself (counted as degenerate)
    std::vector<std::string> notes;        ///< what was read but is not shown ("3 line cells ignored")

    /// Number of faces (polygons of any length).
    std::size_t faceCount() const { return faceEnds.size(); }
    /// Corner range [first, last) of face @a f.
    std::pair<const std::int64_t*, const std::int64_t*> face(std::size_t f) const
    {
        const std::size_t begin = f == 0 ? 0 : faceEnds[f - 1];
        return {corners.data() + begin, corners.data() + faceEnds[f]};
    }
    /// Appends a face with corners [@a begin, @a end) that came from file cell @a cell.
    template <typename It>
    void addFace(It begin, It end, std::uint32_t cell)
    {
        corners.insert(corners.end(), begin, end);
        faceEnds.push_back(corners.size());
        faceCells.push_back(cell);
    }
};

/// The point (@a x, @a y, @a z) as an array of @a type holds it: a Float32 array's coordinates
/// (written as text with more digits, say) rounded to single precision, as VTK reads them.
inline glm::dvec3 storedPoint(double x, double y, double z, ValueType type)
{
    if (type != ValueType::Float32) return {x, y, z};
    return glm::dvec3(glm::vec3(float(x), float(y), float(z)));
}

}  // namespace ivis::core::detail
