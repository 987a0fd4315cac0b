// Builds a SurfaceVolume: OpenVDB's mesh-to-volume conversion for the band and the sign, then an
// exact closest-point pass that fixes distance, triangle ID and barycentrics of every band voxel.
#include <ivis/vdb/surface_volume.h>

#include <ivis/core/closest_point.h>
#include <ivis/core/content_hash.h>
#include <ivis/core/errors.h>
#include <ivis/core/pseudo_normals.h>
#include <ivis/core/triangle_bvh.h>

#include <glm/geometric.hpp>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tree/LeafManager.h>
#include <openvdb/util/Util.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace ivis::vdb {
namespace {


/// OpenVDB MeshDataAdapter over a TriangleMesh whose points are pre-mapped to index space.
class IndexSpaceMesh {
public:
    IndexSpaceMesh(const core::TriangleMesh& mesh, const openvdb::math::Transform& transform)
        : mMesh(mesh), mPoints(mesh.positions.size())
    {
        for (std::size_t i = 0; i < mPoints.size(); ++i) {
            const glm::vec3& p = mesh.positions[i];
            mPoints[i] = transform.worldToIndex(openvdb::Vec3d(p.x, p.y, p.z));
        }
    }
    std::size_t polygonCount() const { return mMesh.triangles.size(); }
    std::size_t pointCount() const { return mPoints.size(); }
    std::size_t vertexCount(std::size_t) const { return 3; }
    void getIndexSpacePoint(std::size_t n, std::size_t v, openvdb::Vec3d& pos) const
    {
        pos = mPoints[mMesh.triangles[n][v]];
    }

private:
    const core::TriangleMesh& mMesh;
    std::vector<openvdb::Vec3d> mPoints;
};

/// Adapts the optional core::Interrupter to OpenVDB's interrupter interface.
class InterrupterAdapter {
public:
    explicit InterrupterAdapter(core::Interrupter* inner) : mInner(inner) {}
    void start(const char* name = nullptr) { if (mInner) mInner->start(name); }
    void end() { if (mInner) mInner->end(); }
    bool wasInterrupted(int percent = -1) { return mInner && mInner->wasInterrupted(percent); }

private:
    core::Interrupter* mInner;
};

/// Exact distance, closest triangle and barycentrics for every band voxel. The sign is OpenVDB's,
/// except within two voxels of a closed, manifold, consistently oriented surface, where the
/// pseudo-normal test is exact (OpenVDB's flood fill mislabels crevices narrower than a voxel).
/// OpenVDB's band values are distances to actual polygons, so |phi| bounds the search radius; a
/// search that finds nothing within it (never seen) retries without bound.
void refineClosestPoints(const core::TriangleMesh& mesh, SurfaceVolume& volume)
{
    using namespace openvdb;
    const core::TriangleBvh bvh(mesh);
    const core::PseudoNormals pseudoNormals(mesh);
    const bool exactSignNearSurface = !volume.unsignedDistance && pseudoNormals.usable();
    const double voxelSize = volume.voxelSize();
    const BoxLattice lattice = volume.lattice();
    Int32Tree& triangleTree = volume.triangle->tree();
    Vec3STree& baryTree = volume.barycentric->tree();
    const bool isUnsigned = volume.unsignedDistance;

    tree::LeafManager<FloatTree> leaves(volume.phi->tree());
    tbb::parallel_for(leaves.leafRange(), [&](const tree::LeafManager<FloatTree>::LeafRange& range) {
        for (auto leaf = range.begin(); leaf; ++leaf) {
            Int32Tree::LeafNodeType* triangleLeaf = triangleTree.probeLeaf(leaf->origin());
            Vec3STree::LeafNodeType* baryLeaf = baryTree.probeLeaf(leaf->origin());
            IVIS_CHECK(triangleLeaf && baryLeaf);
            for (auto voxel = leaf->beginValueOn(); voxel; ++voxel) {
                const Vec3d centre = lattice.worldFromIndex(voxel.getCoord());
                const glm::dvec3 p(centre.x(), centre.y(), centre.z());
                int triangle = -1;
                core::TrianglePoint best = bvh.closestPoint(p, std::abs(*voxel) + 0.01 * voxelSize, triangle);
                if (triangle < 0) best = bvh.closestPoint(p, std::numeric_limits<double>::infinity(), triangle);
                IVIS_CHECK(triangle >= 0);
                const double distance = std::sqrt(best.distanceSquared);
                bool inside = !isUnsigned && *voxel < 0.0f;
                if (exactSignNearSurface && distance < 2.0 * voxelSize)
                    inside = glm::dot(p - best.point, pseudoNormals.at(triangle, best.barycentric)) < 0.0;
                voxel.setValue(float(inside ? -distance : distance));
                triangleLeaf->setValueOnly(voxel.pos(), triangle);
                baryLeaf->setValueOnly(voxel.pos(), Vec3s(float(best.barycentric.x), float(best.barycentric.y),
                                                          float(best.barycentric.z)));
            }
        }
    });
}

}  // namespace

