/// @file python_render.h
/// @brief inversevis.render: a picture of a Mesh as `inversevis render` makes it.
#pragma once

#include "python_mesh.h"
#include "python_picture.h"

#include <ivis/core/color_scale.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/method.h>
#include <ivis/render/renderer.h>
#include <ivis/vdb/surface_volume.h>

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ivis::python {

/// @brief The arguments of render() beside the mesh, with `inversevis render`'s defaults.
struct RenderRequest {
    std::string method = "inversevis-wrap";
    core::SurfaceLoadOptions load;           ///< what it shows: scalar=, cell_to_point=, hotspots=, cap_holes=
    double theta = 90.0, phi = 0.0;
    std::optional<double> fov;               ///< given: fixed, not framed
    bool orthographic = false;               ///< an orthographic camera (--ortho)
    std::optional<pybind11::dict> camera;    ///< a camera file's JSON: fixed, not framed
    std::pair<int, int> size{1000, 1000};    ///< width, height
    std::string colormap = "viridis";
    std::optional<std::pair<double, double>> range;
    std::optional<std::pair<double, double>> rangePercentile;  ///< the range at these percentiles (--range-percentile)
    bool symmetric = false;                  ///< the range centred on 0 (--symmetric)
    bool log = false;                        ///< a log colour scale (--log)
    bool invert = false;                     ///< the colour map reversed (--invert)
    std::string units;                       ///< the colour bar's units (--units)
    std::string legendSide = "right";        ///< the colour bar's side (--legend)
    bool outline = true;                     ///< the direct part's outline (--no-outline)
    bool shadeIndirect = true;               ///< indirect pixels lit (--unshaded-indirect)
    int volumeResolution = 200;
    double minCoherence;                     ///< the readable rule's minimum (0: the method's own rule)
    bool fullTrace = false;
    bool legend = true;
    bool shadows = true;
    bool transparent = false;
    int samplesPerPixel = 1;
    bool measure = false;                    ///< also what `render --measure` measures
    pybind11::dict parameters;               ///< the method's parameters by key
    std::string function = "render";         ///< the Python function asked (its name in messages)
};

/// @brief Method @a method's parameters from the keywords @a function was given beyond its own: each a
///        number, or a sequence of numbers per component.
/// @throw TypeError (py::type_error) for a keyword that names no parameter of the method, or a value
///        of another kind
render::ParameterValues parameterValues(const pybind11::dict& parameters, const std::string& method,
                                        const std::string& function);

/// @brief The method @a name with @a values (render::makeMethod), its errors naming the parameters
///        as keywords (stable_shift) instead of options (--stable-shift).
render::MethodPtr methodWith(const std::string& name, const render::ParameterValues& values);

/// @brief The volume a picture of @a method needs at @a resolution: the far field reaching as far
///        as its rays fly (as `render` raises --reach for them).
vdb::VolumeOptions volumeFor(const render::MethodPtr& method, int resolution);

/// @brief A request's look, checked: the render options (method, size, colours), the colour scale
///        asked for, the method's parameters as given and the volume it needs.
struct PictureLook {
    render::RenderOptions options;
    core::ColorScaleRequest scale;
    render::ParameterValues values;
    vdb::VolumeOptions volume;
    std::vector<std::string> colourKeywords;  ///< the colour keywords given other than their defaults ("log")

    /// @brief Colours by @a field's scalar (of @a mesh): the scale over its data unless given.
    /// @throw InputError when a colour keyword is given and the field has no scalar
    void colourBy(const Mesh& mesh, const core::SurfaceField& field);
    /// @brief Refuses the colour keywords given for a mesh whose @a field shows no scalar, as
    ///        `render` refuses --colormap, --range, --log ... there.
    /// @throw InputError naming the first
    void checkColourKeywords(const Mesh& mesh, const core::SurfaceField& field) const;
};

/// @brief Checks every argument of @a request but the camera's and the mesh's.
/// @throw ValueError / InputError / TypeError naming the argument
PictureLook pictureLook(const RenderRequest& request);

/// @brief The picture of @a mesh that @a request asks for, the GIL released while it is made.
std::shared_ptr<Picture> renderMesh(const std::shared_ptr<Mesh>& drawn, const RenderRequest& request,
                                    const pybind11::object& progress);

}  // namespace ivis::python
