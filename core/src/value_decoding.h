/// @file value_decoding.h
/// @brief Numbers of a file as doubles: binary values of any numeric type in either byte order,
///        and number tokens of text.
/// @note Internal to the VTK readers.
#pragma once

#include <ivis/core/data_array.h>

#include <cstddef>
#include <string_view>
#include <vector>

namespace ivis::core::detail {

/// The @a count values of @a type stored one after another at @a bytes (count * size bytes).
std::vector<double> valuesFromBytes(const char* bytes, std::size_t count, ValueType type, bool bigEndian);

/// Parses a whole token as a number ("nan", "inf" and a leading '+' allowed); false when it is not one.
bool parseNumber(std::string_view token, double& value);

/// Fails "<path>: <what>: value <i> (<v>) does not fit the array's type <Type>" unless @a array's type holds each
/// of its values: any number for a float type, an integer within its range for an integer type
/// (what VTK's stream reading that type reads whole: an ASCII "0.5" in an Int32 array, or "-1" in
/// a UInt8 one, is not). Binary data always holds.
void checkValuesFitType(const std::string& path, const std::string& what, const DataArray& array);

}  // namespace ivis::core::detail
