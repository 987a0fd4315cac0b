/// @file vtk_files.h
/// @brief Writes VTK XML files (.vtp, .vtu) in every layout the readers accept, for tests and the
///        read benchmark: ASCII, inline base64, appended raw or base64, zlib blocks, UInt32 or
///        UInt64 headers, either byte order, any numeric type.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ivis::test {

/// How the file stores its data.
struct VtkXmlLayout {
    enum Format { Ascii, Binary, AppendedRaw, AppendedBase64 } format = Binary;
    bool zlib = false;
    bool header64 = false;          ///< header_type="UInt64"
    bool bigEndian = false;         ///< byte_order="BigEndian"
    std::size_t blockSize = 32768;  ///< uncompressed bytes per zlib block
    bool oneBase64Run = false;      ///< header and data in one base64 run (VTK writes two)
};

/// One DataArray: tuples of @a components values of the VTK type @a type ("Float32", "Int64").
struct VtkArray {
    std::string name;
    std::string type = "Float32";
    int components = 1;
    std::vector<double> values;
};

/// Cells as VTK's XML files store them: connectivity and the end offset of each cell.
struct VtkCells {
    std::vector<std::int64_t> connectivity;
    std::vector<std::int64_t> offsets;
    std::vector<std::int64_t> types;  ///< UnstructuredGrid only: VTK cell type of each cell
};

/// A one-piece data set: PolyData (verts, lines, polys, strips) or UnstructuredGrid (cells).
struct VtkDataSet {
    std::vector<double> points;  ///< x y z per point
    std::string pointType = "Float32";
    std::string indexType = "Int64";  ///< connectivity and offsets
    VtkCells verts, lines, polys, strips, cells;
    std::vector<VtkArray> pointData, cellData;
};

/// The text of a .vtp file (PolyData) holding @a data.
std::string vtpText(const VtkDataSet& data, const VtkXmlLayout& layout);

/// The text of a .vtu file (UnstructuredGrid) holding @a data.
std::string vtuText(const VtkDataSet& data, const VtkXmlLayout& layout);

/// Standard base64 with '=' padding.
std::string base64(const std::string& bytes);

/// @a values as binary values of the VTK type @a type ("Float64"), in the given byte order.
std::string vtkBytes(const std::vector<double>& values, const std::string& type, bool bigEndian);

}  // namespace ivis::test
