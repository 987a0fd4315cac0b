#include "value_decoding.h"

#include <ivis/core/mesh_layout_check.h>
#include <ivis/core/number_text.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace ivis::core::detail {
namespace {

template <typename T>
void convert(const char* bytes, std::size_t count, bool swap, std::vector<double>& values)
{
    values.resize(count);
    char raw[sizeof(T)];
    for (std::size_t i = 0; i < count; ++i) {
        std::memcpy(raw, bytes + i * sizeof(T), sizeof(T));
        if (swap) std::reverse(raw, raw + sizeof(T));
        T v;
        std::memcpy(&v, raw, sizeof(T));
        values[i] = double(v);
    }
}

}  // namespace

std::vector<double> valuesFromBytes(const char* bytes, std::size_t count, ValueType type, bool bigEndian)
{
    std::vector<double> values;
    switch (type) {
    case ValueType::Int8: convert<std::int8_t>(bytes, count, bigEndian, values); break;
    case ValueType::UInt8: convert<std::uint8_t>(bytes, count, bigEndian, values); break;
    case ValueType::Int16: convert<std::int16_t>(bytes, count, bigEndian, values); break;
    case ValueType::UInt16: convert<std::uint16_t>(bytes, count, bigEndian, values); break;
    case ValueType::Int32: convert<std::int32_t>(bytes, count, bigEndian, values); break;
    case ValueType::UInt32: convert<std::uint32_t>(bytes, count, bigEndian, values); break;
    case ValueType::Int64: convert<std::int64_t>(bytes, count, bigEndian, values); break;
    case ValueType::UInt64: convert<std::uint64_t>(bytes, count, bigEndian, values); break;
    case ValueType::Float32: convert<float>(bytes, count, bigEndian, values); break;
    case ValueType::Float64: convert<double>(bytes, count, bigEndian, values); break;
    }
    return values;
}

bool parseNumber(std::string_view token, double& value)
{
    if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const auto [stop, ec] = std::from_chars(token.data(), end, value);
    if (stop != end || token.empty()) return false;
    // Beyond the range of double: strtod gives the infinity or zero a stream would.
    if (ec == std::errc::result_out_of_range) value = std::strtod(std::string(token).c_str(), nullptr);
    return ec == std::errc() || ec == std::errc::result_out_of_range;
}

namespace {

bool typeHolds(ValueType type, double value)
{
    if (type == ValueType::Float32 || type == ValueType::Float64) return true;
    if (!(value == std::floor(value))) return false;  // NaN and fractions
    switch (type) {
    case ValueType::Int8: return value >= -128.0 && value <= 127.0;
    case ValueType::UInt8: return value >= 0.0 && value <= 255.0;
    case ValueType::Int16: return value >= -32768.0 && value <= 32767.0;
    case ValueType::UInt16: return value >= 0.0 && value <= 65535.0;
    case ValueType::Int32: return value >= -2147483648.0 && value <= 2147483647.0;
    case ValueType::UInt32: return value >= 0.0 && value <= 4294967295.0;
    case ValueType::Int64: return value >= -9223372036854775808.0 && value < 9223372036854775808.0;
    default: return value >= 0.0 && value < 18446744073709551616.0;  // UInt64
    }
}

}  // namespace

void checkValuesFitType(const std::string& path, const std::string& what, const DataArray& array)
{
    for (std::size_t i = 0; i < array.values.size(); ++i)
        if (!typeHolds(array.type, array.values[i]))
            failInput(path, what + ": value " + std::to_string(i) + " (" + shortNumber(array.values[i]) +
                                ") does not fit the array's type " + valueTypeName(array.type));
}

}  // namespace ivis::core::detail
