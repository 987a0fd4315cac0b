/// @file color_scale.h
/// @brief How scalar values become positions on a colour map: a range, linear or logarithmic,
///        optionally inverted; and the user's request (--range, --range-percentile, --symmetric,
///        --log, --invert) resolved against the data.
#pragma once

#include <ivis/core/colormap.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core {

/// @brief A scalar range mapped onto a colour map's [0,1], linearly or by the logarithm.
struct ColorScale {
    ScalarRange range{0.0f, 1.0f};
    bool log = false;     ///< positions by log10(value) (range.lo > 0)
    bool invert = false;  ///< lo at the colour map's top end, hi at its bottom

    /// @brief Colour-map position of @a value in [0,1], clamped; NaN stays NaN; values <= 0 on a log
    ///        scale map like range.lo; 0.5 when lo == hi.
    float position(float value) const;
    /// @brief The value at colour-map position @a t in [0,1] (inverse of position within the range).
    double valueAt(double t) const;
};

/// @brief The colour-scale options of a command line; resolve() fixes the range from the data.
struct ColorScaleRequest {
    std::optional<ScalarRange> range;                     ///< --range lo hi
    std::optional<std::pair<double, double>> percentiles; ///< --range-percentile LO HI (0..100)
    bool symmetric = false;                               ///< --symmetric: [-m, m], m the larger |end|
    bool log = false;                                     ///< --log
    bool invert = false;                                  ///< --invert

    /// @brief Checks the options against each other (before any data is read).
    /// @throw ValueError e.g. "--log and --symmetric exclude each other", a percentile outside
    ///        [0, 100] or LO >= HI, --log with a range whose low end is not positive
    void validate() const;
    /// @brief The scale for @a values (NaN and infinities ignored): the given range, else the
    ///        percentiles of the values (of the positive ones on a log scale), else their minimum
    ///        and maximum (the smallest positive value as the low end on a log scale); then
    ///        widened symmetrically about 0 when asked.
    /// @param source the file or series the values are of, which that message names ("" for none)
    /// @throw ValueError for a log scale over data without a positive value
    ColorScale resolve(const std::vector<float>& values, const std::string& source = "") const;
};

/// @brief The @a percent-th percentile (0..100) of the finite @a values by linear interpolation
///        between order statistics (NumPy's default); NaN when no value is finite.
double percentile(std::vector<float> values, double percent);

}  // namespace ivis::core
