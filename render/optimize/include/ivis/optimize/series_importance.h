/// @file series_importance.h
/// @brief The field on which one optimisation serves a whole time series: the scalar energy of
///        its mean importance is the mean of the steps' scalar energies.
#pragma once

#include <ivis/core/colormap.h>
#include <ivis/core/surface_field.h>
#include <ivis/core/surface_series.h>

namespace ivis::optimize {

/// @brief The first step's surface showing, at each vertex (or triangle, for a cell array), the
///        mean over the steps of the importance @a range.normalized(value) (0 for NaN), named
///        "mean importance of N steps".
/// @note Measured with importance range [0, 1], its scalar energy is (1/N) times the sum of the
///       steps' scalar energies (importance range @a range), for every view and method, when no
///       value is NaN and none lies outside @a range: the steps share the geometry, so a view's rays
///       land at the same points in every step, and the importance is then linear in the value
///       (a NaN makes a whole triangle 0 in its step and clipping is not linear, so there the mean
///       is close but not exact). The visibility energy does not depend on the scalar.
/// @throw InputError naming a step's file when its geometry (core::meshHash) differs from the
///        first step's, or its values lie on the other association (point or cell)
core::SurfaceField meanImportanceField(core::SurfaceSeries& series, const core::ScalarRange& range);

}  // namespace ivis::optimize
