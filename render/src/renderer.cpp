#include <ivis/render/renderer.h>

#include <ivis/core/color_bar.h>
#include <ivis/core/errors.h>
#include <ivis/render/outline.h>
#include <ivis/render/screen_map.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>

namespace ivis::render {
namespace {

constexpr const char* kLayerNames[] = {"depth", "region", "triangle", "P.X", "P.Y", "P.Z", "scalar", "steps", nullptr};

/// Sample k of the per-pixel R2 pattern (k = 0 is the pixel centre).
glm::dvec2 sampleOffset(int k)
{
    return {std::fmod(0.5 + k * 0.7548776662466927, 1.0), std::fmod(0.5 + k * 0.5698402909980532, 1.0)};
}

}  // namespace

RenderResult renderImage(const RenderScene& scene, const core::Camera& camera, const RenderOptions& options,
                         core::Interrupter* interrupter)
{
    if (options.samplesPerPixel < 1 || options.samplesPerPixel > 1024)
        throw ValueError("samples per pixel " + std::to_string(options.samplesPerPixel) + " is out of range (1 to 1024)");
    const auto start = std::chrono::steady_clock::now();
    const core::CameraFrame frame(camera, options.width, options.height);
    const ScreenMap screen(scene, frame, options.method);
    const Shader shader(scene, frame, options.shading, *options.method);

    RenderResult result;
    result.image = core::Image(options.width, options.height);
    result.layers = core::ImageLayers(options.width, options.height);
    std::vector<core::Channel*> layers;
    for (const char* const* name = kLayerNames; *name; ++name) layers.push_back(&result.layers.add(*name));
    const float nan = std::numeric_limits<float>::quiet_NaN();

    std::mutex statsMutex;
    std::atomic<int> tilesDone{0};
    std::atomic<bool> cancelled{false};
    const int tileCount = tilesAcross(options.width) * tilesAcross(options.height);
    if (interrupter) interrupter->start("render");
    tbb::parallel_for(tbb::blocked_range<int>(0, tileCount), [&](const tbb::blocked_range<int>& tiles) {
        if (cancelled) return;
        DistanceField::Sampler sampler = scene.distance().sampler();
        RenderStats local;
        TileCounts counts;
        std::vector<PixelMapping> mappings(std::size_t(kAdaptiveTileSize) * kAdaptiveTileSize);
        std::vector<glm::vec4> colours(mappings.size());
        for (int t = tiles.begin(); t != tiles.end(); ++t) {
            const PixelTile tile = tileAt(t, options.width, options.height);
            std::fill(colours.begin(), colours.end(), glm::vec4(0.0f));
            for (int k = 0; k < options.samplesPerPixel; ++k) {
                screen.mapTile(tile, sampleOffset(k), options.adaptive, sampler, mappings.data(), counts);
                for (int y = 0; y < tile.height; ++y)
                    for (int x = 0; x < tile.width; ++x) {
                        const std::size_t inTile = std::size_t(y) * tile.width + x;
                        const PixelMapping& m = mappings[inTile];
                        const std::size_t index = std::size_t(tile.y0 + y) * options.width + tile.x0 + x;
                        bool isNan = false;
                        colours[inTile] += shader.shade(m, sampler, isNan);
                        if (m.launched && m.region == Region::Indirect) ++local.raysLanded;
                        if (k != 0) continue;
                        const bool shown = m.region != Region::Background;
                        (m.region == Region::Direct     ? local.pixelsDirect
                         : m.region == Region::Indirect ? local.pixelsIndirect
                                                        : local.pixelsBackground)++;
                        if (isNan) ++local.nanPixels;
                        (*layers[0])[index] = shown ? m.depth : nan;
                        (*layers[1])[index] = float(m.region);
                        (*layers[2])[index] = shown ? float(m.point.triangle) : -1.0f;
                        (*layers[3])[index] = shown ? m.point.position.x : nan;
                        (*layers[4])[index] = shown ? m.point.position.y : nan;
                        (*layers[5])[index] = shown ? m.point.position.z : nan;
                        (*layers[6])[index] = shown ? scalarAt(scene.field(), m.point) : nan;
                        (*layers[7])[index] = float(m.steps);
                    }
            }
            for (int y = 0; y < tile.height; ++y)
                for (int x = 0; x < tile.width; ++x)
                    result.image.at(tile.x0 + x, tile.y0 + y) =
                        colours[std::size_t(y) * tile.width + x] / float(options.samplesPerPixel);
        }
        local.raysLaunched = counts.raysTraced;
        local.totalSteps = counts.steps;
        local.seedsInterpolated = counts.seedsInterpolated;
        local.pixelsSkipped = counts.pixelsSkipped;
        {
            std::lock_guard<std::mutex> lock(statsMutex);
            RenderStats& s = result.stats;
            s.pixelsDirect += local.pixelsDirect;
            s.pixelsIndirect += local.pixelsIndirect;
            s.pixelsBackground += local.pixelsBackground;
            s.seedsInterpolated += local.seedsInterpolated;
            s.pixelsSkipped += local.pixelsSkipped;
            s.raysLaunched += local.raysLaunched;
            s.raysLanded += local.raysLanded;
            s.totalSteps += local.totalSteps;
            s.nanPixels += local.nanPixels;
        }
        const int done = tilesDone += int(tiles.size());
        if (interrupter && interrupter->wasInterrupted(int(100.0 * done / tileCount))) cancelled = true;
    });
    if (interrupter) interrupter->end();
    if (cancelled) throw Cancelled("render cancelled");

    if (options.outline)
        drawOutline(result.image, result.layers.channel("region"), std::max(1, options.height / 400));
    if (options.legend && scene.field().hasScalar()) {
        const ShadingOptions& shading = options.shading;
        const glm::vec4 margin = shading.transparentBackground ? glm::vec4(0.0f) : glm::vec4(shading.background, 1.0f);
        result.figure = core::withColorBar(result.image, {shading.colormap, shading.scale, options.scalarName, options.units},
                                           options.legendSide, margin, options.legendMinimumMargin);
    } else {
        result.figure = result.image;
    }
    result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace ivis::render
