// VTK legacy .vtk files, ASCII or binary (big-endian): POLYDATA and UNSTRUCTURED_GRID with every
// numeric or bit POINT_DATA and CELL_DATA array, cells in the classic layout ("n size" with a count
// before each cell) or the one of file version 5 (OFFSETS and CONNECTIVITY).
#include <ivis/core/mesh_formats.h>

#include "value_decoding.h"
#include "vtk_cells.h"
#include "vtk_legacy_cursor.h"
#include "vtk_xml_data_array.h"

#include <ivis/core/mesh_layout_check.h>

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>

namespace ivis::core::detail {
namespace {

std::string lower(std::string text)
{
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

/// A legacy data type name as a value type ("float", "vtktypeint64"), or nothing.
std::optional<ValueType> legacyType(const std::string& name)
{
    static const std::map<std::string, ValueType> kTypes = {{"char", ValueType::Int8},
                                                            {"unsigned_char", ValueType::UInt8},
                                                            {"short", ValueType::Int16},
                                                            {"unsigned_short", ValueType::UInt16},
                                                            {"int", ValueType::Int32},
                                                            {"unsigned_int", ValueType::UInt32},
                                                            {"long", ValueType::Int64},
                                                            {"unsigned_long", ValueType::UInt64},
                                                            {"vtkidtype", ValueType::Int64},
                                                            {"vtktypeint64", ValueType::Int64},
                                                            {"vtktypeuint64", ValueType::UInt64},
                                                            {"float", ValueType::Float32},
                                                            {"double", ValueType::Float64}};
    const auto it = kTypes.find(lower(name));
    if (it == kTypes.end()) return std::nullopt;
    return it->second;
}

/// Legacy names encode spaces and other bytes as %XX.
std::string decodeName(const std::string& name)
{
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        int byte = 0;
        if (name[i] == '%' && i + 2 < name.size() &&
            std::from_chars(name.data() + i + 1, name.data() + i + 3, byte, 16).ptr == name.data() + i + 3) {
            out += char(byte);
            i += 2;
        } else {
            out += name[i];
        }
    }
    return out;
}

class LegacyReader {
public:
    LegacyReader(const std::string& path, const std::string& data) : mPath(path), mIn(path, data) {}

    RawMesh read()
    {
        readHeader();
        for (std::vector<std::string> w = mIn.words(); !w.empty(); w = mIn.words()) section(w);
        VtkCellSurface surface(mPath, mMesh.positions.size());
        std::size_t first = 0;
        for (const auto& [order, block] : mBlocks) {
            surface.add(block.second, first, block.first);
            first += block.second.size();
        }
        surface.finish(mMesh, first);
        return std::move(mMesh);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { failInput(mPath, problem); }

    void readHeader()
    {
        const std::string magic = lower(std::string(mIn.line()));
        if (magic.rfind("# vtk datafile version", 0) != 0)
            fail("not a VTK legacy file (no '# vtk DataFile Version' line)");
        mIn.line();  // title
        const std::vector<std::string> format = mIn.words();
        const std::string encoding = format.empty() ? "" : lower(format[0]);
        if (encoding != "ascii" && encoding != "binary") fail("the third line is not ASCII or BINARY");
        mIsBinary = encoding == "binary";
        mIn.setBinary(mIsBinary);
        const std::vector<std::string> dataset = mIn.words();
        if (dataset.size() < 2 || lower(dataset[0]) != "dataset") fail("no DATASET line after the header");
        mDataset = lower(dataset[1]);
        if (mDataset != "polydata" && mDataset != "unstructured_grid") {
            fail("DATASET " + dataset[1] + " is not read (POLYDATA and UNSTRUCTURED_GRID are)");
        }
    }

    std::size_t count(const std::vector<std::string>& w, std::size_t i) const
    {
        if (i >= w.size()) fail(w[0] + ": the line ends before its counts");
        std::size_t value = 0;
        const std::string& text = w[i];
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size() || value > 0xFFFFFFFEull) {
            fail(w[0] + ": '" + text + "' is not a count");
        }
        return value;
    }

