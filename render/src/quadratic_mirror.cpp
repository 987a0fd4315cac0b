#include <ivis/render/quadratic_mirror.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace ivis::render {
namespace {

glm::dvec3 toEye(const core::CameraFrame& frame, const glm::dvec3& v)
{
    return {glm::dot(v, frame.right()), glm::dot(v, frame.upVector()), -glm::dot(v, frame.forward())};
}

glm::dvec3 toWorld(const core::CameraFrame& frame, const glm::dvec3& v)
{
    return v.x * frame.right() + v.y * frame.upVector() - v.z * frame.forward();
}

/// Smallest positive root of a t^2 + b t + c = 0 (linear when a vanishes); false if none.
bool smallestPositiveRoot(double a, double b, double c, double& t)
{
    if (std::abs(a) < 1e-12) {
        if (std::abs(b) < 1e-15) return false;
        t = -c / b;
        return t > 0.0;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return false;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    t = t0 > 0.0 ? t0 : t1;
    return t > 0.0;
}

}  // namespace

bool intersectMirror(const core::CameraFrame& frame, const core::CameraRay& ray, const MirrorParams& params,
                     MirrorHit& hit)
{
    const auto& w = params.w;
    const core::Camera& camera = frame.camera();
    const double zm = -glm::length(camera.target - camera.eye) - params.distanceBehind;
    const glm::dvec3 o = toEye(frame, ray.origin - camera.eye), r = toEye(frame, ray.direction);
    const double a = -(w[0] * r.x * r.x + w[1] * r.y * r.y + w[2] * r.x * r.y);
    const double b = r.z - (2.0 * w[0] * o.x * r.x + 2.0 * w[1] * o.y * r.y + w[2] * (o.x * r.y + o.y * r.x) +
                            w[3] * r.x + w[4] * r.y);
    const double c = o.z - zm - (w[0] * o.x * o.x + w[1] * o.y * o.y + w[2] * o.x * o.y + w[3] * o.x + w[4] * o.y);
    double t;
    if (!smallestPositiveRoot(a, b, c, t)) return false;
    const glm::dvec3 m = o + t * r;
    const glm::dvec3 normal = glm::normalize(glm::dvec3(-2.0 * w[0] * m.x - w[2] * m.y - w[3],
                                                        -2.0 * w[1] * m.y - w[2] * m.x - w[4], 1.0));
    hit.point = glm::vec3(camera.eye + toWorld(frame, m));
    hit.normal = glm::vec3(toWorld(frame, normal));
    return true;
}

}  // namespace ivis::render
