/// @file mesh_layout_check_formats.h
/// @brief Internal to mesh_layout_check: the per-format layout checks and the token rules they share.
/// @note Every failure is an InputError "<path>: <problem>" (failInput).
#pragma once

#include <ivis/core/mesh_layout_check.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ivis::core::detail {

// Layout checks. OpenMesh 9.0's readers trust the file: a truncated PLY header makes the header
// loop grow without bound, a property before any element dereferences an empty vector, and a
// huge vertex count in an OFF/PLY face makes it push billions of handles. Each check walks the
// file as OpenMesh will, so that every file reaching OpenMesh has counts that match its content.

/// Checks a PLY file and returns its face count and 8-bit ASCII properties. OpenMesh starts binary
/// data 12 bytes (14 with CRLF) past the end of the last header token before end_header, which is
/// off when a comment line or trailing blanks precede the data; @a data then gets that canonical
/// tail. An ASCII file's 8-bit properties (other than colours) are declared `short` in @a data's
/// header, since OpenMesh would read their values as characters (MeshLayout::asciiPlyBytes).
MeshLayout preparePly(const std::string& path, std::string& data);

/// ASCII OFF as OpenMesh reads it: header line, counts, per vertex 3 (6 with N) numbers and the
/// rest of the line, per face a length and that many indices (and the rest of the line with C).
/// Returns the face count; @a points gets the vertices in double.
std::size_t checkOff(const std::string& path, const std::string& data, std::vector<glm::dvec3>& points);

/// Checks every "v" line (OpenMesh silently skips unreadable ones, shifting all later indices)
/// and returns the number of "f" lines; @a points gets the vertices in double. OBJ numbering is 1-based.
std::size_t checkObj(const std::string& path, const std::string& data, std::vector<glm::dvec3>& points);

/// Binary when the size matches the triangle count (OpenMesh's test); otherwise ASCII, where the
/// three lines after each "outer loop" line are the corners (as OpenMesh takes them), kept in
/// double in MeshLayout::stlCorners.
MeshLayout checkStl(const std::string& path, const std::string& data);

/// @a text in lower case (ASCII).
std::string lowercase(std::string text);

/// @a text without leading and trailing whitespace.
std::string_view trim(std::string_view text);

/// [+-]digits: a token `std::istream >> int` consumes whole. Anything it reads only in part
/// ("2-1" is 2, then -1) would shift every later value, so the layout checks reject it.
bool isInteger(std::string_view token);

/// [+-] digits [. digits] [e [+-] digits]: a token `std::istream >> float` consumes whole
/// (streams read no hexadecimal, nan or inf).
bool isDecimal(std::string_view token);

/// A count token as `std::istream >> unsigned` reads it without failing, or nothing.
std::optional<std::uint32_t> parseCount(std::string_view token);

/// Validates a coordinate token, naming the vertex in the error.
double checkCoordinate(const std::string& path, std::string_view token, const std::string& where);

}  // namespace ivis::core::detail
