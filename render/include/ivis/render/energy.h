/// @file energy.h
/// @brief The energy of what a view shows (METHOD.md, "Energy"):
///        E = gamma * sum over I+ of s(P(i)) + sum over I- of s(P(i)), times the pixel area,
///        with s the normalised scalar ("scalar") or the paper's voxel visibility ("visibility").
/// @warning EnergyEvaluator is immutable after construction; evaluate() is thread-safe.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/colormap.h>
#include <ivis/render/method.h>
#include <ivis/render/render_scene.h>
#include <ivis/render/screen_map.h>
#include <ivis/render/view_samples.h>
#include <ivis/render/visibility_grid.h>

#include <memory>
#include <string>
#include <vector>

namespace ivis::render {

/// @brief Which importance the energy sums.
enum class EnergyKind {
    Scalar,     ///< s = scalar normalised to [0,1] by the importance range
    Visibility  ///< fraction of marked voxels that some ray lands in
};

/// @brief Kind from its name ("scalar", "visibility"); throws InputError otherwise.
EnergyKind parseEnergyKind(const std::string& name);
/// @brief Name of a kind.
const char* toString(EnergyKind kind);

/// @brief How the energy is measured.
struct EnergyOptions {
    EnergyKind kind = EnergyKind::Visibility;
    float gamma = 1.0f;              ///< weight of the directly visible part
    int resolution = 100;            ///< optimisation resolution: rays per image side
    int visibilityResolution = 200;  ///< voxels per side of the visibility grid (paper: 200)
    core::ScalarRange importanceRange{0.0f, 1.0f};  ///< scalar values mapped to importance 0 and 1
};

/// @brief One measurement of a view.
struct EnergyValue {
    double energy = 0.0;      ///< the energy (visibility: fraction of marked voxels)
    double front = 0.0;       ///< the same measure counting direct pixels only
    double meanImportance = 0.0;  ///< mean s over pixels that show the surface (scalar kind)
    std::size_t pixelsDirect = 0;
    std::size_t pixelsIndirect = 0;
};

/// @brief The landing of one InverseVis pixel and its sensitivity to the pixel's alpha.
struct PixelAlphaDerivative {
    bool landed = false;     ///< false: direct pixel, missed hull, escaped, or a cap
    float alignment = 0.0f;  ///< c at the seed (the adaptive profile's argument)
    SurfacePoint point;      ///< where the curved ray lands
    glm::vec3 dPoint{0.0f};  ///< dP/dalpha of the launch that lands: the end tangent, projected onto the surface
    double dImportance = 0.0;  ///< d s(P)/d(the pixel.s alpha) = grad_S s . dP/dalpha, scaled for relaunches
};

/// @brief Measures views of one scene.
class EnergyEvaluator {
public:
    /// @brief Builds the visibility grid for the visibility kind.
    /// @throw InputError for the scalar kind on a mesh without scalar; ValueError for bad options
    EnergyEvaluator(const RenderScene& scene, const EnergyOptions& options);

    /// @brief Energy of @a camera with @a params at the optimisation resolution.
    EnergyValue evaluate(const core::Camera& camera, const MethodParams& params) const;
    /// @brief Energy of prepared view samples with @a params (which must be compatible with them):
    ///        repeated evaluations of one view share the direct hits and the hull seeds.
    EnergyValue evaluate(const ViewSamples& samples, const MethodParams& params) const;

    /// @brief Gradient of the scalar energy with respect to the curved-ray parameters, from the
    ///        tangent-linear propagation of each curved ray (exact derivative of the discrete steps)
    ///        and the surface gradient of s at its landing point: sum over I- of
    ///        grad_S s(P) . dP/dalpha times dalpha/dparameter, times the pixel area. InverseVis: {dE/dalpha};
    ///        InverseVisAdaptive: {dE/da0, dE/da1, dE/da2} of the alpha profile.
    /// @throw ValueError for the visibility kind (not differentiable: use forward differences) or
    ///        a method without curved rays
    std::vector<double> curvedRayGradient(const core::Camera& camera, const MethodParams& params) const;

    /// @brief The per-pixel term of curvedRayGradient at continuous pixel (x, y) of @a screen, per
    ///        unit change of that pixel's alpha.
    PixelAlphaDerivative pixelAlphaDerivative(const ScreenMap& screen, double x, double y,
                                              DistanceField::Sampler& sampler) const;

    /// @brief Importance in [0,1] of a surface point (0 for caps, NaN data or no scalar).
    float importance(const SurfacePoint& point) const;

    const EnergyOptions& options() const { return mOptions; }
    const RenderScene& scene() const { return mScene; }
    /// @brief The visibility grid (null for the scalar kind).
    const VisibilityGrid* visibilityGrid() const { return mVisibility.get(); }

private:
    const RenderScene& mScene;
    EnergyOptions mOptions;
    std::unique_ptr<VisibilityGrid> mVisibility;
};

}  // namespace ivis::render
