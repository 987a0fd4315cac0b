// The generated vessel tree (scene:vessel-tree, the embedded default scene): blended tubes with
// an aneurysm, open at every inlet and outlet, with a synthetic wall shear stress.
#include <ivis/core/procedural_scenes.h>

#include "generated_field.h"

#include <ivis/core/edge_key.h>
#include <ivis/core/errors.h>
#include <ivis/core/marching_tetrahedra.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ivis::core {
namespace {

using generated::gaussian;

// ---- vessel tree ----------------------------------------------------------------------------
// Tubes follow Catmull-Rom centre lines through design points (in flow direction), radius linear
// along each; they are unions of tapered capsules, blended by a smooth minimum at the junctions.
// Designed directly in normalised units: y up, the default camera looks from +z.

struct Branch {
    std::vector<glm::dvec3> points;  ///< the centre line passes through these
    double radiusStart, radiusEnd;
    bool openAtStart, openAtEnd;
};

constexpr double kBlend = 0.08;      ///< smooth-minimum width at junctions
constexpr double kExtension = 0.08;  ///< tube length kept beyond each end plane before cutting
constexpr int kSegmentsPerSpan = 6;  ///< capsules per span between two design points

struct Ball {
    glm::dvec3 center;
    double radius;
};

const glm::dvec3 kBifurcation{0.0, -0.2, 0.0};
const glm::dvec3 kSplit{0.45, -0.05, 0.0};
const Ball kDome{{0.02, 0.2, -0.14}, 0.27};  ///< the aneurysm sac, tilted to the back
const Ball kBleb{kDome.center + 0.29 * glm::normalize(glm::dvec3(-0.55, 0.7, 0.2)), 0.09};
constexpr double kNeckRadius = 0.12;

/// Parent (inlet at the bottom), left branch, right trunk, its upper and lateral branches.
const std::array<Branch, 5>& branches()
{
    using P = glm::dvec3;
    static const std::array<Branch, 5> kBranches{{
        {{P(0.06, -0.94, 0.06), P(0.12, -0.6, 0.1), kBifurcation}, 0.18, 0.16, true, false},
        {{kBifurcation, P(-0.4, -0.08, 0.12), P(-0.66, 0.3, 0.12), P(-0.8, 0.86, 0.0)}, 0.145,
         0.125, false, true},
        {{kBifurcation, P(0.22, -0.2, 0.04), kSplit}, 0.15, 0.14, false, false},
        {{kSplit, P(0.6, 0.3, -0.1), P(0.68, 0.88, -0.15)}, 0.13, 0.12, false, true},
        {{kSplit, P(0.72, -0.1, 0.1), P(0.86, -0.3, 0.16)}, 0.125, 0.12, false, true},
    }};
    return kBranches;
}

/// Point at @a t in [0,1] on the Catmull-Rom curve through @a q (end tangents along the chords).
glm::dvec3 centerLine(const std::vector<glm::dvec3>& q, double t)
{
    const int spans = int(q.size()) - 1;
    const int i = std::min(int(t * spans), spans - 1);
    const double u = t * spans - i, v = 1.0 - u;
    const auto tangent = [&](int k) {
        const double weight = (k == 0 || k == spans) ? 1.0 : 0.5;
        return weight * (q[std::min(k + 1, spans)] - q[std::max(k - 1, 0)]);
    };
    const glm::dvec3 b1 = q[i] + tangent(i) / 3.0, b2 = q[i + 1] - tangent(i + 1) / 3.0;
    return v * v * v * q[i] + 3.0 * v * v * u * b1 + 3.0 * v * u * u * b2 + u * u * u * q[i + 1];
}

double smoothMin(double a, double b)
{
    const double h = std::max(kBlend - std::abs(a - b), 0.0) / kBlend;
    return std::min(a, b) - 0.25 * kBlend * h * h;
}

/// A capsule whose radius varies linearly from @a ra at @a a to @a rb at @a b.
struct TaperedSegment {
    glm::dvec3 a, b;
    double ra, rb;

