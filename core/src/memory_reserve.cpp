#include <ivis/core/memory_reserve.h>

#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <new>

namespace ivis::core {
namespace {

std::mutex gMutex;                   // guards gUsers and gPrevious
int gUsers = 0;                      // ScopedMemoryReserve objects alive
std::new_handler gPrevious = nullptr;
std::atomic<void*> gBlock{nullptr};  // the reserve, until a failed allocation frees it

/// The new-handler: frees the reserve; retries the allocation when a destructor asks during an
/// unwinding, else throws (the unwinding that follows has the freed room).
void onAllocationFailure()
{
    if (void* block = gBlock.exchange(nullptr)) {
        std::free(block);
        if (std::uncaught_exceptions() > 0) return;
    }
    throw std::bad_alloc();
}

}  // namespace

ScopedMemoryReserve::ScopedMemoryReserve(std::size_t bytes)
{
    const std::lock_guard<std::mutex> lock(gMutex);
    if (gUsers++ > 0) return;
    gBlock = std::malloc(bytes);  // untouched: address space only, no resident pages
    gPrevious = std::set_new_handler(onAllocationFailure);
}

ScopedMemoryReserve::~ScopedMemoryReserve()
{
    const std::lock_guard<std::mutex> lock(gMutex);
    if (--gUsers > 0) return;
    std::set_new_handler(gPrevious);
    std::free(gBlock.exchange(nullptr));
}

}  // namespace ivis::core