openvdb::FloatGrid::Ptr meshToNarrowBand(const core::TriangleMesh& mesh, int resolution, float exteriorVoxels,
                                float interiorVoxels, bool unsignedDistance, core::Interrupter* interrupter, openvdb::Int32Grid* indexGrid)
{
    detail::initializeOpenVdb();
    const auto transform = BoxLattice{resolution}.transform();
    const IndexSpaceMesh adapter(mesh, *transform);
    InterrupterAdapter interrupt(interrupter);
    const int flags = unsignedDistance ? openvdb::tools::UNSIGNED_DISTANCE_FIELD : 0;
    auto grid = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        interrupt, adapter, *transform, exteriorVoxels, interiorVoxels, flags, indexGrid);
    if (interrupt.wasInterrupted()) throw Cancelled("volume build cancelled");
    return grid;
}

bool usesUnsignedDistance(const core::TriangleMesh& mesh, DistanceSign sign)
{
    if (sign == DistanceSign::Signed) return false;
    if (sign == DistanceSign::Unsigned) return true;
    return core::boundaryEdgeCount(mesh) > 0;
}

SurfaceVolume buildSurfaceVolume(const core::TriangleMesh& mesh, const VolumeOptions& options,
                                 core::Interrupter* interrupter)
{
    validate(options);
    if (mesh.triangles.empty()) throw ValueError("cannot build a volume of a mesh with no triangles");

    SurfaceVolume volume;
    volume.options = options;
    volume.unsignedDistance = usesUnsignedDistance(mesh, options.sign);
    volume.triangleCount = mesh.triangles.size();
    volume.meshHash = core::meshHash(mesh);

    // The fine band alone reaches the hull when its voxels are as coarse as the far field's.
    const double voxelSize = volume.voxelSize();
    const bool fineReachesHull = options.resolution <= options.farFieldResolution;
    const float reachVoxels = float(std::ceil(options.farFieldReach / voxelSize)) + 1.0f;
    const float exteriorVoxels = fineReachesHull ? std::max(options.bandVoxels, reachVoxels) : options.bandVoxels;
    const float interiorVoxels = volume.unsignedDistance ? exteriorVoxels : options.bandVoxels;

    volume.phi = meshToNarrowBand(mesh, options.resolution, exteriorVoxels, interiorVoxels, volume.unsignedDistance,
                                  interrupter);
    volume.phi->setName("phi");

    volume.triangle = openvdb::Int32Grid::create(-1);
    volume.triangle->setTree(std::make_shared<openvdb::Int32Tree>(volume.phi->tree(), -1, openvdb::TopologyCopy()));
    volume.triangle->setTransform(volume.phi->transform().copy());
    volume.triangle->setName("triangle");
    volume.barycentric = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    volume.barycentric->setTree(
        std::make_shared<openvdb::Vec3STree>(volume.phi->tree(), openvdb::Vec3s(0.0f), openvdb::TopologyCopy()));
    volume.barycentric->setTransform(volume.phi->transform().copy());
    volume.barycentric->setName("barycentric");

    refineClosestPoints(mesh, volume);

    if (!fineReachesHull) {
        const double farVoxel = volume.farLattice().voxelSize();
        const float farExterior = float(std::ceil(options.farFieldReach / farVoxel)) + 1.0f;
        const float farInterior = volume.unsignedDistance ? farExterior : 3.0f;
        volume.farPhi = meshToNarrowBand(mesh, options.farFieldResolution, farExterior, farInterior,
                                volume.unsignedDistance, interrupter, nullptr);
        volume.farPhi->setName("far_phi");
    }
    return volume;
}

}  // namespace ivis::vdb
