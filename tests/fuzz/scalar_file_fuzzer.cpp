// libFuzzer target: the --scalar-file sidecar reader on arbitrary bytes (expecting 4 values).
#include "fuzz_check.h"

#include <ivis/core/mesh_reader.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size, [](std::string bytes) { ivis::core::detail::parseScalarFile("fuzz.txt", bytes, 4); });
    return 0;
}
