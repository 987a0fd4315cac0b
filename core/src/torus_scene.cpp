// The generated torus (scene:torus): an angular pattern with a hot spot.
#include <ivis/core/procedural_scenes.h>

#include "generated_field.h"

#include <ivis/core/errors.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

namespace ivis::core {
namespace {

constexpr double kTorusMajor = 0.7;
constexpr double kTorusMinor = 0.3;

glm::dvec3 torusPoint(double u, double v)
{
    const double ring = kTorusMajor + kTorusMinor * std::cos(v);
    return {ring * std::cos(u), kTorusMinor * std::sin(v), ring * std::sin(u)};
}

/// Centres the mesh and scales it uniformly so the longest bounding-box side spans [-1,1].
void fitToUnitBox(TriangleMesh& mesh)
{
    glm::vec3 lo = mesh.positions.front(), hi = lo;
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::dvec3 center = 0.5 * (glm::dvec3(lo) + glm::dvec3(hi));
    const glm::dvec3 extent = glm::dvec3(hi) - glm::dvec3(lo);
    const double scale = 2.0 / std::max({extent.x, extent.y, extent.z});
    for (glm::vec3& p : mesh.positions) p = glm::vec3((glm::dvec3(p) - center) * scale);
}

}  // namespace

SurfaceField makeTorus(int majorSegments, int minorSegments)
{
    if (majorSegments < 3 || minorSegments < 3)
        throw ValueError("makeTorus: need at least 3 segments each way, got " +
                         std::to_string(majorSegments) + " x " + std::to_string(minorSegments));
    TriangleMesh mesh;
    const auto index = [&](int i, int j) {
        return std::uint32_t((i % majorSegments) * minorSegments + j % minorSegments);
    };
    for (int i = 0; i < majorSegments; ++i)
        for (int j = 0; j < minorSegments; ++j)
            mesh.positions.emplace_back(
                torusPoint(2.0 * generated::kPi * i / majorSegments, 2.0 * generated::kPi * j / minorSegments));
    for (int i = 0; i < majorSegments; ++i)
        for (int j = 0; j < minorSegments; ++j) {
            mesh.triangles.push_back({index(i, j), index(i, j + 1), index(i + 1, j + 1)});
            mesh.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i + 1, j)});
        }
    fitToUnitBox(mesh);
    const glm::dvec3 hot = torusPoint(-1.2, 0.8) / (kTorusMajor + kTorusMinor);
    return generated::makeField(std::move(mesh), "torus", "pattern", [&](const glm::dvec3& p) {
        return 0.4 + 0.3 * std::sin(3.0 * std::atan2(p.z, p.x)) + 0.6 * generated::gaussian(p, hot, 0.25);
    });
}

}  // namespace ivis::core
