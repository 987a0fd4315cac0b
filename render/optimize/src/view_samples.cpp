#include <ivis/optimize/view_samples.h>

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/render/method_registry.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>

namespace ivis::optimize {

namespace {

/// The direct and indirect surface points of every pixel, mapped as the picture maps them: tile by
/// tile (render::ScreenMap::mapTile), in tile order.
void mapAllPixels(const render::RenderScene& scene, const render::ScreenMap& screen, int resolution,
                  std::vector<render::SurfacePoint>& direct, std::vector<render::SurfacePoint>& indirect)
{
    const int tilesPerSide = render::tilesAcross(resolution);
    struct Tile {
        std::vector<render::SurfacePoint> direct, indirect;
    };
    std::vector<Tile> tiles(std::size_t(tilesPerSide) * std::size_t(tilesPerSide));
    tbb::parallel_for(0, int(tiles.size()), [&](int t) {
        if (core::interruptRequested()) return;  // Ctrl-C: the rest is not needed (thrown by the caller)
        const render::PixelTile tile = render::tileAt(t, resolution, resolution);
        render::DistanceField::Sampler sampler = scene.distance().sampler();
        std::vector<render::PixelMapping> mappings(std::size_t(tile.width) * std::size_t(tile.height));
        render::TileCounts counts;
        screen.mapTile(tile, {0.5, 0.5}, render::AdaptiveSampling{}, sampler, mappings.data(), counts);
        Tile& out = tiles[std::size_t(t)];
        for (const render::PixelMapping& m : mappings)
            if (m.region == render::Region::Direct) out.direct.push_back(m.point);
            else if (m.region == render::Region::Indirect) out.indirect.push_back(m.point);
    });
    for (const Tile& tile : tiles) {  // in tile order: independent of the thread count
        direct.insert(direct.end(), tile.direct.begin(), tile.direct.end());
        indirect.insert(indirect.end(), tile.indirect.begin(), tile.indirect.end());
    }
}

}  // namespace

ViewSamples::ViewSamples(const render::RenderScene& scene, const core::Camera& camera, int resolution,
                         const render::MethodPtr& method)
    : mFrame(camera, resolution, resolution), mMethod(method)
{
    const render::ScreenMap screen(scene, mFrame, method);
    const render::CurvedRayMap* curved = screen.curvedRays();
    if (curved && render::optimisedParameters(*method).empty()) {
        mapAllPixels(scene, screen, resolution, mDirect, mIndirect);
        if (core::interruptRequested()) throw Cancelled("view sampling cancelled");
        return;
    }
    struct Row {
        std::vector<render::SurfacePoint> direct;
        std::vector<MissedPixel> missed;
    };
    std::vector<Row> rows(static_cast<std::size_t>(resolution));
    tbb::parallel_for(0, resolution, [&](int y) {
        if (core::interruptRequested()) return;  // Ctrl-C: the rest is not needed (thrown below)
        render::DistanceField::Sampler sampler = scene.distance().sampler();
        Row& row = rows[std::size_t(y)];
        std::vector<glm::dvec2> missed;  // the row's pixels whose view ray misses the surface
        for (int x = 0; x < resolution; ++x) {
            const render::PixelMapping direct = screen.directHit(x + 0.5, y + 0.5);
            if (direct.region == render::Region::Direct) row.direct.push_back(direct.point);
            else missed.emplace_back(x + 0.5, y + 0.5);
        }
        // A curved-ray method keeps the pixels whose ray it draws, their rays traced together.
        std::vector<render::CurvedRayStart> starts(missed.size());
        std::unique_ptr<bool[]> drawn(new bool[missed.size()]);
        if (curved) curved->startMany(missed.data(), missed.size(), sampler, starts.data(), drawn.get());
        else std::fill(drawn.get(), drawn.get() + missed.size(), true);
        for (std::size_t i = 0; i < missed.size(); ++i)
            if (drawn[i]) row.missed.push_back({float(missed[i].x), float(missed[i].y), starts[i]});
    });
    if (core::interruptRequested()) throw Cancelled("view sampling cancelled");
    for (const Row& row : rows) {  // in row order: independent of the thread count
        mDirect.insert(mDirect.end(), row.direct.begin(), row.direct.end());
        mMissed.insert(mMissed.end(), row.missed.begin(), row.missed.end());
    }
}

bool ViewSamples::compatibleWith(const render::Method& method) const
{
    return render::sameFixedParameters(method, *mMethod);
}

}  // namespace ivis::optimize
