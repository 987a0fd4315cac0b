#include <ivis/core/huge_page_allocator.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace ivis::core {
namespace {

// Blocks of 2 MiB and more start on a huge-page boundary (so madvise can back them with huge
// pages); smaller ones are ordinary heap blocks. Either way every value can be written and read.
TEST(HugePageAllocator, LargeBlocksStartOnAHugePageAndHoldTheirValues)
{
    const std::size_t hugePage = std::size_t(2) << 20;
    for (std::size_t count : {std::size_t(1), std::size_t(1000), hugePage / sizeof(float) + 7, std::size_t(3) * hugePage}) {
        std::vector<float, HugePageAllocator<float>> values(count);
        if (count * sizeof(float) >= hugePage) {
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % hugePage, 0u) << count;
        }
        std::iota(values.begin(), values.end(), 0.0f);
        EXPECT_EQ(values.back(), float(count - 1)) << count;
    }
    const HugePageArray<std::uint32_t> array = makeHugePageArray<std::uint32_t>(hugePage);
    for (std::size_t i = 0; i < hugePage; ++i) array[i] = std::uint32_t(i);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(array.get()) % hugePage, 0u);
    EXPECT_EQ(array[hugePage - 1], hugePage - 1);
}

}  // namespace
}  // namespace ivis::core
