/// @file edge_key.h
/// @brief One key per undirected edge of a triangle mesh, for hash maps keyed by edge.
#pragma once

#include <algorithm>
#include <cstdint>

namespace ivis::core {

/// @brief The key of the edge between vertices @a a and @a b, the same either way round.
inline std::uint64_t undirectedEdgeKey(std::uint32_t a, std::uint32_t b)
{
    return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

}  // namespace ivis::core