    double distance(const glm::dvec3& p) const
    {
        const glm::dvec3 ab = b - a;
        const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
        return glm::length(p - (a + t * ab)) - (ra + t * (rb - ra));
    }
};

/// Open ends of one branch; the cut planes are perpendicular to the end chords.
std::vector<detail::VesselEnd> branchEnds(const Branch& branch)
{
    const auto& q = branch.points;
    std::vector<detail::VesselEnd> ends;
    if (branch.openAtStart)
        ends.push_back({q.front(), glm::normalize(q[0] - q[1]), branch.radiusStart});
    if (branch.openAtEnd)
        ends.push_back({q.back(), glm::normalize(q.back() - q[q.size() - 2]), branch.radiusEnd});
    return ends;
}

/// Segments of one branch, with a straight extension beyond each open end.
std::vector<TaperedSegment> branchSegments(const Branch& branch)
{
    const auto& q = branch.points;
    const int count = kSegmentsPerSpan * int(q.size() - 1);
    const auto radius = [&](double t) {
        return branch.radiusStart + t * (branch.radiusEnd - branch.radiusStart);
    };
    std::vector<TaperedSegment> segments;
    for (int i = 0; i < count; ++i) {
        const double t0 = double(i) / count, t1 = double(i + 1) / count;
        segments.push_back({centerLine(q, t0), centerLine(q, t1), radius(t0), radius(t1)});
    }
    for (const detail::VesselEnd& end : branchEnds(branch))
        segments.push_back(
            {end.center, end.center + kExtension * end.normal, end.radius, end.radius});
    return segments;
}

/// Signed distance-like function of the tree, tubes extended past the end planes; < 0 inside.
class VesselImplicit {
public:
    VesselImplicit()
    {
        for (const Branch& b : branches()) mBranches.push_back(branchSegments(b));
        mBranches.push_back({{kBifurcation, kDome.center, kNeckRadius, kNeckRadius}});
    }

    double operator()(const glm::dvec3& p) const
    {
        double value = smoothMin(glm::length(p - kDome.center) - kDome.radius,
                                 glm::length(p - kBleb.center) - kBleb.radius);
        for (const auto& segments : mBranches) {
            double tube = segments.front().distance(p);
            for (const TaperedSegment& s : segments) tube = std::min(tube, s.distance(p));
            value = smoothMin(value, tube);
        }
        return value;
    }

    /// Box enclosing the zero set with a margin of @a margin.
    Bounds3 bounds(double margin) const
    {
        Bounds3 box{glm::dvec3(1e30), glm::dvec3(-1e30)};
        for (const auto& segments : mBranches)
            for (const TaperedSegment& s : segments) {
                const double r = std::max(s.ra, s.rb) + margin;
                box.lo = glm::min(box.lo, glm::min(s.a, s.b) - r);
                box.hi = glm::max(box.hi, glm::max(s.a, s.b) + r);
            }
        for (const Ball& ball : {kDome, kBleb}) {
            box.lo = glm::min(box.lo, ball.center - (ball.radius + margin));
            box.hi = glm::max(box.hi, ball.center + (ball.radius + margin));
        }
        return box;
    }

private:
    std::vector<std::vector<TaperedSegment>> mBranches;
};

/// Removes what lies beyond the end plane near @a end (no cap). Vertices closer than
/// @a snapDistance to the plane are moved onto it; crossing edges get one shared new vertex.
void cutAtEnd(TriangleMesh& mesh, const detail::VesselEnd& end, double snapDistance)
{
    // The ball holds all of the tube beyond the plane with room to spare; vertices outside it are
    // not affected by this plane (side stays NaN).
    const double region = kExtension + 3.0 * end.radius;
    std::vector<double> side(mesh.positions.size(), std::nan(""));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3 p(mesh.positions[v]);
        if (glm::length(p - end.center) > region) continue;
        side[v] = glm::dot(p - end.center, end.normal);
        if (std::abs(side[v]) < snapDistance) {
            mesh.positions[v] = glm::vec3(p - side[v] * end.normal);
            side[v] = 0.0;
        }
    }
    std::unordered_map<std::uint64_t, std::uint32_t> cutVertex;
    auto cut = [&](std::uint32_t a, std::uint32_t b) {
        const auto [it, isNew] = cutVertex.try_emplace(undirectedEdgeKey(a, b), 0u);
        if (isNew) {
            const double t = side[a] / (side[a] - side[b]);
            const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]);
            it->second = std::uint32_t(mesh.positions.size());
            mesh.positions.emplace_back(pa + t * (pb - pa));
        }
        return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> kept;
    for (const auto& tri : mesh.triangles) {
        std::array<std::uint32_t, 4> poly{};
        int n = 0, beyond = 0, untouched = 0, onPlane = 0;
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = tri[e], b = tri[(e + 1) % 3];
            untouched += std::isnan(side[a]);
            beyond += side[a] > 0.0;
            onPlane += side[a] == 0.0;
            if (!(side[a] > 0.0)) poly[n++] = a;
            if (side[a] * side[b] < 0.0) poly[n++] = cut(a, b);
        }
        IVIS_CHECK(untouched == 0 || beyond == 0);
        for (int i = 2; i < n && onPlane < 3; ++i) kept.push_back({poly[0], poly[i - 1], poly[i]});
    }
    mesh.triangles = std::move(kept);
}

