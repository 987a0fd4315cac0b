// VTK XML PolyData (.vtp) and UnstructuredGrid (.vtu): one piece, its points, cells and every
// numeric PointData and CellData array.
#include <ivis/core/mesh_formats.h>

#include "value_decoding.h"
#include "vtk_cells.h"
#include "vtk_xml_data_array.h"

#include <ivis/core/mesh_layout_check.h>

#include <pugixml.hpp>

#include <cctype>
#include <charconv>
#include <cstring>

namespace ivis::core::detail {
namespace {

/// Moves what follows the '_' of <AppendedData> out of the XML: raw appended data is not XML. The
/// data ends at the file's last </AppendedData> (an array that says it holds more ends early, not
/// in the closing tags), or at the file's end when the file was cut before it.
/// Returns the XML text to parse (the file up to the <AppendedData> tag, closed again).
std::string splitAppended(const std::string& path, const std::string& data, VtkXmlEncoding& encoding)
{
    const std::size_t tag = data.find("<AppendedData");
    if (tag == std::string::npos) return {};
    const std::size_t tagEnd = data.find('>', tag);
    if (tagEnd == std::string::npos) failInput(path, "the <AppendedData> tag is not closed");
    std::size_t underscore = tagEnd + 1;
    while (underscore < data.size() && std::isspace(static_cast<unsigned char>(data[underscore]))) ++underscore;
    if (underscore == data.size() || data[underscore] != '_') failInput(path, "AppendedData does not start with '_'");
    const std::size_t closing = data.rfind("</AppendedData>");
    const std::size_t end = closing != std::string::npos && closing > underscore ? closing : data.size();
    encoding.appended = std::string_view(data).substr(underscore + 1, end - underscore - 1);
    return data.substr(0, tagEnd + 1) + "</AppendedData></VTKFile>";
}

std::size_t countOf(const std::string& path, const pugi::xml_node& node, const char* name, bool required)
{
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) {
        if (required) failInput(path, std::string(node.name()) + " has no " + name);
        return 0;
    }
    const std::string_view text = attribute.value();
    std::size_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value > 0xFFFFFFFEull) {
        failInput(path, std::string(name) + " '" + std::string(text) + "' is not a count");
    }
    return value;
}

/// The child <DataArray Name="name"> of @a parent.
pugi::xml_node namedArray(const std::string& path, const pugi::xml_node& parent, const char* name)
{
    const pugi::xml_node node = parent.find_child_by_attribute("DataArray", "Name", name);
    if (!node) failInput(path, std::string(parent.name()) + " has no DataArray '" + name + "'");
    return node;
}

class PieceReader {
public:
    PieceReader(const std::string& path, const VtkXmlEncoding& encoding, const pugi::xml_node& piece)
        : mPath(path), mEncoding(encoding), mPiece(piece)
    {
    }

