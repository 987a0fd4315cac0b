#include <ivis/core/content_hash.h>

#include <cstdio>

namespace ivis::core {

void ContentHash::add(const void* data, std::size_t size)
{
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        mState ^= bytes[i];
        mState *= 0x100000001b3ull;
    }
}

std::string ContentHash::hex() const
{
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(mState));
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
