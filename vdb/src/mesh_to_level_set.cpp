// Builds a SurfaceVolume: OpenVDB's mesh-to-volume conversion for the band and the sign, then an
// exact closest-point pass that fixes distance, triangle ID and distance gradient of
// every band voxel, and distance and gradient of every far-field voxel.
#include <ivis/vdb/surface_volume.h>
#include <ivis/vdb/build_memory.h>

#include <ivis/core/closest_point.h>
#include <ivis/core/content_hash.h>
#include <ivis/core/errors.h>
#include <ivis/core/memory_reserve.h>
#include <ivis/core/pseudo_normals.h>
#include <ivis/core/triangle_bvh.h>

#include <glm/geometric.hpp>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tree/LeafManager.h>
#include <openvdb/util/Util.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
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

/// Reports a parallel pass over the leaves of a grid to an optional core::Interrupter, by leaves
/// done, and throws Cancelled once it asks to stop.
class LeafPassProgress {
public:
    LeafPassProgress(core::Interrupter* interrupter, const std::string& name, std::size_t leafCount)
        : mInterrupter(interrupter), mLeafCount(std::max<std::size_t>(1, leafCount))
    {
        if (mInterrupter) mInterrupter->start(name.c_str());
    }
    ~LeafPassProgress()
    {
        if (mInterrupter) mInterrupter->end();
    }
    LeafPassProgress(const LeafPassProgress&) = delete;
    LeafPassProgress& operator=(const LeafPassProgress&) = delete;

    /// Counts @a leaves more done; true once the pass is to stop (a Ctrl-C, or the interrupter asks).
    bool advance(std::size_t leaves)
    {
        if (mStop) return true;  // the rest of the pass skips its leaves without asking again
        const std::size_t done = mDone += leaves;
        if (mInterrupter && mInterrupter->wasInterrupted(int(100 * done / mLeafCount))) mStop = true;
        return mStop;
    }
    /// Throws Cancelled when the pass was stopped.
    void finish() const
    {
        if (mStop) throw Cancelled("volume build cancelled");
    }

private:
    core::Interrupter* mInterrupter;
    std::size_t mLeafCount;
    std::atomic<std::size_t> mDone{0};
    std::atomic<bool> mStop{false};
};

/// Unit gradient of the distance at @a p whose closest surface point is @a closest on @a triangle,
/// for the signed value @a phi: (p - closest) / phi; on the surface itself the triangle's normal.
openvdb::Vec3s distanceGradient(const core::TriangleMesh& mesh, int triangle, const glm::dvec3& p,
                                const glm::dvec3& closest, double phi)
{
    glm::dvec3 direction = p - closest;
    double length = glm::length(direction);
    if (length < 1e-9) {
        const auto& t = mesh.triangles[std::size_t(triangle)];
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        direction = glm::cross(b - a, c - a);
        length = glm::length(direction);
        if (length == 0.0) return openvdb::Vec3s(0.0f);
    }
    direction *= (phi < 0.0 ? -1.0 : 1.0) / length;
    return openvdb::Vec3s(float(direction.x), float(direction.y), float(direction.z));
}

/// The exact closest point of @a p on the mesh, searched within @a bound first (OpenVDB's distance
/// to an actual polygon bounds it) and without bound if nothing lies within it (never seen).
core::TrianglePoint closestWithin(const core::TriangleBvh& bvh, const glm::dvec3& p, double bound, int& triangle)
{
    core::TrianglePoint closest = bvh.closestPoint(p, bound, triangle);
    if (triangle < 0) closest = bvh.closestPoint(p, std::numeric_limits<double>::infinity(), triangle);
    IVIS_CHECK(triangle >= 0);
    return closest;
}

