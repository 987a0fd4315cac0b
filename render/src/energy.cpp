#include <ivis/render/energy.h>

#include <ivis/core/errors.h>
#include <ivis/render/curved_ray.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace ivis::render {
namespace {

/// Sums of an energy evaluation over a block of pixels.
struct Tally {
    double direct = 0.0, indirect = 0.0;
    std::size_t pixelsIndirect = 0;
    std::vector<std::uint64_t> directKeys, allKeys;
};

/// Gradient within the triangle's plane of the linear interpolant of per-vertex values.
glm::vec3 surfaceGradient(const core::TriangleMesh& mesh, int triangle, const float values[3])
{
    const auto& t = mesh.triangles[triangle];
    const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float twiceArea = glm::length(n);
    if (!(twiceArea > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 unit = n / twiceArea;
    return (values[0] * glm::cross(unit, c - b) + values[1] * glm::cross(unit, a - c) +
            values[2] * glm::cross(unit, b - a)) /
           twiceArea;
}

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
    if (options.resolution < 4 || options.resolution > 8192)
        throw ValueError("optimisation resolution " + std::to_string(options.resolution) + " is out of range (4 to 8192)");
    if (options.kind == EnergyKind::Scalar && !scene.field().hasScalar())
        throw InputError(scene.field().sourcePath + ": the scalar energy needs a scalar field (--scalar NAME)");
    if (options.kind == EnergyKind::Visibility)
        mVisibility = std::make_unique<VisibilityGrid>(scene.mesh(), scene.bvh(), options.visibilityResolution);
}

float EnergyEvaluator::importance(const SurfacePoint& point) const
{
    const float value = scalarAt(mScene.field(), point);
    return std::isnan(value) ? 0.0f : mOptions.importanceRange.normalized(value);
}

EnergyValue EnergyEvaluator::evaluate(const core::Camera& camera, const MethodParams& params) const
{
    return evaluate(ViewSamples(mScene, camera, mOptions.resolution, params), params);
}

EnergyValue EnergyEvaluator::evaluate(const ViewSamples& samples, const MethodParams& params) const
{
    if (!samples.compatibleWith(params)) throw ValueError("view samples prepared for other method parameters");
    const ScreenMap screen(mScene, samples.frame(), params);
    const bool curved = params.curvedRays();
    const std::vector<MissedPixel>& missed = samples.missed();
    // Fixed blocks summed in block order: the result does not depend on the thread count.
    const std::size_t blockSize = 64, blocks = (missed.size() + blockSize - 1) / blockSize;
    std::vector<Tally> tallies(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
        DistanceField::Sampler sampler = mScene.distance().sampler();
        Tally& tally = tallies[b];
        for (std::size_t i = b * blockSize; i < std::min(missed.size(), (b + 1) * blockSize); ++i) {
            const MissedPixel& pixel = missed[i];
            const PixelMapping m =
                curved ? screen.curvedRay(pixel.start, sampler) : screen.indirect(pixel.x, pixel.y, sampler);
            if (m.region != Region::Indirect) continue;
            ++tally.pixelsIndirect;
            if (mVisibility)
                tally.allKeys.push_back(mVisibility->keyOf(m.point.position));
            else
                tally.indirect += importance(m.point);
        }
    });
    EnergyValue value;
    Tally total;
    value.pixelsDirect = samples.direct().size();
    for (const SurfacePoint& point : samples.direct()) {
        if (mVisibility)
            total.directKeys.push_back(mVisibility->keyOf(point.position));
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
    if (mVisibility) {
        const double marked = double(std::max<std::size_t>(1, mVisibility->markedCount()));
        value.energy = double(mVisibility->countMarked(total.allKeys)) / marked;
        value.front = double(mVisibility->countMarked(total.directKeys)) / marked;
    } else {
        const double pixelArea = 4.0 / (double(n) * n);  // NDC [-1,1]^2
        value.energy = (mOptions.gamma * total.direct + total.indirect) * pixelArea;
        value.front = mOptions.gamma * total.direct * pixelArea;
        const std::size_t shown = value.pixelsDirect + value.pixelsIndirect;
        value.meanImportance = shown ? (total.direct + total.indirect) / double(shown) : 0.0;
    }
    return value;
}

PixelAlphaDerivative EnergyEvaluator::pixelAlphaDerivative(const ScreenMap& screen, double x, double y,
                                                          DistanceField::Sampler& sampler) const
{
    PixelAlphaDerivative result;
    const MethodParams& params = screen.params();
    CurvedRayStart start;
    if (!screen.curvedRayStart(x, y, sampler, start)) return result;
    result.alignment = start.alignment;
    // The tangent follows the launch that lands; its alpha is the pixel's alpha halved per relaunch.
    float alpha;
    if (!screen.traceFrom(start, sampler, alpha).landed) return result;
    const float pixelAlpha = screen.alphaOf(start);
    const double relaunchScale = pixelAlpha > 0.0f ? double(alpha / pixelAlpha) : 1.0;
    const CurvedRayTangent ray = integrateCurvedRayTangent(
        sampler, start.seed, alpha * start.velocityPerAlpha, start.velocityPerAlpha, params.curved,
        landingEpsilon(params.curved, mScene.distance()), 0.999f * mScene.distance().reach());
    if (!ray.end.landed) return result;
    const PixelMapping landed = screen.landedAt(ray.end.position, ray.end.velocity, ray.end.steps, sampler);
    const core::TriangleMesh& mesh = mScene.mesh();
    if (landed.region != Region::Indirect || mesh.isCap(std::size_t(landed.point.triangle))) return result;
    // The landing point moves with the part of the end position's tangent along the surface.
    glm::vec3 normal;
    sampler.phiAndGradient(ray.end.position, normal);
    const float length = glm::length(normal);
    normal = length > 0.0f ? normal / length : glm::vec3(0.0f);
    result.landed = true;
    result.point = landed.point;
    result.dPoint = ray.dPosition - glm::dot(ray.dPosition, normal) * normal;
    const auto& t = mesh.triangles[landed.point.triangle];
    float s[3];
    for (int c = 0; c < 3; ++c) {
        const float v = mScene.field().values[t[c]];
        s[c] = std::isnan(v) ? 0.0f : mOptions.importanceRange.normalized(v);
    }
    result.dImportance = relaunchScale * double(glm::dot(surfaceGradient(mesh, landed.point.triangle, s), result.dPoint));
    return result;
}

std::vector<double> EnergyEvaluator::curvedRayGradient(const core::Camera& camera, const MethodParams& params) const
{
    if (mOptions.kind != EnergyKind::Scalar)
        throw ValueError("the visibility energy has no analytic derivative; use forward differences");
    if (!params.curvedRays())
        throw ValueError(std::string("the analytic gradient needs curved rays, not the method ") + toString(params.method));
    const bool adaptive = params.method == Method::InverseVisAdaptive;
    const std::size_t count = adaptive ? params.profile.coefficients.size() : 1;
    const int n = mOptions.resolution;
    const core::CameraFrame frame(camera, n, n);
    const ScreenMap screen(mScene, frame, params);
    std::vector<std::vector<double>> rows(std::size_t(n), std::vector<double>(count, 0.0));
    tbb::parallel_for(0, n, [&](int y) {
        DistanceField::Sampler sampler = mScene.distance().sampler();
        for (int x = 0; x < n; ++x) {
            const PixelAlphaDerivative d = pixelAlphaDerivative(screen, x + 0.5, y + 0.5, sampler);
            if (!d.landed) continue;
            if (!adaptive) {
                rows[std::size_t(y)][0] += d.dImportance;
                continue;
            }
            // alpha = a0 + a1 c + a2 c^2 moves with a_k by c^k, unless the profile is clamped there.
            const AlphaProfile& profile = params.profile;
            const float raw = profile.at(d.alignment);
            if (raw <= 0.0f || raw >= profile.maxAlpha) continue;
            double power = 1.0;
            for (std::size_t k = 0; k < count; ++k, power *= d.alignment) rows[std::size_t(y)][k] += d.dImportance * power;
        }
    });
    std::vector<double> total(count, 0.0);
    for (const auto& row : rows)  // in row order: independent of the thread count
        for (std::size_t k = 0; k < count; ++k) total[k] += row[k];
    for (double& t : total) t *= 4.0 / (double(n) * n);
    return total;
}

}  // namespace ivis::render
