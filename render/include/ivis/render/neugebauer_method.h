/// @file neugebauer_method.h
/// @brief The `neugebauer` method: the ring map of Neugebauer et al. (2009) around the projected
///        centre plus a back-side disc on the left (docs/method.md, "Baseline 1").
#pragma once

#include <ivis/render/method.h>
#include <ivis/render/neugebauer_map.h>

namespace ivis::render {

/// @brief Description of `neugebauer`: parameters ring_centre (x y z) and ring_width.
const MethodInfo& neugebauerMethodInfo();

/// @brief The ring map with its parameters.
class NeugebauerMethod final : public Method {
public:
    /// @brief The rings of @a params.
    explicit NeugebauerMethod(const RingParams& params) : mParams(params) {}
    const MethodInfo& info() const override { return neugebauerMethodInfo(); }
    ParameterValues values() const override;
    /// @brief The rings' layout (layoutRings): ring_pixel_centre, ring_inner, back_centre, back_radius.
    ParameterValues viewValues(const core::CameraFrame& frame, const core::TriangleMesh& mesh) const override;
    /// @brief False: the rings' straight rays start at the projection centre, inside the object.
    bool indirectRaysArriveFromOutside() const override { return false; }
    /// @brief The ring map: a ring pixel's and the back disc's straight rays from the projection centre.
    std::unique_ptr<IndirectMap> indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const override;
    bool drawsIndirect() const override { return true; }
    /// @brief The outer ring (ringExtent).
    PictureExtent pictureExtent(const RenderScene& scene, const core::Camera& camera) const override;
    /// @brief The ring parameters.
    const RingParams& params() const { return mParams; }

private:
    RingParams mParams;
};

}  // namespace ivis::render
