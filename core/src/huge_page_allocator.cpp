#include <ivis/core/huge_page_allocator.h>

#include <sys/mman.h>
#include <tbb/parallel_for.h>

namespace ivis::core {

void* allocateLarge(std::size_t bytes)
{
    constexpr std::size_t kHugePage = std::size_t(2) << 20;
    if (bytes < kHugePage) {
        void* block = std::malloc(bytes ? bytes : 1);
        if (!block) throw std::bad_alloc();
        return block;
    }
    const std::size_t pages = (bytes + kHugePage - 1) / kHugePage;
    void* block = std::aligned_alloc(kHugePage, pages * kHugePage);
    if (!block) throw std::bad_alloc();
    madvise(block, pages * kHugePage, MADV_HUGEPAGE);  // a hint: without THP, ordinary pages
    // Fault the pages in on every core: the kernel zeroes each one on first touch, which on a
    // virtual machine costs about as much as the caller's own fill.
    tbb::parallel_for(std::size_t(0), pages, [block](std::size_t page) {
        static_cast<volatile char*>(block)[page * kHugePage] = 0;
    });
    return block;
}

}  // namespace ivis::core
