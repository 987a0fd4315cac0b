#include <ivis/render/neugebauer_method.h>

namespace ivis::render {
namespace {

/// The rings of one view.
class RingMap final : public IndirectMap {
public:
    RingMap(const RenderScene& scene, const core::CameraFrame& frame, const RingParams& params)
        : mScene(scene), mFrame(frame), mCentre(params.centre), mLayout(layoutRings(frame, scene.mesh(), params))
    {
    }
    PixelMapping map(double x, double y, DistanceField::Sampler& /*sampler*/) const override
    {
        glm::vec3 direction;
        if (!ringRayDirection(mLayout, mFrame, {x, y}, direction)) return {};
        return straightHit(mScene, mFrame, mCentre, direction);
    }

private:
    const RenderScene& mScene;
    core::CameraFrame mFrame;
    glm::vec3 mCentre;
    RingLayout mLayout;
};

}  // namespace

ParameterValues NeugebauerMethod::values() const
{
    return {{"ring_centre", {mParams.centre.x, mParams.centre.y, mParams.centre.z}}, {"ring_width", {mParams.ringWidth}}};
}

ParameterValues NeugebauerMethod::viewValues(const core::CameraFrame& frame, const core::TriangleMesh& mesh) const
{
    const RingLayout rings = layoutRings(frame, mesh, mParams);
    return {{"ring_pixel_centre", {float(rings.centre.x), float(rings.centre.y)}},
            {"ring_inner", {float(rings.innerRadius)}},
            {"back_centre", {float(rings.backCentre.x), float(rings.backCentre.y)}},
            {"back_radius", {float(rings.backRadius)}}};
}

std::unique_ptr<IndirectMap> NeugebauerMethod::indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const
{
    return std::make_unique<RingMap>(scene, frame, mParams);
}

PictureExtent NeugebauerMethod::pictureExtent(const RenderScene& scene, const core::Camera& camera) const
{
    return ringExtent(camera, scene.mesh(), mParams);
}

const MethodInfo& neugebauerMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "neugebauer";
        i.help = "ring map of Neugebauer et al. 2009 around the silhouette, with a back-side disc on the left";
        i.parameters = {{"ring_centre", "ring map centre x y z (normalised units)", {0.0f, 0.0f, 0.0f}, -2.5f, 2.5f},
                        {"ring_width", "ring width r2 - r1 (fraction of the image half-height; at most 0.75, so that a "
                         "framed picture keeps room for the object from every view)", {0.3f}, 0.01f, 0.75f}};
        i.viewValueKeys = {"ring_pixel_centre", "ring_inner", "back_centre", "back_radius"};
        i.create = [](const ParameterValues& v) {
            RingParams params;
            const std::vector<float>& c = v.at("ring_centre");
            params.centre = {c[0], c[1], c[2]};
            params.ringWidth = v.at("ring_width")[0];
            return std::make_shared<const NeugebauerMethod>(params);
        };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
