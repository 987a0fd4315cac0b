#include <ivis/optimize/curved_ray_gradient.h>

#include <ivis/core/errors.h>
#include <ivis/optimize/curved_ray_tangent.h>
#include <ivis/optimize/hessian.h>
#include <ivis/render/method_registry.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>

namespace ivis::optimize {
namespace {

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

/// The closest surface point of @a p (the landing rule of render::landedAt), which lies within
/// @a bound of it.
glm::vec3 closestSurfacePoint(const render::RenderScene& scene, const glm::vec3& p, double bound)
{
    int triangle = -1;
    return glm::vec3(scene.bvh().closestPoint(glm::dvec3(p), bound, triangle).point);
}

/// The derivative of the closest surface point as the ray's end @a p, @a distance off the surface,
/// moves by @a dp: a central difference over a hundredth of a voxel. (Projecting dp onto the tangent
/// plane would ignore that a point off a curved surface moves its closest point by
/// 1 / (1 + phi kappa) less.)
glm::vec3 closestPointDerivative(const render::RenderScene& scene, const glm::vec3& p, float distance,
                                 const glm::vec3& dp)
{
    const float length = glm::length(dp);
    if (!(length > 0.0f)) return glm::vec3(0.0f);
    const float offset = 0.01f * scene.distance().voxelSize();
    const float step = offset / length;
    // The moved points are within offset of p, so their closest points within distance + offset.
    const double bound = double(distance) + 2.0 * double(offset);
    return (closestSurfacePoint(scene, p + step * dp, bound) - closestSurfacePoint(scene, p - step * dp, bound)) /
           (2.0f * step);
}

}  // namespace

PixelLaunchDerivative pixelLaunchDerivative(const EnergyEvaluator& evaluator, const render::ScreenMap& screen,
                                            double x, double y, render::DistanceField::Sampler& sampler)
{
    PixelLaunchDerivative result;
    const render::CurvedRayMap& rays = *screen.curvedRays();
    const render::CurvedRayMethod& method = rays.method();
    render::CurvedRayStart start;
    if (!rays.start(x, y, sampler, start)) return result;
    // The tangent follows the launch that lands.
    const render::CurvedRayTrace trace = rays.trace(start, sampler);
    render::LaunchSensitivity sensitivity;
    if (!trace.end.landed || !method.launchSensitivity(start, trace.launch, sensitivity)) return result;
    const render::RenderScene& scene = evaluator.scene();
    HessianSampler hessian(sampler);
    const CurvedRayTangent ray = integrateCurvedRayTangent(
        hessian, start.seed, method.launchVelocity(start, trace.launch), sensitivity.direction, method.rayParams(),
        rays.epsilon(), render::escapeDistance(scene.distance()));
    if (!ray.end.landed) return result;
    const render::PixelMapping landed = rays.landedAt(ray.end, sampler);
    const core::TriangleMesh& mesh = scene.mesh();
    if (landed.region != render::Region::Indirect || mesh.isCap(std::size_t(landed.point.triangle))) return result;
    result.landed = true;
    result.point = landed.point;
    result.dPoint = closestPointDerivative(scene, ray.end.position,
                                           glm::length(landed.point.position - ray.end.position), ray.dPosition);
    result.perParameter = sensitivity.perParameter;
    // A cell scalar is constant on the triangle: its corners agree and the gradient is zero.
    const std::array<float, 3> corners = core::cornerScalars(scene.field(), std::size_t(landed.point.triangle));
    float s[3];
    for (int c = 0; c < 3; ++c) {
        s[c] = std::isnan(corners[c]) ? 0.0f : evaluator.options().importanceRange.normalized(corners[c]);
    }
    result.dImportance = double(glm::dot(surfaceGradient(mesh, landed.point.triangle, s), result.dPoint));
    return result;
}

std::vector<double> curvedRayGradient(const EnergyEvaluator& evaluator, const core::Camera& camera,
                                      const render::MethodPtr& method)
{
    if (evaluator.options().kind != EnergyKind::Scalar)
        throw ValueError("the visibility energy has no analytic derivative; use forward differences");
    if (!method->info().tangentLinearGradient)
        throw ValueError("the analytic gradient needs curved rays, not the method " + method->name());
    const std::size_t count = render::optimisedParameters(*method).size();
    const int n = evaluator.options().resolution;
    const core::CameraFrame frame(camera, n, n);
    const render::ScreenMap screen(evaluator.scene(), frame, method);
    std::vector<std::vector<double>> rows(std::size_t(n), std::vector<double>(count, 0.0));
    tbb::parallel_for(0, n, [&](int y) {
        render::DistanceField::Sampler sampler = evaluator.scene().distance().sampler();
        for (int x = 0; x < n; ++x) {
            const PixelLaunchDerivative d = pixelLaunchDerivative(evaluator, screen, x + 0.5, y + 0.5, sampler);
            if (!d.landed) continue;
            for (std::size_t k = 0; k < count; ++k) rows[std::size_t(y)][k] += d.perParameter[k] * d.dImportance;
        }
    });
    std::vector<double> total(count, 0.0);
    for (const auto& row : rows)  // in row order: independent of the thread count
        for (std::size_t k = 0; k < count; ++k) total[k] += row[k];
    for (double& t : total) t *= 4.0 / (double(n) * n);
    return total;
}

}  // namespace ivis::optimize
