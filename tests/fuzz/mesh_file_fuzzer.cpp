// libFuzzer target: core::readMesh end to end on arbitrary bytes (written to a temporary file, as it
// reads files): the format's reader, then the conversion every reader's output goes through (the
// points a triangle uses, the file cell of each triangle, the array shown, its cells averaged onto
// the points), which the per-format targets stop before. The first byte chooses the format and
// what is shown; the rest is the file.
#include "fuzz_check.h"

#include <ivis/core/mesh_reader.h>

#include <unistd.h>

#include <array>
#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0) return 0;
    static constexpr std::array<const char*, 7> kExtensions = {".ply", ".obj", ".off", ".stl", ".vtk", ".vtp", ".vtu"};
    static const std::string stem = "/tmp/ivis_mesh_file_fuzzer." + std::to_string(::getpid());
    const std::uint8_t choice = data[0];
    const std::string path = stem + kExtensions[choice % kExtensions.size()];
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    ivis::core::MeshReadOptions options;
    const int shown = (choice / kExtensions.size()) % 4;  // none, or an array of the VTK seeds (vtk_fuzz_seeds.cpp)
    if (shown == 1) options.scalarName = "p";
    if (shown == 2) options.scalarName = "cell:c", options.cellToPoint = true;
    if (shown == 3) options.scalarName = "v:1";
    ivis::fuzz::checkReader(data, size, [&](const std::string&) { ivis::core::readMesh(path, options); });
    return 0;
}
