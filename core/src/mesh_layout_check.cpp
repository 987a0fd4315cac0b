#include <ivis/core/mesh_layout_check.h>

#include "mesh_layout_check_formats.h"

#include <ivis/core/errors.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <system_error>

namespace ivis::core::detail {
namespace {

std::size_t skipDigits(std::string_view text, std::size_t i)
{
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    return i;
}

std::size_t skipSign(std::string_view text) { return !text.empty() && (text[0] == '+' || text[0] == '-'); }

}  // namespace

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

bool isInteger(std::string_view token)
{
    const std::size_t start = skipSign(token);
    return token.size() > start && skipDigits(token, start) == token.size();
}

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

double checkCoordinate(const std::string& path, std::string_view token, const std::string& where)
{
    const FloatToken number = parseFloatToken(token);
    if (number.kind == FloatToken::NonFinite) failInput(path, where + " has a non-finite coordinate");
    if (number.kind == FloatToken::NotANumber) {
        failInput(path, where + " has a non-numeric coordinate '" + std::string(token) + "'");
    }
    return number.value;
}

void failInput(const std::string& path, const std::string& problem)
{
    // Bytes of the file quoted in the problem stay on one printable line.
    std::string line = path + ": ";
    for (const char c : problem) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte != 0x7f) {
            line += c;
        } else {
            static const char* const kHex = "0123456789abcdef";
            line += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
        }
    }
    throw InputError(line);
}

const char* formatName(MeshFormat format)
{
    static const char* const kNames[] = {"obj", "off", "ply", "stl"};
    return kNames[int(format)];
}

MeshLayout checkMeshLayout(const std::string& path, MeshFormat format, std::string& data)
{
    if (format == MeshFormat::Ply) return preparePly(path, data);
    MeshLayout layout;
    if (format == MeshFormat::Off) layout.facesInFile = checkOff(path, data, layout.filePoints);
    if (format == MeshFormat::Obj) layout.facesInFile = checkObj(path, data, layout.filePoints);
    if (format == MeshFormat::Off || format == MeshFormat::Obj) return layout;
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
