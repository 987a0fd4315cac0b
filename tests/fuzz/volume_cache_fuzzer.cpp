// libFuzzer target: the .vdb volume cache's content checksum on arbitrary bytes (written to a
// temporary file, since OpenVDB reads files). The checksum is what stands between damaged bytes and
// OpenVDB's reader, which trusts the sizes in a file: bytes whose checksum matches are a cache
// inversevis wrote, or one crafted to look like one (libFuzzer does that, copying the computed hash
// into the trailer from the comparison), and go no further here (tests/fuzz/README.md).
#include "fuzz_check.h"

#include <ivis/vdb/volume_cache.h>

#include <unistd.h>

#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const std::string path = "/tmp/ivis_volume_cache_fuzzer." + std::to_string(::getpid()) + ".vdb";
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    ivis::fuzz::checkReader(data, size, [](const std::string&) { ivis::vdb::checkVolumeChecksum(path); });
    return 0;
}