/// Exact distance, closest triangle and distance gradient for every band voxel. The
/// sign is OpenVDB's, except within two voxels of a closed, manifold, consistently oriented
/// surface, where the pseudo-normal test is exact (OpenVDB's flood fill mislabels crevices
/// narrower than a voxel).
void refineClosestPoints(const core::TriangleMesh& mesh, const core::TriangleBvh& bvh, SurfaceVolume& volume,
                         core::Interrupter* interrupter)
{
    using namespace openvdb;
    const core::PseudoNormals pseudoNormals(mesh);
    const bool isUnsigned = volume.unsignedDistance;
    const bool exactSignNearSurface = !isUnsigned && pseudoNormals.usable();
    const BoxLattice lattice = volume.lattice();
    const double voxelSize = lattice.voxelSize();
    tree::LeafManager<FloatTree> leaves(volume.phi->tree());
    LeafPassProgress progress(interrupter, "closest points N=" + std::to_string(volume.options.resolution),
                              leaves.leafCount());
    tbb::parallel_for(leaves.leafRange(), [&](const tree::LeafManager<FloatTree>::LeafRange& range) {
        // Each leaf counts (the ranges TBB hands out hold a few leaves each: counted per 64 leaves
        // of a range, a Ctrl-C went unheard for the whole pass).
        for (auto leaf = range.begin(); leaf; ++leaf) {
            if (progress.advance(1)) return;
            Int32Tree::LeafNodeType* triangleLeaf = volume.triangle->tree().probeLeaf(leaf->origin());
            Vec3STree::LeafNodeType* gradientLeaf = volume.gradient->tree().probeLeaf(leaf->origin());
            IVIS_CHECK(triangleLeaf && gradientLeaf);
            for (auto voxel = leaf->beginValueOn(); voxel; ++voxel) {
                const Vec3d centre = lattice.worldFromIndex(voxel.getCoord());
                const glm::dvec3 p(centre.x(), centre.y(), centre.z());
                int triangle = -1;
                const core::TrianglePoint best = closestWithin(bvh, p, std::abs(*voxel) + 0.01 * voxelSize, triangle);
                const double distance = std::sqrt(best.distanceSquared);
                bool inside = !isUnsigned && *voxel < 0.0f;
                if (exactSignNearSurface && distance < 2.0 * voxelSize)
                    inside = glm::dot(p - best.point, pseudoNormals.at(triangle, best.barycentric)) < 0.0;
                const double value = inside ? -distance : distance;
                voxel.setValue(float(value));
                triangleLeaf->setValueOnly(voxel.pos(), triangle);
                gradientLeaf->setValueOnly(voxel.pos(), distanceGradient(mesh, triangle, p, best.point, value));
            }
        }
    });
    progress.finish();
}

/// Exact distance and gradient of every far-field voxel, by the bounded BVH query of the band (no
/// triangle); the sign is OpenVDB's. (The triangles OpenVDB's polygon-index grid
/// names at the voxel and its 26 neighbours cost a third as much but miss the closest triangle at
/// some far voxels, whose gradients are then degrees off: docs/volume.md.)
void farFieldDistances(const core::TriangleMesh& mesh, const core::TriangleBvh& bvh, const BoxLattice& lattice,
                       openvdb::FloatGrid& phi, openvdb::Vec3SGrid& gradient, core::Interrupter* interrupter)
{
    using namespace openvdb;
    const double voxelSize = lattice.voxelSize();
    tree::LeafManager<FloatTree> leaves(phi.tree());
    LeafPassProgress progress(interrupter, "far field N=" + std::to_string(lattice.resolution), leaves.leafCount());
    tbb::parallel_for(leaves.leafRange(), [&](const tree::LeafManager<FloatTree>::LeafRange& range) {
        // Each leaf counts (the ranges TBB hands out hold a few leaves each: counted per 64 leaves
        // of a range, a Ctrl-C went unheard for the whole pass).
        for (auto leaf = range.begin(); leaf; ++leaf) {
            if (progress.advance(1)) return;
            Vec3STree::LeafNodeType* gradientLeaf = gradient.tree().probeLeaf(leaf->origin());
            IVIS_CHECK(gradientLeaf);
            for (auto voxel = leaf->beginValueOn(); voxel; ++voxel) {
                const Vec3d centre = lattice.worldFromIndex(voxel.getCoord());
                const glm::dvec3 p(centre.x(), centre.y(), centre.z());
                int triangle = -1;
                const core::TrianglePoint closest = closestWithin(bvh, p, std::abs(*voxel) + 0.01 * voxelSize, triangle);
                const double distance = std::sqrt(closest.distanceSquared);
                const double value = *voxel < 0.0f ? -distance : distance;
                voxel.setValue(float(value));
                gradientLeaf->setValueOnly(voxel.pos(), distanceGradient(mesh, triangle, p, closest.point, value));
            }
        }
    });
    progress.finish();
}