    ValueType type(const std::vector<std::string>& w, std::size_t i) const
    {
        if (i >= w.size()) fail(w[0] + ": the line ends before its data type");
        const std::optional<ValueType> t = legacyType(w[i]);
        if (!t) fail(w[0] + ": data type '" + w[i] + "' is not a numeric type");
        return *t;
    }

    /// A data array's type: a numeric type, or VTK's `bit`, whose 0s and 1s are read as UInt8.
    struct ArrayType {
        ValueType type = ValueType::UInt8;
        bool bits = false;
    };

    ArrayType arrayType(const std::vector<std::string>& w, std::size_t i) const
    {
        if (i < w.size() && lower(w[i]) == "bit") return {ValueType::UInt8, true};
        return {type(w, i), false};
    }

    std::vector<double> arrayValues(std::size_t count, ArrayType t, const std::string& what)
    {
        return t.bits ? mIn.bits(count, what) : mIn.values(count, t.type, what);
    }

    void section(const std::vector<std::string>& w)
    {
        const std::string key = lower(w[0]);
        if (key == "points") {
            const std::size_t n = count(w, 1);
            const ValueType pointType = type(w, 2);
            const std::vector<double> xyz = mIn.values(3 * n, pointType, "POINTS");
            mMesh.positions.resize(n);
            for (std::size_t i = 0; i < n; ++i)
                mMesh.positions[i] = detail::storedPoint(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], pointType);
        } else if (mDataset == "polydata" &&
                   (key == "vertices" || key == "lines" || key == "polygons" || key == "triangle_strips")) {
            static const std::map<std::string, std::pair<int, std::uint8_t>> kBlocks = {
                {"vertices", {0, 2}}, {"lines", {1, 4}}, {"polygons", {2, 7}}, {"triangle_strips", {3, 6}}};
            const auto [order, cellType] = kBlocks.at(key);
            VtkCellArray cells = cellArray(w);
            cells.types.assign(cells.size(), cellType);
            addBlock(order, w[0], std::move(cells));
        } else if (mDataset == "unstructured_grid" && key == "cells") {
            mCells = cellArray(w);
        } else if (mDataset == "unstructured_grid" && key == "cell_types") {
            cellTypes(w);
        } else if (key == "point_data" || key == "cell_data") {
            attributeSection(w, key == "point_data" ? Association::Point : Association::Cell);
        } else if (key == "field") {
            fieldArrays(w);
        } else if (key == "scalars" || key == "vectors" || key == "normals" || key == "tensors" || key == "tensors6" ||
                   key == "texture_coordinates" || key == "global_ids" || key == "pedigree_ids" ||
                   key == "color_scalars") {
            attribute(w, key);
        } else if (key == "lookup_table") {
            const std::size_t n = count(w, 2);
            mIn.values(4 * n, mIsBinary ? ValueType::UInt8 : ValueType::Float32, "LOOKUP_TABLE");
        } else if (key == "metadata") {
            skipMetadataLines();
        } else {
            double number = 0.0;
            const bool isNumber = std::from_chars(w[0].data(), w[0].data() + w[0].size(), number).ptr != w[0].data();
            fail("'" + w[0] + "' is not a section of a " + mDataset + " file" +
                 (isNumber ? " (a section holds more values than its header says)" : ""));
        }
    }

