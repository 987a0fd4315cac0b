/// @file colormap.h
/// @brief Named colour maps (viridis, coolwarm, grey and the published tables of assets/colormaps:
///        blue-white-red, inferno, magma, plasma, turbo) and the scalar range that feeds them.
/// @note Colour maps return LINEAR-light RGB; encode to sRGB only when writing 8-bit images.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace ivis::core {

/// @brief Name of the colour map used when none is chosen.
inline constexpr const char* kDefaultColormap = "viridis";

/// @brief A colour map: sRGB knots evenly spaced over [0,1], interpolated linearly in sRGB (as
///        matplotlib's LinearSegmentedColormap does) and returned in linear light.
class Colormap {
public:
    /// @brief Map called @a name through @a srgbKnots (sRGB-encoded, each channel in [0,1]).
    /// @throw ValueError for fewer than two knots
    Colormap(std::string name, std::vector<glm::vec3> srgbKnots);

    /// @brief The name colormap() knows this map by.
    const std::string& name() const { return mName; }
    /// @brief Linear-light RGB in [0,1] at @a t, which is clamped to [0,1] (NaN maps like 0).
    glm::vec3 at(float t) const;

private:
    std::string mName;
    std::vector<glm::vec3> mSrgbKnots;
};

/// @brief Names colormap() accepts, default first: viridis, coolwarm, grey, then the tables.
std::vector<std::string> colormapNames();

/// @brief The built-in map called @a name: "viridis" (matplotlib), "coolwarm" (Moreland's
///        diverging map, Msh interpolation through white), "grey" (black to white, even in sRGB).
/// @return a reference valid for the whole program
/// @throw InputError "unknown colour map 'x' (known: viridis, coolwarm, grey, ...)"
/// @warning Thread-safe; the maps are built on first use.
const Colormap& colormap(const std::string& name);

/// @brief Scalar interval mapped onto a colour map's [0,1].
struct ScalarRange {
    float lo = 0.0f;
    float hi = 1.0f;

    /// @brief (value - lo) / (hi - lo) clamped to [0,1]; 0.5 when lo == hi; NaN stays NaN.
    float normalized(float value) const;
};

/// @brief Finite minimum and maximum of @a values (NaN and infinities ignored); {0,0} when no
///        value is finite.
ScalarRange scalarRangeFromData(const std::vector<float>& values);

/// @brief A range given by the user (--range lo hi).
/// @throw ValueError unless lo and hi are finite, representable as float, and lo < hi
ScalarRange scalarRangeFromUser(double lo, double hi);

}  // namespace ivis::core
