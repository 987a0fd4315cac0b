#include <ivis/render/view_samples.h>

#include <tbb/parallel_for.h>

namespace ivis::render {

ViewSamples::ViewSamples(const RenderScene& scene, const core::Camera& camera, int resolution,
                         const MethodParams& params)
    : mFrame(camera, resolution, resolution), mParams(params)
{
    const ScreenMap screen(scene, mFrame, params);
    const bool curved = params.curvedRays();
    struct Row {
        std::vector<SurfacePoint> direct;
        std::vector<MissedPixel> missed;
    };
    std::vector<Row> rows(static_cast<std::size_t>(resolution));
    tbb::parallel_for(0, resolution, [&](int y) {
        DistanceField::Sampler sampler = scene.distance().sampler();
        Row& row = rows[std::size_t(y)];
        for (int x = 0; x < resolution; ++x) {
            MissedPixel pixel{float(x + 0.5), float(y + 0.5), {}};
            const PixelMapping direct = screen.directHit(pixel.x, pixel.y);
            if (direct.region == Region::Direct)
                row.direct.push_back(direct.point);
            else if (!curved || screen.curvedRayStart(pixel.x, pixel.y, sampler, pixel.start))
                row.missed.push_back(pixel);
        }
    });
    for (const Row& row : rows) {  // in row order: independent of the thread count
        mDirect.insert(mDirect.end(), row.direct.begin(), row.direct.end());
        mMissed.insert(mMissed.end(), row.missed.begin(), row.missed.end());
    }
}

bool ViewSamples::compatibleWith(const MethodParams& params) const
{
    return params.method == mParams.method && params.curved.hullOffset == mParams.curved.hullOffset &&
           params.ring.centre == mParams.ring.centre && params.ring.ringWidth == mParams.ring.ringWidth;
}

}  // namespace ivis::render
