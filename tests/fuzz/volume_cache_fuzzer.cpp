// libFuzzer target: the .vdb volume cache reader on arbitrary bytes (written to a temporary file,
// since OpenVDB reads files).
#include "fuzz_check.h"

#include <ivis/vdb/volume_cache.h>

#include <unistd.h>

#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const std::string path = "/tmp/ivis_volume_cache_fuzzer." + std::to_string(::getpid()) + ".vdb";
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    ivis::fuzz::checkReader(data, size, [](const std::string&) { ivis::vdb::readVolume(path); });
    return 0;
}
