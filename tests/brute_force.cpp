#include "brute_force.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivis::test {

BruteForceClosest::BruteForceClosest(const core::TriangleMesh& mesh) : mMesh(mesh)
{
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        const glm::dvec3 centre = (a + b + c) / 3.0;
        mCentres.push_back(centre);
        mRadii.push_back(std::max({glm::length(a - centre), glm::length(b - centre), glm::length(c - centre)}));
    }
}

core::TrianglePoint BruteForceClosest::closest(const glm::dvec3& p, std::int32_t* triangle) const
{
    core::TrianglePoint best;
    best.distanceSquared = std::numeric_limits<double>::infinity();
    std::int32_t bestIndex = -1;
    for (std::size_t i = 0; i < mMesh.triangles.size(); ++i) {
        const double lower = glm::length(p - mCentres[i]) - mRadii[i];
        if (lower > 0.0 && lower * lower > best.distanceSquared) continue;
        const auto& t = mMesh.triangles[i];
        const core::TrianglePoint c = core::closestPointOnTriangle(
            p, mMesh.positions[t[0]], mMesh.positions[t[1]], mMesh.positions[t[2]]);
        if (c.distanceSquared < best.distanceSquared) {
            best = c;
            bestIndex = std::int32_t(i);
        }
    }
    if (triangle) *triangle = bestIndex;
    return best;
}

double BruteForceClosest::windingNumber(const glm::dvec3& p) const
{
    // Van Oosterom & Strackee solid angle of each triangle seen from p.
    double total = 0.0;
    for (const auto& t : mMesh.triangles) {
        const glm::dvec3 a = glm::dvec3(mMesh.positions[t[0]]) - p;
        const glm::dvec3 b = glm::dvec3(mMesh.positions[t[1]]) - p;
        const glm::dvec3 c = glm::dvec3(mMesh.positions[t[2]]) - p;
        const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
        const double numerator = glm::dot(a, glm::cross(b, c));
        const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
        total += 2.0 * std::atan2(numerator, denominator);
    }
    return total / (4.0 * M_PI);
}

glm::dvec3 BruteForceClosest::distanceGradient(const glm::dvec3& p) const
{
    const glm::dvec3 away = p - closest(p).point;
    return away / glm::length(away) * (windingNumber(p) > 0.5 ? -1.0 : 1.0);
}

}  // namespace ivis::test
