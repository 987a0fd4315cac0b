/// @file raw_mesh_import.h
/// @brief Parses a mesh file with OpenMesh 9.0 into raw positions, faces and per-vertex scalar
///        properties, without half-edge topology, so no face is refused or dropped.
/// @note Internal to readMesh: pass only bytes that checkMeshLayout accepted, since OpenMesh's
///       readers trust the counts and tokens of a file.
#pragma once

#include <ivis/core/mesh_layout_check.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core::detail {

/// One per-vertex scalar property of a file, by name.
struct NamedValues {
    std::string name;
    std::vector<float> values;
};

/// A mesh as its file gives it: coordinates may be non-finite and indices out of range.
struct RawMesh {
    std::vector<glm::vec3> positions;   ///< in the file's own units
    std::vector<int> corners;           ///< corner indices of every face, 0-based, in face order
    std::vector<std::size_t> faceEnds;  ///< end of each face's corners in @a corners
    std::vector<NamedValues> scalars;   ///< every per-vertex float/double property, file order

    /// Number of faces (polygons of any length).
    std::size_t faceCount() const { return faceEnds.size(); }
    /// Corner range [first, last) of face @a f.
    std::pair<const int*, const int*> face(std::size_t f) const
    {
        const std::size_t begin = f == 0 ? 0 : faceEnds[f - 1];
        return {corners.data() + begin, corners.data() + faceEnds[f]};
    }
};

/// Reads the checked bytes @a data of @a path with OpenMesh (one import at a time, its logging silenced).
RawMesh importRawMesh(const std::string& path, MeshFormat format, bool binaryStl, std::string data);

}  // namespace ivis::core::detail
