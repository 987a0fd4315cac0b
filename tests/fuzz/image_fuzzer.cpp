// libFuzzer target: the picture readers (core::readPng, core::readExrChannel and
// core::readExrMeshUnits: the tests read back what `render` writes) on arbitrary bytes, written to
// a temporary file as libpng and OpenEXR read files. Built twice: IVIS_FUZZ_EXR set for the EXR
// readers, unset for the PNG one.
#include "fuzz_check.h"

#include <ivis/core/image_io.h>

#include <unistd.h>

#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
#ifdef IVIS_FUZZ_EXR
    static const std::string path = "/tmp/ivis_exr_fuzzer." + std::to_string(::getpid()) + ".exr";
#else
    static const std::string path = "/tmp/ivis_png_fuzzer." + std::to_string(::getpid()) + ".png";
#endif
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    ivis::fuzz::checkReader(data, size, [](const std::string&) {
#ifdef IVIS_FUZZ_EXR
        ivis::core::readExrMeshUnits(path);
        ivis::core::readExrChannel(path, "R");
#else
        ivis::core::readPng(path);
#endif
    });
    return 0;
}
