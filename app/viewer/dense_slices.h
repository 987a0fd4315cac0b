/// @file dense_slices.h
/// @brief The volume as the viewer uploads it ("dense slices"): the CPU renderer's dense far-field
///        copy, a dense box of the fine narrow band and a dense closest-triangle box around the
///        surface, at the finest band resolution that fits a GPU memory budget.
/// @note Built on the CPU from a RenderScene; the GL side only copies the arrays into 3D textures.
///       The shaders combine the boxes exactly as render::DistanceField::Sampler does: the far copy
///       everywhere, the fine band where all eight corners of a fine cell are in the band.
#pragma once

#include <ivis/core/interrupter.h>
#include <ivis/render/render_scene.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief Value of a band voxel the CPU would not use (inactive in the fine grid).
inline constexpr float kInactiveBandValue = 1e30f;

/// @brief A dense box of voxels on the lattice of one resolution: voxel i is centred at
///        @a origin + i * voxel size on each axis; x varies fastest.
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

/// @brief What the shaders sample, and how it was made.
struct DenseSlices {
    /// The CPU's dense far copy (render::DenseGrid of the far field, or of the fine grid when the
    /// volume has no far field): (phi, exact gradient) at farResolution; outside it phi is @a outside.
    DenseBox<glm::vec4> far;
    /// Fine band (phi, exact gradient) at shownResolution over the band's active box plus one voxel;
    /// phi = kInactiveBandValue where the CPU would not use the band. Empty when !hasFineBand.
    DenseBox<glm::vec4> band;
    /// Closest triangle at shownResolution over the band's active box plus one voxel (-1 = none),
    /// read at the nearest voxel as DistanceField::Sampler::nearestTriangle.
    DenseBox<std::int32_t> triangles;
    /// Each registered method's render::MethodInfo::vertexArrays, in order, by method name.
    std::map<std::string, std::vector<std::vector<float>>> methodArrays;
    bool hasFineBand = false;  ///< the volume has a far field, so the band refines it near the surface
    float farVoxelSize = 0.0f; ///< voxel size of @a far
    float voxelSize = 0.0f;    ///< voxel size of @a band and @a triangles
    float outside = 0.0f;      ///< phi outside @a far (the field's clamp value)
    float fineFrom = 0.0f;     ///< far values below this use the band alone (DistanceField's rule)
    float fineUntil = 0.0f;    ///< far values above this never use the band; blended between
    float reach = 0.0f;        ///< exterior distance up to which phi is exact
    bool unsignedDistance = false;  ///< phi is |distance| (open mesh)
    int volumeResolution = 0;  ///< resolution of the sparse volume
    int shownResolution = 0;   ///< resolution of band and triangles (== volumeResolution unless resampled)
    int farResolution = 0;     ///< resolution of @a far
    std::size_t budgetBytes = 0;

    /// @brief True when the boxes hold the volume's own voxels (no resampling).
    bool exact() const { return shownResolution == volumeResolution; }
    /// @brief Bytes of all boxes.
    std::size_t bytes() const { return far.bytes() + band.bytes() + triangles.bytes(); }
    /// @brief One line for the panel and stdout: what resolution is shown and why.
    std::string describe() const;
};

/// @brief Limits of the upload.
struct DenseSliceOptions {
    std::size_t budgetBytes = std::size_t(512) << 20;  ///< all boxes together
    int maxTextureSize = 2048;                          ///< GL_MAX_3D_TEXTURE_SIZE
};

/// @brief The largest resolution N' <= the volume's whose boxes fit the budget and the texture
///        size limit (band and triangle boxes shrink with N'^3; the far copy stays at its own).
/// @throw ValueError when not even N' = 16 fits
int chooseShownResolution(const render::RenderScene& scene, const DenseSliceOptions& options);

/// @brief Fills the boxes at chooseShownResolution(). At the volume's own resolution every value
///        is a voxel of the grids, so the shaders interpolate exactly the numbers the CPU does.
///        Resampled (N' < N): band = DistanceField::Sampler::phiAndGradient at the coarse centres whose fine
///        cell lies in the band, triangle = the exact closest triangle (BVH) of each centre within
///        2.5 coarse voxels of the surface; without a far field the far copy itself is resampled.
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
