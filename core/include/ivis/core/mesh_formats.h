/// @file mesh_formats.h
/// @brief The registry of mesh file formats: one reader per extension, each turning the bytes of
///        a file into a RawMesh.
/// @note Internal to readMesh. Adding a format = one reader file plus one row in mesh_formats.cpp.
#pragma once

#include <ivis/core/raw_mesh.h>

#include <string>
#include <vector>

namespace ivis::core::detail {

/// Reads the bytes @a data of the file @a path; every failure is an InputError "<path>: <problem>".
using MeshFileReader = RawMesh (*)(const std::string& path, std::string data);

/// One registered format.
struct MeshFileFormat {
    const char* extension;  ///< lower case with its dot: ".vtp"
    const char* name;       ///< what `info` calls it: "vtp"
    MeshFileReader read;
};

/// Every registered format, in the order they are listed to users.
const std::vector<MeshFileFormat>& meshFileFormats();

/// The format of @a path by its extension (case-insensitive), or null when none is registered.
const MeshFileFormat* findMeshFileFormat(const std::string& path);

/// The format of @a path by its extension (case-insensitive).
/// @throw InputError "<path>: unknown mesh format '.xyz' (expected .obj, .off, ...)"
const MeshFileFormat& meshFileFormat(const std::string& path);

/// VTK legacy `.vtk` files, ASCII or binary: POLYDATA and UNSTRUCTURED_GRID (vtk_legacy_reader.cpp).
RawMesh readVtkLegacy(const std::string& path, std::string data);

/// VTK XML `.vtp` (PolyData) and `.vtu` (UnstructuredGrid) files (vtk_xml_reader.cpp).
RawMesh readVtkXml(const std::string& path, std::string data);

}  // namespace ivis::core::detail
