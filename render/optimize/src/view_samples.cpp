#include <ivis/optimize/view_samples.h>

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/render/method_registry.h>

#include <tbb/parallel_for.h>

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
        for (int x = 0; x < resolution; ++x) {
            MissedPixel pixel{float(x + 0.5), float(y + 0.5), {}};
            const render::PixelMapping direct = screen.directHit(pixel.x, pixel.y);
            if (direct.region == render::Region::Direct)
                row.direct.push_back(direct.point);
            else if (!curved || curved->start(pixel.x, pixel.y, sampler, pixel.start))
                row.missed.push_back(pixel);
        }
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