/// Drops zero-area triangles and the vertices no triangle uses, keeping the order of the rest.
void dropDegenerate(TriangleMesh& mesh)
{
    std::vector<std::array<std::uint32_t, 3>> kept;
    std::vector<std::uint32_t> remap(mesh.positions.size(), UINT32_MAX);
    std::vector<glm::vec3> positions;
    for (const auto& tri : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]),
            c(mesh.positions[tri[2]]);
        if (glm::length(glm::cross(b - a, c - a)) == 0.0) continue;
        std::array<std::uint32_t, 3> out{};
        for (int i = 0; i < 3; ++i) {
            if (remap[tri[i]] == UINT32_MAX) {
                remap[tri[i]] = std::uint32_t(positions.size());
                positions.push_back(mesh.positions[tri[i]]);
            }
            out[i] = remap[tri[i]];
        }
        kept.push_back(out);
    }
    mesh.positions = std::move(positions);
    mesh.triangles = std::move(kept);
}

/// Synthetic wall shear stress, roughly in [0,1]: a gentle rise along the tree, high at the two
/// bifurcation apices, hot spots on the back (z < 0) of the parent, the left branch and the dome.
double vesselWss(const glm::dvec3& p)
{
    const auto& b = branches();
    const glm::dvec3 splitApex =
        kSplit + 0.14 * glm::normalize(glm::normalize(b[3].points[1] - kSplit) +
                                       glm::normalize(b[4].points[1] - kSplit));
    const glm::dvec3 back(0.0, 0.0, -1.0);
    const glm::dvec3 domeBack =
        kDome.center + kDome.radius * glm::normalize(glm::dvec3(0.3, 0.45, -0.84));
    return 0.12 + 0.08 * (p.y + 1.0) +
           0.45 * gaussian(p, kBifurcation + glm::dvec3(0.0, 0.17, 0.0), 0.1) +
           0.35 * gaussian(p, splitApex, 0.08) + 0.7 * gaussian(p, domeBack, 0.13) +
           0.5 * gaussian(p, b[1].points[2] + 0.14 * back, 0.1) +
           0.45 * gaussian(p, b[0].points[1] + 0.18 * back, 0.1);
}

}  // namespace

namespace detail {

std::vector<VesselEnd> vesselTreeEnds()
{
    std::vector<VesselEnd> ends;
    for (const Branch& b : branches())
        for (const VesselEnd& end : branchEnds(b)) ends.push_back(end);
    return ends;
}

}  // namespace detail

SurfaceField makeVesselTree(int gridResolution)
{
    if (gridResolution < 32 || gridResolution > 1024)
        throw ValueError("makeVesselTree: grid resolution must be in [32, 1024], got " +
                         std::to_string(gridResolution));
    const VesselImplicit implicit;
    const Bounds3 tight = implicit.bounds(0.0);
    const glm::dvec3 extent = tight.hi - tight.lo;
    const double cellSize = std::max({extent.x, extent.y, extent.z}) / gridResolution;
    TriangleMesh mesh = marchingTetrahedra(std::cref(implicit), implicit.bounds(2.0 * cellSize),
                                           cellSize);
    for (const detail::VesselEnd& end : detail::vesselTreeEnds())
        cutAtEnd(mesh, end, 0.01 * cellSize);
    dropDegenerate(mesh);
    return generated::makeField(std::move(mesh), "vessel-tree", "wss", vesselWss);
}

}  // namespace ivis::core
