#include <ivis/core/large_block.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>

namespace ivis::core {

void* allocateLarge(std::size_t bytes)
{
    if (bytes > std::size_t(-1) - kLargeBlockAlignment) throw std::bad_alloc();  // its rounding up would wrap
    const std::size_t size = (std::max<std::size_t>(bytes, 1) + kLargeBlockAlignment - 1) / kLargeBlockAlignment *
                             kLargeBlockAlignment;
    void* block = std::aligned_alloc(kLargeBlockAlignment, size);
    if (!block) throw std::bad_alloc();
    if (size < kFaultInFrom) return block;
    // Fault the pages in on every core: the kernel zeroes each one on first touch, which on a
    // virtual machine costs about as much as the caller's own fill. One byte of each page the
    // block overlaps, the first and last partial ones included.
    constexpr std::uintptr_t kPage = 4096, kPagesPerTask = 64;
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(block), end = begin + size;
    const std::uintptr_t firstPage = begin / kPage, pages = (end - 1) / kPage - firstPage + 1;
    tbb::parallel_for(std::uintptr_t(0), (pages + kPagesPerTask - 1) / kPagesPerTask, [=](std::uintptr_t task) {
        const std::uintptr_t last = std::min(pages, (task + 1) * kPagesPerTask);
        for (std::uintptr_t page = task * kPagesPerTask; page < last; ++page)
            *reinterpret_cast<volatile char*>(std::max(begin, (firstPage + page) * kPage)) = 0;
    });
    return block;
}

}  // namespace ivis::core
