/// @file python_optimize.h
/// @brief inversevis.optimize: the best view of a Mesh and its picture, as `inversevis optimize`
///        finds and draws it.
#pragma once

#include "python_mesh.h"
#include "python_picture.h"
#include "python_render.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace ivis::python {

/// @brief The arguments of optimize() beside the mesh, with `inversevis optimize`'s defaults.
struct OptimizeRequest {
    RenderRequest look;                        ///< method, its parameters, scalar, size, colours, volume
    std::string energy = "visibility";         ///< "visibility" or "scalar"
    std::optional<float> gamma;                ///< weight of the direct part (scalar energy; none: 1)
    int optResolution = 100;                   ///< rays per side while optimising
    int ascentResolution = 0;                  ///< rays per side of the per-view ascent; 0: optResolution
    int steps = 20;                            ///< annealing proposals after the start view
    std::uint64_t seed = 1;
    int finalists = 5;                         ///< best views measured again at 200 rays per side; 0, 1: none
    std::optional<int> hotSpotViews;           ///< views the hot-spot rule judges (scalar energy; none: 8); 0: none
    std::optional<std::pair<double, double>> start;  ///< (theta, phi) of the start; none: the best axis view
    int views = 1;                             ///< several views (Picture::views) when above 1
};

/// @brief The best view of @a mesh that @a request asks for, rendered; its measures and the
///        search's result (Picture::optimization). The GIL is released while it runs.
std::shared_ptr<Picture> optimizeMesh(const std::shared_ptr<Mesh>& drawn, const OptimizeRequest& request,
                                      const pybind11::object& progress);

}  // namespace ivis::python
