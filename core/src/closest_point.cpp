#include <ivis/core/closest_point.h>

#include <glm/geometric.hpp>

#include <initializer_list>

namespace ivis::core {
namespace {
TrianglePoint atWeights(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                        const glm::dvec3& c, double u, double v, double w)
{
    TrianglePoint result;
    result.barycentric = {u, v, w};
    result.point = u * a + v * b + w * c;
    const glm::dvec3 d = p - result.point;
    result.distanceSquared = glm::dot(d, d);
    return result;
}
}  // namespace

TrianglePoint closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c)
{
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return atWeights(p, a, b, c, 1, 0, 0);

    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return atWeights(p, a, b, c, 0, 1, 0);

    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return atWeights(p, a, b, c, 1 - v, v, 0);
    }

    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return atWeights(p, a, b, c, 0, 0, 1);

    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        return atWeights(p, a, b, c, 1 - w, 0, w);
    }

    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return atWeights(p, a, b, c, 0, 1 - w, w);
    }

    const double denom = va + vb + vc;
    if (denom <= 0.0) {  // degenerate triangle not caught above: fall back to its vertices
        TrianglePoint best = atWeights(p, a, b, c, 1, 0, 0);
        for (const TrianglePoint& t : {atWeights(p, a, b, c, 0, 1, 0), atWeights(p, a, b, c, 0, 0, 1)})
            if (t.distanceSquared < best.distanceSquared) best = t;
        return best;
    }
    const double v = vb / denom, w = vc / denom;
    return atWeights(p, a, b, c, 1 - v - w, v, w);
}

}  // namespace ivis::core
