/// @file mirror_method.h
/// @brief The `mirror` method: a quadratic height-field mirror behind the object whose normal is
///        the new ray direction, sphere-traced onto the surface (docs/method.md, "Baseline 2").
#pragma once

#include <ivis/render/method.h>
#include <ivis/render/quadratic_mirror.h>

namespace ivis::render {

/// @brief Description of `mirror`: parameters mirror_w (w1..w5, optimised) and mirror_distance_behind.
const MethodInfo& mirrorMethodInfo();

/// @brief The quadratic mirror with its parameters.
class MirrorMethod final : public Method {
public:
    /// @brief The mirror @a params.
    explicit MirrorMethod(const MirrorParams& params) : mParams(params) {}
    const MethodInfo& info() const override { return mirrorMethodInfo(); }
    ParameterValues values() const override;
    /// @brief Each pixel's view ray reflected by the quadratic mirror behind the object.
    std::unique_ptr<IndirectMap> indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const override;
    bool drawsIndirect() const override { return true; }
    /// @brief The object and the mirror's footprint (mirrorFootprint).
    PictureExtent pictureExtent(const RenderScene& scene, const core::Camera& camera) const override;
    /// @brief The mirror parameters.
    const MirrorParams& params() const { return mParams; }

private:
    MirrorParams mParams;
};

}  // namespace ivis::render
