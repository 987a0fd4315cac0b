/// @file show_array.h
/// @brief Chooses the array a surface shows: a point or a cell array by name, one component or
///        the magnitude of a vector, a cell array flat per triangle or averaged onto the vertices.
#pragma once

#include <ivis/core/surface_field.h>

#include <string>
#include <vector>

namespace ivis::core {

/// @brief Shows the array @a spec names: sets field.values, valuesOn and name.
/// @param spec "NAME" (a vector by its magnitude), "NAME:magnitude" or "NAME:<k>" for component
///        k, each after "point:" or "cell:" to choose the association; a name that exists as it
///        is wins over a split at its last ':' or its first, a point array over a cell array of
///        the same name
/// @param cellToPoint show a cell array averaged onto the vertices (cellToPoint) instead of one
///        flat value per triangle
/// @throw InputError "<source>: no array 'x'; available: ...", naming a component that does
///        not exist, or when @a cellToPoint and the array is a point array
void showArray(SurfaceField& field, const std::string& spec, bool cellToPoint);

/// @brief The spec that names @a array and no other of its name: "point:NAME" or "cell:NAME".
std::string qualifiedArrayName(const DataArray& array);

/// @brief One thing a surface can be coloured by: an array, or one component of a vector array.
struct ArrayChoice {
    std::string spec;                        ///< what showArray takes: "point:NAME", "cell:NAME:magnitude", "point:NAME:1"
    std::string name;                        ///< the name showArray then gives the field ("NAME", "NAME magnitude", "NAME[1]")
    Association association = Association::Point;
};

/// @brief What @a field can be coloured by, as ParaView's "Color by" lists it: each of its arrays
///        in the file's order, a vector array by its magnitude and then by each component; not an
///        array whose name holds '*' or '?' (a pattern to --scalar), nor a vector's part whose
///        spec names another array.
std::vector<ArrayChoice> arrayChoices(const SurfaceField& field);

/// @brief The array shown when a file carries arrays and none is chosen: the active point scalars,
///        else the active cell scalars (DataArray::activeScalars: what ParaView colours by), else
///        the first point array, else the first cell array. With @a cellToPoint only the cell
///        arrays count: the active cell scalars, else the first cell array.
/// @note Without @a cellToPoint call only when field.arrays is not empty.
/// @throw InputError when @a cellToPoint and the field has no cell array
const DataArray& defaultArray(const SurfaceField& field, bool cellToPoint = false);

/// @brief True when @a spec is a pattern of array names: it holds '*' (any run of characters) or
///        '?' (one character).
bool isArrayPattern(const std::string& spec);

/// @brief The names of @a field's arrays that the pattern @a pattern matches whole, each once, in
///        natural order (runs of digits compared as numbers: "p_t200" before "p_t1000").
/// @throw InputError "<source>: no array matches 'x*'; available: ..."
std::vector<std::string> arraysMatching(const SurfaceField& field, const std::string& pattern);

}  // namespace ivis::core
