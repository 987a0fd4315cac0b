#include <ivis/core/triangle_bvh.h>

#include <ivis/core/errors.h>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <new>
#include <string>
#include <vector>

namespace ivis::core {

struct TriangleBvh::Impl {
    const TriangleMesh* mesh = nullptr;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<glm::vec3> normals;
};

namespace {

/// Triangles a closest-point query tests together (closestPointsOnTriangles).
constexpr int kTestedTogether = 8;

/// State of one closest-point query: the best triangle so far and the triangles visited since the
/// last test.
struct ClosestSearch {
    const TriangleMesh* mesh = nullptr;
    glm::dvec3 p{0.0};
    TrianglePoint best;
    int triangle = -1;
    float radius = 0.0f;  ///< the query's radius as it stands
    int waiting = 0;
    unsigned visited[kTestedTogether];

    /// Tests the waiting triangles; true when one became the best. The best is the least distance
    /// within the radius, ties to the lowest index, whatever the order of the tests.
    bool testWaiting()
    {
        glm::dvec3 corners[3 * kTestedTogether];
        TrianglePoint points[kTestedTogether];
        for (int k = 0; k < waiting; ++k) {
            const auto& t = mesh->triangles[visited[k]];
            for (int corner = 0; corner < 3; ++corner) corners[3 * k + corner] = mesh->positions[t[corner]];
        }
        closestPointsOnTriangles(p, corners, waiting, points);
        bool improved = false;
        for (int k = 0; k < waiting; ++k) {
            const TrianglePoint& candidate = points[k];
            if (candidate.distanceSquared > double(radius) * double(radius)) continue;
            if (candidate.distanceSquared < best.distanceSquared ||
                (candidate.distanceSquared == best.distanceSquared && int(visited[k]) < triangle)) {
                best = candidate;
                triangle = int(visited[k]);
                improved = true;
            }
        }
        waiting = 0;
        return improved;
    }
};

/// The query radius a hair above the best distance of @a search, so that exact ties are still
/// visited: Embree measures its boxes from the query point rounded to floats, up to about 2e-7 off
/// within the volume's box [-2.5, 2.5]^3.
float radiusAbove(const ClosestSearch& search)
{
    return std::nextafter(float(std::sqrt(search.best.distanceSquared)) * (1.0f + 1e-6f) + 1e-6f, 1e30f);
}

/// Embree point-query callback: Embree visits every triangle whose box meets the query sphere; the
/// visited triangles wait until kTestedTogether of them are tested at once, and a better one found
/// shrinks the search radius.
bool visitTriangle(RTCPointQueryFunctionArguments* args)
{
    auto* search = static_cast<ClosestSearch*>(args->userPtr);
    search->visited[search->waiting++] = args->primID;
    if (search->waiting < kTestedTogether || !search->testWaiting()) return false;
    search->radius = std::min(search->radius, radiusAbove(*search));
    args->query->radius = search->radius;
    return true;
}

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) : mImpl(std::make_unique<Impl>())
{
    mImpl->mesh = &mesh;
    if (mesh.triangles.empty()) throw ValueError("cannot build a BVH of a mesh with no triangles");
    mImpl->device = rtcNewDevice("verbose=0");
    if (!mImpl->device) {
        // Under an address-space limit Embree cannot reserve its threads' and allocator's room:
        // the programs' out-of-memory line, not an internal error.
        const RTCError error = rtcGetDeviceError(nullptr);  // read once: reading clears it
        if (error == RTC_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
        throw InternalError("Embree device creation failed (error " + std::to_string(int(error)) + ")");
    }
    mImpl->scene = rtcNewScene(mImpl->device);
    rtcSetSceneFlags(mImpl->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(mImpl->scene, RTC_BUILD_QUALITY_HIGH);

    RTCGeometry geometry = rtcNewGeometry(mImpl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                 RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                 mesh.positions.size()));
    std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * 3 * sizeof(float));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                   RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                                   mesh.triangles.size()));
    std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(unsigned));
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(mImpl->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(mImpl->scene);

    mImpl->normals.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        const glm::vec3 n =
            glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
        const float length = glm::length(n);
        mImpl->normals.push_back(length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f));
    }
}

TriangleBvh::~TriangleBvh()
{
    if (mImpl->scene) rtcReleaseScene(mImpl->scene);
    if (mImpl->device) rtcReleaseDevice(mImpl->device);
}

RayHit TriangleBvh::intersect(const glm::vec3& origin, const glm::vec3& direction, float tNear, float tFar,
                            FaceFilter filter) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    float start = tNear;
    for (int attempt = 0; attempt < 64; ++attempt) {
        RTCRayHit query;
        query.ray.org_x = origin.x;
        query.ray.org_y = origin.y;
        query.ray.org_z = origin.z;
        query.ray.dir_x = direction.x;
        query.ray.dir_y = direction.y;
        query.ray.dir_z = direction.z;
        query.ray.tnear = start;
        query.ray.tfar = tFar;
        query.ray.time = 0.0f;
        query.ray.mask = std::numeric_limits<unsigned>::max();
        query.ray.id = 0;
        query.ray.flags = 0;
        query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(mImpl->scene, &context, &query);
        if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};

        RayHit hit;
        hit.t = query.ray.tfar;
        hit.triangle = int(query.hit.primID);
        hit.barycentric = {1.0f - query.hit.u - query.hit.v, query.hit.u, query.hit.v};
        hit.normal = mImpl->normals[query.hit.primID];
        if (filter == FaceFilter::Any || glm::dot(hit.normal, direction) > 0.0f) return hit;
        // Skip the front-facing hit and continue just past it.
        start = std::nextafter(hit.t, std::numeric_limits<float>::infinity()) * (1.0f + 1e-6f) + 1e-7f;
    }
    return {};
}

TrianglePoint TriangleBvh::closestPoint(const glm::dvec3& p, double radius, int& triangle) const
{
    ClosestSearch search;
    search.mesh = mImpl->mesh;
    search.p = p;
    search.best.distanceSquared = std::numeric_limits<double>::infinity();
    RTCPointQuery query;
    query.x = float(p.x);
    query.y = float(p.y);
    query.z = float(p.z);
    query.time = 0.0f;
    query.radius = std::isfinite(radius) ? std::nextafter(float(radius) * (1.0f + 1e-5f), 1e30f) + 1e-7f
                                         : std::numeric_limits<float>::infinity();
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    search.radius = query.radius;
    rtcPointQuery(mImpl->scene, &query, &context, visitTriangle, &search);
    search.testWaiting();
    triangle = search.triangle;
    return search.best;
}

}  // namespace ivis::core
