/// @file series_survey.h
/// @brief What loading every step of a time series finds before anything is shown: the colour
///        range shared by all steps and each step's geometry.
#pragma once

#include <ivis/core/color_bar.h>
#include <ivis/core/color_scale.h>
#include <ivis/core/colormap.h>
#include <ivis/core/surface_series.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief Most values SeriesSurvey::sample holds (before the extremes are added).
inline constexpr std::size_t kSurveySampleSize = 4000000;

/// @brief The facts of a series that take every step to know.
struct SeriesSurvey {
    core::ScalarRange range{0.0f, 0.0f};    ///< finite range of the shown scalars over all steps ({0, 0}: none)
    std::vector<core::ColorScale> stepScales;   ///< each step's own scale (surveySeries' eachStep; else empty)
    std::vector<float> sample;              ///< the shown scalars of all steps for the colour scale: all of
                                            ///< them up to kSurveySampleSize, else an even subsample plus the
                                            ///< extremes (the smallest positive value included)
    std::vector<std::uint64_t> meshHashes;  ///< core::meshHash of each step's normalised mesh
    bool scalar = false;                    ///< whether the steps show a scalar (each shows the same array)
};

/// @brief The colour bar's title of @a step of @a series showing the scalar @a name: the name, and
///        which step it is unless the name says it (a pattern's array): "pressure, t = 600" (a
///        .pvd), "pressure, b.vtp" (a list of files).
std::string seriesStepTitle(const core::SurfaceSeries& series, const core::SeriesStep& step, const std::string& name);

/// @brief The widest colour-bar margin over the steps of @a series beside a @a width x @a height
///        picture, so that every frame has the same size: each step's title (of the scalar @a name,
///        or of the step's own array) with @a look's colour map, scale and units, or each step's own
///        scale where @a stepScales gives it (each frame's range its own).
int seriesLegendMargin(const core::SurfaceSeries& series, const core::ColorBarContent& look, const std::string& name,
                       int width, int height, core::LegendSide side,
                       const std::vector<core::ColorScale>& stepScales = {});

/// @brief Loads every step of @a series silently (so that a bad step fails alone, before anything
///        is written or said) and surveys them; with @a eachStep, resolves each step's own scale
///        from its values (each frame's range its own: --range-per-frame).
/// @param cancel when given and set, the survey stops before its next step (the viewer's survey in
///        the background)
/// @throw InputError naming the step's file for a step that cannot be loaded; ValueError when
///        @a eachStep cannot resolve a step's scale (a log scale over a step without a positive value);
///        Cancelled when @a cancel is set
SeriesSurvey surveySeries(core::SurfaceSeries& series, const core::ColorScaleRequest* eachStep = nullptr,
                          const std::atomic<bool>* cancel = nullptr);

}  // namespace ivis::app
