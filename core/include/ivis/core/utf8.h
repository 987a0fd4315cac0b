/// @file utf8.h
/// @brief The characters of UTF-8 text whose bytes may not all be UTF-8 (names read from files
///        written in Latin-1, units typed in another encoding).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ivis::core {

/// @brief Bytes of the UTF-8 character starting at @a text[@a i]: 1 to 4, or 0 where the bytes
///        there are not one (a Latin-1 byte, a lone continuation byte, a sequence cut short).
inline std::size_t utf8Length(std::string_view text, std::size_t i)
{
    const unsigned char lead = static_cast<unsigned char>(text[i]);
    const std::size_t length = lead < 0x80            ? 1
                               : (lead >> 5) == 0x6  ? 2
                               : (lead >> 4) == 0xE  ? 3
                               : (lead >> 3) == 0x1E ? 4
                                                     : 0;
    for (std::size_t k = 1; k < length; ++k)
        if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return 0;
    return length;
}

/// @brief The code point of the UTF-8 character of @a length bytes (utf8Length) at @a text[@a i].
inline std::uint32_t utf8CodePoint(std::string_view text, std::size_t i, std::size_t length)
{
    const unsigned char lead = static_cast<unsigned char>(text[i]);
    std::uint32_t c = length == 1 ? lead : lead & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) c = (c << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
    return c;
}

}  // namespace ivis::core
