/// @file raw_mesh_import.h
/// @brief Parses a mesh file with OpenMesh 9.0 into raw positions, faces and the numeric PLY
///        vertex and face properties, without half-edge topology, so no face is refused or dropped.
/// @note Internal to readMesh: OpenMesh's readers trust the counts and tokens of a file, so the
///       bytes pass checkMeshLayout first.
#pragma once

#include <ivis/core/mesh_layout_check.h>
#include <ivis/core/raw_mesh.h>

#include <string>

namespace ivis::core::detail {

/// Checks the layout of the bytes @a data of @a path, then reads them with OpenMesh (one import
/// at a time, its logging silenced), except an ASCII STL, whose mesh is built from the corners its
/// check read in double. PLY vertex and face properties of numeric types become point and cell
/// arrays; faces dropped for a repeated corner are counted in RawMesh::skippedFaces.
RawMesh readOpenMeshFile(const std::string& path, MeshFormat format, std::string data);

}  // namespace ivis::core::detail
