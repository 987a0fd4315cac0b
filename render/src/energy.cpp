#include <ivis/render/energy.h>

#include <ivis/core/errors.h>
#include <ivis/render/curved_ray.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <cmath>
#include <mutex>

namespace ivis::render {
namespace {

/// Per-thread sums of an energy evaluation.
struct Tally {
    double direct = 0.0, indirect = 0.0;
    std::size_t pixelsDirect = 0, pixelsIndirect = 0;
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
    const int n = mOptions.resolution;
    const core::CameraFrame frame(camera, n, n);
    const ScreenMap screen(mScene, frame, params);
    std::vector<Tally> rows(static_cast<std::size_t>(n));
    tbb::parallel_for(0, n, [&](int y) {
        DistanceField::Sampler sampler = mScene.distance().sampler();
        Tally& tally = rows[std::size_t(y)];
        for (int x = 0; x < n; ++x) {
            const PixelMapping m = screen.map(x + 0.5, y + 0.5, sampler);
            if (m.region == Region::Background) continue;
            const bool direct = m.region == Region::Direct;
            (direct ? tally.pixelsDirect : tally.pixelsIndirect)++;
            if (mVisibility) {
                const std::uint64_t key = mVisibility->keyOf(m.point.position);
                tally.allKeys.push_back(key);
                if (direct) tally.directKeys.push_back(key);
            } else {
                (direct ? tally.direct : tally.indirect) += importance(m.point);
            }
        }
    });
    EnergyValue value;
    Tally total;
    for (Tally& row : rows) {  // in row order: the result does not depend on the thread count
        total.direct += row.direct;
        total.indirect += row.indirect;
        value.pixelsDirect += row.pixelsDirect;
        value.pixelsIndirect += row.pixelsIndirect;
        total.allKeys.insert(total.allKeys.end(), row.allKeys.begin(), row.allKeys.end());
        total.directKeys.insert(total.directKeys.end(), row.directKeys.begin(), row.directKeys.end());
    }
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
    glm::vec3 seed, velocityPerAlpha;
    if (!screen.curvedRayStart(x, y, sampler, seed, velocityPerAlpha)) return result;
    const CurvedRayTangent ray = integrateCurvedRayTangent(
        sampler, seed, params.curved.alpha * velocityPerAlpha, velocityPerAlpha, params.curved,
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
    result.dImportance = double(glm::dot(surfaceGradient(mesh, landed.point.triangle, s), result.dPoint));
    return result;
}

double EnergyEvaluator::alphaDerivative(const core::Camera& camera, const MethodParams& params) const
{
    if (mOptions.kind != EnergyKind::Scalar)
        throw ValueError("the visibility energy has no analytic derivative; use forward differences");
    const int n = mOptions.resolution;
    const core::CameraFrame frame(camera, n, n);
    const ScreenMap screen(mScene, frame, params);
    std::vector<double> rows(std::size_t(n), 0.0);
    tbb::parallel_for(0, n, [&](int y) {
        DistanceField::Sampler sampler = mScene.distance().sampler();
        for (int x = 0; x < n; ++x) rows[std::size_t(y)] += pixelAlphaDerivative(screen, x + 0.5, y + 0.5, sampler).dImportance;
    });
    double total = 0.0;
    for (double row : rows) total += row;  // in row order: independent of the thread count
    return total * 4.0 / (double(n) * n);
}

}  // namespace ivis::render