    /// A cell list: "KEY n size" then n counted cells, or "KEY n+1 m" then OFFSETS and CONNECTIVITY.
    VtkCellArray cellArray(const std::vector<std::string>& w)
    {
        const std::size_t n = count(w, 1), size = count(w, 2);
        VtkCellArray cells;
        if (mIn.peekWord() == "offsets") {
            const std::vector<std::string> offsets = mIn.words();
            cells.offsets = toIndices(mPath, w[0] + " OFFSETS", mIn.values(n, type(offsets, 1), w[0] + " OFFSETS"));
            if (cells.offsets.empty()) cells.offsets.push_back(0);
            const std::vector<std::string> connectivity = mIn.words();
            if (connectivity.empty() || lower(connectivity[0]) != "connectivity")
                fail(w[0] + ": OFFSETS are not followed by CONNECTIVITY");
            cells.connectivity = toIndices(mPath, w[0] + " CONNECTIVITY",
                                           mIn.values(size, type(connectivity, 1), w[0] + " CONNECTIVITY"));
            return cells;
        }
        const std::vector<std::int64_t> list = toIndices(mPath, w[0], mIn.values(size, ValueType::Int32, w[0]));
        std::size_t i = 0;
        for (std::size_t c = 0; c < n; ++c) {
            if (i == list.size())
                fail(w[0] + ": the list of " + std::to_string(size) + " values ends within cell " + std::to_string(c));
            const std::int64_t corners = list[i++];
            if (corners < 0 || std::uint64_t(corners) > list.size() - i) {
                fail(w[0] + ": cell " + std::to_string(c) + " has " + std::to_string(corners) +
                     " points, more than the list holds");
            }
            cells.connectivity.insert(cells.connectivity.end(), list.begin() + std::ptrdiff_t(i),
                                      list.begin() + std::ptrdiff_t(i + std::size_t(corners)));
            i += std::size_t(corners);
            cells.offsets.push_back(std::int64_t(cells.connectivity.size()));
        }
        if (i != list.size()) {
            fail(w[0] + ": " + std::to_string(n) + " cells use " + std::to_string(i) + " values, but the header says " +
                 std::to_string(size));
        }
        return cells;
    }

    void cellTypes(const std::vector<std::string>& w)
    {
        const std::size_t n = count(w, 1);
        if (!mCells) fail("CELL_TYPES come before CELLS");
        if (n != mCells->size()) {
            fail("CELL_TYPES lists " + std::to_string(n) + " cells, but CELLS has " + std::to_string(mCells->size()));
        }
        mCells->types = toCellTypes(mPath, mIn.values(n, ValueType::Int32, "CELL_TYPES"));
        addBlock(0, "CELLS", std::move(*mCells));
        mCells.reset();
    }

    void addBlock(int order, const std::string& what, VtkCellArray cells)
    {
        if (mBlocks.count(order)) fail(what + " appears twice");
        mCellCount += cells.size();
        mBlocks.emplace(order, std::make_pair(what, std::move(cells)));
    }

    void attributeSection(const std::vector<std::string>& w, Association association)
    {
        if (mCells) fail("CELLS are not followed by CELL_TYPES");
        const std::size_t n = count(w, 1);
        const std::size_t expected = association == Association::Point ? mMesh.positions.size() : mCellCount;
        if (n != expected) {
            fail(w[0] + " " + std::to_string(n) + " disagrees with the file's " + std::to_string(expected) +
                 (association == Association::Point ? " points" : " cells"));
        }
        mAssociation = association;
        mTuples = n;
        mActiveScalarsRead = false;
    }

    void addArray(std::string name, ArrayType type, std::size_t components, const std::string& what)
    {
        if (!mAssociation) fail(what + " comes before POINT_DATA or CELL_DATA");
        if (components < 1 || components > 1024) fail(what + ": " + std::to_string(components) + " components");
        DataArray array{decodeName(name), *mAssociation, type.type, int(components), {}};
        array.values = arrayValues(mTuples * std::size_t(components), type, what);
        checkValuesFitType(mPath, what, array);
        mMesh.arrays.push_back(std::move(array));
    }

