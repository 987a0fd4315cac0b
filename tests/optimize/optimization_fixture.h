/// @file optimization_fixture.h
/// @brief The energy options and methods the optimisation tests share.
#pragma once

#include <ivis/core/colormap.h>
#include <ivis/core/surface_field.h>
#include <ivis/optimize/energy.h>
#include <ivis/render/method_registry.h>

namespace ivis::optimize {

using render::makeMethod;
using render::MethodPtr;

/// The scalar energy at @a resolution rays per side, importance over @a field's data range.
inline EnergyOptions scalarOptions(const core::SurfaceField& field, int resolution)
{
    EnergyOptions options;
    options.kind = EnergyKind::Scalar;
    options.resolution = resolution;
    options.importanceRange = core::scalarRangeFromData(field.values);
    return options;
}

/// The visibility energy at @a resolution rays per side, on a 64^3 grid.
inline EnergyOptions visibilityOptions(int resolution)
{
    EnergyOptions options;
    options.resolution = resolution;
    options.visibilityResolution = 64;
    return options;
}

/// The adaptive InverseVis with the alpha profile (@a a0, @a a1, @a a2).
inline MethodPtr adaptive(float a0, float a1, float a2)
{
    return makeMethod("inversevis-adaptive", {{"alpha_profile", {a0, a1, a2}}});
}

/// The faithful InverseVis at @a alpha.
inline MethodPtr faithful(float alpha = 0.5f) { return makeMethod("inversevis", {{"alpha", {alpha}}}); }

}  // namespace ivis::optimize
