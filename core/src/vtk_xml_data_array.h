/// @file vtk_xml_data_array.h
/// @brief Reads the values of one <DataArray> of a VTK XML file: ASCII, inline base64 binary or
///        appended data (raw or base64), optionally zlib-compressed in blocks, with UInt32 or
///        UInt64 headers, in either byte order.
/// @note Internal to the VTK XML reader. Every failure is an InputError "<path>: <what>: <problem>".
#pragma once

#include <ivis/core/data_array.h>

#include <pugixml.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ivis::core::detail {

/// How the binary data of one file is stored (attributes of <VTKFile> and <AppendedData>).
struct VtkXmlEncoding {
    bool bigEndian = false;       ///< byte_order="BigEndian"
    std::size_t headerBytes = 4;  ///< header_type UInt32 (4, the default) or UInt64 (8)
    bool zlib = false;            ///< compressor="vtkZLibDataCompressor"
    std::string_view appended;    ///< the bytes after the '_' of <AppendedData>; empty without one
    bool appendedBase64 = false;  ///< <AppendedData encoding="base64">
};

/// The numeric type a DataArray's type attribute names ("Float32"), or nothing (String, Bit).
std::optional<ValueType> vtkXmlValueType(std::string_view name);

/// Reads the values of the DataArray @a node.
/// @param what names the array in messages ("Points", "PointData array 'pressure'")
/// @param expectedTuples the tuples the piece declares for it
/// @param declaredBy what declares that count, for messages ("NumberOfPoints")
/// @return name, type, components and values; the association is left to the caller
/// @throw InputError when the type is not numeric, the data is malformed (truncated base64, a
///        corrupt zlib block, a header past the end) or holds another number of tuples
DataArray readVtkXmlDataArray(const std::string& path, const std::string& what, const pugi::xml_node& node,
                              const VtkXmlEncoding& encoding, std::size_t expectedTuples,
                              const std::string& declaredBy);

/// @a values as indices: every one a whole number in the range of std::int64_t.
/// @throw InputError "<path>: <what>: value <v> at position <i> is not an index"
std::vector<std::int64_t> toIndices(const std::string& path, const std::string& what,
                                    const std::vector<double>& values);

}  // namespace ivis::core::detail
