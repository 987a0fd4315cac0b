#include <ivis/core/mesh_formats.h>

#include <ivis/core/file_extension.h>
#include <ivis/core/raw_mesh_import.h>

namespace ivis::core::detail {
namespace {

template <MeshFormat format>
RawMesh readWithOpenMesh(const std::string& path, std::string data)
{
    return readOpenMeshFile(path, format, std::move(data));
}

}  // namespace

const std::vector<MeshFileFormat>& meshFileFormats()
{
    static const std::vector<MeshFileFormat> kFormats = {
        {".obj", "obj", &readWithOpenMesh<MeshFormat::Obj>},
        {".off", "off", &readWithOpenMesh<MeshFormat::Off>},
        {".ply", "ply", &readWithOpenMesh<MeshFormat::Ply>},
        {".stl", "stl", &readWithOpenMesh<MeshFormat::Stl>},
        {".vtk", "vtk", &readVtkLegacy},
        {".vtp", "vtp", &readVtkXml},
        {".vtu", "vtu", &readVtkXml},
    };
    return kFormats;
}

const MeshFileFormat* findMeshFileFormat(const std::string& path)
{
    const std::string ext = lowerCaseExtension(path);
    for (const MeshFileFormat& format : meshFileFormats())
        if (ext == format.extension) return &format;
    return nullptr;
}

const MeshFileFormat& meshFileFormat(const std::string& path)
{
    if (const MeshFileFormat* format = findMeshFileFormat(path)) return *format;
    std::string known;
    for (const MeshFileFormat& format : meshFileFormats()) known += (known.empty() ? "" : ", ") + std::string(format.extension);
    failInput(path, "unknown mesh format '" + lowerCaseExtension(path) + "' (expected " + known + ")");
}

}  // namespace ivis::core::detail
