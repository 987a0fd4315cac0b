#include <ivis/optimize/energy.h>

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/render/screen_map.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ivis::optimize {

using namespace render;
namespace {

/// Sums of an energy evaluation over a block of pixels.
struct Tally {
    double direct = 0.0, indirect = 0.0;
    std::size_t pixelsIndirect = 0;
    std::vector<std::uint64_t> directKeys, allKeys;
};

}  // namespace

EnergyKind parseEnergyKind(const std::string& name)
{
    if (name == "scalar") return EnergyKind::Scalar;
    if (name == "visibility") return EnergyKind::Visibility;
    throw InputError("unknown energy '" + name + "' (known: scalar, visibility)");
}

const char* toString(EnergyKind kind) { return kind == EnergyKind::Scalar ? "scalar" : "visibility"; }

EnergyEvaluator::EnergyEvaluator(const RenderScene& scene, const EnergyOptions& options)
    : mScene(scene), mOptions(options)
{
    if (options.resolution < kMinOptimizationResolution || options.resolution > kMaxOptimizationResolution)
        throw ValueError("optimisation resolution " + std::to_string(options.resolution) + " is out of range (" +
                         std::to_string(kMinOptimizationResolution) + " to " +
                         std::to_string(kMaxOptimizationResolution) + ")");
    if (options.kind == EnergyKind::Scalar && !scene.field().hasScalar())
        throw InputError(scene.field().sourcePath + ": the scalar energy needs a scalar field (--scalar NAME)");
    if (options.kind == EnergyKind::Scalar) {
        // All NaN, every view's energy is 0 and the search's result arbitrary (it returned theta 0).
        const std::vector<float>& values = scene.field().values;
        if (std::all_of(values.begin(), values.end(), [](float v) { return std::isnan(v); }))
            throw InputError(scene.field().sourcePath + ": the scalar energy needs values of '" + scene.field().name +
                             "', which has none (every value is NaN)");
    }
    // The grids of the mesh alone are the scene's, made once per resolution (the reveal's depends
    // on the scalar's values, which a time series changes under the same scene).
    const int resolution = options.visibilityResolution;
    if (options.kind == EnergyKind::Visibility)
        mSurface = &scene.derived<SurfaceVoxels>("surface voxels " + std::to_string(resolution),
                                                 [resolution](const RenderScene& s) {
                                                     return SurfaceVoxels(s.mesh(), resolution);
                                                 });
    if (options.kind == EnergyKind::Visibility && options.reveal)
        mReveal = std::make_unique<RevealMeasure>(scene.field(), options.importanceRange, options.visibilityResolution);
    if (options.kind == EnergyKind::Visibility && options.paperLiteral)
        mLiteral = &scene.derived<VisibilityGrid>("paper-literal grid " + std::to_string(resolution),
                                                  [resolution](const RenderScene& s) {
                                                      return VisibilityGrid(s.mesh(), s.bvh(), resolution);
                                                  });
}

float EnergyEvaluator::importance(const SurfacePoint& point) const
{
    const float value = scalarAt(mScene.field(), point);
    return std::isnan(value) ? 0.0f : mOptions.importanceRange.normalized(value);
}

EnergyValue EnergyEvaluator::evaluate(const core::Camera& camera, const MethodPtr& method) const
{
    return evaluate(ViewSamples(mScene, camera, mOptions.resolution, method), method);
}

EnergyValue EnergyEvaluator::evaluate(const ViewSamples& samples, const MethodPtr& method) const
{
    if (!samples.compatibleWith(*method)) throw ValueError("view samples prepared for other method parameters");
    const ScreenMap screen(mScene, samples.frame(), method);
    const CurvedRayMap* curved = screen.curvedRays();
    const std::vector<MissedPixel>& missed = samples.missed();
    auto count = [&](const SurfacePoint& point, Tally& tally) {  // an indirect pixel showing point
        ++tally.pixelsIndirect;
        if (mSurface)
            tally.allKeys.push_back(mSurface->keyOf(point.position));
        else
            tally.indirect += importance(point);
    };
    // Fixed blocks summed in block order: the result does not depend on the thread count.
    const std::size_t blockSize = 64, blocks = (missed.size() + blockSize - 1) / blockSize;
    std::vector<Tally> tallies(blocks + 1);  // the last: the samples' own mapped pixels
    for (const SurfacePoint& point : samples.indirect()) count(point, tallies.back());
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
        if (core::interruptRequested()) return;  // Ctrl-C: the rest is not needed (thrown below)
        DistanceField::Sampler sampler = mScene.distance().sampler();
        Tally& tally = tallies[b];
        const std::size_t begin = b * blockSize, end = std::min(missed.size(), begin + blockSize);
        std::vector<PixelMapping> mappings(end - begin);
        if (curved) {  // the block's rays traced together
            std::vector<CurvedRayStart> starts;
            for (std::size_t i = begin; i < end; ++i) starts.push_back(missed[i].start);
            curved->landingMany(starts.data(), starts.size(), sampler, mappings.data());
        } else {
            for (std::size_t i = begin; i < end; ++i) mappings[i - begin] = screen.indirect(missed[i].x, missed[i].y, sampler);
        }
        for (const PixelMapping& m : mappings)
            if (m.region == Region::Indirect) count(m.point, tally);
    });
    if (core::interruptRequested()) throw Cancelled("energy evaluation cancelled");
    EnergyValue value;
    Tally total;
    value.pixelsDirect = samples.direct().size();
    for (const SurfacePoint& point : samples.direct()) {
        if (mSurface)
            total.directKeys.push_back(mSurface->keyOf(point.position));
        else
            total.direct += importance(point);
    }
    total.allKeys = total.directKeys;
    for (Tally& tally : tallies) {
        total.indirect += tally.indirect;
        value.pixelsIndirect += tally.pixelsIndirect;
        total.allKeys.insert(total.allKeys.end(), tally.allKeys.begin(), tally.allKeys.end());
    }
    const int n = samples.frame().width();
    if (mSurface) {
        const SurfaceShare all = mSurface->shareSeen(total.allKeys);
        value.energy = all.area;
        value.voxelVisibility = all.voxels;
        value.front = mSurface->shareSeen(total.directKeys).area;
        if (mLiteral) value.paperLiteral = mLiteral->fractionVisited(total.allKeys);
        if (mReveal) value.reveal = mReveal->measure(total.directKeys, total.allKeys);
        value.seenVoxels = std::move(total.allKeys);
    } else {
        const double pixelArea = 4.0 / (double(n) * n);  // NDC [-1,1]^2
        value.energy = (mOptions.gamma * total.direct + total.indirect) * pixelArea;
        value.front = mOptions.gamma * total.direct * pixelArea;
        const std::size_t shown = value.pixelsDirect + value.pixelsIndirect;
        value.meanImportance = shown ? (total.direct + total.indirect) / double(shown) : 0.0;
    }
    return value;
}

}  // namespace ivis::optimize
