/// @file orbit_camera.h
/// @brief The viewer's camera: an eye on a sphere around a target (the CLI's --theta/--phi
///        convention), turned, zoomed and panned with the mouse, and eased toward a new view; its
///        field of view and window centre framed for the picture (the viewer fits them each frame)
///        until a zoom or pan.
#pragma once

#include <ivis/core/camera.h>

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace ivis::app {

/// @brief Orbit state; camera() turns it into a core::Camera.
struct OrbitCamera {
    double thetaDeg = 90.0;  ///< polar angle from +y
    double phiDeg = 0.0;     ///< azimuth around y from +z toward +x
    double distance = core::kCameraDistance;
    glm::dvec3 target{0.0};
    double fovYDeg = core::kDefaultFovYDeg;
    bool orthographic = false;
    double orthoHalfHeight = 1.6;
    glm::dvec2 windowCentre{0.0};  ///< the image's centre on the image plane (core::Camera::windowCentre)
    /// A camera read from a file, shown exactly (its own up vector) until the user moves.
    std::optional<core::Camera> fixed;
    /// The field of view (orthographic: the half height) and the window centre are fitted to
    /// each frame's picture.
    bool framed = false;

    /// @brief Orbit state of @a camera (kept exactly as @a fixed when @a keepExact).
    static OrbitCamera fromCamera(const core::Camera& camera, bool keepExact);
    /// @brief The camera: Camera::fromAngles around the target (or the fixed one).
    core::Camera camera() const;
    /// @brief Turns by a mouse drag of (dx, dy) pixels (0.4 degree per pixel); theta stays in (0, 180).
    void orbit(double dx, double dy);
    /// @brief Zooms by @a steps wheel clicks (10% each); distance in [0.3, 20]. Ends the framing.
    void zoom(double steps);
    /// @brief Moves the target in the image plane by a drag of (dx, dy) pixels of a viewport
    ///        @a viewportHeight pixels high, so the point under the cursor follows it. Ends the framing.
    void pan(double dx, double dy, int viewportHeight);
    /// @brief Back on the radius-2.5 sphere around the origin (same angles), framed.
    void frameAgain();
};

/// @brief Eases from one orbit state (and a method's optimised parameters) to another in
///        @a seconds (smoothstep), the azimuth along the shorter way round.
class CameraAnimation {
public:
    CameraAnimation() = default;
    /// @param parametersFrom, parametersTo the method's optimised parameters (same length, or empty)
    CameraAnimation(const OrbitCamera& from, std::vector<double> parametersFrom, const OrbitCamera& to,
                    std::vector<double> parametersTo, double startTime, double seconds = 1.0);
    /// @brief True between start and end.
    bool active(double now) const { return mActive && now < mStart + mSeconds + 1e-9; }
    /// @brief True from the start until stop().
    bool started() const { return mActive; }
    /// @brief State at time @a now (the end state after the end).
    void at(double now, OrbitCamera& camera, std::vector<double>& parameters) const;
    /// @brief Stops the animation (e.g. when the user grabs the camera).
    void stop() { mActive = false; }

private:
    OrbitCamera mFrom, mTo;
    std::vector<double> mParametersFrom, mParametersTo;
    double mStart = 0.0, mSeconds = 1.0;
    bool mActive = false;
};

}  // namespace ivis::app