/// A grid of @a type over the topology of @a phi, named @a name, with @a background.
template <typename GridT>
typename GridT::Ptr topologyCopy(const openvdb::FloatGrid& phi, const typename GridT::ValueType& background,
                                 const char* name)
{
    auto grid = GridT::create(background);
    grid->setTree(std::make_shared<typename GridT::TreeType>(phi.tree(), background, openvdb::TopologyCopy()));
    grid->setTransform(phi.transform().copy());
    grid->setName(name);
    return grid;
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
    interrupt.start(("volume N=" + std::to_string(resolution)).c_str());
    auto grid = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        interrupt, adapter, *transform, exteriorVoxels, interiorVoxels, flags, indexGrid);
    interrupt.end();
    if (interrupt.wasInterrupted()) throw Cancelled("volume build cancelled");
    return grid;
}

bool usesUnsignedDistance(const core::TriangleMesh& mesh, DistanceSign sign)
{
    if (sign == DistanceSign::Signed) return false;
    if (sign == DistanceSign::Unsigned) return true;
    return core::boundaryEdgeCount(mesh) > 0;
}

NarrowBandWidth narrowBandWidth(const VolumeOptions& options, bool unsignedDistance)
{
    const double voxelSize = BoxLattice{options.resolution}.voxelSize();
    const bool fineReachesHull = options.resolution <= options.farFieldResolution;
    const float reachVoxels = float(std::ceil(options.farFieldReach / voxelSize)) + 1.0f;
    const float farVoxels = float(std::ceil(BoxLattice{options.farFieldResolution}.voxelSize() / voxelSize)) + 2.0f;
    NarrowBandWidth band;
    band.exterior = std::max(options.bandVoxels, fineReachesHull ? reachVoxels : farVoxels);
    band.interior = unsignedDistance ? band.exterior : options.bandVoxels;
    return band;
}

SurfaceVolume buildSurfaceVolume(const core::TriangleMesh& mesh, const VolumeOptions& options,
                                 core::Interrupter* interrupter)
{
    validate(options);
    if (mesh.triangles.empty()) throw ValueError("cannot build a volume of a mesh with no triangles");

    // Declared before the grids, so it outlives them: their destructors allocate as a bad_alloc unwinds.
    const core::ScopedMemoryReserve reserve;
    SurfaceVolume volume;
    volume.options = options;
    volume.unsignedDistance = usesUnsignedDistance(mesh, options.sign);
    volume.triangleCount = mesh.triangles.size();
    volume.meshHash = core::meshHash(mesh);

    checkBuildFits(mesh, options, volume.unsignedDistance, allocatableBytes());
    const NarrowBandWidth band = narrowBandWidth(options, volume.unsignedDistance);
    volume.phi = meshToNarrowBand(mesh, options.resolution, band.exterior, band.interior, volume.unsignedDistance,
                                  interrupter);
    volume.phi->setName("phi");

    volume.triangle = topologyCopy<openvdb::Int32Grid>(*volume.phi, -1, "triangle");
    volume.gradient = topologyCopy<openvdb::Vec3SGrid>(*volume.phi, openvdb::Vec3s(0.0f), "gradient");
    const core::TriangleBvh bvh(mesh);
    refineClosestPoints(mesh, bvh, volume, interrupter);

    if (options.resolution > options.farFieldResolution) {  // the fine band does not reach the hull
        const double farVoxel = volume.farLattice().voxelSize();
        const float farExterior = float(std::ceil(options.farFieldReach / farVoxel)) + 1.0f;
        const float farInterior = volume.unsignedDistance ? farExterior : 3.0f;
        volume.farPhi = meshToNarrowBand(mesh, options.farFieldResolution, farExterior, farInterior,
                                volume.unsignedDistance, interrupter, nullptr);
        volume.farPhi->setName("far_phi");
        volume.farGradient = topologyCopy<openvdb::Vec3SGrid>(*volume.farPhi, openvdb::Vec3s(0.0f), "far_gradient");
        farFieldDistances(mesh, bvh, volume.farLattice(), *volume.farPhi, *volume.farGradient, interrupter);
    }
    return volume;
}

}  // namespace ivis::vdb
