/// @file content_hash.h
/// @brief Stable 64-bit content hashes (FNV-1a over 8-byte words) used to key volume caches.
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace ivis::core {

/// @brief Incremental FNV-1a-style 64-bit hash (words of 8 bytes, then single bytes).
class ContentHash {
public:
    /// @brief Mixes @a size raw bytes into the hash.
    void add(const void* data, std::size_t size);
    /// @brief Mixes a trivially copyable value into the hash.
    template <typename T>
    void addValue(const T& value) { add(&value, sizeof(T)); }
    /// @brief Current hash value.
    std::uint64_t value() const { return mState; }
    /// @brief Current hash as 16 lowercase hex digits.
    std::string hex() const;

private:
    std::uint64_t mState = 0xcbf29ce484222325ull;
};

/// @brief A 64-bit value as 16 lowercase hex digits.
std::string toHex(std::uint64_t value);

/// @brief Hash of the mesh geometry (positions, triangles, cap count): equal meshes, equal hash.
std::uint64_t meshHash(const TriangleMesh& mesh);

}  // namespace ivis::core
