/// @file view_file.h
/// @brief A view file: everything but the mesh that fixes a picture (camera, method and its
///        parameters, scalar, colour map and scale, units, legend and look) in one JSON file, which
///        `optimize` and `render` write (--view-out), and `render --view`, `optimize --view` and
///        the viewer read; the viewer saves its own.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/color_bar.h>
#include <ivis/core/color_scale.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/renderer.h>

#include <nlohmann/json.hpp>

#include <string>

namespace ivis::app {

/// @brief The contents of a view file.
struct ViewFile {
    core::Camera camera;  ///< with the field of view the picture had (a view file is never re-framed)
    int width = 0;        ///< the picture's size in pixels
    int height = 0;
    render::MethodPtr method = render::defaultMethod();
    std::string scalar;   ///< --scalar as given ("" = the mesh's default array)
    std::string scalarFile;  ///< --scalar-file, as an absolute path ("" = none)
    bool cellToPoint = false;  ///< --cell-to-point
    int hotSpots = 0;     ///< --hotspots as given (0 = none)
    bool capHoles = false;  ///< --cap-holes
    std::string colormap = core::kDefaultColormap;
    core::ColorScale scale;
    std::string units;
    bool legend = true;
    core::LegendSide legendSide = core::LegendSide::Right;
    bool outline = true;
    bool shadows = true;
    bool shadeIndirect = true;
    int samplesPerPixel = 1;    ///< --spp
    bool transparent = false;   ///< --transparent
    core::Similarity meshUnits;  ///< the mesh's normalising transform (for reference: a picture does not use it)
};

/// @brief Version written as "inversevis_view"; readers reject newer ones.
inline constexpr int kViewFileVersion = 1;

/// @brief The view of a picture rendered from @a camera with @a options, its scalar chosen by
///        @a load, of a mesh normalised by @a meshUnits.
ViewFile viewOfPicture(const core::Camera& camera, const render::RenderOptions& options, const core::SurfaceLoadOptions& load,
                       const core::Similarity& meshUnits);

/// @brief The view as JSON: {"inversevis_view": 1, "camera": {...}, "size": [w, h], "method": {...},
///        "scalar", "scalar_file", "cell_to_point", "hotspots",
///        "colormap", "scale": {"range": [lo, hi], "log", "invert"}, "units", "legend": side or
///        null, "outline", "shadows", "shade_indirect", "spp", "transparent"}.
nlohmann::json viewToJson(const ViewFile& view);

/// @brief Reads a view file written by viewToJson (every key required but "units", "scalar",
///        "scalar_file", "cell_to_point", "hotspots", "spp" and "transparent", which files of
///        earlier versions of the program lack).
/// @throw InputError naming @a path for unreadable JSON, a missing key, a bad value or a newer version
ViewFile readViewFile(const std::string& path);

namespace detail {
/// @brief readViewFile on @a text, the bytes of the file @a path (what the fuzz target feeds).
ViewFile parseViewFile(const std::string& path, const std::string& text);
}  // namespace detail

/// @brief Writes @a view to @a path atomically.
void writeViewFile(const ViewFile& view, const std::string& path);

}  // namespace ivis::app
