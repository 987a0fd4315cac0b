#include <ivis/core/show_array.h>

#include <ivis/core/cell_to_point.h>
#include <ivis/core/errors.h>
#include <ivis/core/mesh_layout_check.h>
#include <ivis/core/number_text.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <charconv>
#include <cctype>
#include <limits>
#include <optional>
#include <string_view>

namespace ivis::core {
namespace {

/// The array named @a name (of association @a only, when given), a point array before a cell
/// array; nullptr when there is none.
const DataArray* findArray(const SurfaceField& field, const std::string& name,
                           std::optional<Association> only = std::nullopt)
{
    const DataArray* found = nullptr;
    for (const DataArray& a : field.arrays) {
        if (a.name == name && (!only || a.association == *only) &&
            (found == nullptr || (found->association == Association::Cell && a.association == Association::Point))) {
            found = &a;
        }
    }
    return found;
}

std::string availableArrays(const SurfaceField& field)
{
    std::string list;
    bool twoOfAName = false;
    for (const DataArray& a : field.arrays) {
        list += (list.empty() ? "" : ", ") + a.name + " (" + associationName(a.association) +
                (a.components > 1 ? ", " + std::to_string(a.components) + " components" : "") + ")";
        twoOfAName = twoOfAName || std::any_of(field.arrays.begin(), field.arrays.end(), [&](const DataArray& b) {
                         return b.name == a.name && b.association != a.association;
                     });
    }
    if (twoOfAName) list += " (of a point and a cell array of one name, cell:NAME chooses the cell array)";
    return list.empty() ? "none" : list;
}

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

/// Natural order: runs of digits compare as numbers (without leading zeros), the rest byte by byte.
bool naturalLess(const std::string& a, const std::string& b)
{
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (isDigit(a[i]) && isDigit(b[j])) {
            std::size_t endA = i, endB = j;
            while (endA < a.size() && isDigit(a[endA])) ++endA;
            while (endB < b.size() && isDigit(b[endB])) ++endB;
            std::size_t startA = i, startB = j;
            while (startA + 1 < endA && a[startA] == '0') ++startA;
            while (startB + 1 < endB && b[startB] == '0') ++startB;
            const std::string_view numberA(a.data() + startA, endA - startA), numberB(b.data() + startB, endB - startB);
            if (numberA.size() != numberB.size()) return numberA.size() < numberB.size();
            if (numberA != numberB) return numberA < numberB;
            i = endA;
            j = endB;
        } else {
            if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
            ++i;
            ++j;
        }
    }
    if ((a.size() - i) != (b.size() - j)) return a.size() - i < b.size() - j;
    return a < b;  // equal up to leading zeros: any fixed order
}

/// Whether @a pattern matches the whole of @a name, '*' matching any run of characters and '?' any
/// one; every other character, '[' and '\\' among them (fnmatch's classes and escapes), stands for
/// itself, as in CFD array names such as "WSS [Pa]".
bool wildcardMatches(const std::string& pattern, const std::string& name)
{
    std::size_t p = 0, n = 0;
    std::size_t star = std::string::npos, resume = 0;  // the last '*' seen, and where its run ends in name
    while (n < name.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = n;
        } else if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
            ++p;
            ++n;
        } else if (star != std::string::npos) {  // let the last '*' take one more character
            p = star + 1;
            n = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

}  // namespace

bool isArrayPattern(const std::string& spec) { return spec.find_first_of("*?") != std::string::npos; }

std::vector<std::string> arraysMatching(const SurfaceField& field, const std::string& pattern)
{
    std::vector<std::string> names;
    for (const DataArray& a : field.arrays)
        if (wildcardMatches(pattern, a.name) &&
            std::find(names.begin(), names.end(), a.name) == names.end())
            names.push_back(a.name);
    if (names.empty())
        detail::failInput(field.sourcePath, "no array matches '" + pattern + "'; available: " + availableArrays(field));
    std::sort(names.begin(), names.end(), naturalLess);
    return names;
}

std::string qualifiedArrayName(const DataArray& array)
{
    return std::string(associationName(array.association)) + ":" + array.name;
}

std::vector<ArrayChoice> arrayChoices(const SurfaceField& field)
{
    std::vector<ArrayChoice> choices;
    // A part of a vector whose spec names another array ("v:0" beside a vector "v") would show that one.
    auto named = [&](const std::string& name, Association association) {
        return std::any_of(field.arrays.begin(), field.arrays.end(),
                           [&](const DataArray& a) { return a.name == name && a.association == association; });
    };
    for (const DataArray& array : field.arrays) {
        if (isArrayPattern(array.name)) continue;  // its name would be read as a pattern of names
        const std::string spec = qualifiedArrayName(array);
        if (array.components == 1) {
            choices.push_back({spec, array.name, array.association});
            continue;
        }
        if (!named(array.name + ":magnitude", array.association))
            choices.push_back({spec + ":magnitude", array.name + " magnitude", array.association});
        for (int k = 0; k < array.components; ++k)
            if (!named(array.name + ":" + std::to_string(k), array.association))
                choices.push_back({spec + ":" + std::to_string(k), array.name + "[" + std::to_string(k) + "]",
                                   array.association});
    }
    return choices;
}

void showArray(SurfaceField& field, const std::string& spec, bool cellToPoint)
{
    // In order: the whole spec as a name; "point:" or "cell:" and what follows (a name, or a name
    // and a component); the whole spec split at its last ':' into a name and a component.
    const DataArray* array = findArray(field, spec);
    std::string name = spec;
    std::optional<Association> only;
    auto splitFinds = [&](const std::string& text, std::optional<Association> association) {
        const std::size_t colon = text.rfind(':');
        return findArray(field, text, association) != nullptr ||
               (colon != std::string::npos && findArray(field, text.substr(0, colon), association) != nullptr);
    };
    for (const Association association : {Association::Point, Association::Cell}) {
        const std::string prefix = std::string(associationName(association)) + ":";
        if (array == nullptr && !only && spec.size() > prefix.size() && spec.rfind(prefix, 0) == 0 &&
            splitFinds(spec.substr(prefix.size()), association)) {
            name = spec.substr(prefix.size());
            only = association;
        }
    }
    if (array == nullptr) array = findArray(field, name, only);
    int component = array != nullptr ? array->defaultComponent() : kMagnitude;
    const std::size_t colon = name.rfind(':');
    if (array == nullptr && colon != std::string::npos) {
        array = findArray(field, name.substr(0, colon), only);
        const std::string part = name.substr(colon + 1);
        if (array != nullptr && part != "magnitude") {
            const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), component);
            if (ec != std::errc() || end != part.data() + part.size() || component < 0 ||
                component >= array->components) {
                detail::failInput(field.sourcePath,
                                  "array '" + array->name + "' has " + std::to_string(array->components) +
                                      " component" + (array->components == 1 ? "" : "s") + "; '" + part +
                                      "' is not one of magnitude, 0.." + std::to_string(array->components - 1));
            }
        } else if (array != nullptr) {
            component = kMagnitude;
        }
    }
    if (array == nullptr) {
        detail::failInput(field.sourcePath, "no array '" + spec + "'; available: " + availableArrays(field));
    }

    field.name = array->name;
    if (array->components > 1 || component == kMagnitude) {
        field.name += component == kMagnitude ? " magnitude" : "[" + std::to_string(component) + "]";
    }
    const TriangleMesh& mesh = field.mesh;
    // The pictures colour 32-bit floats: a finite value beyond them became inf (undefined in C++),
    // and the picture one colour.
    const auto shown = [&](std::size_t tuple) {
        const double value = array->at(tuple, component);
        if (std::isfinite(value) && std::abs(value) > double(std::numeric_limits<float>::max()))
            detail::failInput(field.sourcePath,
                              "array '" + array->name + "' holds " + shortNumber(value) +
                                  ", beyond the 32-bit floats the pictures colour (3.4e+38): scale it");
        return float(value);
    };
    if (cellToPoint && array->association == Association::Point) {
        detail::failInput(field.sourcePath, "--cell-to-point averages a cell array; '" + array->name +
                                                "' is a point array (a cell array by name: --scalar cell:NAME)");
    }
    if (array->association == Association::Point) {
        // Vertices beyond the file's points (hole caps) have no value.
        field.values.assign(mesh.positions.size(), std::numeric_limits<float>::quiet_NaN());
        for (std::size_t v = 0; v < std::min(array->tuples(), field.values.size()); ++v) {
            field.values[v] = shown(v);
        }
        field.valuesOn = Association::Point;
        return;
    }
    IVIS_CHECK(field.triangleCells.size() == mesh.dataTriangleCount);
    std::vector<float> perTriangle(mesh.dataTriangleCount);
    for (std::size_t t = 0; t < perTriangle.size(); ++t)
        perTriangle[t] = shown(field.triangleCells[t]);
    if (cellToPoint) {
        field.values = core::cellToPoint(mesh, perTriangle);
        field.valuesOn = Association::Point;
        field.name += " (averaged)";
    } else {
        field.values = std::move(perTriangle);
        field.valuesOn = Association::Cell;
    }
}

const DataArray& defaultArray(const SurfaceField& field, bool cellToPoint)
{
    auto first = [&](auto chosen) { return std::find_if(field.arrays.begin(), field.arrays.end(), chosen); };
    const std::vector<Association> order =
        cellToPoint ? std::vector{Association::Cell} : std::vector{Association::Point, Association::Cell};
    for (const bool activeOnly : {true, false})
        for (const Association association : order) {
            const auto shown = first([&](const DataArray& a) {
                return (a.activeScalars || !activeOnly) && a.association == association;
            });
            if (shown != field.arrays.end()) return *shown;
        }
    IVIS_CHECK(cellToPoint);  // callers ask only of a field with arrays
    detail::failInput(field.sourcePath, "--cell-to-point averages a cell array, and the file has none");
}

}  // namespace ivis::core
