#include <ivis/core/mesh_layout_check.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

namespace ivis::core::detail {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Tokens
// ---------------------------------------------------------------------------------------------

std::string lowercase(std::string text)
{
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::string_view trim(std::string_view text)
{
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    return text;
}

std::size_t skipDigits(std::string_view text, std::size_t i)
{
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    return i;
}

std::size_t skipSign(std::string_view text) { return !text.empty() && (text[0] == '+' || text[0] == '-'); }

/// [+-]digits: a token `std::istream >> int` consumes whole. Anything it reads only in part
/// ("2-1" is 2, then -1) would shift every later value, so the layout checks reject it.
bool isInteger(std::string_view token)
{
    const std::size_t start = skipSign(token);
    return token.size() > start && skipDigits(token, start) == token.size();
}

/// [+-] digits [. digits] [e [+-] digits]: a token `std::istream >> float` consumes whole
/// (streams read no hexadecimal, nan or inf).
bool isDecimal(std::string_view token)
{
    std::size_t i = skipSign(token);
    std::size_t digits = skipDigits(token, i) - i;
    i += digits;
    if (i < token.size() && token[i] == '.') {
        const std::size_t fraction = skipDigits(token, i + 1) - (i + 1);
        digits += fraction;
        i += 1 + fraction;
    }
    if (digits == 0) return false;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
        const std::size_t start = i + 1 + skipSign(token.substr(i + 1));
        i = skipDigits(token, start);
        if (i == start) return false;
    }
    return i == token.size();
}

/// A count token as `std::istream >> unsigned` reads it without failing, or nothing.
std::optional<std::uint32_t> parseCount(std::string_view token)
{
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (token.empty() || ec != std::errc() || end != token.data() + token.size() ||
        value > std::numeric_limits<std::uint32_t>::max()) {
        return std::nullopt;
    }
    return std::uint32_t(value);
}

/// Validates a coordinate token, naming the vertex in the error.
void checkCoordinate(const std::string& path, std::string_view token, const std::string& where)
{
    const FloatToken number = parseFloatToken(token);
    if (number.kind == FloatToken::NonFinite) failInput(path, where + " has a non-finite coordinate");
    if (number.kind == FloatToken::NotANumber) {
        failInput(path, where + " has a non-numeric coordinate '" + std::string(token) + "'");
    }
}

// ---------------------------------------------------------------------------------------------
// Layout checks. OpenMesh 9.0's readers trust the file: a truncated PLY header makes the header
// loop grow without bound, a property before any element dereferences an empty vector, and a
// huge vertex count in an OFF/PLY face makes it push billions of handles. Each check walks the
// file as OpenMesh will, so that every file reaching OpenMesh has counts that match its content.
// ---------------------------------------------------------------------------------------------

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
            const std::string first(in.token());
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
                const std::string second(in.token());
                if (plyType(first)) {
                    p.type = *plyType(first);
                    p.name = second;
                } else if (plyType(second)) {
                    p.type = *plyType(second);
                    p.name = first;
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
            if (layout.ascii && p.role == PlyRole::Custom && plySize(p.type) == 1) {
                bad(what + " has an 8-bit type, which ASCII PLY reading does not support");
            }
        }
        if (e.name == "face") break;  // OpenMesh stops after the faces
    }
    if (!haveVertex) bad("no vertex element");
}

/// Reads a binary list length of @a type at @a offset.
std::int64_t binaryCount(const std::string& data, std::size_t offset, PlyType type, bool bigEndian)
{
    std::array<unsigned char, 4> bytes{};
    const std::size_t size = plySize(type);
    for (std::size_t i = 0; i < size; ++i) {
        bytes[bigEndian ? size - 1 - i : i] = static_cast<unsigned char>(data[offset + i]);
    }
    const std::uint32_t raw = bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (std::uint32_t(bytes[3]) << 24);
    return type == PlyType::Int32 ? std::int64_t(std::int32_t(raw)) : std::int64_t(raw);
}

