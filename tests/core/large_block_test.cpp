#include <ivis/core/large_block.h>

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace ivis::core {
namespace {

// Every block starts on a cache line, and every value can be written and read.
TEST(LargeBlockAllocator, BlocksStartOnACacheLineAndHoldTheirValues)
{
    for (std::size_t count : {std::size_t(1), std::size_t(1000), kFaultInFrom / sizeof(float) + 7, 3 * kFaultInFrom}) {
        std::vector<float, LargeBlockAllocator<float>> values(count);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % kLargeBlockAlignment, 0u) << count;
        std::iota(values.begin(), values.end(), 0.0f);
        EXPECT_EQ(values.back(), float(count - 1)) << count;
    }
    const LargeBlockArray<std::uint32_t> array = makeLargeBlockArray<std::uint32_t>(kFaultInFrom);
    for (std::size_t i = 0; i < kFaultInFrom; ++i) array[i] = std::uint32_t(i);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(array.get()) % kLargeBlockAlignment, 0u);
    EXPECT_EQ(array[kFaultInFrom - 1], kFaultInFrom - 1);
    // A size whose rounding up to the alignment would wrap round is refused, not served small.
    EXPECT_THROW(allocateLarge(std::size_t(-1) - 10), std::bad_alloc);
    EXPECT_THROW(LargeBlockAllocator<double>().allocate(std::size_t(-1) / 4), std::bad_alloc);
}

// A large block comes with every page of it resident (faulted in before it is returned), as the
// kernel reports them (mincore), the first and the last partial page included.
TEST(LargeBlockAllocator, LargeBlocksAreFaultedInWhole)
{
    const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
    for (std::size_t bytes : {kFaultInFrom, 5 * kFaultInFrom + 12345}) {
        const LargeBlockArray<char> block = makeLargeBlockArray<char>(bytes);
        const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(block.get()) / page * page;
        const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(block.get()) + bytes - 1) / page * page;
        const std::size_t pages = (last - first) / page + 1;
        std::vector<unsigned char> resident(pages);
        ASSERT_EQ(mincore(reinterpret_cast<void*>(first), pages * page, resident.data()), 0) << bytes;
        std::size_t missing = 0;
        for (const unsigned char r : resident) missing += (r & 1) ? 0 : 1;
        EXPECT_EQ(missing, 0u) << bytes << " bytes, " << pages << " pages";
    }
}

}  // namespace
}  // namespace ivis::core
