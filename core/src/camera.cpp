#include <ivis/core/camera.h>

#include <ivis/core/errors.h>
#include <ivis/core/number_text.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::core {
namespace {
constexpr double kDegToRad = M_PI / 180.0;
}

Camera Camera::fromAngles(double thetaDeg, double phiDeg, double radius, double fovYDeg)
{
    const double theta = thetaDeg * kDegToRad, phi = phiDeg * kDegToRad;
    Camera camera;
    camera.eye = radius * glm::dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
    camera.fovYDeg = fovYDeg;
    // At the poles the view is parallel to +y: use the azimuth direction as "up" instead.
    if (std::abs(std::sin(theta)) < 1e-6)
        camera.up = glm::dvec3(-std::sin(phi), 0.0, -std::cos(phi)) * (std::cos(theta) > 0 ? 1.0 : -1.0);
    return camera;
}

glm::dvec2 Camera::angles() const
{
    const glm::dvec3 d = eye - target;
    const double r = glm::length(d);
    return {std::acos(std::clamp(d.y / r, -1.0, 1.0)) / kDegToRad, std::atan2(d.x, d.z) / kDegToRad};
}

void Camera::validate() const
{
    const glm::dvec3 view = target - eye;
    if (!(glm::length(view) > 1e-9) || !std::isfinite(glm::length(view)))
        throw ValueError("camera eye and target must differ and be finite");
    if (!(glm::length(glm::cross(view, up)) > 1e-9 * glm::length(view) * glm::length(up)))
        throw ValueError("camera up vector is parallel to the view direction");
    if (!orthographic && !(fovYDeg > 0.0 && fovYDeg < 180.0))
        throw ValueError("field of view " + shortNumber(fovYDeg) + " is out of range (0 to 180 degrees)");
    if (orthographic && !(orthoHalfHeight > 0.0 && std::isfinite(orthoHalfHeight)))
        throw ValueError("orthographic half height must be positive");
    if (!(std::isfinite(windowCentre.x) && std::isfinite(windowCentre.y)))
        throw ValueError("camera window centre must be finite");
    const auto within = [](double value) { return std::abs(value) <= kMaxCameraCoordinate; };
    const std::string limit = " is out of range (at most " + shortNumber(kMaxCameraCoordinate) + ")";
    const std::string fromCentre = " normalised units from the object's centre" + limit;
    if (!within(glm::length(eye))) throw ValueError("camera eye at " + shortNumber(glm::length(eye)) + fromCentre);
    if (!within(glm::length(target)))
        throw ValueError("camera target at " + shortNumber(glm::length(target)) + fromCentre);
    if (orthographic && !within(orthoHalfHeight))
        throw ValueError("orthographic half height " + shortNumber(orthoHalfHeight) + limit);
    if (!within(windowCentre.x) || !within(windowCentre.y))
        throw ValueError("camera window centre " +
                         shortNumber(std::max(std::abs(windowCentre.x), std::abs(windowCentre.y))) + limit);
}

CameraFrame::CameraFrame(const Camera& camera, int width, int height) : mCamera(camera), mWidth(width), mHeight(height)
{
    camera.validate();
    if (width < 1 || height < 1 || width > 32768 || height > 32768)
        throw ValueError("image size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range");
    mForward = glm::normalize(camera.target - camera.eye);
    mRight = glm::normalize(glm::cross(mForward, camera.up));
    mUp = glm::cross(mRight, mForward);
    mHalfHeight = camera.orthographic ? camera.orthoHalfHeight : std::tan(0.5 * camera.fovYDeg * kDegToRad);
    mAspect = double(width) / double(height);
}

CameraRay CameraFrame::ray(double x, double y) const
{
    return rayThrough(mCamera.windowCentre +
                      glm::dvec2((2.0 * x / mWidth - 1.0) * mHalfHeight * mAspect, (1.0 - 2.0 * y / mHeight) * mHalfHeight));
}

CameraRay CameraFrame::rayThrough(const glm::dvec2& point) const
{
    if (mCamera.orthographic) return {mCamera.eye + point.x * mRight + point.y * mUp, mForward};
    return {mCamera.eye, glm::normalize(mForward + point.x * mRight + point.y * mUp)};
}

glm::dvec2 CameraFrame::imagePlane(const glm::dvec3& world) const
{
    const glm::dvec3 d = world - mCamera.eye;
    const glm::dvec2 point(glm::dot(d, mRight), glm::dot(d, mUp));
    return mCamera.orthographic ? point : point / glm::dot(d, mForward);
}

glm::dvec2 CameraFrame::project(const glm::dvec3& world) const
{
    const glm::dvec2 s = imagePlane(world) - mCamera.windowCentre;
    return {(s.x / (mHalfHeight * mAspect) + 1.0) * 0.5 * mWidth, (1.0 - s.y / mHalfHeight) * 0.5 * mHeight};
}

}  // namespace ivis::core
