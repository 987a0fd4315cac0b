/// @file dense_slices.h
/// @brief The volume as the viewer uploads it ("dense slices"): a dense distance box over the
///        region the curved rays fly through and a dense closest-triangle box around the surface,
///        at the finest resolution that fits a GPU memory budget.
/// @note Built on the CPU from a RenderScene; the GL side only copies the arrays into 3D textures.
#pragma once

#include <ivis/core/interrupter.h>
#include <ivis/render/render_scene.h>

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief A dense box of voxels on the lattice of one resolution: voxel i is centred at
///        -2.5 + (firstIndex + i + 0.5) * voxelSize on each axis; x varies fastest.
template <typename T>
struct DenseBox {
    std::array<int, 3> dims{0, 0, 0};
    glm::vec3 origin{0.0f};  ///< world (normalised) centre of voxel (0,0,0)
    std::vector<T> values;

    /// @brief Number of voxels.
    std::size_t count() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }
    /// @brief Bytes of the value array.
    std::size_t bytes() const { return count() * sizeof(T); }
};

/// @brief What the shaders sample: distance and closest triangle, plus how they were made.
struct DenseSlices {
    /// phi at voxel centres over the far field's (or, without one, the fine band's) active box plus
    /// one voxel; trilinear in the shader exactly as render::DenseGrid. Outside: @a outside.
    DenseBox<float> distance;
    /// Closest triangle index at voxel centres over the fine band's active box plus one voxel
    /// (-1 = none), read at the nearest voxel as DistanceField::Sampler::nearestTriangle.
    DenseBox<std::int32_t> triangles;
    float voxelSize = 0.0f;    ///< voxel size of both boxes (normalised units)
    float outside = 0.0f;      ///< phi outside the distance box (the field's clamp value)
    float reach = 0.0f;        ///< exterior distance up to which phi is exact
    int volumeResolution = 0;  ///< resolution of the sparse volume
    int shownResolution = 0;   ///< resolution of the boxes (== volumeResolution unless resampled)
    std::size_t budgetBytes = 0;

    /// @brief True when the boxes hold the volume's own voxels (no resampling).
    bool exact() const { return shownResolution == volumeResolution; }
    /// @brief Bytes of both boxes.
    std::size_t bytes() const { return distance.bytes() + triangles.bytes(); }
    /// @brief One line for the panel and stdout: what resolution is shown and why.
    std::string describe() const;
};

/// @brief Limits of the upload.
struct DenseSliceOptions {
    std::size_t budgetBytes = std::size_t(512) << 20;  ///< both boxes together
    int maxTextureSize = 2048;                          ///< GL_MAX_3D_TEXTURE_SIZE
};

/// @brief The largest resolution N' <= the volume's whose two boxes fit the budget and the texture
///        size limit (the boxes shrink with N'^3).
/// @throw ValueError when not even N' = 16 fits
int chooseShownResolution(const render::RenderScene& scene, const DenseSliceOptions& options);

/// @brief Fills both boxes at chooseShownResolution(). At the volume's own resolution the values are
///        the grids' voxels (distance: fine voxel when active, else the far field); when resampled,
///        distance = DistanceField::Sampler::phi at the coarse centres and triangle = the exact
///        closest triangle (BVH) of each centre within 2.5 coarse voxels of the surface.
/// @param interrupter progress (percent) and cancel
/// @throw ValueError (see chooseShownResolution); Cancelled when interrupted
/// @warning Uses all TBB threads.
DenseSlices buildDenseSlices(const render::RenderScene& scene, const DenseSliceOptions& options,
                             core::Interrupter* interrupter = nullptr);

namespace detail {
/// @brief First and last lattice index (resolution @a resolution) whose voxel centres cover the
///        world interval [lo, hi], clamped to the box [-2.5, 2.5].
std::array<int, 2> latticeRange(double lo, double hi, int resolution);
}  // namespace detail

}  // namespace ivis::app
