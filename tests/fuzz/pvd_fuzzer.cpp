// libFuzzer target: the ParaView collection reader (.pvd) on arbitrary bytes.
#include "fuzz_check.h"

#include <ivis/core/pvd_reader.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size, [](std::string bytes) { ivis::core::detail::parsePvd("fuzz.pvd", std::move(bytes)); });
    return 0;
}
