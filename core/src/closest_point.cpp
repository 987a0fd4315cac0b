#include <ivis/core/closest_point.h>

#include <glm/geometric.hpp>

#include <algorithm>
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

namespace {

// Four doubles of four triangles and the masks their comparisons give (GCC vector extensions:
// four AVX2 lanes, or two SSE2 pairs on CPUs without AVX2). Every lane computes what
// closestPointOnTriangle computes, in the same order; neither the x86-64 baseline nor the AVX2
// clone has fused multiply-adds to contract them into, so each lane's result has the scalar
// function's bits (the test of the two says so on any other build).
using Lanes = double __attribute__((vector_size(32)));
using LaneMask = long long __attribute__((vector_size(32)));
constexpr int kLanes = 4;

// An AVX2 clone beside the baseline one, chosen when the program loads (x86-64 with GCC's ifuncs).
#if defined(__x86_64__) && defined(__GNUC__)
#define IVIS_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define IVIS_AVX2_CLONE
#endif

struct LaneVec3 {
    Lanes x, y, z;
};

// The helpers below write their results through references: a 32-byte vector passed or returned by
// value between functions compiled without AVX changes the ABI (GCC warns, clang refuses). They are
// inlined into each clone of closestPointsOfFour. (GCC's warning ignored to the end of the file:
// it warns where it makes the clones.)
#pragma GCC diagnostic ignored "-Wpsabi"
/// out = a - b.
inline void minus(const LaneVec3& a, const LaneVec3& b, LaneVec3& out)
{
    out.x = a.x - b.x, out.y = a.y - b.y, out.z = a.z - b.z;
}
/// out = a . b, summed as glm::dot sums it.
inline void dot(const LaneVec3& a, const LaneVec3& b, Lanes& out) { out = a.x * b.x + a.y * b.y + a.z * b.z; }
/// out = u a + v b + w c, summed left to right as glm sums it.
inline void weighted(const Lanes& u, const Lanes& a, const Lanes& v, const Lanes& b, const Lanes& w, const Lanes& c,
                     Lanes& out)
{
    out = u * a + v * b + w * c;
}

/// Four triangles' closest points to p into out[0, count); the lanes past count repeat the last
/// triangle and are dropped. Lanes whose triangle is degenerate in a way the vertex and edge regions
/// do not catch are done by closestPointOnTriangle itself.
IVIS_AVX2_CLONE void closestPointsOfFour(const glm::dvec3& p, const glm::dvec3* corners, int count,
                                         TrianglePoint* out)
{
    LaneVec3 a, b, c;
    for (int k = 0; k < kLanes; ++k) {
        const glm::dvec3* t = corners + 3 * std::min(k, count - 1);
        a.x[k] = t[0].x, a.y[k] = t[0].y, a.z[k] = t[0].z;
        b.x[k] = t[1].x, b.y[k] = t[1].y, b.z[k] = t[1].z;
        c.x[k] = t[2].x, c.y[k] = t[2].y, c.z[k] = t[2].z;
    }
    const LaneVec3 q{Lanes{} + p.x, Lanes{} + p.y, Lanes{} + p.z};
    const Lanes zero{}, one = zero + 1.0;

    LaneVec3 ab, ac, ap, bp, cp;
    Lanes d1, d2, d3, d4, d5, d6;
    minus(b, a, ab), minus(c, a, ac), minus(q, a, ap);
    dot(ab, ap, d1), dot(ac, ap, d2);
    minus(q, b, bp);
    dot(ab, bp, d3), dot(ac, bp, d4);
    const Lanes vc = d1 * d4 - d3 * d2;
    minus(q, c, cp);
    dot(ab, cp, d5), dot(ac, cp, d6);
    const Lanes vb = d5 * d2 - d1 * d6;
    const Lanes va = d3 * d6 - d5 * d4;
    const Lanes denom = va + vb + vc;

    // The regions in closestPointOnTriangle's order: each lane takes the first that holds.
    const LaneMask inA = (d1 <= 0.0) & (d2 <= 0.0);
    const LaneMask inB = (d3 >= 0.0) & (d4 <= d3);
    const LaneMask onAB = (vc <= 0.0) & (d1 >= 0.0) & (d3 <= 0.0);
    const LaneMask inC = (d6 >= 0.0) & (d5 <= d6);
    const LaneMask onAC = (vb <= 0.0) & (d2 >= 0.0) & (d6 <= 0.0);
    const LaneMask onBC = (va <= 0.0) & ((d4 - d3) >= 0.0) & ((d5 - d6) >= 0.0);
    const LaneMask degenerate = denom <= 0.0;

    const Lanes vAB = d1 / (d1 - d3);
    const Lanes wAC = d2 / (d2 - d6);
    const Lanes wBC = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    const Lanes vFace = vb / denom, wFace = vc / denom;

    // From the last region to the first, so that the first that holds is the one left.
    Lanes u = one - vFace - wFace, v = vFace, w = wFace;
    u = onBC ? zero : u, v = onBC ? one - wBC : v, w = onBC ? wBC : w;
    u = onAC ? one - wAC : u, v = onAC ? zero : v, w = onAC ? wAC : w;
    u = inC ? zero : u, v = inC ? zero : v, w = inC ? one : w;
    u = onAB ? one - vAB : u, v = onAB ? vAB : v, w = onAB ? zero : w;
    u = inB ? zero : u, v = inB ? one : v, w = inB ? zero : w;
    u = inA ? one : u, v = inA ? zero : v, w = inA ? zero : w;
    const LaneMask byItself = degenerate & ~(inA | inB | onAB | inC | onAC | onBC);

    LaneVec3 point, d;
    weighted(u, a.x, v, b.x, w, c.x, point.x), weighted(u, a.y, v, b.y, w, c.y, point.y);
    weighted(u, a.z, v, b.z, w, c.z, point.z);
    minus(q, point, d);
    Lanes distanceSquared;
    dot(d, d, distanceSquared);
    for (int k = 0; k < count; ++k) {
        if (byItself[k]) {
            out[k] = closestPointOnTriangle(p, corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]);
            continue;
        }
        out[k].point = {point.x[k], point.y[k], point.z[k]};
        out[k].barycentric = {u[k], v[k], w[k]};
        out[k].distanceSquared = distanceSquared[k];
    }
}
}  // namespace

void closestPointsOnTriangles(const glm::dvec3& p, const glm::dvec3* corners, int count, TrianglePoint* out)
{
    for (int first = 0; first < count; first += kLanes)
        closestPointsOfFour(p, corners + 3 * first, std::min(kLanes, count - first), out + first);
}

}  // namespace ivis::core