    RawMesh read(bool polyData)
    {
        const std::size_t points = countOf(mPath, mPiece, "NumberOfPoints", true);
        readPoints(points);
        VtkCellSurface surface(mPath, points);
        std::size_t cells = 0;
        if (polyData) {
            // vtkPolyData numbers its cells verts, lines, polys, strips.
            const std::pair<const char*, std::uint8_t> kBlocks[] = {
                {"Verts", 2}, {"Lines", 4}, {"Polys", 7}, {"Strips", 6}};
            for (const auto& [block, type] : kBlocks) {
                const std::size_t count = countOf(mPath, mPiece, (std::string("NumberOf") + block).c_str(), false);
                if (count > 0) surface.add(cellBlock(block, count, &type), cells, block);
                cells += count;
            }
        } else {
            cells = countOf(mPath, mPiece, "NumberOfCells", true);
            surface.add(cellBlock("Cells", cells, nullptr), 0, "Cells");
        }
        surface.finish(mMesh, cells);
        readArrays("PointData", Association::Point, points, "NumberOfPoints");
        readArrays("CellData", Association::Cell, cells,
                   polyData ? "NumberOfVerts+Lines+Polys+Strips" : "NumberOfCells");
        return std::move(mMesh);
    }

private:
    void readPoints(std::size_t count)
    {
        if (count == 0) return;
        const pugi::xml_node node = mPiece.child("Points").child("DataArray");
        if (!node) failInput(mPath, "the piece has " + std::to_string(count) + " points but no <Points> DataArray");
        const DataArray points = readVtkXmlDataArray(mPath, "Points", node, mEncoding, count, "NumberOfPoints");
        if (points.components != 3)
            failInput(mPath, "Points have " + std::to_string(points.components) + " components, not 3");
        mMesh.positions.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const double* xyz = &points.values[3 * i];
            mMesh.positions[i] = detail::storedPoint(xyz[0], xyz[1], xyz[2], points.type);
        }
    }

    /// The @a count cells of <@a block>: all of type @a *uniformType, or of the types its "types" array gives.
    VtkCellArray cellBlock(const char* block, std::size_t count, const std::uint8_t* uniformType)
    {
        const pugi::xml_node node = mPiece.child(block);
        if (!node)
            failInput(mPath,
                      "the piece has " + std::to_string(count) + " cells in " + block + " but no <" + block + ">");
        const std::string where = std::string(block) + " ";
        VtkCellArray cells;
        const std::vector<std::int64_t> ends = toIndices(
            mPath, where + "offsets", cellValues(node, where + "offsets", count, std::string("NumberOf") + block));
        cells.offsets.insert(cells.offsets.end(), ends.begin(), ends.end());
        if (cells.offsets.back() < 0) failInput(mPath, where + "offsets: the last offset is negative");
        const std::size_t corners = std::size_t(cells.offsets.back());
        cells.connectivity = toIndices(mPath, where + "connectivity",
                                       cellValues(node, where + "connectivity", corners, "the last offset"));
        if (uniformType != nullptr) {
            cells.types.assign(count, *uniformType);
            return cells;
        }
        cells.types = toCellTypes(mPath, cellValues(node, where + "types", count, "NumberOfCells"));
        return cells;
    }

    /// The values of the one-component DataArray of @a block named by the last word of @a what.
    std::vector<double> cellValues(const pugi::xml_node& block, const std::string& what, std::size_t expected,
                                   const std::string& declaredBy)
    {
        const std::string name = what.substr(what.rfind(' ') + 1);
        const DataArray array =
            readVtkXmlDataArray(mPath, what, namedArray(mPath, block, name.c_str()), mEncoding, expected, declaredBy);
        if (array.components != 1) {
            failInput(mPath, what + ": " + std::to_string(array.components) + " components, not 1");
        }
        return array.values;
    }

    void readArrays(const char* section, Association association, std::size_t tuples, const std::string& declaredBy)
    {
        int index = 0;
        const std::string active = mPiece.child(section).attribute("Scalars").value();
        bool activeFound = false;
        for (const pugi::xml_node& node : mPiece.child(section).children("DataArray")) {
            std::string name = node.attribute("Name").value();
            if (name.empty()) name = std::string(associationName(association)) + "_array_" + std::to_string(index);
            ++index;
            const std::string what = std::string(section) + " array '" + name + "'";
            if (!vtkXmlValueType(node.attribute("type").value())) {
                mMesh.notes.push_back("left out " + what + " of type " + node.attribute("type").value() +
                                      ": only numeric arrays are read");
                continue;
            }
            DataArray array = readVtkXmlDataArray(mPath, what, node, mEncoding, tuples, declaredBy);
            checkValuesFitType(mPath, what, array);
            array.name = name;
            array.association = association;
            array.activeScalars = !activeFound && !active.empty() && name == active;
            activeFound = activeFound || array.activeScalars;
            mMesh.arrays.push_back(std::move(array));
        }
    }

    const std::string& mPath;
    const VtkXmlEncoding& mEncoding;
    const pugi::xml_node mPiece;
    RawMesh mMesh;
};

}  // namespace

RawMesh readVtkXml(const std::string& path, std::string data)
{
    VtkXmlEncoding encoding;
    std::string xml = splitAppended(path, data, encoding);
    std::string& text = xml.empty() ? data : xml;
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_buffer_inplace(text.data(), text.size());
    if (!parsed) {
        failInput(path, std::string("not valid XML (") + parsed.description() + " at byte " +
                            std::to_string(parsed.offset) + ")");
    }
    const pugi::xml_node root = document.child("VTKFile");
    if (!root) failInput(path, "not a VTK XML file (no <VTKFile> element)");
    const std::string type = root.attribute("type").value();
    if (type != "PolyData" && type != "UnstructuredGrid") {
        failInput(path, "VTK XML type '" + type + "' is not read (PolyData and UnstructuredGrid are)");
    }
    const std::string byteOrder = root.attribute("byte_order").as_string("LittleEndian");
    if (byteOrder != "LittleEndian" && byteOrder != "BigEndian")
        failInput(path, "byte_order '" + byteOrder + "' is unknown");
    encoding.bigEndian = byteOrder == "BigEndian";
    const std::string header = root.attribute("header_type").as_string("UInt32");
    if (header != "UInt32" && header != "UInt64")
        failInput(path, "header_type '" + header + "' is not UInt32 or UInt64");
    encoding.headerBytes = header == "UInt64" ? 8 : 4;
    const std::string compressor = root.attribute("compressor").value();
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor") {
        failInput(path, "compressor '" + compressor + "' is not supported (vtkZLibDataCompressor is)");
    }
    encoding.zlib = !compressor.empty();
    if (encoding.appended.data() != nullptr) {
        const std::string appendedEncoding = root.child("AppendedData").attribute("encoding").as_string("raw");
        if (appendedEncoding != "raw" && appendedEncoding != "base64") {
            failInput(path, "AppendedData encoding '" + appendedEncoding + "' is not raw or base64");
        }
        encoding.appendedBase64 = appendedEncoding == "base64";
    }

    const pugi::xml_node dataset = root.child(type.c_str());
    if (!dataset) failInput(path, "the file's type is " + type + " but it holds no <" + type + "> element");
    const auto pieces = dataset.children("Piece");
    const std::size_t pieceCount = std::size_t(std::distance(pieces.begin(), pieces.end()));
    if (pieceCount != 1) {
        failInput(path,
                  "the " + type + " has " + std::to_string(pieceCount) + " pieces; files with one piece are read");
    }
    return PieceReader(path, encoding, *pieces.begin()).read(type == "PolyData");
}

}  // namespace ivis::core::detail
