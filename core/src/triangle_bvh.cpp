#include <ivis/core/triangle_bvh.h>

#include <ivis/core/errors.h>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace ivis::core {

struct TriangleBvh::Impl {
    const TriangleMesh* mesh = nullptr;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<glm::vec3> normals;
};

namespace {

/// State of one closest-point query.
struct ClosestSearch {
    const TriangleMesh* mesh;
    glm::dvec3 p;
    TrianglePoint best;
    int triangle = -1;
};

/// Embree point-query callback: tests one triangle (Embree visits every triangle whose box meets
/// the query sphere) and shrinks the search radius when it is closer than the radius.
bool visitTriangle(RTCPointQueryFunctionArguments* args)
{
    auto* search = static_cast<ClosestSearch*>(args->userPtr);
    const auto& t = search->mesh->triangles[args->primID];
    const TrianglePoint candidate = closestPointOnTriangle(
        search->p, search->mesh->positions[t[0]], search->mesh->positions[t[1]], search->mesh->positions[t[2]]);
    const double radius = args->query->radius;
    if (candidate.distanceSquared > radius * radius) return false;
    const bool better = candidate.distanceSquared < search->best.distanceSquared ||
                        (candidate.distanceSquared == search->best.distanceSquared && int(args->primID) < search->triangle);
    if (!better) return false;
    search->best = candidate;
    search->triangle = int(args->primID);
    // Keep the radius a hair above the distance so that exact ties are still visited.
    args->query->radius = std::min(args->query->radius,
                                   std::nextafter(float(std::sqrt(candidate.distanceSquared)) * (1.0f + 1e-6f), 1e30f));
    return true;
}

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) : mImpl(std::make_unique<Impl>())
{
    mImpl->mesh = &mesh;
    if (mesh.triangles.empty()) throw ValueError("cannot build a BVH of a mesh with no triangles");
    mImpl->device = rtcNewDevice("verbose=0");
    if (!mImpl->device) throw InternalError("Embree device creation failed");
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
    ClosestSearch search{mImpl->mesh, p, {}, -1};
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
    rtcPointQuery(mImpl->scene, &query, &context, visitTriangle, &search);
    triangle = search.triangle;
    return search.best;
}

}  // namespace ivis::core
