/// @file large_block.h
/// @brief Large uninitialised blocks: the per-frame image and layer buffers and the distance
///        field's dense copies (the far field, the band bricks). Large ones are faulted in on every
///        core at once: the kernel zeroes a fresh page on its first touch, which on a virtual
///        machine costs about as much as the caller's own fill. Ordinary 4 KiB pages: transparent
///        huge pages made that first touch slower and the frames no faster
///        (docs/decisions/page-size.md).
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

namespace ivis::core {

/// @brief Blocks start on a cache line (so no 16-byte voxel of them straddles two).
inline constexpr std::size_t kLargeBlockAlignment = 64;
/// @brief From this many bytes on a block's pages are faulted in by every core before it is returned.
inline constexpr std::size_t kFaultInFrom = std::size_t(2) << 20;

/// @brief Uninitialised block of @a bytes aligned to kLargeBlockAlignment, released with std::free;
///        from kFaultInFrom bytes on every page of it is already faulted in. @throw std::bad_alloc
void* allocateLarge(std::size_t bytes);

/// @brief std::allocator-compatible allocator on allocateLarge.
template <typename T>
struct LargeBlockAllocator {
    using value_type = T;

    LargeBlockAllocator() = default;
    /// @brief The allocator of another value type (it holds no state).
    template <typename U>
    LargeBlockAllocator(const LargeBlockAllocator<U>&) noexcept {}

    /// @brief Room for @a n values of T.
    T* allocate(std::size_t n)
    {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_alloc();
        return static_cast<T*>(allocateLarge(n * sizeof(T)));
    }
    /// @brief Frees a block of allocate().
    void deallocate(T* block, std::size_t) noexcept { std::free(block); }

    template <typename U>
    bool operator==(const LargeBlockAllocator<U>&) const noexcept { return true; }
    template <typename U>
    bool operator!=(const LargeBlockAllocator<U>&) const noexcept { return false; }
};

/// @brief Deleter of allocateLarge's blocks.
struct LargeBlockDeleter {
    /// @brief Frees @a block.
    void operator()(void* block) const noexcept { std::free(block); }
};

/// @brief An uninitialised array on allocateLarge.
template <typename T>
using LargeBlockArray = std::unique_ptr<T[], LargeBlockDeleter>;

/// @brief @a n uninitialised values of a trivial type T on allocateLarge. @throw std::bad_alloc
template <typename T>
LargeBlockArray<T> makeLargeBlockArray(std::size_t n)
{
    static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>);
    return LargeBlockArray<T>(LargeBlockAllocator<T>().allocate(n));
}

}  // namespace ivis::core
