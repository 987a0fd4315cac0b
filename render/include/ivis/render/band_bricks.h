/// @file band_bricks.h
/// @brief The fine narrow band of a distance volume rearranged for sampling: one brick of 9^3
///        interleaved (phi, exact gradient) voxels per OpenVDB leaf (its 8^3 voxels and the first
///        voxel of its +x, +y and +z neighbours), found through a hash of leaf origins. Every fine
///        cell's eight corners lie in one brick, in four cache lines, where the sparse grids spread
///        them over two trees and up to eight leaves.
#pragma once

#include <ivis/core/large_block.h>

#include <openvdb/openvdb.h>

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace ivis::render {

/// @brief Bricks of a band's (phi, gradient) voxels; an inactive voxel has phi NaN (so any blend
///        that touches it is NaN) and a zero gradient.
class BandBricks {
public:
    /// @brief Voxels along a brick's edge: a leaf's 8 and one of the next leaf.
    static constexpr int kEdge = 9;

    BandBricks() = default;
    /// @brief Bricks of every leaf of @a phi, with @a gradient of the same topology.
    BandBricks(const openvdb::FloatGrid& phi, const openvdb::Vec3SGrid& gradient);

    /// @brief The brick of the leaf that contains fine index (x, y, z) (all >= 0), nullptr when
    ///        the band has no leaf there; voxel (x, y, z) is at brick[voxelOffset(x & 7, y & 7, z & 7)].
    const glm::vec4* find(int x, int y, int z) const;
    /// @brief Offset in a brick of local voxel (x, y, z), each in [0, kEdge).
    static int voxelOffset(int x, int y, int z) { return (z * kEdge + y) * kEdge + x; }

private:
    /// Hash key of the leaf holding fine index (x, y, z), x, y, z >= 0 and below 2^24.
    static std::uint64_t leafKey(int x, int y, int z)
    {
        return std::uint64_t(x >> 3) | std::uint64_t(y >> 3) << 21 | std::uint64_t(z >> 3) << 42;
    }
    /// Slot of @a key in the open-addressed table (where it is or where it would go).
    std::size_t slot(std::uint64_t key) const;

    static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);
    std::vector<std::uint64_t> mKeys;    ///< open addressing, linear probing; kEmpty = free slot
    std::vector<std::uint32_t> mBricks;  ///< brick index of each used slot
    core::LargeBlockArray<glm::vec4> mVoxels;  ///< brick after brick, kEdge^3 voxels each (filled in parallel, never zeroed first)
};

inline std::size_t BandBricks::slot(std::uint64_t key) const
{
    const std::size_t mask = mKeys.size() - 1;
    std::size_t i = std::size_t((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
    while (mKeys[i] != key && mKeys[i] != kEmpty) i = (i + 1) & mask;
    return i;
}

inline const glm::vec4* BandBricks::find(int x, int y, int z) const
{
    if (mKeys.empty()) return nullptr;
    const std::size_t i = slot(leafKey(x, y, z));
    if (mKeys[i] == kEmpty) return nullptr;
    return mVoxels.get() + std::size_t(mBricks[i]) * (kEdge * kEdge * kEdge);
}

}  // namespace ivis::render
