#include <ivis/render/band_bricks.h>

#include <ivis/core/errors.h>

#include <tbb/parallel_for.h>

#include <limits>

namespace ivis::render {

BandBricks::BandBricks(const openvdb::FloatGrid& phi, const openvdb::Vec3SGrid& gradient)
{
    IVIS_CHECK(phi.tree().hasSameTopology(gradient.tree()));
    // Leaves that a sample can reach: the sampler asks for non-negative indices only.
    std::vector<openvdb::Coord> origins;
    for (auto leaf = phi.tree().cbeginLeaf(); leaf; ++leaf) {
        const openvdb::Coord origin = leaf->origin();
        if (origin.x() >= 0 && origin.y() >= 0 && origin.z() >= 0 && origin.x() < (1 << 24) &&
            origin.y() < (1 << 24) && origin.z() < (1 << 24))
            origins.push_back(origin);
    }
    if (origins.empty()) return;

    std::size_t tableSize = 1;
    while (tableSize < 2 * origins.size()) tableSize *= 2;
    mKeys.assign(tableSize, kEmpty);
    mBricks.assign(tableSize, 0);
    for (std::size_t b = 0; b < origins.size(); ++b) {
        const std::uint64_t key = leafKey(origins[b].x(), origins[b].y(), origins[b].z());
        const std::size_t i = slot(key);
        mKeys[i] = key;
        mBricks[i] = std::uint32_t(b);
    }

    constexpr int kVoxels = kEdge * kEdge * kEdge;
    mVoxels = core::makeLargeBlockArray<glm::vec4>(origins.size() * kVoxels);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, origins.size()), [&](const tbb::blocked_range<std::size_t>& range) {
        auto phiAccessor = phi.getConstAccessor();
        auto gradientAccessor = gradient.getConstAccessor();
        for (std::size_t b = range.begin(); b != range.end(); ++b) {
            glm::vec4* brick = mVoxels.get() + b * kVoxels;
            // The leaf's own voxels straight from its buffers, the last layer from its neighbours.
            const auto* phiLeaf = phiAccessor.probeConstLeaf(origins[b]);
            const auto* gradientLeaf = gradientAccessor.probeConstLeaf(origins[b]);
            for (int z = 0; z < kEdge; ++z)
                for (int y = 0; y < kEdge; ++y)
                    for (int x = 0; x < kEdge; ++x) {
                        glm::vec4& voxel = brick[voxelOffset(x, y, z)];
                        float value;
                        openvdb::Vec3s g;
                        bool active;
                        if (x < 8 && y < 8 && z < 8) {
                            const openvdb::Index offset = openvdb::Index(x << 6 | y << 3 | z);
                            active = phiLeaf->isValueOn(offset);
                            value = phiLeaf->getValue(offset);
                            g = gradientLeaf->getValue(offset);
                        } else {
                            const openvdb::Coord ijk = origins[b].offsetBy(x, y, z);
                            active = phiAccessor.probeValue(ijk, value);
                            g = gradientAccessor.getValue(ijk);
                        }
                        voxel = active ? glm::vec4(value, g.x(), g.y(), g.z()) : glm::vec4(nan, 0.0f, 0.0f, 0.0f);
                    }
        }
    });
}

}  // namespace ivis::render
