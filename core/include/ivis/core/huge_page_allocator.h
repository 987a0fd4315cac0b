/// @file huge_page_allocator.h
/// @brief Large blocks backed by transparent huge pages: the per-frame image and layer buffers (a
///        fresh 1000 x 1000 frame touches about 50 MB, which 4 KiB page faults make slow on a
///        virtual machine) and the distance field's dense copies that every ray samples at random
///        (fewer TLB misses). docs/performance.md has the measurements.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

namespace ivis::core {

/// @brief Uninitialised block of @a bytes, released with std::free; from 2 MiB on it is 2 MiB
///        aligned and advised as huge pages (Linux madvise MADV_HUGEPAGE, which the default
///        "madvise" THP mode honours). @throw std::bad_alloc
void* allocateLarge(std::size_t bytes);

/// @brief std::allocator-compatible allocator on allocateLarge.
template <typename T>
struct HugePageAllocator {
    using value_type = T;

    HugePageAllocator() = default;
    template <typename U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    /// @brief Room for @a n values of T.
    T* allocate(std::size_t n)
    {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_alloc();
        return static_cast<T*>(allocateLarge(n * sizeof(T)));
    }
    /// @brief Frees a block of allocate().
    void deallocate(T* block, std::size_t) noexcept { std::free(block); }

    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const noexcept { return true; }
    template <typename U>
    bool operator!=(const HugePageAllocator<U>&) const noexcept { return false; }
};

/// @brief Deleter of allocateLarge's blocks.
struct LargeBlockDeleter {
    void operator()(void* block) const noexcept { std::free(block); }
};

/// @brief An uninitialised array on allocateLarge.
template <typename T>
using HugePageArray = std::unique_ptr<T[], LargeBlockDeleter>;

/// @brief @a n uninitialised values of a trivial type T on allocateLarge. @throw std::bad_alloc
template <typename T>
HugePageArray<T> makeHugePageArray(std::size_t n)
{
    static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>);
    return HugePageArray<T>(HugePageAllocator<T>().allocate(n));
}

}  // namespace ivis::core
