// libFuzzer target: the VTK legacy reader (.vtk) on arbitrary bytes.
#include "fuzz_check.h"

#include <ivis/core/mesh_formats.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size,
                            [](std::string bytes) { ivis::core::detail::readVtkLegacy("fuzz.vtk", std::move(bytes)); });
    return 0;
}
