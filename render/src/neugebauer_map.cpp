#include <ivis/render/neugebauer_map.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::render {

namespace {

/// The projected ring centre and the silhouette radius around it, on the image plane.
struct Silhouette {
    glm::dvec2 centre{0.0};
    double radius = 0.0;
};

Silhouette silhouette(const core::CameraFrame& frame, const core::TriangleMesh& mesh, const glm::vec3& centre)
{
    Silhouette s;
    s.centre = frame.imagePlane(glm::dvec3(centre));
    for (const glm::vec3& p : mesh.positions)
        s.radius = std::max(s.radius, glm::length(frame.imagePlane(glm::dvec3(p)) - s.centre));
    return s;
}

}  // namespace

RingLayout layoutRings(const core::CameraFrame& frame, const core::TriangleMesh& mesh, const RingParams& params)
{
    const double halfHeight = 0.5 * frame.height();
    RingLayout layout;
    layout.centre = frame.project(glm::dvec3(params.centre));
    const double pixelsPerUnit = halfHeight / frame.imagePlaneHalfHeight();
    layout.innerRadius = silhouette(frame, mesh, params.centre).radius * pixelsPerUnit + params.silhouetteGap * halfHeight;
    layout.outerRadius = layout.innerRadius + params.ringWidth * halfHeight;
    layout.backRadius = params.backRadius * halfHeight;
    const double margin = 0.04 * halfHeight;
    layout.backCentre = {margin + layout.backRadius, margin + layout.backRadius};
    return layout;
}

PictureExtent ringExtent(const core::Camera& camera, const core::TriangleMesh& mesh, const RingParams& params)
{
    const Silhouette s = silhouette(core::CameraFrame(camera, 1, 1), mesh, params.centre);
    return {s.centre - s.radius, s.centre + s.radius, glm::dvec2(params.silhouetteGap + params.ringWidth)};
}

bool ringRayDirection(const RingLayout& layout, const core::CameraFrame& frame, const glm::dvec2& pixel,
                      glm::vec3& direction)
{
    const glm::dvec3 n = frame.forward();
    const glm::dvec2 back = pixel - layout.backCentre;
    const double backR = glm::length(back);
    if (backR <= layout.backRadius) {
        const double angle = 0.5 * M_PI * backR / layout.backRadius;
        // Seen from behind, the camera's right points to the screen's left.
        const glm::dvec3 u = backR > 0.0 ? glm::normalize(-back.x * frame.right() - back.y * frame.upVector())
                                         : glm::dvec3(0.0);
        direction = glm::vec3(std::cos(angle) * n + std::sin(angle) * u);
        return true;
    }
    const glm::dvec2 offset = pixel - layout.centre;
    const double r = glm::length(offset);
    if (r < layout.innerRadius || r > layout.outerRadius) return false;
    const glm::dvec3 u = glm::normalize(offset.x * frame.right() - offset.y * frame.upVector());
    const double k = 2.0 * r / (layout.innerRadius + layout.outerRadius) - 1.0;
    direction = glm::vec3(glm::normalize(u + k * n));
    return true;
}

}  // namespace ivis::render
