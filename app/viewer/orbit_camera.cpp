#include "orbit_camera.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::app {

OrbitCamera OrbitCamera::fromCamera(const core::Camera& camera, bool keepExact)
{
    OrbitCamera orbit;
    const glm::dvec2 angles = camera.angles();
    orbit.thetaDeg = angles.x;
    orbit.phiDeg = angles.y;
    orbit.distance = glm::length(camera.eye - camera.target);
    orbit.target = camera.target;
    orbit.fovYDeg = camera.fovYDeg;
    orbit.orthographic = camera.orthographic;
    orbit.orthoHalfHeight = camera.orthoHalfHeight;
    orbit.windowCentre = camera.windowCentre;
    if (keepExact) orbit.fixed = camera;
    return orbit;
}

core::Camera OrbitCamera::camera() const
{
    if (fixed) return *fixed;
    core::Camera camera = core::Camera::fromAngles(thetaDeg, phiDeg, distance, fovYDeg);
    camera.eye += target;
    camera.target = target;
    camera.orthographic = orthographic;
    camera.orthoHalfHeight = orthoHalfHeight;
    camera.windowCentre = windowCentre;
    return camera;
}

void OrbitCamera::orbit(double dx, double dy)
{
    fixed.reset();
    phiDeg = std::fmod(phiDeg - 0.4 * dx, 360.0);
    thetaDeg = std::clamp(thetaDeg - 0.4 * dy, 0.5, 179.5);
}

void OrbitCamera::zoom(double steps)
{
    fixed.reset();
    framed = false;
    const double factor = std::pow(0.9, steps);
    distance = std::clamp(distance * factor, 0.3, 20.0);
    orthoHalfHeight = std::clamp(orthoHalfHeight * factor, 0.05, 20.0);
}

void OrbitCamera::pan(double dx, double dy, int viewportHeight)
{
    const core::Camera current = camera();
    fixed.reset();
    framed = false;
    const core::CameraFrame frame(current, std::max(1, viewportHeight), std::max(1, viewportHeight));
    const double halfHeight =
        orthographic ? orthoHalfHeight : distance * std::tan(0.5 * fovYDeg * M_PI / 180.0);
    const double worldPerPixel = 2.0 * halfHeight / std::max(1, viewportHeight);
    target += worldPerPixel * (-dx * frame.right() + dy * frame.upVector());
}

void OrbitCamera::frameAgain()
{
    fixed.reset();
    distance = core::kCameraDistance;
    target = glm::dvec3(0.0);
    framed = true;
}

CameraAnimation::CameraAnimation(const OrbitCamera& from, std::vector<double> parametersFrom, const OrbitCamera& to,
                                 std::vector<double> parametersTo, double startTime, double seconds)
    : mFrom(from),
      mTo(to),
      mParametersFrom(std::move(parametersFrom)),
      mParametersTo(std::move(parametersTo)),
      mStart(startTime),
      mSeconds(seconds),
      mActive(true)
{
    mFrom.fixed.reset();
    mTo.fixed.reset();
    // Azimuth the shorter way round.
    const double delta = std::fmod(mTo.phiDeg - mFrom.phiDeg + 540.0, 360.0) - 180.0;
    mTo.phiDeg = mFrom.phiDeg + delta;
}

void CameraAnimation::at(double now, OrbitCamera& camera, std::vector<double>& parameters) const
{
    const double s = std::clamp((now - mStart) / mSeconds, 0.0, 1.0), w = s * s * (3.0 - 2.0 * s);
    camera = mFrom;
    camera.thetaDeg = mFrom.thetaDeg + w * (mTo.thetaDeg - mFrom.thetaDeg);
    camera.phiDeg = mFrom.phiDeg + w * (mTo.phiDeg - mFrom.phiDeg);
    camera.distance = mFrom.distance + w * (mTo.distance - mFrom.distance);
    camera.target = mFrom.target + w * (mTo.target - mFrom.target);
    camera.orthoHalfHeight = mFrom.orthoHalfHeight + w * (mTo.orthoHalfHeight - mFrom.orthoHalfHeight);
    camera.windowCentre = mFrom.windowCentre + w * (mTo.windowCentre - mFrom.windowCentre);
    parameters = mParametersFrom;
    for (std::size_t i = 0; i < parameters.size() && i < mParametersTo.size(); ++i)
        parameters[i] += w * (mParametersTo[i] - mParametersFrom[i]);
}

}  // namespace ivis::app
