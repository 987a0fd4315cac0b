/// @file python_render.h
/// @brief inversevis.render: a picture of a Mesh as `inversevis render` makes it.
#pragma once

#include "python_mesh.h"
#include "python_picture.h"

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
    std::string scalar;                      ///< "" : the file's default array
    double theta = 90.0, phi = 0.0;
    std::optional<double> fov;               ///< given: fixed, not framed
    std::optional<pybind11::dict> camera;    ///< a camera file's JSON: fixed, not framed
    std::pair<int, int> size{1000, 1000};    ///< width, height
    std::string colormap = "viridis";
    std::optional<std::pair<double, double>> range;
    int volumeResolution = 200;
    double minCoherence;                     ///< the readable rule's minimum (0: the method's own rule)
    bool fullTrace = false;
    bool legend = true;
    bool shadows = true;
    bool transparent = false;
    int samplesPerPixel = 1;
    pybind11::dict parameters;               ///< the method's parameters by key
};

/// @brief The picture of @a mesh that @a request asks for, the GIL released while it is made.
std::shared_ptr<Picture> renderMesh(Mesh& mesh, const RenderRequest& request, const pybind11::object& progress);

}  // namespace ivis::python
