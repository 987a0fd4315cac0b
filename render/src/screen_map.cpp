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

void ScreenMap::mapMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                        PixelMapping* mappings) const
{
    std::vector<glm::dvec2> missed;  // positions whose view ray misses the surface
    std::vector<std::size_t> where;  // and their pixels
    for (std::size_t i = 0; i < count; ++i) {
        mappings[i] = directHit(positions[i].x, positions[i].y);
        if (mappings[i].region == Region::Direct) continue;
        missed.push_back(positions[i]);
        where.push_back(i);
    }
    if (!mIndirect || missed.empty()) return;
    std::vector<PixelMapping> indirect(missed.size());
    mIndirect->mapMany(missed.data(), missed.size(), sampler, indirect.data());
    for (std::size_t j = 0; j < missed.size(); ++j) mappings[where[j]] = indirect[j];
}

void ScreenMap::mapTile(const PixelTile& tile, const glm::dvec2& offset, const AdaptiveSampling& adaptive,
                        DistanceField::Sampler& sampler, PixelMapping* mappings, TileCounts& counts) const
{
    // The hull-exit methods trace every pixel: their seeds are cheap and they have no stability rule to spare.
    if (mCurved && adaptive.enabled && mCurved->method().seedRule() == SeedRule::ClosestApproach) {
        mapTileAdaptively(*this, *mCurved, adaptive, tile, offset, sampler, mappings, counts);
        return;
    }
    std::vector<glm::dvec2> positions(std::size_t(tile.width));
    for (int y = 0; y < tile.height; ++y) {
        for (int x = 0; x < tile.width; ++x) positions[std::size_t(x)] = {tile.x0 + x + offset.x, tile.y0 + y + offset.y};
        PixelMapping* row = mappings + std::size_t(y) * tile.width;
        mapMany(positions.data(), positions.size(), sampler, row);
        for (int x = 0; x < tile.width; ++x)
            if (row[x].launched) counts.raysTraced += 1, counts.steps += std::size_t(row[x].steps);
    }
}

PixelMapping ScreenMap::indirect(double x, double y, DistanceField::Sampler& sampler) const
{
    return mIndirect ? mIndirect->map(x, y, sampler) : PixelMapping{};
}

}  // namespace ivis::render
