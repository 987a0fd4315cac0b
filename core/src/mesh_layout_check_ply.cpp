#include "mesh_layout_check_formats.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core::detail {
namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> plyType(std::string_view name)
{
    static const std::pair<std::string_view, PlyType> kNames[] = {
        {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
        {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
        {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
        {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
        {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
        {"float64", PlyType::Float64}};
    for (const auto& [text, type] : kNames) {
        if (text == name) return type;
    }
    return std::nullopt;
}

std::size_t plySize(PlyType type)
{
    static const std::size_t kSizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    return kSizes[int(type)];
}

bool isPlyFloat(PlyType type) { return type == PlyType::Float32 || type == PlyType::Float64; }

/// How OpenMesh's PLY reader treats a property.
enum class PlyRole { Position, Vector, Color, Indices, Custom };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;     ///< value type (entry type of a list)
    std::optional<PlyType> countType;    ///< set for list properties
    PlyRole role = PlyRole::Custom;
    std::size_t typeAt = 0;              ///< where the header names its value type (not for lists)
    std::size_t typeLength = 0;
};

struct PlyElement {
    std::string name;
    std::uint32_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyLayout {
    bool ascii = true;
    bool bigEndian = false;
    std::vector<PlyElement> elements;
    std::size_t bodyOffset = 0;    ///< where the element data starts
    std::size_t headerTokens = 0;  ///< end of the last header token before end_header
};

PlyRole plyRole(const std::string& element, const PlyProperty& p)
{
    const auto is = [&](std::initializer_list<std::string_view> names) {
        return std::find(names.begin(), names.end(), p.name) != names.end();
    };
    if (element == "vertex" && !p.countType) {
        if (is({"x", "y", "z"})) return PlyRole::Position;
        if (is({"nx", "ny", "nz", "u", "v", "s", "t"})) return PlyRole::Vector;
        if (is({"red", "green", "blue", "alpha", "diffuse_red", "diffuse_green", "diffuse_blue"})) {
            return PlyRole::Color;
        }
    }
    if (element == "face") {
        if (p.countType && is({"vertex_index", "vertex_indices"})) return PlyRole::Indices;
        if (!p.countType && is({"red", "green", "blue", "alpha"})) return PlyRole::Color;
    }
    return PlyRole::Custom;
}

/// Parses the header token by token, exactly as OpenMesh does.
PlyLayout parsePlyHeader(const std::string& path, const std::string& data)
{
    const auto bad = [&](const std::string& why) { failInput(path, "not a valid PLY mesh (" + why + ")"); };
    TextCursor in(data);
    const std::string_view magic = trim(in.line());
    if (magic != "ply" && magic != "PLY") failInput(path, "not a valid PLY mesh");

    PlyLayout layout;
    in.token();  // "format"
    const std::string encoding(in.token());
    if (parseFloatToken(in.token()).kind != FloatToken::Finite) bad("bad format line");
    if (encoding == "binary_little_endian" || encoding == "binary_big_endian") {
        layout.ascii = false;
        layout.bigEndian = encoding == "binary_big_endian";
    } else if (encoding != "ascii") {
        bad("unsupported format '" + encoding + "'");
    }

    for (;;) {
        const std::size_t before = in.pos();
        const std::string_view keyword = in.token();
        if (keyword.empty()) bad("the header has no end_header");
        if (keyword == "end_header") {
            layout.headerTokens = before;
            if (!layout.ascii) in.line();  // binary data starts on the next line
            layout.bodyOffset = in.pos();
            break;
        }
        if (keyword == "comment") {
            in.line();
        } else if (keyword == "element") {
            PlyElement element;
            element.name = in.token();
            const std::optional<std::uint32_t> count = parseCount(in.token());
            if (!count) bad("bad count for element '" + element.name + "'");
            element.count = *count;
            layout.elements.push_back(std::move(element));
        } else if (keyword == "property") {
            if (layout.elements.empty()) bad("property before any element");
            PlyProperty p;
            const std::string_view firstToken = in.token();
            const std::string first(firstToken);
            if (first == "list") {
                const std::string count(in.token());
                const std::string entry(in.token());
                p.name = in.token();
                // The only list length types OpenMesh 9.0 accepts.
                if (count != "uint8" && count != "uint16" && count != "uchar" && count != "int") {
                    bad("unsupported list length type '" + count + "'");
                }
                p.countType = plyType(count);
                if (!plyType(entry)) bad("unknown property type '" + entry + "'");
                p.type = *plyType(entry);
            } else {
                const std::string_view secondToken = in.token();
                const std::string second(secondToken);
                const auto typeToken = [&](std::string_view token) {
                    p.typeAt = std::size_t(token.data() - data.data());
                    p.typeLength = token.size();
                };
                if (plyType(first)) {
                    p.type = *plyType(first);
                    p.name = second;
                    typeToken(firstToken);
                } else if (plyType(second)) {
                    p.type = *plyType(second);
                    p.name = first;
                    typeToken(secondToken);
                } else {
                    bad("unknown property type in 'property " + first + " " + second + "'");
                }
            }
            if (p.name.empty()) bad("the header ends early");
            p.role = plyRole(layout.elements.back().name, p);
            layout.elements.back().properties.push_back(std::move(p));
        }
        // Any other keyword (obj_info, ...) is skipped one token at a time, as OpenMesh does.
    }
    return layout;
}

/// Rejects property layouts that OpenMesh 9.0 would read misaligned or not at all.
void checkPlySupport(const std::string& path, const PlyLayout& layout)
{
    const auto bad = [&](const std::string& why) { failInput(path, "not a valid PLY mesh (" + why + ")"); };
    // A second face element sent OpenMesh's ASCII reader into gigabytes of memory (a fuzzer's
    // finding: tests/fuzz/regressions/ply/two-face-elements.ply).
    const auto faceElements = std::count_if(layout.elements.begin(), layout.elements.end(),
                                            [](const PlyElement& e) { return e.name == "face"; });
    if (faceElements > 1) bad("two face elements");
    bool haveVertex = false;
    for (const PlyElement& e : layout.elements) {
        if (e.count > 0 && e.properties.empty()) bad("element '" + e.name + "' has no properties");
        if (e.name == "vertex") {
            if (haveVertex) bad("two vertex elements");
            haveVertex = true;
            for (const char* axis : {"x", "y", "z"}) {
                const auto n = std::count_if(e.properties.begin(), e.properties.end(),
                                             [&](const PlyProperty& p) { return p.name == axis; });
                if (n != 1) bad("the vertex element needs exactly one property '" + std::string(axis) + "'");
            }
        }
        if (e.name == "face" && !haveVertex) bad("the face element comes before the vertex element");
        bool afterIndices = false;
        for (const PlyProperty& p : e.properties) {
            const std::string what = "property '" + p.name + "' of element '" + e.name + "'";
            if (p.role == PlyRole::Indices) {
                if (isPlyFloat(p.type)) bad("vertex indices must be integers");
                afterIndices = true;
            } else if (p.countType && e.name != "vertex" && !(e.name == "face" && afterIndices)) {
                bad("list " + what + " is not supported");
            }
            if (!layout.ascii && (p.role == PlyRole::Position || p.role == PlyRole::Vector) &&
                !isPlyFloat(p.type)) {
                bad(what + " must be float or double in binary PLY");
            }
            if (!layout.ascii && p.role == PlyRole::Color && p.type == PlyType::Float64) {
                bad(what + " cannot be double in binary PLY");
            }
            if (layout.ascii && p.role == PlyRole::Custom && plySize(p.type) == 1 && p.countType) {
                bad("list " + what + " has an 8-bit type, which ASCII PLY reading does not support");
            }
        }
        if (e.name == "face") break;  // OpenMesh stops after the faces
    }
    if (!haveVertex) bad("no vertex element");
}

/// The bytes of a binary value of @a type at @a offset, least significant first, zero beyond its size.
std::array<unsigned char, 8> littleEndianBytes(const std::string& data, std::size_t offset, PlyType type,
                                               bool bigEndian)
{
    std::array<unsigned char, 8> bytes{};
    const std::size_t size = plySize(type);
    for (std::size_t i = 0; i < size; ++i) {
        bytes[bigEndian ? size - 1 - i : i] = static_cast<unsigned char>(data[offset + i]);
    }
    return bytes;
}

/// Reads a binary list length of @a type at @a offset.
std::int64_t binaryCount(const std::string& data, std::size_t offset, PlyType type, bool bigEndian)
{
    const std::array<unsigned char, 8> bytes = littleEndianBytes(data, offset, type, bigEndian);
    const std::uint32_t raw = bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (std::uint32_t(bytes[3]) << 24);
    return type == PlyType::Int32 ? std::int64_t(std::int32_t(raw)) : std::int64_t(raw);
}

/// Reads a binary float or double of @a type at @a offset; beyond single precision infinite (as
/// OpenMesh's single-precision point would be).
double binaryCoordinate(const std::string& data, std::size_t offset, PlyType type, bool bigEndian)
{
    const std::array<unsigned char, 8> bytes = littleEndianBytes(data, offset, type, bigEndian);
    double value;
    if (type == PlyType::Float64) {
        std::memcpy(&value, bytes.data(), sizeof value);
    } else {
        float single;
        std::memcpy(&single, bytes.data(), sizeof single);
        value = single;
    }
    return std::abs(value) <= std::numeric_limits<float>::max() ? value : std::numeric_limits<double>::infinity();
}

/// Checks that OpenMesh reads an ASCII value whole, into the C++ type it uses for that property:
/// float for normals, texture coordinates and float colours, the declared type for other
/// properties, and an integer for everything else (positions: checkCoordinate).
void checkPlyValue(const std::string& path, std::string_view token, const PlyProperty& p,
                   const std::string& where)
{
    const bool asFloat = p.role == PlyRole::Vector ||
                         (p.role == PlyRole::Color ? p.type == PlyType::Float32 : isPlyFloat(p.type));
    if (asFloat ? isDecimal(token) : isInteger(token)) {
        if (p.role != PlyRole::Custom || plySize(p.type) != 1) return;
        // An 8-bit property is read as a 16-bit one (preparePly): its values must fit its own type.
        const long long v = std::strtoll(std::string(token).c_str(), nullptr, 10);
        const bool isSigned = p.type == PlyType::Int8;
        if (v >= (isSigned ? -128 : 0) && v <= (isSigned ? 127 : 255)) return;
        failInput(path, where + " has value '" + std::string(token) + "' for the " +
                            (isSigned ? "8-bit signed" : "8-bit unsigned") + " property '" + p.name + "' (" +
                            (isSigned ? "-128 to 127" : "0 to 255") + ")");
    }
    const bool nonFinite = parseFloatToken(token).kind == FloatToken::NonFinite;
    failInput(path, where + " has " + (nonFinite ? "a non-finite" : "an invalid") + " value '" +
                        std::string(token) + "' for property '" + p.name + "'" +
                        (nonFinite ? " (ASCII PLY cannot hold nan or inf)" : ""));
}

/// Walks the element data up to the faces: every value present, list lengths sane, ASCII values
/// readable whole; the vertices' points into @a points in double where the file holds more than
/// single precision (ASCII, or a double coordinate), else left empty.
void checkPlyBody(const std::string& path, const std::string& data, const PlyLayout& layout,
                  std::vector<glm::dvec3>& points)
{
    const auto truncated = [&] { failInput(path, "not a valid PLY mesh (the file is truncated)"); };
    TextCursor text(data, layout.bodyOffset);
    std::size_t offset = layout.bodyOffset;
    if (offset > data.size()) truncated();

    // Consumes one value; returns its ASCII token ("" for binary).
    const auto value = [&](PlyType type) -> std::string_view {
        if (layout.ascii) {
            const std::string_view token = text.token();
            if (token.empty()) truncated();
            return token;
        }
        if (data.size() - offset < plySize(type)) truncated();
        offset += plySize(type);
        return {};
    };
    const auto listLength = [&](PlyType type) -> std::uint64_t {
        if (layout.ascii) {
            const std::optional<std::uint32_t> n = parseCount(value(type));
            if (!n) failInput(path, "not a valid PLY mesh (bad list length)");
            return *n;
        }
        const std::size_t at = offset;
        value(type);
        const std::int64_t n = binaryCount(data, at, type, layout.bigEndian);
        if (n < 0) failInput(path, "not a valid PLY mesh (negative list length)");
        return std::uint64_t(n);
    };

    const auto isDoublePosition = [](const PlyProperty& p) {
        return p.role == PlyRole::Position && p.type == PlyType::Float64;
    };
    for (const PlyElement& e : layout.elements) {
        // OpenMesh reads other elements as text it skips.
        const bool checked = layout.ascii && (e.name == "vertex" || e.name == "face");
        const bool collect = e.name == "vertex" &&
                             (layout.ascii || std::any_of(e.properties.begin(), e.properties.end(), isDoublePosition));
        for (std::uint32_t r = 0; r < e.count; ++r) {
            const std::string where = e.name + " " + std::to_string(r);
            if (collect) points.emplace_back(0.0);
            for (const PlyProperty& p : e.properties) {
                if (!p.countType) {
                    const std::size_t at = offset;
                    const std::string_view token = value(p.type);
                    if (p.role == PlyRole::Position && (layout.ascii || collect)) {
                        const double coordinate = layout.ascii ? checkCoordinate(path, token, where)
                                                               : binaryCoordinate(data, at, p.type, layout.bigEndian);
                        if (collect) points.back()[p.name[0] - 'x'] = coordinate;
                    } else if (checked) {
                        checkPlyValue(path, token, p, where);
                    }
                    continue;
                }
                const std::uint64_t n = listLength(*p.countType);
                if (!layout.ascii) {
                    if (n > (data.size() - offset) / plySize(p.type)) truncated();
                    offset += n * plySize(p.type);
                } else {
                    for (std::uint64_t k = 0; k < n; ++k) {
                        const std::string_view token = value(p.type);
                        if (checked) checkPlyValue(path, token, p, where);
                    }
                }
            }
        }
        if (e.name == "face") break;
    }
}

}  // namespace

MeshLayout preparePly(const std::string& path, std::string& data)
{
    const PlyLayout layout = parsePlyHeader(path, data);
    checkPlySupport(path, layout);
    MeshLayout out;
    checkPlyBody(path, data, layout, out.filePoints);
    if (!layout.ascii && data.compare(layout.headerTokens, layout.bodyOffset - layout.headerTokens,
                                      "\nend_header\n") != 0) {
        data = data.substr(0, layout.headerTokens) + "\nend_header\n" + data.substr(layout.bodyOffset);
    }
    std::string header;  // an ASCII header with its 8-bit properties declared `short`
    std::size_t copied = 0;
    for (const PlyElement& e : layout.elements) {
        for (const PlyProperty& p : e.properties) {
            if (!layout.ascii || p.role != PlyRole::Custom || plySize(p.type) != 1 || p.countType) continue;
            header.append(data, copied, p.typeAt - copied).append("short");
            copied = p.typeAt + p.typeLength;
            if (e.name == "vertex" || e.name == "face")  // other elements OpenMesh reads past
                out.asciiPlyBytes.push_back({e.name == "face" ? Association::Cell : Association::Point, p.name,
                                             p.type == PlyType::Int8 ? ValueType::Int8 : ValueType::UInt8});
        }
        if (e.name == "face") {
            out.facesInFile = e.count;
            break;
        }
    }
    if (copied > 0) data = header + data.substr(copied);
    return out;
}

}  // namespace ivis::core::detail
