#include <ivis/optimize/view_samples.h>

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/render/method_registry.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>

namespace ivis::optimize {

ViewSamples::ViewSamples(const render::RenderScene& scene, const core::Camera& camera, int resolution,
                         const render::MethodPtr& method)
    : mFrame(camera, resolution, resolution), mMethod(method)
{
    const render::ScreenMap screen(scene, mFrame, method);
    const render::CurvedRayMap* curved = screen.curvedRays();
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
