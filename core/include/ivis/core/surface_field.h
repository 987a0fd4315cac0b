/// @file surface_field.h
/// @brief A triangle mesh with the arrays of its file, the scalar it shows (per vertex or per
///        triangle) and its normalising transform.
/// @note After normalize(), positions lie in [-1,1]^3; meshFromNormalized maps them back.
#pragma once

#include <ivis/core/data_array.h>
#include <ivis/core/similarity.h>
#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core {

/// @brief Mesh + the arrays of its file + the scalar it shows.
/// @note The shown scalar is per vertex (values.size() == mesh.positions.size()) or, for a cell
///       array, per data triangle (values.size() == mesh.dataTriangleCount); NaN allowed.
struct SurfaceField {
    TriangleMesh mesh;
    std::vector<float> values;                  ///< the shown scalar; empty when there is none
    Association valuesOn = Association::Point;  ///< whether @a values are per vertex or per triangle
    std::string name;                           ///< the shown scalar's name ("" when there is none)
    std::string sourcePath;                     ///< file it came from, or "generated:<scene>"
    Similarity normalization;                   ///< file units -> the positions' (readMesh: a shift at most)
    std::vector<DataArray> arrays;              ///< the file's arrays: a tuple per vertex (the file's points
                                                ///< some triangle uses) or per file cell
    std::vector<std::uint32_t> triangleCells;   ///< file cell of each data triangle (empty when generated)

    /// @brief True when a scalar is shown.
    bool hasScalar() const { return !values.empty(); }
};

/// @brief The shown scalar at the point of data triangle @a triangle with weights @a barycentric:
///        the triangle's value for a cell scalar, the linear blend of its vertices' otherwise; NaN
///        for a cap triangle, a field without scalar or a NaN value.
float scalarAt(const SurfaceField& field, std::size_t triangle, const glm::vec3& barycentric);

/// @brief The shown scalar at the three corners of @a triangle as the triangle sees them (a cell
///        scalar's value three times, so its surface gradient is zero).
/// @note Call only for a data triangle of a field with a scalar.
std::array<float, 3> cornerScalars(const SurfaceField& field, std::size_t triangle);

/// @brief Makes @a field show what @a step shows (scalar, its association and name, source, arrays,
///        cell map), keeping @a field's mesh: a time step of the same geometry, whose mesh the
///        scenes built on @a field still refer to.
void showStepData(SurfaceField& field, SurfaceField&& step);

/// @brief Scales and centres the mesh uniformly so its bounding box fits [-1,1]^3 (longest side
///        spans exactly [-1,1]); records the transform in field.normalization.
/// @throw ValueError if the mesh has zero extent.
void normalize(SurfaceField& field);

/// @brief Maps the surface by @a frame (normalised from the file's units, as a normalised field's
///        normalization) instead of its own normalising transform, composed into
///        field.normalization as normalize() composes it: the steps of a time series share their
///        first step's frame.
void normalizeBy(SurfaceField& field, const Similarity& frame);

/// @brief The transform normalize() applies to a mesh bounded by @a box: its centre to 0, its
///        longest side to length 2.
/// @throw ValueError "zero or non-finite extent"
Similarity normalizingTransform(const Bounds3& box);

/// @brief Finite (min, max) of the values, ignoring NaN; {0,0} when there is none.
std::pair<float, float> finiteRange(const std::vector<float>& values);

}  // namespace ivis::core
