/// @file data_array.h
/// @brief A named array of values per point or per cell, with its type and components, as VTK's
///        vtkDataArray.
/// @note Values are held as double whatever the file's type: exact for every type except 64-bit
///       integers beyond 2^53, which round.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core {

/// @brief What an array's tuples belong to: the file's points or its cells (faces).
enum class Association { Point, Cell };

/// @brief The numeric type an array has in its file.
enum class ValueType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

/// @brief Component index meaning "the Euclidean length of the tuple".
inline constexpr int kMagnitude = -1;

/// @brief One array of a file: tuples of @a components values, one tuple per point or per cell.
struct DataArray {
    std::string name;
    Association association = Association::Point;
    ValueType type = ValueType::Float32;
    int components = 1;
    std::vector<double> values;  ///< tuple after tuple: values[tuple * components + component]
    /// The file's active scalars of its association, which ParaView colours by: a VTK XML file's
    /// PointData / CellData "Scalars" attribute, a legacy file's first SCALARS (or COLOR_SCALARS)
    /// of the section.
    bool activeScalars = false;

    /// @brief Number of tuples.
    std::size_t tuples() const { return components > 0 ? values.size() / std::size_t(components) : 0; }
    /// @brief Component @a component of tuple @a tuple, or its Euclidean length when @a component
    ///        is kMagnitude.
    double at(std::size_t tuple, int component) const;
    /// @brief The component shown when none is named: 0 for one component, else kMagnitude.
    int defaultComponent() const { return components == 1 ? 0 : kMagnitude; }
};

/// @brief "point" or "cell".
const char* associationName(Association association);

/// @brief The VTK XML name of @a type: "Int8" .. "Float64".
const char* valueTypeName(ValueType type);

/// @brief Bytes one value of @a type takes in a binary file.
std::size_t valueTypeSize(ValueType type);

/// @brief Finite (min, max) of component @a component (or kMagnitude) over the tuples @a keep marks
///        (all when it is empty; tuples beyond it are not kept), ignoring NaN and infinities;
///        {NaN, NaN} when there is none (an array of NaN only).
std::pair<double, double> finiteRange(const DataArray& array, int component, const std::vector<char>& keep = {});

}  // namespace ivis::core
