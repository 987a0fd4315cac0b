#include <ivis/render/mirror_method.h>

#include <ivis/render/curved_ray.h>
#include <ivis/vdb/box_lattice.h>

#include <cmath>

namespace ivis::render {
namespace {

/// The mirror of one view.
class MirrorMap final : public IndirectMap {
public:
    MirrorMap(const RenderScene& scene, const core::CameraFrame& frame, const MirrorParams& params)
        : mScene(scene), mFrame(frame), mParams(params), mEpsilon(landingEpsilon(CurvedRayParams{}, scene.distance()))
    {
    }
    PixelMapping map(double x, double y, DistanceField::Sampler& sampler) const override
    {
        MirrorHit hit;
        if (!intersectMirror(mFrame, mFrame.ray(x, y), mParams, hit)) return {};
        const float half = float(vdb::kBoxHalfExtent);
        glm::vec3 p = hit.point;
        int steps = 0;
        for (; steps < mParams.maxSteps; ++steps) {
            if (std::abs(p.x) > half || std::abs(p.y) > half || std::abs(p.z) > half) break;
            const float phi = sampler.phi(p);
            if (phi < mEpsilon) return landedAt(mScene, mFrame, p, hit.normal, steps, sampler);
            p += phi * hit.normal;
        }
        return launchedMiss(steps);
    }

private:
    const RenderScene& mScene;
    core::CameraFrame mFrame;
    MirrorParams mParams;
    float mEpsilon;
};

}  // namespace

ParameterValues MirrorMethod::values() const
{
    return {{"mirror_w", {mParams.w.begin(), mParams.w.end()}}, {"mirror_distance_behind", {mParams.distanceBehind}}};
}

std::unique_ptr<IndirectMap> MirrorMethod::indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const
{
    return std::make_unique<MirrorMap>(scene, frame, mParams);
}

PictureExtent MirrorMethod::pictureExtent(const RenderScene& scene, const core::Camera& camera) const
{
    return Method::pictureExtent(scene, camera).united(mirrorFootprint(camera, mParams, scene.bvh(), scene.bounds()));
}

const MethodInfo& mirrorMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "mirror";
        i.help = "quadratic height-field mirror behind the object";
        i.parameters = {ParameterSpec{"mirror_w", "mirror coefficients w1 w2 w3 w4 w5 (eye space)",
                                      {0.3f, 0.3f, 0.0f, 0.0f, 0.0f}, -10.0f, 10.0f}
                            .movedByTheAscent(),
                        {"mirror_distance_behind", "mirror apex behind the object's centre (normalised units)", {1.0f},
                         0.0f, 2.5f}};
        i.create = [](const ParameterValues& v) {
            MirrorParams params;
            for (std::size_t k = 0; k < params.w.size(); ++k) params.w[k] = v.at("mirror_w")[k];
            params.distanceBehind = v.at("mirror_distance_behind")[0];
            return std::make_shared<const MirrorMethod>(params);
        };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
