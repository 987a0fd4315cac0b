// libFuzzer target: the camera file reader (--camera, a view file's "camera") on arbitrary bytes.
#include "fuzz_check.h"

#include <ivis/core/camera.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size,
                            [](std::string bytes) { ivis::core::detail::parseCameraJson("fuzz.json", bytes); });
    return 0;
}