    void attribute(const std::vector<std::string>& w, const std::string& key)
    {
        if (w.size() < 2) fail(w[0] + ": the line ends before the array's name");
        const std::string what = w[0] + " " + w[1];
        if (key == "color_scalars") {
            addArray(w[1], {mIsBinary ? ValueType::UInt8 : ValueType::Float32}, count(w, 2), what);
            // vtkDataReader sets COLOR_SCALARS as the section's scalars too, the first of either.
            mMesh.arrays.back().activeScalars = !mActiveScalarsRead;
            mActiveScalarsRead = true;
        } else if (key == "texture_coordinates") {
            addArray(w[1], arrayType(w, 3), count(w, 2), what);
        } else if (key == "scalars") {
            const std::size_t components = w.size() > 3 ? count(w, 3) : 1;
            if (components < 1 || components > 4)
                fail(what + ": " + std::to_string(components) + " components (1 to 4 allowed)");
            if (mIn.peekWord() == "lookup_table") mIn.words();
            addArray(w[1], arrayType(w, 2), components, what);
            // vtkDataReader makes the section's first SCALARS (or COLOR_SCALARS) its active scalars.
            mMesh.arrays.back().activeScalars = !mActiveScalarsRead;
            mActiveScalarsRead = true;
        } else {
            const std::size_t components = key == "tensors"                               ? 9
                                   : key == "tensors6"                            ? 6
                                   : key == "global_ids" || key == "pedigree_ids" ? 1
                                                                                  : 3;
            addArray(w[1], arrayType(w, 2), components, what);
        }
    }

    /// The lines of a METADATA block (component names, information keys) after its keyword, up to
    /// the empty line that ends it: read past.
    void skipMetadataLines()
    {
        while (!mIn.atEnd() && !mIn.line().empty()) {
        }
    }

    /// "FIELD name n" and n arrays "name components tuples type", each maybe followed by a METADATA
    /// block (as ParaView 5 writes them); outside POINT_DATA and CELL_DATA these belong to the
    /// dataset and are read past.
    void fieldArrays(const std::vector<std::string>& w)
    {
        const std::size_t n = count(w, 2);
        for (std::size_t a = 0; a < n; ++a) {
            const std::vector<std::string> header = mIn.words();
            if (header.empty()) fail("FIELD " + w[1] + ": the file ends before array " + std::to_string(a));
            if (header[0] == "NULL_ARRAY") continue;
            const std::string what = "FIELD array " + header[0];
            if (header.size() < 4) fail(what + ": the line ends before its data type");
            const std::size_t components = count(header, 1), tuples = count(header, 2);
            if (components < 1 || components > 1024) fail(what + ": " + std::to_string(components) + " components");
            const ArrayType t = arrayType(header, 3);
            if (!mAssociation) {
                arrayValues(components * tuples, t, what);
            } else {
                if (tuples != mTuples) {
                    fail(what + " has " + std::to_string(tuples) + " tuples, but " +
                         (*mAssociation == Association::Point ? "POINT_DATA" : "CELL_DATA") + " says " +
                         std::to_string(mTuples));
                }
                addArray(header[0], t, components, what);
            }
            if (mIn.peekWord() == "metadata") {
                mIn.words();
                skipMetadataLines();
            }
        }
    }

    const std::string& mPath;
    VtkLegacyCursor mIn;
    std::string mDataset;
    bool mIsBinary = false;
    RawMesh mMesh;
    std::map<int, std::pair<std::string, VtkCellArray>> mBlocks;  ///< by VTK's cell order
    std::optional<VtkCellArray> mCells;                           ///< CELLS waiting for CELL_TYPES
    std::size_t mCellCount = 0;
    std::optional<Association> mAssociation;
    std::size_t mTuples = 0;
    bool mActiveScalarsRead = false;  ///< whether the section's first SCALARS or COLOR_SCALARS came
};

}  // namespace

RawMesh readVtkLegacy(const std::string& path, std::string data)
{
    return LegacyReader(path, data).read();
}

}  // namespace ivis::core::detail
