/// @file camera.h
/// @brief Pinhole (or orthographic) camera looking at a target; angles on a sphere; JSON files.
/// @note Angle convention: y is up; polar angle theta from +y, azimuth phi around y from +z toward +x.
///       theta = 90, phi = 0 puts the eye at (0, 0, radius) looking down -z.
#pragma once

#include <ivis/core/similarity.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace ivis::core {

/// @brief Default distance of the eye from the target (the paper's camera sphere).
inline constexpr double kCameraDistance = 2.5;
/// @brief Vertical field of view of a camera whose picture is not framed (render/framing.h fits it
///        per view): fits the hull (phi0 = 0.4) of a unit sphere seen from 2.5, whose half-angle is
///        asin(1.4 / 2.5) = 34 degrees, with a margin.
inline constexpr double kDefaultFovYDeg = 75.0;

/// @brief How far from the origin (the normalised object's centre, the object within about 1 of
///        it) a camera's eye and target may lie, and how large its orthographic half height and
///        window centre may be: beyond, a ray's origin or direction leaves what single-precision
///        ray tracing represents.
inline constexpr double kMaxCameraCoordinate = 1e6;

/// @brief A camera: where it is, what it looks at, and how it projects.
struct Camera {
    glm::dvec3 eye{0.0, 0.0, kCameraDistance};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDeg = kDefaultFovYDeg;  ///< vertical field of view (perspective)
    bool orthographic = false;
    double orthoHalfHeight = 1.6;      ///< half the view height in world units (orthographic)
    /// The image's centre on the image plane (CameraFrame::imagePlane units), as VTK's window
    /// centre: framing shifts it to centre a picture that lies to one side of the view axis, which
    /// stays on the target.
    glm::dvec2 windowCentre{0.0};

    /// @brief Eye on the sphere of @a radius around the origin at polar @a thetaDeg, azimuth @a phiDeg.
    static Camera fromAngles(double thetaDeg, double phiDeg, double radius = kCameraDistance,
                             double fovYDeg = kDefaultFovYDeg);
    /// @brief Polar and azimuth angles (degrees) of the eye around the target.
    glm::dvec2 angles() const;
    /// @brief Throws ValueError unless eye != target, up is not parallel to the view, 0 < fov < 180,
    ///        and the eye, the target, the orthographic half height and the window centre lie
    ///        within kMaxCameraCoordinate.
    void validate() const;
};

/// @brief A ray from the camera: origin and unit direction, world space.
struct CameraRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};
};

/// @brief A camera bound to an image size: generates rays for continuous pixel coordinates and
///        projects world points back to pixels. Pixel (0,0) is the top-left corner of the image.
class CameraFrame {
public:
    /// @brief Precomputes the basis; throws ValueError for a bad camera or size.
    CameraFrame(const Camera& camera, int width, int height);
    /// @brief Ray through continuous pixel position (x, y) (pixel centres at +0.5).
    CameraRay ray(double x, double y) const;
    /// @brief Continuous pixel position of a world point (may lie outside the image).
    glm::dvec2 project(const glm::dvec3& world) const;
    /// @brief Where a world point lies on the image plane, along right() and upVector() from the
    ///        view axis: at unit distance from the eye (perspective: the tangents of its angles) or
    ///        in world units (orthographic). Independent of the field of view and the image size.
    glm::dvec2 imagePlane(const glm::dvec3& world) const;
    /// @brief The camera ray through image-plane point @a point (as imagePlane() measures it;
    ///        the image centre is at Camera::windowCentre).
    CameraRay rayThrough(const glm::dvec2& point) const;
    /// @brief Half the image height on the image plane: tan(fov / 2) or orthoHalfHeight.
    double imagePlaneHalfHeight() const { return mHalfHeight; }
    /// @brief Unit view direction (eye toward target).
    const glm::dvec3& forward() const { return mForward; }
    /// @brief Unit right vector of the image plane.
    const glm::dvec3& right() const { return mRight; }
    /// @brief Unit up vector of the image plane.
    const glm::dvec3& upVector() const { return mUp; }
    /// @brief The camera it was built from.
    const Camera& camera() const { return mCamera; }
    /// @brief The picture's width in pixels.
    int width() const { return mWidth; }
    /// @brief The picture's height in pixels.
    int height() const { return mHeight; }

private:
    Camera mCamera;
    int mWidth, mHeight;
    glm::dvec3 mForward, mRight, mUp;
    double mHalfHeight;  ///< tan(fov/2) (perspective) or orthoHalfHeight (orthographic)
    double mAspect;
};

/// @brief Reads a camera JSON file {"eye":[x,y,z],"target":[...],"up":[...],"fov_y_deg":f,
///        "orthographic":b,"ortho_half_height":f,"window_centre":[x,y]}; "eye" is required, missing
///        other keys keep their defaults.
/// @throw InputError naming the file for unreadable JSON or bad values
Camera readCameraJson(const std::string& path);

namespace detail {
/// @brief readCameraJson on @a text, the bytes of the file @a path (what the fuzz target feeds).
Camera parseCameraJson(const std::string& path, const std::string& text);
}  // namespace detail

/// @brief Writes a camera as JSON (with its angles for reference, and the mesh's normalising
///        transform @a meshUnits as "mesh_units": the camera is in normalised units), atomically.
/// @throw InputError naming the file when it cannot be written
void writeCameraJson(const Camera& camera, const std::string& path, const Similarity& meshUnits = {});

}  // namespace ivis::core
