#include <ivis/core/content_hash.h>

#include <cstdio>
#include <cstring>

namespace ivis::core {

void ContentHash::add(const void* data, std::size_t size)
{
    // FNV-1a over 8-byte words, then the remaining bytes.
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes + i, 8);
        mState ^= word;
        mState *= 0x100000001b3ull;
    }
    for (; i < size; ++i) {
        mState ^= bytes[i];
        mState *= 0x100000001b3ull;
    }
}

std::string ContentHash::hex() const { return toHex(mState); }

std::string toHex(std::uint64_t value)
{
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
    return buffer;
}

std::uint64_t meshHash(const TriangleMesh& mesh)
{
    ContentHash hash;
    hash.addValue(mesh.positions.size());
    hash.add(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    hash.addValue(mesh.triangles.size());
    hash.add(mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
    hash.addValue(mesh.dataTriangleCount);
    return hash.value();
}

}  // namespace ivis::core
