// libFuzzer target: the VTK XML reader (.vtp and .vtu) on arbitrary bytes.
#include "fuzz_check.h"

#include <ivis/core/mesh_formats.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size, [](std::string bytes) { ivis::core::detail::readVtkXml("fuzz.vtp", std::move(bytes)); });
    return 0;
}
