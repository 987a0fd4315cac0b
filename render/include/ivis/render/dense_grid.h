/// @file dense_grid.h
/// @brief A dense float copy of a sparse grid's active region, sampled trilinearly with the
///        analytic gradient of the trilinear cell (the fast path for far-field distances).
#pragma once

#include <openvdb/openvdb.h>

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace ivis::render {

/// @brief Dense box of voxel values; outside the box every sample is the background value.
class DenseGrid {
public:
    DenseGrid() = default;
    /// @brief Copies the active bounding box (plus one voxel) of @a grid; inactive voxels keep
    ///        their (signed) background value.
    explicit DenseGrid(const openvdb::FloatGrid& grid);
    /// @brief Adopts @a values (x fastest, then y, then z) of a box of @a dims voxels whose voxel
    ///        (0,0,0) is centred at @a origin.
    DenseGrid(const glm::vec3& origin, const std::array<int, 3>& dims, float voxelSize, std::vector<float> values,
              float background);

    /// @brief Trilinear value at world point p (background outside the box).
    float value(const glm::vec3& p) const;
    /// @brief Trilinear value and its exact gradient within the cell containing p.
    float valueAndGradient(const glm::vec3& p, glm::vec3& gradient) const;
    /// @brief World-space voxel size.
    float voxelSize() const { return mVoxelSize; }
    /// @brief Value used outside the box.
    float background() const { return mBackground; }
    /// @brief Bytes held by the value array.
    std::size_t memoryBytes() const { return mValues.size() * sizeof(float); }

private:
    /// Cell origin index and fractional position of p; false when the cell is outside the box.
    bool locate(const glm::vec3& p, std::size_t& base, glm::vec3& t) const;

    std::vector<float> mValues;
    int mDims[3] = {0, 0, 0};
    glm::vec3 mOrigin{0.0f};  ///< world position of voxel (0,0,0) of the box
    float mVoxelSize = 1.0f;
    float mInvVoxelSize = 1.0f;
    float mBackground = 0.0f;
};

namespace detail {
/// @brief Trilinear interpolation of 8 corner values c[zyx bits] at fractions t, with gradient
///        (in index units) written to @a gradient when not null.
float trilinear(const float c[8], const glm::vec3& t, glm::vec3* gradient);
}  // namespace detail

}  // namespace ivis::render