/// Checks that OpenMesh reads an ASCII value whole, into the C++ type it uses for that property:
/// float for positions, normals, texture coordinates and float colours, the declared type for
/// other properties, and an integer for everything else.
void checkPlyValue(const std::string& path, std::string_view token, const PlyProperty& p,
                   const std::string& where)
{
    if (p.role == PlyRole::Position) return checkCoordinate(path, token, where);
    const bool asFloat = p.role == PlyRole::Vector ||
                         (p.role == PlyRole::Color ? p.type == PlyType::Float32 : isPlyFloat(p.type));
    if (asFloat ? isDecimal(token) : isInteger(token)) return;
    const bool nonFinite = parseFloatToken(token).kind == FloatToken::NonFinite;
    failInput(path, where + " has " + (nonFinite ? "a non-finite" : "an invalid") + " value '" +
                        std::string(token) + "' for property '" + p.name + "'" +
                        (nonFinite ? " (ASCII PLY cannot hold nan or inf)" : ""));
}

/// Walks the element data up to the faces: every value present, list lengths sane, ASCII values
/// readable whole.
void checkPlyBody(const std::string& path, const std::string& data, const PlyLayout& layout)
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

    for (const PlyElement& e : layout.elements) {
        // OpenMesh reads other elements as text it skips.
        const bool checked = layout.ascii && (e.name == "vertex" || e.name == "face");
        for (std::uint32_t r = 0; r < e.count; ++r) {
            const std::string where = e.name + " " + std::to_string(r);
            for (const PlyProperty& p : e.properties) {
                if (!p.countType) {
                    const std::string_view token = value(p.type);
                    if (checked) checkPlyValue(path, token, p, where);
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

/// Checks a PLY file and returns its face count. OpenMesh starts binary data 12 bytes (14 with
/// CRLF) past the end of the last header token before end_header, which is off when a comment
/// line or trailing blanks precede the data; @a data then gets that canonical tail.
std::size_t preparePly(const std::string& path, std::string& data)
{
    const PlyLayout layout = parsePlyHeader(path, data);
    checkPlySupport(path, layout);
    checkPlyBody(path, data, layout);
    if (!layout.ascii && data.compare(layout.headerTokens, layout.bodyOffset - layout.headerTokens,
                                      "\nend_header\n") != 0) {
        data = data.substr(0, layout.headerTokens) + "\nend_header\n" + data.substr(layout.bodyOffset);
    }
    for (const PlyElement& e : layout.elements) {
        if (e.name == "face") return e.count;
    }
    return 0;
}

/// ASCII OFF as OpenMesh reads it: header line, counts, per vertex 3 (6 with N) numbers and the
/// rest of the line, per face a length and that many indices (and the rest of the line with C).
std::size_t checkOff(const std::string& path, const std::string& data)
{
    const auto truncated = [&] { failInput(path, "not a valid OFF mesh (the file is truncated)"); };
    TextCursor in(data);
    const std::string_view header = in.line();
    std::size_t i = header.compare(0, 2, "ST") == 0 ? 2 : 0;
    const bool colors = i < header.size() && header[i] == 'C';
    i += colors;
    const bool normals = i < header.size() && header[i] == 'N';
    i += normals;
    if (i < header.size() && (header[i] == '4' || header[i] == 'n')) {
        failInput(path, "not a valid OFF mesh (only 3D vertices are supported)");
    }
    if (header.compare(i, 3, "OFF") != 0) failInput(path, "not a valid OFF mesh");
    if (header.find("BINARY", i) != std::string_view::npos) failInput(path, "binary OFF is not supported");

    std::array<std::uint32_t, 3> counts{};  // vertices, faces, edges
    for (std::uint32_t& count : counts) {
        const std::optional<std::uint32_t> n = parseCount(in.token());
        if (!n) failInput(path, "not a valid OFF mesh (bad vertex/face/edge counts)");
        count = *n;
    }
    for (std::uint32_t v = 0; v < counts[0]; ++v) {
        for (int k = 0; k < (normals ? 6 : 3); ++k) {
            const std::string_view token = in.token();
            if (token.empty()) truncated();
            if (k < 3) {
                checkCoordinate(path, token, "vertex " + std::to_string(v));
            } else if (!isDecimal(token)) {
                failInput(path, "vertex " + std::to_string(v) + " has an invalid normal '" +
                                    std::string(token) + "'");
            }
        }
        in.line();
    }
    for (std::uint32_t f = 0; f < counts[1]; ++f) {
        const std::string_view length = in.token();
        if (length.empty()) truncated();
        const std::optional<std::uint32_t> n = parseCount(length);
        if (!n) {
            failInput(path, "not a valid OFF mesh (face " + std::to_string(f) + " has length '" +
                                std::string(length) + "')");
        }
        for (std::uint32_t k = 0; k < *n; ++k) {
            const std::string_view index = in.token();
            if (index.empty()) truncated();
            if (!isInteger(index)) {
                failInput(path, "face " + std::to_string(f) + " has an invalid index '" +
                                    std::string(index) + "'");
            }
        }
        if (colors) in.line();
    }
    return counts[1];
}

/// Checks every "v" line (OpenMesh silently skips unreadable ones, shifting all later indices)
/// and returns the number of "f" lines. OBJ numbering is 1-based.
std::size_t checkObj(const std::string& path, const std::string& data)
{
    TextCursor lines(data);
    std::size_t vertices = 0;
    std::size_t faces = 0;
    while (!lines.atEnd()) {
        const std::string content(trim(lines.line()));
        TextCursor in(content);
        const std::string_view keyword = in.token();
        if (keyword == "f") ++faces;
        if (keyword != "v") continue;
        const std::string where = "vertex " + std::to_string(++vertices);
        for (int k = 0; k < 3; ++k) {
            const std::string_view token = in.token();
            if (token.empty()) failInput(path, where + " has fewer than three coordinates");
            checkCoordinate(path, token, where);
        }
    }
    return faces;
}

/// Binary when the size matches the triangle count (OpenMesh's test); otherwise ASCII, where
/// OpenMesh takes the three lines after each "outer loop" line as the corners.
MeshLayout checkStl(const std::string& path, const std::string& data)
{
    if (data.size() >= 84) {
        std::uint32_t count = 0;
        for (int i = 3; i >= 0; --i) count = (count << 8) | static_cast<unsigned char>(data[80 + i]);
        if (84 + 50 * std::uint64_t(count) == data.size()) return {count, true};
    }
    const std::string start(trim(std::string_view(data).substr(0, 64)).substr(0, 5));
    if (lowercase(start) != "solid") {
        failInput(path, "not a valid STL mesh");
    }
    TextCursor lines(data);
    std::size_t facets = 0;
    while (!lines.atEnd()) {
        const std::string_view line = lines.line();
        if (line.find("outer") == std::string_view::npos && line.find("OUTER") == std::string_view::npos) {
            continue;
        }
        const std::string where = "facet " + std::to_string(facets++);
        for (int corner = 0; corner < 3; ++corner) {
            if (lines.atEnd()) failInput(path, "not a valid STL mesh (the file is truncated)");
            const std::string content(lines.line());
            TextCursor in(content);
            in.token();  // "vertex"
            for (int k = 0; k < 3; ++k) {
                const std::string_view token = in.token();
                if (token.empty()) failInput(path, where + " has a corner with fewer than three coordinates");
                checkCoordinate(path, token, where);
            }
        }
    }
    return {facets, false};
}

}  // namespace

void failInput(const std::string& path, const std::string& problem)
{
    throw InputError(path + ": " + problem);
}

MeshFormat meshFormat(const std::string& path)
{
    const std::string ext = lowercase(fs::path(path).extension().string());
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".off") return MeshFormat::Off;
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".stl") return MeshFormat::Stl;
    failInput(path, "unknown mesh format '" + ext + "' (expected .obj, .off, .ply, .stl)");
}

const char* formatName(MeshFormat format)
{
    static const char* const kNames[] = {"obj", "off", "ply", "stl"};
    return kNames[int(format)];
}

MeshLayout checkMeshLayout(const std::string& path, MeshFormat format, std::string& data)
{
    if (format == MeshFormat::Ply) return {preparePly(path, data), false};
    if (format == MeshFormat::Off) return {checkOff(path, data), false};
    if (format == MeshFormat::Obj) return {checkObj(path, data), false};
    return checkStl(path, data);
}

// Hexadecimal is NotANumber: streams do not read it.
FloatToken parseFloatToken(std::string_view token)
{
    const std::string text(token);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (!isDecimal(token)) {
        const bool spelled = !text.empty() && end == text.c_str() + text.size() && !std::isfinite(value);
        return {spelled ? FloatToken::NonFinite : FloatToken::NotANumber, value};
    }
    const bool fits = std::isfinite(value) && std::abs(value) <= std::numeric_limits<float>::max();
    return {fits ? FloatToken::Finite : FloatToken::NonFinite, value};
}

}  // namespace ivis::core::detail
