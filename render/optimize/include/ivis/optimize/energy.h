/// @file energy.h
/// @brief The energy of what a view shows (docs/method.md, "Energy"):
///        E = gamma * sum over I+ of s(P(i)) + sum over I- of s(P(i)), times the pixel area,
///        with s the normalised scalar ("scalar"), or the surface visibility of docs/measures.md's
///        measures ("visibility", surface_voxels.h).
/// @warning EnergyEvaluator is immutable after construction; evaluate() is thread-safe.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/colormap.h>
#include <ivis/optimize/reveal.h>
#include <ivis/optimize/surface_voxels.h>
#include <ivis/optimize/view_samples.h>
#include <ivis/optimize/visibility_grid.h>
#include <ivis/render/method.h>
#include <ivis/render/render_scene.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ivis::optimize {

/// @brief Which importance the energy sums.
enum class EnergyKind {
    Scalar,     ///< s = scalar normalised to [0,1] by the importance range
    Visibility  ///< surface visibility: share of the surface area inside the voxels some ray lands in
};

/// @brief Kind from its name ("scalar", "visibility"); throws InputError otherwise.
EnergyKind parseEnergyKind(const std::string& name);
/// @brief Name of a kind.
const char* toString(EnergyKind kind);

/// Rays per image side an optimisation resolution may have, at least and at most.
inline constexpr int kMinOptimizationResolution = 4;
inline constexpr int kMaxOptimizationResolution = 8192;

/// @brief How the energy is measured.
struct EnergyOptions {
    EnergyKind kind = EnergyKind::Visibility;
    float gamma = 1.0f;              ///< weight of the directly visible part
    int resolution = 100;            ///< optimisation resolution: rays per image side
    int visibilityResolution = 200;  ///< voxels per side of the visibility grid (paper: 200)
    bool paperLiteral = false;       ///< visibility kind: also measure the paper-literal figure
    bool reveal = false;             ///< visibility kind, with a scalar: also measure the hot-spot reveal
    core::ScalarRange importanceRange{0.0f, 1.0f};  ///< scalar values mapped to importance 0 and 1
};

/// @brief One measurement of a view.
struct EnergyValue {
    double energy = 0.0;      ///< the energy (visibility: surface visibility, area-weighted)
    double front = 0.0;       ///< the same measure counting direct pixels only
    double voxelVisibility = 0.0;  ///< visibility kind: seen surface voxels / surface voxels
    double paperLiteral = 0.0;  ///< visited / marked voxels (when EnergyOptions::paperLiteral)
    RevealValue reveal;         ///< hot-spot reveal (when EnergyOptions::reveal)
    double meanImportance = 0.0;  ///< mean s over pixels that show the surface (scalar kind)
    std::size_t pixelsDirect = 0;
    std::size_t pixelsIndirect = 0;
    std::vector<std::uint64_t> seenVoxels;  ///< visibility kind: the voxels the pixels' points fall in (sorted, once each)
};

/// @brief Measures views of one scene.
class EnergyEvaluator {
public:
    /// @brief Builds the visibility grid for the visibility kind.
    /// @throw InputError for the scalar kind on a mesh without scalar; ValueError for bad options
    EnergyEvaluator(const render::RenderScene& scene, const EnergyOptions& options);

    /// @brief Energy of @a camera with @a method at the optimisation resolution.
    EnergyValue evaluate(const core::Camera& camera, const render::MethodPtr& method) const;
    /// @brief Energy of prepared view samples with @a method (which must be compatible with them):
    ///        repeated evaluations of one view share the direct hits and the hull seeds.
    /// @throw Cancelled once Ctrl-C was pressed (core/interrupt_signal.h), for both forms
    EnergyValue evaluate(const ViewSamples& samples, const render::MethodPtr& method) const;

    /// @brief Importance in [0,1] of a surface point (0 for caps, NaN data or no scalar).
    float importance(const render::SurfacePoint& point) const;

    /// @brief How this evaluator measures.
    const EnergyOptions& options() const { return mOptions; }
    /// @brief The scene it measures.
    const render::RenderScene& scene() const { return mScene; }
    /// @brief The surface voxels of the visibility kind (null for the scalar kind), the scene's
    ///        for this resolution (made once per scene and resolution, shared by its evaluators).
    const SurfaceVoxels* surfaceVoxels() const { return mSurface; }
    /// @brief The reveal measure (null unless EnergyOptions::reveal).
    const RevealMeasure* revealMeasure() const { return mReveal.get(); }
    /// @brief The paper-literal grid (null unless EnergyOptions::paperLiteral), shared as the
    ///        surface voxels are.
    const VisibilityGrid* literalGrid() const { return mLiteral; }

private:
    const render::RenderScene& mScene;
    EnergyOptions mOptions;
    const SurfaceVoxels* mSurface = nullptr;
    const VisibilityGrid* mLiteral = nullptr;
    std::unique_ptr<RevealMeasure> mReveal;
};

}  // namespace ivis::optimize
