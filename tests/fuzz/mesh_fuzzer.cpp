// libFuzzer target: one OpenMesh-backed mesh reader (layout check, then OpenMesh) on arbitrary
// bytes; built once per format with IVIS_FUZZ_FORMAT = Obj, Off, Ply or Stl and IVIS_FUZZ_PATH a
// file name with that format's extension.
#include "fuzz_check.h"

#include <ivis/core/raw_mesh_import.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size, [](std::string bytes) {
        ivis::core::detail::readOpenMeshFile(IVIS_FUZZ_PATH, ivis::core::detail::MeshFormat::IVIS_FUZZ_FORMAT, std::move(bytes));
    });
    return 0;
}
