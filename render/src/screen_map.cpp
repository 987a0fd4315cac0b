#include <ivis/render/screen_map.h>

#include <ivis/core/errors.h>

#include <glm/geometric.hpp>

namespace ivis::render {

ScreenMap::ScreenMap(const RenderScene& scene, const core::CameraFrame& frame, MethodPtr method)
    : mScene(scene), mFrame(frame), mMethod(std::move(method))
{
    IVIS_CHECK(mMethod != nullptr);
    mIndirect = mMethod->indirectMap(scene, mFrame);
    mCurved = dynamic_cast<const CurvedRayMap*>(mIndirect.get());
}

PixelMapping ScreenMap::directHit(double x, double y) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    const glm::vec3 direction(ray.direction);
    const core::RayHit hit = mScene.bvh().intersect(glm::vec3(ray.origin), direction, 0.0f, 1e30f, mMethod->directFaces());
    if (!hit.hit()) return {};
    PixelMapping direct;
    direct.region = Region::Direct;
    direct.point = pointOnTriangle(mScene.mesh(), hit.triangle, hit.barycentric);
    direct.depth = glm::length(direct.point.position - glm::vec3(mFrame.camera().eye));
    direct.arrival = direction;
    return direct;
}

PixelMapping ScreenMap::map(double x, double y, DistanceField::Sampler& sampler) const
{
    const PixelMapping direct = directHit(x, y);
    return direct.region == Region::Direct ? direct : indirect(x, y, sampler);
}

PixelMapping ScreenMap::indirect(double x, double y, DistanceField::Sampler& sampler) const
{
    return mIndirect ? mIndirect->map(x, y, sampler) : PixelMapping{};
}

}  // namespace ivis::render
