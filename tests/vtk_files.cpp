#include "vtk_files.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace ivis::test {
namespace {

template <typename T>
void put(std::string& out, double value, bool bigEndian)
{
    const T v = T(value);
    char raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    if (bigEndian) std::reverse(raw, raw + sizeof(T));
    out.append(raw, sizeof(T));
}

std::string header(std::uint64_t value, const VtkXmlLayout& layout)
{
    std::string out;
    if (layout.header64)
        put<std::uint64_t>(out, double(value), layout.bigEndian);
    else
        put<std::uint32_t>(out, double(value), layout.bigEndian);
    return out;
}

/// The blob of one array: header and data, compressed in blocks when asked; base64 runs as VTK
/// writes them (header and data encoded separately) unless oneBase64Run.
std::string blob(const std::string& data, const VtkXmlLayout& layout, bool encode)
{
    std::string head, body;
    if (!layout.zlib) {
        head = header(data.size(), layout);
        body = data;
    } else {
        const std::size_t blocks = (data.size() + layout.blockSize - 1) / layout.blockSize;
        head =
            header(blocks, layout) + header(layout.blockSize, layout) + header(data.size() % layout.blockSize, layout);
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::size_t size = std::min(layout.blockSize, data.size() - b * layout.blockSize);
            uLongf packedSize = compressBound(uLong(size));
            std::string packed(packedSize, '\0');
            compress2(reinterpret_cast<Bytef*>(packed.data()), &packedSize,
                      reinterpret_cast<const Bytef*>(data.data() + b * layout.blockSize), uLong(size), 6);
            packed.resize(packedSize);
            head += header(packedSize, layout);
            body += packed;
        }
    }
    if (!encode) return head + body;
    return layout.oneBase64Run ? base64(head + body) : base64(head) + base64(body);
}

std::string asciiValues(const std::vector<double>& values)
{
    std::ostringstream out;
    out.precision(17);
    for (double v : values) out << v << ' ';
    return out.str();
}

class Writer {
public:
    explicit Writer(const VtkXmlLayout& layout) : mLayout(layout) {}

    std::string array(const VtkArray& a)
    {
        std::string tag = "<DataArray type=\"" + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
                          std::to_string(a.components) + "\" format=\"";
        if (mLayout.format == VtkXmlLayout::Ascii) return tag + "ascii\">" + asciiValues(a.values) + "</DataArray>\n";
        const std::string bytes = vtkBytes(a.values, a.type, mLayout.bigEndian);
        if (mLayout.format == VtkXmlLayout::Binary)
            return tag + "binary\">\n" + blob(bytes, mLayout, true) + "\n</DataArray>\n";
        const std::size_t offset = mAppended.size();
        mAppended += blob(bytes, mLayout, mLayout.format == VtkXmlLayout::AppendedBase64);
        return tag + "appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    }

    std::string cells(const char* element, const VtkCells& c, const std::string& indexType, bool withTypes)
    {
        const auto asDoubles = [](const std::vector<std::int64_t>& v) {
            return std::vector<double>(v.begin(), v.end());
        };
        std::string out = std::string("<") + element + ">\n" +
                          array({"connectivity", indexType, 1, asDoubles(c.connectivity)}) +
                          array({"offsets", indexType, 1, asDoubles(c.offsets)});
        if (withTypes) out += array({"types", "UInt8", 1, asDoubles(c.types)});
        return out + "</" + element + ">\n";
    }

    std::string file(const std::string& type, const std::string& pieceAttributes, const std::string& body)
    {
        std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + type + "\" version=\"1.0\" byte_order=\"" +
                          (mLayout.bigEndian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" +
                          (mLayout.header64 ? "UInt64" : "UInt32") + "\"" +
                          (mLayout.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<" + type + ">\n<Piece " +
                          pieceAttributes + ">\n" + body + "</Piece>\n</" + type + ">\n";
        if (mLayout.format == VtkXmlLayout::AppendedRaw || mLayout.format == VtkXmlLayout::AppendedBase64) {
            out += std::string("<AppendedData encoding=\"") +
                   (mLayout.format == VtkXmlLayout::AppendedRaw ? "raw" : "base64") + "\">\n   _" + mAppended +
                   "\n</AppendedData>\n";
        }
        return out + "</VTKFile>\n";
    }

    std::string data(const VtkDataSet& d)
    {
        std::string out = "<PointData>\n";
        for (const VtkArray& a : d.pointData) out += array(a);
        out += "</PointData>\n<CellData>\n";
        for (const VtkArray& a : d.cellData) out += array(a);
        return out + "</CellData>\n<Points>\n" + array({"Points", d.pointType, 3, d.points}) + "</Points>\n";
    }

private:
    const VtkXmlLayout& mLayout;
    std::string mAppended;
};

}  // namespace

std::string vtkBytes(const std::vector<double>& values, const std::string& type, bool bigEndian)
{
    std::string out;
    for (double v : values) {
        if (type == "Int8")
            put<std::int8_t>(out, v, bigEndian);
        else if (type == "UInt8")
            put<std::uint8_t>(out, v, bigEndian);
        else if (type == "Int16")
            put<std::int16_t>(out, v, bigEndian);
        else if (type == "UInt16")
            put<std::uint16_t>(out, v, bigEndian);
        else if (type == "Int32")
            put<std::int32_t>(out, v, bigEndian);
        else if (type == "UInt32")
            put<std::uint32_t>(out, v, bigEndian);
        else if (type == "Int64")
            put<std::int64_t>(out, v, bigEndian);
        else if (type == "UInt64")
            put<std::uint64_t>(out, v, bigEndian);
        else if (type == "Float32")
            put<float>(out, v, bigEndian);
        else if (type == "Float64")
            put<double>(out, v, bigEndian);
        else
            throw std::invalid_argument("vtkBytes: unknown type " + type);
    }
    return out;
}

std::string base64(const std::string& bytes)
{
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t bits = 0;
        for (std::size_t k = 0; k < 3; ++k) bits = bits << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? alphabet[(bits >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

std::string vtpText(const VtkDataSet& d, const VtkXmlLayout& layout)
{
    Writer w(layout);
    std::string body = w.data(d);
    const std::pair<const char*, const VtkCells*> blocks[] = {
        {"Verts", &d.verts}, {"Lines", &d.lines}, {"Strips", &d.strips}, {"Polys", &d.polys}};
    for (const auto& [name, cells] : blocks) body += w.cells(name, *cells, d.indexType, false);
    const std::string attributes = "NumberOfPoints=\"" + std::to_string(d.points.size() / 3) + "\" NumberOfVerts=\"" +
                                   std::to_string(d.verts.offsets.size()) + "\" NumberOfLines=\"" +
                                   std::to_string(d.lines.offsets.size()) + "\" NumberOfStrips=\"" +
                                   std::to_string(d.strips.offsets.size()) + "\" NumberOfPolys=\"" +
                                   std::to_string(d.polys.offsets.size()) + "\"";
    return w.file("PolyData", attributes, body);
}

std::string vtuText(const VtkDataSet& d, const VtkXmlLayout& layout)
{
    Writer w(layout);
    const std::string body = w.data(d) + w.cells("Cells", d.cells, d.indexType, true);
    const std::string attributes = "NumberOfPoints=\"" + std::to_string(d.points.size() / 3) + "\" NumberOfCells=\"" +
                                   std::to_string(d.cells.offsets.size()) + "\"";
    return w.file("UnstructuredGrid", attributes, body);
}

}  // namespace ivis::test
