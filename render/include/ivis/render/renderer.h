/// @file renderer.h
/// @brief The TBB-parallel CPU renderer: one picture of a method at any size, with per-pixel
///        layers (depth, region, triangle, P, scalar, steps) and statistics.
/// @note The result does not depend on the number of threads.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/color_bar.h>
#include <ivis/core/image.h>
#include <ivis/core/interrupter.h>
#include <ivis/render/adaptive_sampling.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/render_scene.h>
#include <ivis/render/shading.h>

#include <cstddef>
#include <string>

namespace ivis::render {

/// @brief What to render and how.
struct RenderOptions {
    int width = 1000;
    int height = 1000;
    int samplesPerPixel = 1;  ///< supersampling: a fixed R2 pattern per pixel, the first at its centre
    MethodPtr method = defaultMethod();  ///< the method and its parameters
    AdaptiveSampling adaptive;  ///< how a curved-ray method's rays are sampled (off: the full trace)
    ShadingOptions shading;
    bool outline = true;      ///< dark outline around the directly visible object
    bool legend = true;       ///< colour bar with the scalar's name and range, in a margin
    core::LegendSide legendSide = core::LegendSide::Right;  ///< the margin's side
    int legendMinimumMargin = 0;  ///< the margin's least extent across the bar (equal frames of a series)
    std::string scalarName;   ///< legend title
    std::string units;        ///< legend units
};

/// @brief Counts over the pixel centres (regions) and over every traced indirect ray.
struct RenderStats {
    double seconds = 0.0;
    std::size_t pixelsDirect = 0;
    std::size_t pixelsIndirect = 0;
    std::size_t pixelsBackground = 0;
    std::size_t seedsInterpolated = 0;  ///< samples whose seeds adaptive sampling took from its lattice
    std::size_t pixelsSkipped = 0;      ///< samples adaptive sampling set to background without a ray
    std::size_t raysLaunched = 0;  ///< indirect rays traced (all samples; a curved-ray method's stability probes not counted)
    std::size_t raysLanded = 0;    ///< samples drawn from a ray of their own that landed
    std::size_t totalSteps = 0;    ///< integration steps over the traced rays
    std::size_t nanPixels = 0;     ///< pixel centres showing NaN data
    /// @brief Mean integration steps per launched ray (0 when none).
    double meanSteps() const { return raysLaunched ? double(totalSteps) / double(raysLaunched) : 0.0; }
};

/// @brief A rendered picture, its layers and its statistics.
struct RenderResult {
    core::Image image;               ///< the picture, width x height of the options
    core::Image figure;              ///< the picture with the colour bar in its margin (or the picture alone)
    core::ImageLayers layers{0, 0};  ///< per pixel of the picture
    RenderStats stats;
};

/// @brief Renders @a scene from @a camera.
/// @param interrupter optional progress (percent of rows) and cancel
/// @throw ValueError for bad options; Cancelled when interrupted
RenderResult renderImage(const RenderScene& scene, const core::Camera& camera, const RenderOptions& options,
                         core::Interrupter* interrupter = nullptr);

}  // namespace ivis::render
